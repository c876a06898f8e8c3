#!/usr/bin/env bash
# tests/bench/bench_an521.sh: the an521 boards against the virt board.
#   - guest instructions per pixel of the NCs (all NCs' instructions over the
#     frame's pixels, from boot to shutdown: the an521 NCs' count includes
#     their 1 ms ticks while they wait), demo.scn 160x120 on 4 NCs, float,
#     soft and fixed, Cortex-M33 against Cortex-A15;
#   - wall time of the frame (the board's render time) with 8 NCs: 5 an521
#     boards (5 QEMU processes) against one virt board, on this host.
# One run each (instruction counts repeat exactly; wall times do not).
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
} | tee "${BENCH_AN521_OUT:-/dev/null}"
