#!/usr/bin/env bash
# tests/bench/bench_escalate.sh: what escalation costs and what it buys
# (links1 render, by default in float and fixed; render/wide.h).  For each
# scene, float and fixed Q12.19 escalated (the default) and plain
# (--no-escalate) on the board: the NCs' guest
# instructions per pixel (--count-insns, the sum over the NCs), the pixels
# escalated, and against the double build (links1 ref --arith double) the
# share of pixels beyond 2/255, with and without the pixels explained by an
# edge moved by under a pixel (links1 compare --moved), and the PSNR.
# One run each (instruction counts do not depend on the host's load).
#   bash tests/bench/bench_escalate.sh [OUT-DIR]   (default build/bench-escalate)
#   ESC_SCENES="demo glass" ESC_SIZE=320x240 ESC_NCS=4
#   ESC_MACHINE=an521: on the an521 boards (their M33s' double is software)
set -eu
cd "$(dirname "$0")/../.."
. host-tools/gen/scene_of.sh # scene_of NAME: its path (city, fig9: build/scenes/)
out=${1:-build/bench-escalate}
SCENES=${ESC_SCENES:-demo glass molecule}
SIZE=${ESC_SIZE:-320x240}
NCS=${ESC_NCS:-4}
MACHINE=${ESC_MACHINE:-virt}
export FW_DIR=${FW_DIR:-build}
mkdir -p "$out"
make -s --no-print-directory build/links1 build/links1-ref-double
pixels=$(( ${SIZE%x*} * ${SIZE#*x} ))

# beyond REF IMG [--moved]: the percentage of pixels beyond 2/255
beyond() {
    build/links1 compare "$1" "$2" --within 2 --min-fraction 0 ${3:-} |
        sed -nE 's/.*on every channel: ([0-9.]+)%.*/\1/p' | awk '{ printf "%.4f", 100 - $1 }'
}

tsv=$out/escalate.tsv
printf 'scene\tarith\tescalate\tnc_insns_per_pixel\tescalated_pixels\tbeyond2_pct\tbeyond2_not_moved_pct\tpsnr_db\n' >"$tsv"
for s in $SCENES; do
    ref=$out/$s-double.ppm
    build/links1 ref "$(scene_of $s)" --arith double --size "$SIZE" -o "$ref" >/dev/null 2>&1
    for a in float fixed; do
        for e in plain escalated; do
            img=$out/$s-$a-$e.ppm
            log=$img.log
            build/links1 render --count-insns "$(scene_of $s)" --arith "$a" --ncs "$NCS" \
                --machine "$MACHINE" --size "$SIZE" -o "$img" $([ $e = escalated ] && echo --verbose || echo --no-escalate) >"$log" 2>&1 || {
                echo "bench_escalate: $s $a $e failed: $(tail -n 1 "$log")" >&2
                exit 1
            }
            total=$(grep -o 'NCs total [0-9]*' "$log" | grep -o '[0-9]*$')
            esc=$(grep -o '[0-9]* pixels escalated' "$log" | grep -o '^[0-9]*' || echo 0)
            psnr=$(build/links1 compare "$ref" "$img" --min-fraction 0 | sed -nE 's/.*PSNR ([0-9.]+) dB.*/\1/p')
            printf '%s\t%s\t%s\t%.0f\t%s\t%s\t%s\t%s\n' "$s" "$a" "$e" \
                "$(echo "$total / $pixels" | bc -l)" "$esc" "$(beyond "$ref" "$img")" \
                "$(beyond "$ref" "$img" --moved)" "$psnr" >>"$tsv"
        done
    done
done
# the cost ratio of each escalated configuration to its plain one
awk -F'\t' -v OFS='\t' 'NR == 1 { print $0, "cost_ratio"; next }
    $3 == "plain" { plain[$1 " " $2] = $4; print $0, "1.000"; next }
    { printf "%s\t%.3f\n", $0, $4 / plain[$1 " " $2] }' "$tsv" >"$tsv.tmp" && mv "$tsv.tmp" "$tsv"
column -t -s$'\t' "$tsv"
if command -v gnuplot >/dev/null; then
    # one arrow a scene and arithmetic, from its plain point to its escalated one
    awk -F'\t' 'NR > 1 && $3 == "plain" { x[$1 " " $2] = $4; y[$1 " " $2] = $6 }
        NR > 1 && $3 == "escalated" { k = $1 " " $2; printf "%s %s %s %s \"%s %s\"\n", x[k], y[k], $4, $6, $1, $2 }' \
        "$tsv" >"$out/pairs.dat"
    gnuplot <<GP
set terminal pngcairo size 900,520 font ",9" noenhanced
set output "$out/escalate.png"
set title "Escalation on the $MACHINE board ($NCS NCs, $SIZE): NC instructions per pixel against pixels beyond 2/255 of double"
set xlabel "NC guest instructions per pixel (sum over the NCs)"
set ylabel "pixels beyond 2/255 of the double build, %"
set logscale x
set grid
set key top left
set offsets 0, graph 0.12, graph 0.1, 0
plot "$out/pairs.dat" using 1:2:(\$3-\$1):(\$4-\$2) with vectors head filled lc rgb "gray60" title "plain to escalated", \
     "$out/pairs.dat" using 1:2 with points pt 7 ps 1.2 lc rgb "#9400d3" title "plain (float, fixed Q12.19; --no-escalate)", \
     "$out/pairs.dat" using 3:4 with points pt 11 ps 1.5 lc rgb "#009e73" title "escalated (the default)", \
     "$out/pairs.dat" using 1:2:5 with labels font ",8" rotate by 35 offset 0.5,0.9 left notitle
GP
    echo "chart: $out/escalate.png"
fi
