#!/usr/bin/env bash
# bench_link_noise.sh: the host link under --link-noise, 1e-5 .. 1e-2 per byte.
#  The real board with its go-back-N retransmission: links1 render of a
#     64x48 scene on 2 NCs, SEEDS seeds (default 3) per rate and path (PATHS,
#     default "fast serial"): how many gave the host build's exact image, how
#     many ended with the link giving up (a clear error); for the exact runs
#     the median wall time, upload and pull times and (serial path) the
#     goodput, the compiled scene's and the frame's bytes (64x48x3) over
#     upload plus pull; the median time to a give-up; a wrong image fails the
#     bench.
set -eu
cd "$(dirname "$0")/../.."
SEEDS=${SEEDS:-3}
PATHS=${PATHS:-fast serial}
tmp=$(mktemp -d /tmp/links1-bench-noise.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
echo "== the board: links1 render --link-noise RATE:SEED, $SEEDS seeds"
build/links1 ref scenes/demo.scn -o "$tmp/ref.ppm" --arith float --size 64x48 >/dev/null 2>&1
printf '%-8s %-7s %6s %6s %6s %9s %9s %7s %9s %7s\n' rate path exact error wrong \
    median_ms upload_ms pull_ms goodput gaveup_s
median() { printf '%s\n' "$@" | sort -n | awk 'NF {a[++n]=$1} END {print n ? a[int((n+1)/2)] : "-"}'; }
wrong_total=0
for rate in 1e-5 1e-4 1e-3 1e-2; do
    for path in $PATHS; do
        exact=0 error=0 wrong=0 times="" ups="" pulls="" fails="" scene_bytes=0
        for seed in $(seq "$SEEDS"); do
            rm -f "$tmp/out.ppm"
            t0=$(date +%s%N)
            if timeout 120 build/links1 render --ncs 2 --size 64x48 --link $path \
                --link-noise "$rate:$seed" scenes/demo.scn -o "$tmp/out.ppm" \
                >"$tmp/log" 2>&1 && cmp -s "$tmp/ref.ppm" "$tmp/out.ppm"; then
                exact=$((exact + 1))
                times="$times $((($(date +%s%N) - t0) / 1000000))"
                ups="$ups $(grep -o 'upload [0-9]* ms' "$tmp/log" | head -1 | awk '{print $2}')"
                pulls="$pulls $(grep -o 'pull [0-9]* ms' "$tmp/log" | head -1 | awk '{print $2}')"
                scene_bytes=$(grep -o '[0-9]* bytes compiled' "$tmp/log" | head -1 | awk '{print $1}')
            elif [ -e "$tmp/out.ppm" ] && ! cmp -s "$tmp/ref.ppm" "$tmp/out.ppm"; then
                wrong=$((wrong + 1))
            else
                error=$((error + 1))
                grep -q 'the host link gave up' "$tmp/log" &&
                    fails="$fails $((($(date +%s%N) - t0) / 1000000000))"
            fi
        done
        wrong_total=$((wrong_total + wrong))
        up=$(median $ups) pull=$(median $pulls)
        # Goodput on the serial path: the scene's and the frame's bytes over
        # the upload and pull time (KiB/s); the fast path moves them in memory.
        goodput=-
        if [ "$path" = serial ] && [ "$up" != - ]; then
            goodput=$(awk -v u="$up" -v p="$pull" -v b=$((scene_bytes + 64 * 48 * 3)) \
                'BEGIN {printf "%.1f", b / 1.024 / (u + p)}')
        fi
        printf '%-8s %-7s %4d/%d %4d/%d %4d/%d %9s %9s %7s %9s %7s\n' $rate $path $exact "$SEEDS" \
            $error "$SEEDS" $wrong "$SEEDS" "$(median $times)" "$up" "$pull" "$goodput" "$(median $fails)"
    done
done
[ $wrong_total -eq 0 ]
