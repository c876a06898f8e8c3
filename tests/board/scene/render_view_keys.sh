#!/usr/bin/env bash
# Keys move the camera and the lights (scenes/fly.scn): the board's DM
# interpolates each frame's view as it prepares the frame, so frames
# between keys equal the host build's bit for bit, in float (two frames in
# one run: frame 5 is prepared while frame 4 renders) and in fixed point.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready render_view_keys || exit 0
SIZE=64x48
ref=$(render_ref scenes/fly.scn float $SIZE 4:5)
out="$RENDER_TMP/fly.ppm"
if render_board render_view_keys "$out" scenes/fly.scn -o "$out" --ncs 3 --size $SIZE \
    --frames 4:5; then
    for f in 4 5; do
        render_same render_view_keys_float_frame$f "${ref%.ppm}-000$f.ppm" "${out%.ppm}-000$f.ppm"
    done
fi
ref=$("$LINKS1" ref scenes/fly.scn -o "$RENDER_TMP/fly7-fixed-ref.ppm" --arith fixed --size $SIZE \
    --frame 7 >"$RENDER_TMP/fly7.log" 2>&1 && echo "$RENDER_TMP/fly7-fixed-ref.ppm")
out="$RENDER_TMP/fly7-fixed.ppm"
if render_board render_view_keys_fixed "$out" scenes/fly.scn -o "$out" --arith fixed --ncs 2 \
    --size $SIZE --frame 7; then
    render_same render_view_keys_fixed_frame7 "${ref:-$RENDER_TMP/none.ppm}" "$out"
fi
