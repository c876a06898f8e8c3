#!/usr/bin/env bash
# tests/sweeps/pareto.sh: speed against accuracy, one point per configuration
# (docs/results/speed-vs-accuracy.md).  `make figures` runs it.
#
# Scene: scenes/demo.scn at SIZE (default 160x120): refraction, a mirror,
# density spheres, colour and bump maps.  Reference: the double build with
# max_depth 8 and adaptive depth off.  Configurations: the arithmetic
# (double, float = soft on the host, fixed with every fraction-bit count
# that builds, 12..19), max_depth 1..8, adaptive depth on (min_weight 1/512)
# and off, density root-finder steps 8..64 (--density-steps),
# refraction off (transmitted rays never bend), float and fixed Q12.19 at
# depth 5 escalated (a pixel that lost precision traced again in double;
# float escalated is the default, marked in both charts; every other
# configuration runs with --no-escalate).
# Cost on the host: ns per pixel of tracing ("traced in" of links1 ref), the
# median of RUNS (default 3) runs.  Cost on the board: the NCs' guest
# instructions per pixel (links1 render --count-insns, the TCG plugin; the
# sum over the NCs, which does not depend on how the areas were shared
# out), one run (it varies by a few instructions per pixel between runs),
# for every configuration the board runs: float (VFP) and soft at every
# depth, adaptive on and off, refraction off, double (VFP in double
# precision) at every depth adaptive and at depth 5 without, fixed Q12.19
# at depth 5, and the other fixed formats at depth 5 with firmware built
# by this script into DIR/fw-qF (make B=DIR/fw-qF
# FW_EXTRA_CFLAGS=-DNUM_FRAC_BITS=F, never the default build); no
# density-step variants on the board.  Error: PSNR against the reference, share of
# pixels beyond 1/255 and 2/255; a board image is also checked to be the
# host image of the same arithmetic, byte for byte.  The Pareto front (no
# other point both cheaper and closer) is marked on each chart; the board's
# chart also marks the front of an NC without an FPU (soft and fixed).  Writes
# DIR/pareto.tsv and DIR/pareto.png (host), DIR/pareto-board.tsv and
# DIR/pareto-board.png (board).
#   bash tests/sweeps/pareto.sh [--out DIR] [--charts-only]
#     (--charts-only: the fronts and charts again from DIR/*.raw, nothing run)
#   PARETO_SMALL=1 bash tests/sweeps/pareto.sh --out DIR   # the reduced run
#     (tests/sweeps/pareto_small.sh: 40x30, one run, depth 2 only; on the
#     board float, soft, double and fixed adaptive and float with
#     refraction off)
set -eu
cd "$(dirname "$0")/../.."
. tests/bench/bench_args.sh
bench_args pareto.sh build/pareto "$@"
SMALL=${PARETO_SMALL:-0}
if [ "$SMALL" = 1 ]; then
    SIZE=${SIZE:-40x30} RUNS=${RUNS:-1} DEPTHS=2 FRACS= STEPS=
else
    SIZE=${SIZE:-160x120} RUNS=${RUNS:-3} DEPTHS="1 2 3 4 5 6 8" FRACS="12 13 14 15 16 17 18"
    STEPS="8 16 32 64"
fi
NCS=${PARETO_NCS:-4}
LIMIT_S=${PARETO_RUN_LIMIT_S:-900}
export FW_DIR=${FW_DIR:-build}
scene=scenes/demo.scn
# front RAW TSV: RAW sorted by cost (column 2), the last column "yes"
# on the front: closer (column 3, PSNR) than every cheaper point
front() {
    {
        head -n 1 "$1"
        tail -n +2 "$1" | sort -t$'\t' -k2,2g -k3,3gr |
            awk -F'\t' -v OFS='\t' '{ $NF = ($3 + 0 > best) ? "yes" : ""; if ($3 + 0 > best) best = $3 + 0; print }'
    } >"$2"
}

dm=5 # the depth of the escalated and fixed-format configurations, and the default's
[ "$SMALL" = 1 ] && dm=2

if bench_measuring; then # --charts-only redraws from DIR/*.raw
mkdir -p "$out/bin"
make -s --no-print-directory build/links1 build/links1-ref-double build/links1-ref-float \
    build/links1-ref-fixed
srcs=$(make -s --no-print-directory \
    --eval 'print-ref-srcs: ; @echo $(links1-ref-fixed_SRCS) $(SHARED_SRCS)' print-ref-srcs)
libs=$(make -s --no-print-directory \
    --eval 'print-ref-libs: ; @echo $(links1-ref-fixed_LIBS)' print-ref-libs)
