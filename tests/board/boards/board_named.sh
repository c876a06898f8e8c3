#!/usr/bin/env bash
# Named boards (links1 board start/stop/list, render --board): a board
# started once renders twice, equal to the host build (both escalating, as
# by default in float); a second start of the same name is refused; a
# render killed mid-frame leaves the board running,
# listed, and the next session renders; stop powers it off and removes its
# state; a board whose QEMU was killed is found, reported and removed.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready board_named_start board_named_render_1 board_named_render_2 board_named_twice \
    board_named_killed_tool board_named_stop board_named_stale || exit 0
export LINKS1_BOARDS="$RENDER_TMP/boards"
# Whatever happens, no QEMU of this test outlives it.
trap 'for f in "$LINKS1_BOARDS"/*/board; do [ -e "$f" ] && kill -9 "$(awk "/^pid/ {print \$2}" "$f")" 2>/dev/null; done; rm -rf "$RENDER_TMP"' EXIT
SIZE=64x48
scene=scenes/demo.scn
ref=$(render_ref $scene float $SIZE)
# A QEMU that has exited may linger as a zombie until it is reaped: alive
# means it still has a command line.
qemu_alive() { tr '\0' ' ' <"/proc/$1/cmdline" 2>/dev/null | grep -q qemu; }

if render_run start board start --ncs 2 --name b1 --quiet && render_run list1 board list &&
    grep -q '^board b1: running' "$RENDER_TMP/list1.log"; then
    echo "PASS board_named_start"
else
    echo "FAIL board_named_start: board start failed or board list does not show b1 running"
fi
for i in 1 2; do
    render_run render$i render --board b1 --quiet $scene --size $SIZE -o "$RENDER_TMP/r$i.ppm"
    render_same board_named_render_$i "$ref" "$RENDER_TMP/r$i.ppm"
done
if ! render_run twice board start --ncs 2 --name b1 --quiet &&
    grep -q 'board b1 is already running' "$RENDER_TMP/twice.log"; then
    echo "PASS board_named_twice"
else
    echo "FAIL board_named_twice: a second start of b1 was not refused as already running"
fi
# A render killed in the middle of its frame: killed as soon as it says the
# scene is loaded (the frame's command follows at once; 320x240 on 2 NCs
# then takes seconds), and it must not have finished the frame.
"$LINKS1" render --board b1 $scene --size 320x240 -o "$RENDER_TMP/killed.ppm" \
    >"$RENDER_TMP/killed.log" 2>&1 &
victim=$!
for ((i = 0; i < BOARD_RUN_LIMIT_S * 20; i++)); do
    grep -q 'loaded: ' "$RENDER_TMP/killed.log" 2>/dev/null && break
    kill -0 $victim 2>/dev/null || break
    sleep 0.05
done
kill -9 $victim 2>/dev/null
wait $victim 2>/dev/null
render_run list2 board list
render_run after render --board b1 $scene --size $SIZE -o "$RENDER_TMP/after.ppm"
if ! grep -q 'loaded: ' "$RENDER_TMP/killed.log"; then
    echo "FAIL board_named_killed_tool: the render never said its scene was loaded: $(tail -n 1 "$RENDER_TMP/killed.log")"
elif grep -q 'links1 render: frame 0 ' "$RENDER_TMP/killed.log" || [ -e "$RENDER_TMP/killed.ppm" ]; then
    echo "FAIL board_named_killed_tool: the frame was finished before the render was killed"
elif grep -q '^board b1: running' "$RENDER_TMP/list2.log" && cmp -s "$ref" "$RENDER_TMP/after.ppm"; then
    echo "PASS board_named_killed_tool"
else
    echo "FAIL board_named_killed_tool: after a render killed mid-frame b1 is not listed running, or the next render differs from the host build"
fi
pid=$(render_board_pid b1)
if render_run stop board stop b1 && [ -n "$pid" ] && ! qemu_alive "$pid" &&
    [ ! -e "$LINKS1_BOARDS/b1" ]; then
    echo "PASS board_named_stop"
else
    echo "FAIL board_named_stop: board stop failed, QEMU (pid $pid) still runs or the state remains"
fi
# A board whose QEMU died: found, reported and removed.
render_run start2 board start --ncs 1 --name b2 --quiet
pid=$(render_board_pid b2)
[ -n "$pid" ] && kill -9 "$pid"
for ((i = 0; i < 200; i++)); do # until it is gone (a zombie has no command line)
    [ -n "$pid" ] && qemu_alive "$pid" || break
    sleep 0.05
done
render_run list3 board list
if [ -n "$pid" ] && grep -q "board b2: its QEMU (pid $pid) is gone" "$RENDER_TMP/list3.log" &&
    [ ! -e "$LINKS1_BOARDS/b2" ]; then
    echo "PASS board_named_stale"
else
    echo "FAIL board_named_stale: the dead board b2 (pid $pid) was not reported and removed"
fi
