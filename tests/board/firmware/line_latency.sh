#!/usr/bin/env bash
# links1 selftest latency: timed ping round trips on one serial line
# (CMD_LINE_LATENCY), on the virt board (a doorbell interrupt wakes the
# receiver) and across an521 boards (RC on board 0, NC 2 on board 1: the
# receiver looks at its line at its next tick).  Checks that every round
# answered and that the board's min <= median <= max hold together; the
# numbers themselves are the benchmark's (tests/bench/bench_an521.sh).  A
# far end the board does not have is refused before it boots.
. "$(dirname "$0")/../lib.sh"
board_ready latency_virt_boot latency_virt_latency latency_virt_shutdown \
    latency_virt_link-errors latency_an521_boot latency_an521_latency latency_an521_shutdown \
    latency_an521_link-errors line_latency_refused || exit 0
board_selftest latency_virt --ncs 2 latency --rounds 100
if [ -r "$FW_DIR/an521/links1-float.elf" ]; then
    board_selftest latency_an521 --machine an521 --ncs 2 latency --rounds 100
else
    for n in boot latency shutdown link-errors; do
        echo "FAIL latency_an521_$n: firmware $FW_DIR/an521/links1-float.elf is not built (run make)"
    done
fi
out=$("$LINKS1" selftest --quiet --ncs 2 latency --core 4 2>&1)
rc=$?
echo "    $out"
if [ $rc -ne 0 ] && echo "$out" | grep -q -- '--core 4, but the board has 4 cores' &&
    ! echo "$out" | grep -q 'selftest boot'; then
    echo "PASS line_latency_refused"
else
    echo "FAIL line_latency_refused: --core 4 on a board of 4 cores was not refused before booting (exit $rc)"
fi
