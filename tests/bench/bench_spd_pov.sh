#!/usr/bin/env bash
# tests/bench/bench_spd_pov.sh: links1 ref (float and double) against
# POV-Ray 3.7 on the seven SPD databases at their default sizes, POV-Ray
# given the NFF's own primitives (tests/bench/nff2pov.py: true spheres,
# cylinders and cones open at the ends, polygons, smooth triangles), not
# links1 export-pov's triangles.
#   Both: 512x512 (the NFF's resolution), one ray through each pixel's
#   centre (POV-Ray -A, no anti-aliasing), one thread (+WT1), depth 5
#   counting the camera ray (links1 --max-depth 4, POV-Ray
#   max_trace_level 5), no adaptive depth (--min-weight 0, adc_bailout 0),
#   nothing past the depth limit (--refractionless off: POV-Ray has no
#   straight continuation of a transmitted ray there).
#   Times: the trace's CPU seconds (links1 ref's "traced in (S CPU)",
#   POV-Ray's "Trace Time ... CPU-seconds"), BENCH_RUNS rounds (default
#   3), each running POV-Ray, float and double in turn on one database
#   before the next (alternating), medians; the ratios are those medians'
#   from this one run.
#   bash tests/bench/bench_spd_pov.sh [OUT-DIR]   (default build/bench-spd-pov)
#   BENCH_SPD_DBS="balls-4 tetra-6" picks databases (NAME-SIZE).
# Writes OUT-DIR/spd-pov.tsv and the chart OUT-DIR/spd-pov.png (gnuplot).
set -u
cd "$(dirname "$0")/../.."
LINKS1=${LINKS1:-build/links1}
SPD=${SPD:-build/links1-spd}
out=${1:-build/bench-spd-pov}
RUNS=${BENCH_RUNS:-3}
DBS=${BENCH_SPD_DBS:-balls-4 gears-4 mount-6 rings-7 teapot-6 tetra-6 tree-11}
if ! command -v povray >/dev/null; then
    echo "bench_spd_pov: povray is not installed (apt-get install povray); skipped"
    exit 0
fi
make -s --no-print-directory build/links1 build/links1-ref-float build/links1-ref-double \
    build/links1-spd >&2 || exit 1
mkdir -p "$out"
TMP=$(mktemp -d /tmp/links1-bench-spd-pov.XXXXXX)
trap 'rm -rf "$TMP"' EXIT

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

# ref NFF ARITH: the trace's CPU seconds of one links1 ref run
ref() {
    local log="$TMP/ref.log"
    if ! "$LINKS1" ref "$1" --arith "$2" --max-depth 4 --min-weight 0 --refractionless off \
        -o "$TMP/ref.ppm" >"$log" 2>&1; then
        echo "bench_spd_pov: links1 ref $1 --arith $2 failed: $(tail -n 1 "$log")" >&2
        exit 1
    fi
    sed -n 's/.*traced in [0-9.]* s (\([0-9.]*\) s CPU).*/\1/p' "$log"
}

# pov POV: the trace's CPU seconds of one POV-Ray run
pov() {
    local log="$TMP/pov.log"
    povray -D +I"$1" +O"$TMP/pov.png" +W512 +H512 -A +WT1 File_Gamma=1.0 >"$log" 2>&1
    grep -A1 'Trace Time:' "$log" | sed -n 's/.*with \([0-9.]*\) CPU-seconds.*/\1/p'
}

tsv="$out/spd-pov.tsv"
printf 'scene\tpov_s\tfloat_s\tdouble_s\tfloat_over_pov\tdouble_over_pov\n' >"$tsv"
echo "### SPD at default sizes, 512x512, trace CPU seconds, medians of $RUNS alternating runs"
for db in $DBS; do
    name=${db%-*} size=${db#*-}
    nff="$TMP/$name.nff" scene="$TMP/$name.pov"
    "$SPD" "$name" "$size" -o "$nff" >/dev/null 2>&1 || { echo "links1-spd $db failed" >&2; exit 1; }
    python3 tests/bench/nff2pov.py "$nff" -o "$scene" || exit 1
    : >"$TMP/p" && : >"$TMP/f" && : >"$TMP/d"
    for _ in $(seq "$RUNS"); do
        pov "$scene" >>"$TMP/p"
        ref "$nff" float >>"$TMP/f"
        ref "$nff" double >>"$TMP/d"
    done
    p=$(median <"$TMP/p") f=$(median <"$TMP/f") d=$(median <"$TMP/d")
    awk -v s="$name $size" -v p="$p" -v f="$f" -v d="$d" \
        'BEGIN { printf "%s\t%.3f\t%.3f\t%.3f\t%.2f\t%.2f\n", s, p, f, d, f / p, d / p }' >>"$tsv"
done
column -t -s$'\t' "$tsv"
if command -v gnuplot >/dev/null; then
    awk -F'\t' 'NR > 1 { gsub(/ /, "_", $1); print $1, $5, $6 }' "$tsv" >"$TMP/ratios.dat"
    gnuplot <<GP
set terminal pngcairo size 900,480 font ",10" noenhanced
set output "$out/spd-pov.png"
set title "links1 ref against POV-Ray 3.7 on the SPD (NFF's own primitives; 512x512, one thread, depth 5, medians of $RUNS)"
set ylabel "trace CPU time / POV-Ray's"
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.8 border -1
set boxwidth 0.9
set yrange [0:*]
set grid ytics
set key top left
set xtics nomirror
plot "$TMP/ratios.dat" using 2:xtic(1) title "links1 ref --arith float", \
     "" using 3 title "links1 ref --arith double", \
     1 with lines lw 2 dt 2 lc rgb "black" title "POV-Ray (1.0)"
GP
    echo "chart: $out/spd-pov.png"
fi
