#!/usr/bin/env bash
# An animation of four frames rendered in one run (the DM prepares frame k+1
# while frame k renders): one image per frame, numbered, each equal bit for
# bit to the host build's frame.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready render_anim || exit 0
SIZE=96x72
ref=$(render_ref scenes/anim.scn float $SIZE 0:3)
out="$RENDER_TMP/anim.ppm"
if render_board render_anim "$out" scenes/anim.scn -o "$out" --ncs 4 --size $SIZE \
    --balance dynamic --areas 64 --frames 0:3; then
    for f in 0 1 2 3; do
        render_same render_anim_frame$f "${ref%.ppm}-000$f.ppm" "${out%.ppm}-000$f.ppm"
    done
fi
