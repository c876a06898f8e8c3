#!/usr/bin/env bash
# tests/sweeps/pareto.sh: speed against accuracy, one point per configuration
# (docs/RESULTS.md, "The Pareto chart").  `make figures` runs it.
#
# Scene: scenes/demo.scn at SIZE (default 160x120): refraction, a mirror,
# density spheres, colour and bump maps.  Reference: the double build with
# max_depth 8 and adaptive depth off.  Configurations: the arithmetic
# (double, float = soft on the host, fixed with every fraction-bit count
# that builds, 12..19), max_depth 1..8, adaptive depth on (min_weight 1/512)
# and off, density root-finder steps 8..64 (RENDER_DENSITY_SAMPLES).
# Cost: host ns per pixel of tracing ("traced in" of links1 ref), the median
# of RUNS (default 3) runs.  Error: PSNR against the reference, share of
# pixels beyond 1/255 and 2/255.  The Pareto front (no other point both
# cheaper and closer) is marked.  Writes DIR/pareto.tsv and DIR/pareto.png.
#   bash tests/sweeps/pareto.sh [--out DIR]
set -eu
cd "$(dirname "$0")/../.."
out=build/pareto
[ "${1:-}" = --out ] && out=$2
SIZE=${SIZE:-160x120}
RUNS=${RUNS:-3}
scene=scenes/demo.scn
mkdir -p "$out/bin"
make -s --no-print-directory build/links1 build/links1-ref-double build/links1-ref-float \
    build/links1-ref-fixed
srcs=$(make -s --no-print-directory \
    --eval 'print-ref-srcs: ; @echo $(links1-ref-fixed_SRCS) $(SHARED_SRCS)' print-ref-srcs)
libs=$(make -s --no-print-directory \
    --eval 'print-ref-libs: ; @echo $(links1-ref-fixed_LIBS)' print-ref-libs)
# variant NAME FLAGS...: a reference renderer built with other constants
variant() {
    local name=$1; shift
    [ -x "$out/bin/$name" ] ||
        cc -std=gnu11 -O2 -I. -ffp-contract=off "$@" $srcs $libs -lpng -lm -o "$out/bin/$name"
}
for f in 12 13 14 15 16 17 18; do variant fixed-$f -DLINKS1_NUM_FIXED -DNUM_FRAC_BITS=$f; done
for s in 8 16 32 64; do variant float-steps$s -DLINKS1_NUM_FLOAT -DRENDER_DENSITY_SAMPLES=$s; done

ref=$out/reference.png
build/links1-ref-double "$scene" --size "$SIZE" --max-depth 8 --min-weight 0 -o "$ref" >/dev/null 2>&1

# name|program|arguments
configs=()
for d in 1 2 3 4 5 6 8; do
    configs+=("float d$d adaptive|build/links1-ref-float|--max-depth $d")
    configs+=("float d$d fixed cutoff|build/links1-ref-float|--max-depth $d --min-weight 0")
done
configs+=("double d5 adaptive|build/links1-ref-double|--max-depth 5")
configs+=("double d5 fixed cutoff|build/links1-ref-double|--max-depth 5 --min-weight 0")
configs+=("fixed Q12.19 d5 adaptive|build/links1-ref-fixed|--max-depth 5")
configs+=("fixed Q12.19 d5 fixed cutoff|build/links1-ref-fixed|--max-depth 5 --min-weight 0")
for f in 12 13 14 15 16 17 18; do
    configs+=("fixed Q$((31 - f)).$f d5 adaptive|$out/bin/fixed-$f|--max-depth 5")
done
for s in 8 16 32 64; do
    configs+=("float d5 adaptive, $s density steps|$out/bin/float-steps$s|--max-depth 5")
done

pixels=$(( ${SIZE%x*} * ${SIZE#*x} ))
printf 'config\tns_per_pixel\tpsnr_db\tbeyond1_pct\tbeyond2_pct\tlost_pixels\tfront\n' >"$out/pareto.raw"
for c in "${configs[@]}"; do
    IFS='|' read -r name prog args <<<"$c"
    img=$out/$(echo "$name" | tr ' ,.' '___').png
    times=()
    for ((r = 0; r < RUNS; r++)); do
        log=$("$prog" "$scene" --size "$SIZE" $args -o "$img" 2>&1)
        times+=("$(echo "$log" | sed -nE 's/.*traced in ([0-9.]+) s.*/\1/p')")
    done
    secs=$(printf '%s\n' "${times[@]}" | sort -g | sed -n "$(( (RUNS + 1) / 2 ))p")
    lost=$(echo "$log" | grep -o '[0-9]* pixels lost' | grep -o '^[0-9]*')
    c1=$(build/links1 compare "$ref" "$img" --within 1 --min-fraction 0)
    c2=$(build/links1 compare "$ref" "$img" --within 2 --min-fraction 0)
    w1=$(echo "$c1" | sed -nE 's/.*on every channel: ([0-9.]+)%.*/\1/p')
    w2=$(echo "$c2" | sed -nE 's/.*on every channel: ([0-9.]+)%.*/\1/p')
    psnr=$(echo "$c2" | sed -nE 's/.*PSNR ([0-9.]+) dB.*/\1/p')
    awk -v n="$name" -v s="$secs" -v p="$pixels" -v q="$psnr" -v w1="$w1" -v w2="$w2" -v l="$lost" \
        'BEGIN { printf "%s\t%.0f\t%s\t%.3f\t%.3f\t%s\t\n", n, s * 1e9 / p, q, 100 - w1, 100 - w2, l }' \
        >>"$out/pareto.raw"
done
# the front: sorted by cost, a point is on it when it is closer than every cheaper one
{
    head -n 1 "$out/pareto.raw"
    tail -n +2 "$out/pareto.raw" | sort -t$'\t' -k2,2g -k3,3gr |
        awk -F'\t' -v OFS='\t' '{ $7 = ($3 + 0 > best) ? "yes" : ""; if ($3 + 0 > best) best = $3 + 0; print }'
} >"$out/pareto.tsv"
awk -F'\t' 'NR > 1 { print $2, $3 }' "$out/pareto.tsv" >"$out/all.dat"
awk -F'\t' 'NR > 1 && $7 == "yes" { print $2, $3 }' "$out/pareto.tsv" >"$out/front.dat"
awk -F'\t' 'NR > 1 { gsub(/ /, "_", $1); print $2, $3, $1 }' "$out/pareto.tsv" >"$out/labels.dat"
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
plot "$out/all.dat" using 1:2 with points pt 7 ps 0.8 title "configuration", \
     "$out/front.dat" using 1:2 with linespoints lw 2 pt 6 ps 1.5 title "Pareto front", \
     "$out/labels.dat" using 1:2:3 with labels font ",7" offset 0,0.7 notitle
GP
fi
column -t -s$'\t' "$out/pareto.tsv"