# the sources' own flags (a FILE_CFLAGS of a module.mk: libassimp's soname)
src_flags=$(make -s --no-print-directory \
    --eval 'print-src-flags: ; @echo $(foreach f,$(links1-ref-fixed_SRCS) $(SHARED_SRCS),$($(f)_CFLAGS))' \
    print-src-flags)
# variant NAME FLAGS...: a reference renderer built with other constants
variant() {
    local name=$1; shift
    [ -x "$out/bin/$name" ] ||
        cc -std=gnu11 -O2 -I. -ffp-contract=off $src_flags "$@" $srcs $libs -lpng -lm -o "$out/bin/$name"
}
for f in $FRACS; do variant fixed-$f -DLINKS1_NUM_FIXED -DNUM_FRAC_BITS=$f; done

ref=$out/reference.png
build/links1-ref-double "$scene" --size "$SIZE" --max-depth 8 --min-weight 0 -o "$ref" >/dev/null 2>&1
pixels=$(( ${SIZE%x*} * ${SIZE#*x} ))

# image NAME: the file of configuration NAME's image
image() { echo "$out/$(echo "$1" | tr ' ,.' '___').png"; }

# errors IMG: "PSNR<TAB>beyond 1/255 %<TAB>beyond 2/255 %" against the reference
errors() {
    local c1 c2 w1 w2 psnr
    c1=$(build/links1 compare "$ref" "$1" --within 1 --min-fraction 0)
    c2=$(build/links1 compare "$ref" "$1" --within 2 --min-fraction 0)
    w1=$(echo "$c1" | sed -nE 's/.*on every channel: ([0-9.]+)%.*/\1/p')
    w2=$(echo "$c2" | sed -nE 's/.*on every channel: ([0-9.]+)%.*/\1/p')
    psnr=$(echo "$c2" | sed -nE 's/.*PSNR ([0-9.]+) dB.*/\1/p')
    awk -v q="$psnr" -v w1="$w1" -v w2="$w2" \
        'BEGIN { printf "%s\t%.3f\t%.3f", q, 100 - w1, 100 - w2 }'
}

# ------------------------------------------------------------------ host
# name|program|arguments
configs=()
for d in $DEPTHS; do
    configs+=("float d$d adaptive|build/links1-ref-float|--max-depth $d")
    configs+=("float d$d fixed cutoff|build/links1-ref-float|--max-depth $d --min-weight 0")
    configs+=("double d$d adaptive|build/links1-ref-double|--max-depth $d")
done
configs+=("float d$dm adaptive, refraction off|build/links1-ref-float|--max-depth $dm --refraction off")
configs+=("double d$dm fixed cutoff|build/links1-ref-double|--max-depth $dm --min-weight 0")
configs+=("fixed Q12.19 d$dm adaptive|build/links1-ref-fixed|--max-depth $dm")
configs+=("fixed Q12.19 d$dm fixed cutoff|build/links1-ref-fixed|--max-depth $dm --min-weight 0")
# escalation: a pixel that lost precision traced again in double
configs+=("float d$dm adaptive, escalated|build/links1-ref-float|--max-depth $dm --escalate")
configs+=("fixed Q12.19 d$dm adaptive, escalated|build/links1-ref-fixed|--max-depth $dm --escalate")
for f in $FRACS; do
    configs+=("fixed Q$((31 - f)).$f d5 adaptive|$out/bin/fixed-$f|--max-depth 5")
done
for s in $STEPS; do
    configs+=("float d5 adaptive, $s density steps|build/links1-ref-float|--max-depth 5 --density-steps $s")
done

printf 'config\tns_per_pixel\tpsnr_db\tbeyond1_pct\tbeyond2_pct\tlost_pixels\tfront\n' >"$out/pareto.raw"
for c in "${configs[@]}"; do
    IFS='|' read -r name prog args <<<"$c"
    [[ $args == *--escalate* ]] || args="$args --no-escalate" # plain: the arithmetic's own
    img=$(image "$name")
    times=()
    for ((r = 0; r < RUNS; r++)); do
        log=$("$prog" "$scene" --size "$SIZE" $args -o "$img" 2>&1)
        times+=("$(echo "$log" | sed -nE 's/.*traced in ([0-9.]+) s.*/\1/p')")
    done
    secs=$(printf '%s\n' "${times[@]}" | sort -g | sed -n "$(( (RUNS + 1) / 2 ))p")
    lost=$(echo "$log" | grep -o '[0-9]* pixels in doubt' | grep -o '^[0-9]*')
    err=$(errors "$img")
    awk -v n="$name" -v s="$secs" -v p="$pixels" -v e="$err" -v l="$lost" \
        'BEGIN { printf "%s\t%.0f\t%s\t%s\t\n", n, s * 1e9 / p, e, l }' >>"$out/pareto.raw"
done

# ----------------------------------------------------------------- board
# name|arithmetic|arguments|the host configuration whose image it must be
bconfigs=()
for d in $DEPTHS; do
    for a in float soft; do
        bconfigs+=("$a d$d adaptive|$a|--max-depth $d|float d$d adaptive")
        [ "$SMALL" = 1 ] ||
            bconfigs+=("$a d$d fixed cutoff|$a|--max-depth $d --min-weight 0|float d$d fixed cutoff")
    done
    bconfigs+=("double d$d adaptive|double|--max-depth $d|double d$d adaptive")
done
[ "$SMALL" = 1 ] ||
    bconfigs+=("double d$dm fixed cutoff|double|--max-depth $dm --min-weight 0|double d$dm fixed cutoff")
bconfigs+=("float d$dm adaptive, refraction off|float|--max-depth $dm --refraction off|float d$dm adaptive, refraction off")
[ "$SMALL" = 1 ] ||
    bconfigs+=("soft d$dm adaptive, refraction off|soft|--max-depth $dm --refraction off|float d$dm adaptive, refraction off")
bconfigs+=("fixed Q12.19 d$dm adaptive|fixed|--max-depth $dm|fixed Q12.19 d$dm adaptive")
[ "$SMALL" = 1 ] ||
    bconfigs+=("fixed Q12.19 d$dm fixed cutoff|fixed|--max-depth $dm --min-weight 0|fixed Q12.19 d$dm fixed cutoff")
# escalated (the -esc firmware, which needs the VFP for its double)
bconfigs+=("float d$dm adaptive, escalated|float|--max-depth $dm --escalate|float d$dm adaptive, escalated")
bconfigs+=("fixed Q12.19 d$dm adaptive, escalated|fixed|--max-depth $dm --escalate|fixed Q12.19 d$dm adaptive, escalated")
for f in $FRACS; do # firmware with another fixed format, in this script's own build dir
    fw=$out/fw-q$f
    make -s --no-print-directory B="$fw" FW_EXTRA_CFLAGS=-DNUM_FRAC_BITS=$f "$fw/links1-fixed.elf"
    bconfigs+=("fixed Q$((31 - f)).$f d5 adaptive|fixed|--max-depth 5 --firmware $fw/links1-fixed.elf|fixed Q$((31 - f)).$f d5 adaptive")
done

printf 'config\tnc_insns_per_pixel\tpsnr_db\tbeyond1_pct\tbeyond2_pct\tarith\tsame_as_host\tfront\n' \
    >"$out/pareto-board.raw"
for c in "${bconfigs[@]}"; do
    IFS='|' read -r name arith args host <<<"$c"
    [[ $args == *--escalate* ]] || args="$args --no-escalate" # plain: the arithmetic's own
    img="$out/board-$(basename "$(image "$name")")"
    log="$img.log"
    if ! timeout "$LIMIT_S" build/links1 render --count-insns "$scene" --arith "$arith" \
        --ncs "$NCS" --size "$SIZE" $args -o "$img" >"$log" 2>&1; then
        echo "pareto: links1 render $name failed: $(tail -n 1 "$log")" >&2
        exit 1
    fi
    total=$(grep -o 'NCs total [0-9]*' "$log" | grep -o '[0-9]*$' || true)
    if [ -z "$total" ]; then
        echo "pareto: no instruction counts in $log" >&2
        exit 1
    fi
    same=no
    cmp -s "$img" "$(image "$host")" && same=yes
    err=$(errors "$img")
    awk -v n="$name" -v t="$total" -v p="$pixels" -v e="$err" -v a="$arith" -v s="$same" \
        'BEGIN { printf "%s\t%.0f\t%s\t%s\t%s\t\n", n, t / p, e, a, s }' >>"$out/pareto-board.raw"
done
fi
pixels=$(( ${SIZE%x*} * ${SIZE#*x} ))
front "$out/pareto.raw" "$out/pareto.tsv"
# the board's front, and the front of the NCs without an FPU (soft, fixed)
front "$out/pareto-board.raw" "$out/pareto-board.sorted"
awk -F'\t' -v OFS='\t' 'NR == 1 { print $0, "front_no_fpu"; next }
    { f = ""; if ($6 != "float" && $6 != "double" && $1 !~ /escalated/ && $3 + 0 > best) { f = "yes"; best = $3 + 0 } print $0, f }' \
    "$out/pareto-board.sorted" >"$out/pareto-board.tsv"
rm -f "$out/pareto-board.sorted"

# ---------------------------------------------------------------- charts
awk -F'\t' 'NR > 1 { print $2, $3 }' "$out/pareto.tsv" >"$out/all.dat"
awk -F'\t' 'NR > 1 && $7 == "yes" { print $2, $3 }' "$out/pareto.tsv" >"$out/front.dat"
# labels on the front's points only (the table has them all)
awk -F'\t' 'NR > 1 && $7 == "yes" { printf "%s %s \"%s\"\n", $2, $3, $1 }' "$out/pareto.tsv" >"$out/labels.dat"
for a in float soft fixed double; do
    awk -F'\t' -v a=$a 'NR > 1 && $6 == a && $1 !~ /escalated/ { print $2, $3 }' \
        "$out/pareto-board.tsv" >"$out/board-$a.dat"
done
awk -F'\t' 'NR > 1 && $1 ~ /escalated/ { print $2, $3 }' "$out/pareto-board.tsv" \
    >"$out/board-escalated.dat"
# the default configuration: float at the scenes' depth, escalating
default="float d$dm adaptive, escalated"
awk -F'\t' -v d="$default" 'NR > 1 && $1 == d { print $2, $3 }' "$out/pareto.tsv" >"$out/default.dat"
awk -F'\t' -v d="$default" 'NR > 1 && $1 == d { print $2, $3 }' "$out/pareto-board.tsv" \
    >"$out/board-default.dat"
awk -F'\t' 'NR > 1 && $8 == "yes" { print $2, $3 }' "$out/pareto-board.tsv" >"$out/board-front.dat"
awk -F'\t' 'NR > 1 && $9 == "yes" { print $2, $3 }' "$out/pareto-board.tsv" >"$out/board-front-nofpu.dat"
# labels on the fronts' points only (the table has them all), each front's
# by turns left and right of its points (column 4: 0 left, 1 right)
awk -F'\t' 'NR > 1 && ($8 == "yes" || $9 == "yes") { n = $1; sub(/^(float|soft|fixed|double) /, "", n);
    k = $8 == "yes" ? 0 : 1; printf "%s %s \"%s\" %d\n", $2, $3, n, turn[k]++ % 2 }' \
    "$out/pareto-board.tsv" >"$out/board-labels.dat"
if command -v gnuplot >/dev/null; then
    gnuplot <<GP
set terminal pngcairo size 900,560 font ",9" noenhanced
set output "$out/pareto.png"
set title "demo.scn $SIZE: host cost against PSNR (reference: double, max_depth 8, no adaptive depth)"
set xlabel "host ns per pixel (median of $RUNS runs)"
set ylabel "PSNR against the reference, dB"
set logscale x
set grid
set key bottom right
plot "$out/all.dat" using 1:2 with points pt 7 ps 0.8 title "configuration (all: pareto.tsv)", \
     "$out/front.dat" using 1:2 with linespoints lw 2 pt 6 ps 1.5 title "Pareto front", \
     "$out/labels.dat" using 1:2:3 with labels font ",7" offset 0,0.7 notitle, \
     "$out/default.dat" using 1:2 with points pt 4 ps 2.2 lw 2 title "the default ($default)"
set output "$out/pareto-board.png"
set title "demo.scn $SIZE on the board ($NCS NCs): NC instructions per pixel against PSNR (same reference)"
set xlabel "NC guest instructions per pixel (sum over the NCs, TCG plugin)"
plot "$out/board-float.dat" using 1:2 with points pt 7 ps 0.9 title "float (VFP)", \
     "$out/board-soft.dat" using 1:2 with points pt 5 ps 0.9 title "soft float", \
     "$out/board-fixed.dat" using 1:2 with points pt 9 ps 1.1 title "fixed point (Q12.19, and the other formats' firmware)", \
     "$out/board-double.dat" using 1:2 with points pt 13 ps 1.0 title "double (VFP, double precision)", \
     "$out/board-escalated.dat" using 1:2 with points pt 11 ps 1.4 title "float and fixed escalated (lost pixels traced again in double; --no-escalate: the others)", \
     "$out/board-default.dat" using 1:2 with points pt 4 ps 2.2 lw 2 title "the default ($default)", \
     "$out/board-front.dat" using 1:2 with linespoints lw 2 pt 6 ps 1.5 title "Pareto front", \
     "$out/board-front-nofpu.dat" using 1:2 with linespoints lw 2 dt 2 pt 6 ps 1.5 title "Pareto front without an FPU (soft, fixed)", \
     "$out/board-labels.dat" using 1:(\$4 == 0 ? \$2 : NaN):3 with labels right font ",7" offset -1,0 notitle, \
     "$out/board-labels.dat" using 1:(\$4 == 1 ? \$2 : NaN):3 with labels left font ",7" offset 1,0 notitle
GP
fi
column -t -s$'\t' "$out/pareto.tsv"
echo
column -t -s$'\t' "$out/pareto-board.tsv"
