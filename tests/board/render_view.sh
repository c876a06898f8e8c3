#!/usr/bin/env bash
# The live view: with --view the firmware shows the frame memory through
# QEMU's ramfb as it fills.  Screen dumps taken over QEMU's monitor while the
# frame renders must show only finished pixels (each equal to the final
# image's), a count of them that never shrinks, and at least one partly
# rendered frame.
. "$(dirname "$0")/lib.sh"
. "$(dirname "$0")/render_lib.sh"
board_ready render_view || exit 0
dumps="$RENDER_TMP/dumps"
mkdir -p "$dumps"
out="$RENDER_TMP/view.ppm"
python3 "$(dirname "$0")/view_dumps.py" "$RENDER_TMP/monitor.sock" "$dumps" &
grabber=$!
if LINKS1_MONITOR="$RENDER_TMP/monitor.sock" LINKS1_DISPLAY=none \
    render_board render_view "$out" scenes/demo.scn -o "$out" --view --ncs 2 \
    --size 480x360 --balance dynamic --areas 256; then
    wait "$grabber"
    python3 "$(dirname "$0")/view_dumps.py" --check "$dumps" "$out"
else
    kill "$grabber" 2>/dev/null
fi
