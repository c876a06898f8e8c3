#!/usr/bin/env bash
# tests/bench/bench_aa.sh: anti-aliasing's cost against its error
# (docs/results/speed-vs-accuracy.md, "Anti-aliasing").  For each scene
# (demo.scn, glass.scn and SPD balls 1) at SIZE (default 96x72): the
# reference is `links1 ref --supersample 16` (double: each pixel the box
# mean of 16x16 rays); each configuration renders on the board (float,
# NCS NCs, --count-insns) and is scored against it: PSNR and the share of
# pixels more than 2/255 off.  Cost: the NCs' guest instructions a pixel
# (the sum over the NCs).  Configurations: no anti-aliasing, --aa 0
# (corner rays), and depths 1..3 at thresholds 0.1 (the default) and 0.
# Each board image is checked to be the host's (links1 ref --arith float)
# byte for byte.  Writes DIR/aa.tsv and DIR/aa.png.
#   bash tests/bench/bench_aa.sh [--out DIR]   # also in make bench
#     (--charts-only: the chart again from DIR/aa.tsv, nothing run)
set -eu
cd "$(dirname "$0")/../.."
. tests/bench/bench_args.sh
bench_args bench_aa.sh build/bench-aa "$@"
SIZE=${SIZE:-96x72}
NCS=${AA_NCS:-4}
SUPER=${AA_SUPER:-16}
export FW_DIR=${FW_DIR:-build}
mkdir -p "$out"
scenes="scenes/demo.scn scenes/glass.scn $out/balls1.scn"
if bench_measuring; then # --charts-only redraws from DIR/aa.tsv
make -s --no-print-directory build/links1 build/links1-spd build/links1-ref-double \
    build/links1-ref-float
build/links1-spd balls 1 -o "$out/balls1.scn" --size "$SIZE" >/dev/null
pixels=$(( ${SIZE%x*} * ${SIZE#*x} ))

# configurations: name|arguments
configs=("no anti-aliasing|--no-aa" "aa 0 (corner rays)|--aa 0")
for d in 1 2 3; do
    for t in 0.1 0; do
        configs+=("aa $d, threshold $t|--aa $d --aa-threshold $t")
    done
done

printf 'scene\tconfig\tnc_insns_per_pixel\tpsnr_db\tbeyond2_pct\tsame_as_host\n' >"$out/aa.tsv"
for scn in $scenes; do
    base=$(basename "$scn" .scn)
    ref=$out/$base-ref.png
    build/links1 ref "$scn" --size "$SIZE" --supersample "$SUPER" -o "$ref" >/dev/null 2>&1
    for c in "${configs[@]}"; do
        IFS='|' read -r name args <<<"$c"
        tag=$(echo "$name" | tr ' ,.()' '_____')
        img=$out/$base-$tag.png host=$out/$base-$tag-host.png log=$out/$base-$tag.log
        build/links1 render "$scn" --size "$SIZE" --ncs "$NCS" --count-insns $args -o "$img" \
            >"$log" 2>&1 || { echo "bench_aa: $scn $name failed: $(tail -n 1 "$log")" >&2; exit 1; }
        build/links1 ref "$scn" --arith float --size "$SIZE" $args -o "$host" >/dev/null 2>&1
        total=$(grep -o 'NCs total [0-9]*' "$log" | grep -o '[0-9]*$')
        cmpl=$(build/links1 compare "$ref" "$img" --within 2 --min-fraction 0)
        psnr=$(echo "$cmpl" | sed -nE 's/.*PSNR ([0-9.]+) dB.*/\1/p')
        w2=$(echo "$cmpl" | sed -nE 's/.*on every channel: ([0-9.]+)%.*/\1/p')
        same=no
        cmp -s "$img" "$host" && same=yes
        awk -v s="$base" -v n="$name" -v t="$total" -v p="$pixels" -v q="$psnr" -v w="$w2" \
            -v m="$same" 'BEGIN { printf "%s\t%s\t%.0f\t%s\t%.3f\t%s\n", s, n, t / p, q, 100 - w, m }' \
            >>"$out/aa.tsv"
    done
done
fi

for scn in $scenes; do
    base=$(basename "$scn" .scn)
    awk -F'\t' -v s="$base" 'NR > 1 && $1 == s { print $3, $4 }' "$out/aa.tsv" >"$out/$base.dat"
    awk -F'\t' -v s="$base" 'NR > 1 && $1 == s && $2 ~ /^no / { print $3, $4 }' "$out/aa.tsv" \
        >"$out/$base-off.dat"
done
# each point's label: its depth, "T0" at threshold 0
awk -F'\t' 'NR > 1 && $2 ~ /^aa / { l = $2; sub(/^aa /, "", l); sub(/ \(corner rays\)/, "", l);
    sub(/, threshold 0\.1/, "", l); sub(/, threshold 0$/, " T0", l); printf "%s %s \"%s\"\n", $3, $4, l }' \
    "$out/aa.tsv" >"$out/labels.dat"
gnuplot <<GP
set terminal pngcairo size 900,560 font ",9" noenhanced
set output "$out/aa.png"
set title "Anti-aliasing at $SIZE on the board (float, $NCS NCs): NC instructions a pixel against PSNR to a ${SUPER}x${SUPER} supersampled reference"
set xlabel "NC guest instructions per pixel (sum over the NCs, TCG plugin)"
set ylabel "PSNR against the ${SUPER}x${SUPER} reference, dB"
set logscale x
set grid
set key bottom right
set label 1 "labels: --aa depth at threshold 0.1; T0: threshold 0" at graph 0.02, graph 0.95 font ",8"
plot "$out/demo.dat" using 1:2 with points pt 7 ps 1 title "demo.scn: none, --aa 0, --aa 1..3 at thresholds 0.1 and 0", \
     "$out/glass.dat" using 1:2 with points pt 5 ps 1 title "glass.scn", \
     "$out/balls1.dat" using 1:2 with points pt 9 ps 1.2 title "SPD balls 1", \
     "$out/demo-off.dat" using 1:2 with points pt 4 ps 2.4 lw 2 title "the default (no anti-aliasing), each scene", \
     "$out/glass-off.dat" using 1:2 with points pt 4 ps 2.4 lw 2 notitle, \
     "$out/balls1-off.dat" using 1:2 with points pt 4 ps 2.4 lw 2 notitle, \
     "$out/labels.dat" using 1:2:3 with labels left font ",7" offset 0.8,0 notitle
GP
column -t -s$'\t' "$out/aa.tsv"
