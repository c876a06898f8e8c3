#!/usr/bin/env bash
# The live view: with --view the firmware shows the frame memory through
# QEMU's ramfb as it fills.  Screen dumps taken over QEMU's monitor, one
# after another until the view equals the finished image (the host build's,
# which the board's must equal), must show only finished pixels (each equal
# to the final image's), a count of them that never shrinks, at least one
# partly rendered frame, and the final image last.  The board is a named one
# started with --view: it stays up after the frame, so the dumps reach the
# finished view however late they come (a board that powers off when the
# render ends could go before the last dump on a loaded host).  No check
# depends on how fast the dumps come.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready render_view || exit 0
export LINKS1_BOARDS="$RENDER_TMP/boards"
trap 'kill -9 "$(render_board_pid v)" 2>/dev/null; rm -rf "$RENDER_TMP"' EXIT
dumps="$RENDER_TMP/dumps"
mkdir -p "$dumps"
out="$RENDER_TMP/view.ppm"
size=320x240
ref=$(render_ref scenes/demo.scn float "$size")
if ! LINKS1_MONITOR="$RENDER_TMP/monitor.sock" LINKS1_DISPLAY=none \
    render_run view_start board start --name v --view --ncs 2 --quiet; then
    echo "FAIL render_view_image: board start --view failed"
    exit 0
fi
python3 "$(dirname "$0")/view_dumps.py" "$RENDER_TMP/monitor.sock" "$dumps" "$ref" &
grabber=$!
if render_board render_view "$out" scenes/demo.scn -o "$out" --board v \
    --size "$size" --balance dynamic --areas 256; then
    wait "$grabber"
    render_same render_view_image "$ref" "$out"
    python3 "$(dirname "$0")/view_dumps.py" --check "$dumps" "$out"
else
    kill "$grabber" 2>/dev/null
fi
render_run view_stop board stop v >/dev/null
