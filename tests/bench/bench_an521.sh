#!/usr/bin/env bash
# tests/bench/bench_an521.sh: the an521 boards against the virt board.
#   - guest instructions per pixel of the NCs (all NCs' instructions over the
#     frame's pixels, from boot to shutdown: the an521 NCs' count includes
#     their 1 ms ticks while they wait), demo.scn 160x120 on 4 NCs, float,
#     soft and fixed, each its own pixels (--no-escalate: escalation's
#     double is software on the M33, bench_escalate.sh ESC_MACHINE=an521),
#     Cortex-M33 against Cortex-A15;
#   - wall time of the frame (the board's render time) with 8 NCs: 5 an521
#     boards (5 QEMU processes) against one virt board, on this host.
#   - the latency of one message, measured: `links1 selftest latency`
#     times LAT_ROUNDS ping round trips one after another on one line with
#     the board's own counter (RC on board 0 <-> NC 2 on board 1 on the
#     an521 boards, where the receiver looks at its line at its next tick;
#     DM <-> RC on board 0; RC <-> NC 2 on the virt board, where a doorbell
#     interrupt wakes the receiver): the median round trip, half of it one
#     way;
#   - the replay of an an521 trace and of a virt trace (demo.scn 512x480,
#     8 NCs) on equal-speed unit computers at 1, 8 and 64 NCs, with the
#     replay's default message latency and with each machine's measured
#     one: the one-way median at the emulated NCs' measured speed (the
#     NCs' instructions over their render time in that trace's run) is that
#     many instructions; at the replay's 1 MIPS, that many microseconds.
#   - where fixed point's instructions go on each machine, function by
#     function (tests/bench/bench_insn_funcs.sh fixed 12).
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
        --size ${W}x$H --no-escalate --count-insns >"$out/i.log" 2>&1
    sed -nE 's/.*NCs total ([0-9]+) .*/\1/p' "$out/i.log"
}
render_ms() { # MACHINE: the board's render time of the frame, 8 NCs, float
    "$LINKS1" render scenes/demo.scn -o "$out/w.png" --machine "$1" --ncs 8 --size 320x240 \
        >"$out/w.log" 2>&1
    sed -nE 's/.*\(board: prepare [0-9]+ ms, render ([0-9]+) ms.*/\1/p' "$out/w.log" | head -n 1
}
LAT_ROUNDS=${LAT_ROUNDS:-1000}
latency() { # MACHINE CORE: "median min max" round trip in us (links1 selftest latency)
    "$LINKS1" selftest --quiet --machine "$1" --ncs 2 latency --rounds "$LAT_ROUNDS" \
        --core "$2" >"$out/l.log" 2>&1
    sed -nE 's/.*: median ([0-9.]+) us \(min ([0-9.]+), max ([0-9.]+);.*/\1 \2 \3/p' "$out/l.log"
}
lat_row() { # LABEL "median min max"
    set -- "$1" $2
    awk -v l="$1" -v m="$2" -v lo="$3" -v hi="$4" \
        'BEGIN { printf "| %s | %.1f | %.1f .. %.1f | %.1f |\n", l, m, lo, hi, m / 2 }'
}
# trace MACHINE "median min max": renders the trace, prints its row and
# sets line_MACHINE (the one-way median in instructions of an NC); the
# replays into $out/rMACHINE.txt and $out/rMACHINE-default.txt.
trace() {
    local m=$1 lat=${2%% *} insns render mips one line
    "$LINKS1" render scenes/demo.scn -o "$out/t.png" --machine "$m" --ncs 8 --size 512x480 \
        --trace "$out/t-$m.trace" --count-insns >"$out/t.log" 2>&1
    insns=$(sed -nE 's/.*NCs total ([0-9]+) .*/\1/p' "$out/t.log")
    render=$(sed -nE 's/.*\(board: prepare [0-9]+ ms, render ([0-9]+) ms.*/\1/p' "$out/t.log" | head -n 1)
    mips=$(awk -v i="$insns" -v ms="$render" 'BEGIN { printf "%.1f", i / 8 / (ms * 1000) }')
    one=$(awk -v l="$lat" 'BEGIN { printf "%.1f", l / 2 }')
    line=$(awk -v o="$one" -v m="$mips" 'BEGIN { printf "%.0f", o * m }')
    printf -v "line_$m" '%s' "$line"
    echo "| $m | $insns | $render | $mips | $one | $line |"
    "$LINKS1" replay "$out/t-$m.trace" --ncs 1,8,64 >"$out/r$m-default.txt"
    "$LINKS1" replay "$out/t-$m.trace" --ncs 1,8,64 --line-us "$line" >"$out/r$m.txt"
}
speedup() { # REPLAY NCS
    sed -nE "s/^ncs $2 .*speed-up ([0-9.]+) .*/\1/p" "$out/r$1.txt"
}
{
    echo "| arithmetic (--no-escalate) | A15 (virt) NC instructions / pixel | M33 (an521) | M33 / A15 |"
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
    echo "| one message, median of $LAT_ROUNDS round trips | round trip (us) | min .. max (us) | one way (us) |"
    echo "| --- | --- | --- | --- |"
    lat_an=$(latency an521 2) lat_an_rc=$(latency an521 1) lat_virt=$(latency virt 2)
    lat_row "an521: RC (board 0) <-> NC 2 (board 1)" "$lat_an"
    lat_row "an521: DM <-> RC (both on board 0)" "$lat_an_rc"
    lat_row "virt: RC <-> NC 2 (doorbell interrupt)" "$lat_virt"
    echo
    echo "| demo.scn 512x480, 8 NCs | NC instructions | render (ms) | instructions / us / NC | one way (us) | --line-us |"
    echo "| --- | --- | --- | --- | --- | --- |"
    trace an521 "$lat_an"
    trace virt "$lat_virt"
    echo
    echo "| NCs | virt trace, default latency (1000 us) | virt trace, its measured latency (${line_virt} us) | an521 trace, default latency | an521 trace, its measured latency (${line_an521} us) |"
    echo "| --- | --- | --- | --- | --- |"
    for n in 1 8 64; do
        echo "| $n | $(speedup virt-default $n)x | $(speedup virt $n)x | $(speedup an521-default $n)x | $(speedup an521 $n)x |"
    done
    echo
    bash tests/bench/bench_insn_funcs.sh fixed 12
} | tee "${BENCH_AN521_OUT:-/dev/null}"
