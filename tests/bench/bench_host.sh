#!/usr/bin/env bash
# bench_host.sh: speed of the renderer on the host, per arithmetic:
# rays per second (primary + shadow + reflection + refraction +
# transmission, as counted by the renderer) on the demo and paper-like
# scenes with `links1 ref`.  Wall-clock time: a benchmark, not a test.
set -eu
cd "$(dirname "$0")/../.."
. host-tools/gen/scene_of.sh # scene_of NAME: its path (city, fig9: build/scenes/)
make -s --no-print-directory build/links1 build/links1-ref-double build/links1-ref-float \
    build/links1-ref-fixed
out=build/bench-host
mkdir -p "$out"
printf '%-10s %-7s %9s %12s %12s\n' scene arith seconds rays rays/s
for s in demo glass molecule city; do
    for a in double float fixed; do
        start=$(date +%s.%N)
        log=$(build/links1 ref "$(scene_of $s)" -o "$out/$s-$a.ppm" --arith "$a" 2>&1)
        end=$(date +%s.%N)
        rays=$(echo "$log" | sed -n 's/.*rays: \([0-9]*\) primary, \([0-9]*\) shadow, \([0-9]*\) reflection, \([0-9]*\) refraction, \([0-9]*\) transmission.*/\1 \2 \3 \4 \5/p' |
               awk '{print $1 + $2 + $3 + $4 + $5}')
        awk -v s="$s" -v a="$a" -v t0="$start" -v t1="$end" -v r="$rays" \
            'BEGIN { t = t1 - t0; printf "%-10s %-7s %9.3f %12d %12.0f\n", s, a, t, r, r / t }'
    done
done
