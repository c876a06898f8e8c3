#!/usr/bin/env bash
# bench_link_noise.sh: the host link under --link-noise, 1e-5 .. 1e-2 per byte.
#  1. build/bench-link-arq: the stop-and-wait retransmission of
#     proto/link_arq.h through the same damage, simulated on the host (not
#     yet wired into the board or the tool): runs exact / given up, median
#     goodput (payload taken per byte on the line), resends per frame.
#  2. The real board as it is (no retransmission yet): links1 render of a
#     64x48 scene on 2 NCs, SEEDS seeds (default 3) per rate and path: how
#     many gave the host build's exact image, how many a clear error; a wrong
#     image is counted and fails the bench.
set -eu
cd "$(dirname "$0")/../.."
SEEDS=${SEEDS:-3}
tmp=$(mktemp -d /tmp/links1-bench-noise.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
echo "== simulated retransmission (build/bench-link-arq)"
build/bench-link-arq
echo "== the board today: links1 render --link-noise RATE:SEED, $SEEDS seeds"
build/links1 ref scenes/demo.scn -o "$tmp/ref.ppm" --arith float --size 64x48 >/dev/null 2>&1
printf '%-8s %-7s %6s %6s %6s\n' rate path exact error wrong
wrong_total=0
for rate in 1e-5 1e-4 1e-3 1e-2; do
    for path in fast serial; do
        exact=0 error=0 wrong=0
        for seed in $(seq "$SEEDS"); do
            rm -f "$tmp/out.ppm"
            if timeout 120 build/links1 render --quiet --ncs 2 --size 64x48 --link $path \
                --link-noise "$rate:$seed" scenes/demo.scn -o "$tmp/out.ppm" \
                >"$tmp/log" 2>&1 && cmp -s "$tmp/ref.ppm" "$tmp/out.ppm"; then
                exact=$((exact + 1))
            elif [ -e "$tmp/out.ppm" ] && ! cmp -s "$tmp/ref.ppm" "$tmp/out.ppm"; then
                wrong=$((wrong + 1))
            else
                error=$((error + 1))
            fi
        done
        wrong_total=$((wrong_total + wrong))
        printf '%-8s %-7s %4d/%d %4d/%d %4d/%d\n' $rate $path $exact "$SEEDS" $error "$SEEDS" \
            $wrong "$SEEDS"
    done
done
[ $wrong_total -eq 0 ]
