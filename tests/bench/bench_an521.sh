#!/usr/bin/env bash
# tests/bench/bench_an521.sh: the an521 boards against the virt board.
#   - guest instructions per pixel of the NCs (all NCs' instructions over the
#     frame's pixels, from boot to shutdown: the an521 NCs' count includes
#     their 1 ms ticks while they wait), demo.scn 160x120 on 4 NCs, float,
#     soft and fixed, Cortex-M33 against Cortex-A15;
#   - wall time of the frame (the board's render time) with 8 NCs: 5 an521
#     boards (5 QEMU processes) against one virt board, on this host.
#   - the replay of an an521 trace (demo.scn 512x480, 8 NCs) on equal-speed
#     unit computers at 1, 8 and 64 NCs, with the replay's default message
#     latency and with the an521 boards' own: a message to a unit of another
#     board waits for the receiver's next tick, half a tick (AN521_TICK_US)
#     on average, which at the emulated cores' measured speed (the NCs'
#     instructions over their render time) is that many instructions; at
#     the replay's 1 MIPS, that many microseconds.
# One run each (the virt board's instruction counts repeat exactly; the
# an521 NCs' vary by the ticks they take while they wait; wall times vary).
# Writes a Markdown table to stdout (and BENCH_AN521_OUT if set).
set -eu
cd "$(dirname "$0")/../.."
LINKS1=${LINKS1:-build/links1}
export FW_DIR=${FW_DIR:-build}
out=$(mktemp -d /tmp/links1-bench-an521.XXXXXX)
trap 'rm -rf "$out"' EXIT
W=160 H=120
ncs_insns() { # MACHINE ARITH: the NCs' instructions summed
    "$LINKS1" render scenes/demo.scn -o "$out/i.png" --machine "$1" --arith "$2" --ncs 4 \
        --size ${W}x$H --count-insns --quiet >"$out/i.log" 2>&1
    sed -nE 's/.*NCs total ([0-9]+) .*/\1/p' "$out/i.log"
}
render_ms() { # MACHINE: the board's render time of the frame, 8 NCs, float
    "$LINKS1" render scenes/demo.scn -o "$out/w.png" --machine "$1" --ncs 8 --size 320x240 \
        --quiet >"$out/w.log" 2>&1
    sed -nE 's/.*\(board: prepare [0-9]+ ms, render ([0-9]+) ms.*/\1/p' "$out/w.log" | head -n 1
}
{
    echo "| arithmetic | A15 (virt) NC instructions / pixel | M33 (an521) | M33 / A15 |"
    echo "| --- | --- | --- | --- |"
    for a in float soft fixed; do
        v=$(ncs_insns virt $a) m=$(ncs_insns an521 $a)
        awk -v a=$a -v v="$v" -v m="$m" -v p=$((W * H)) \
            'BEGIN { printf "| %s | %.0f | %.0f | %.2fx |\n", a, v / p, m / p, m / v }'
    done
    echo
    v=$(render_ms virt) m=$(render_ms an521)
    echo "| demo.scn 320x240, 8 NCs, float | virt (1 QEMU) | an521 (5 QEMUs) |"
    echo "| --- | --- | --- |"
    echo "| board's render time (wall, ms) | $v | $m |"
    echo
    "$LINKS1" render scenes/demo.scn -o "$out/t.png" --machine an521 --ncs 8 --size 512x480 \
        --trace "$out/t.trace" --count-insns --quiet >"$out/t.log" 2>&1
    nc_insns=$(sed -nE 's/.*NCs total ([0-9]+) .*/\1/p' "$out/t.log")
    render=$(sed -nE 's/.*\(board: prepare [0-9]+ ms, render ([0-9]+) ms.*/\1/p' "$out/t.log" | head -n 1)
    tick_us=$(sed -nE 's/^#define AN521_TICK_US ([0-9]+)u.*/\1/p' drivers/an521/an521_map.h)
    # instructions per microsecond of one emulated NC while the frame renders
    mips=$(awk -v i="$nc_insns" -v ms="$render" 'BEGIN { printf "%.1f", i / 8 / (ms * 1000) }')
    line_us=$(awk -v t="$tick_us" -v m="$mips" 'BEGIN { printf "%.0f", t / 2 * m }')
    echo "an521 trace: demo.scn 512x480, 8 NCs: NCs $nc_insns instructions in a $render ms render:"
    echo "$mips instructions per microsecond per emulated NC; half a tick ($tick_us us / 2) is"
    echo "$line_us instructions, the replay's --line-us $line_us at 1 MIPS."
    echo
    echo "| NCs | speed-up, default latency (1000 us) | speed-up, the an521 boards' latency ($line_us us) |"
    echo "| --- | --- | --- |"
    "$LINKS1" replay "$out/t.trace" --ncs 1,8,64 >"$out/r1.txt"
    "$LINKS1" replay "$out/t.trace" --ncs 1,8,64 --line-us "$line_us" >"$out/r2.txt"
    for n in 1 8 64; do
        a=$(sed -nE "s/^ncs $n .*speed-up ([0-9.]+) .*/\1/p" "$out/r1.txt")
        b=$(sed -nE "s/^ncs $n .*speed-up ([0-9.]+) .*/\1/p" "$out/r2.txt")
        echo "| $n | ${a}x | ${b}x |"
    done
} | tee "${BENCH_AN521_OUT:-/dev/null}"
