#!/usr/bin/env bash
# bench_faults.sh: what a failed NC costs a frame.  demo.scn at 160x120 on
# 8 NCs (float, decreasing): the board's render time (RC: broadcast to the
# last pixel, generic-timer ms) with no failure, with 1 NC failing and with
# 7 of 8 failing, for a fault (undefined instruction: the RC sees the halted
# word) and a hang (interrupts off: only the watchdog catches it).  Each
# case BENCH_FAULT_RUNS (3) times with seeds 1..runs; prints the median and
# the range, and checks every frame equals the host build's.
set -u
cd "$(dirname "$0")/../.."
LINKS1=${LINKS1:-build/links1}
export FW_DIR=${FW_DIR:-build}
RUNS=${BENCH_FAULT_RUNS:-3}
SIZE=160x120
TMP=$(mktemp -d /tmp/links1-bench-faults.XXXXXX)
trap 'rm -rf "$TMP"' EXIT
"$LINKS1" ref scenes/demo.scn -o "$TMP/ref.ppm" --arith float --size $SIZE >/dev/null 2>&1
bad=0
echo "| failing NCs of 8 | kind | render ms, median of $RUNS | min..max | frames equal to the host's |"
echo "| --- | --- | --- | --- | --- |"
for c in "0 none" "1 undef" "1 hang" "7 undef" "7 hang"; do
    set -- $c
    k=$1 kind=$2 ms=() same=0
    for ((r = 1; r <= RUNS; r++)); do
        args=()
        [ "$k" -gt 0 ] && args=(--inject-faults "$k:$r" --inject-kind "$kind")
        timeout 600 "$LINKS1" render --quiet scenes/demo.scn -o "$TMP/out.ppm" --ncs 8 \
            --size $SIZE "${args[@]}" >"$TMP/log" 2>&1
        ms+=("$(grep -o 'render [0-9]* ms' "$TMP/log" | grep -o '[0-9]*')")
        cmp -s "$TMP/ref.ppm" "$TMP/out.ppm" && same=$((same + 1))
        rm -f "$TMP/out.ppm"
    done
    sorted=($(printf '%s\n' "${ms[@]}" | sort -n))
    echo "| $k | $kind | ${sorted[$((RUNS / 2))]} | ${sorted[0]}..${sorted[$((RUNS - 1))]} | $same of $RUNS |"
    [ $same -eq $RUNS ] || bad=1
done
exit $bad
