#!/usr/bin/env bash
# An animation of four frames rendered in one run (the DM prepares frame k+1
# while frame k renders): one image per frame, numbered, each equal bit for
# bit to the host build's frame.  Then animations whose camera stands
# still while a few clusters move, where the DM prepares only those again
# over the frame before in its block (render_prepare_again): pendulum.scn
# in float and fixed, SPD tetra 3 with a ball passing in front of it;
# every frame equal to the host build's, which prepares each one whole.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready render_anim render_anim_pendulum_float render_anim_pendulum_fixed render_anim_ball_float ||
    exit 0
SIZE=96x72
ref=$(render_ref scenes/anim.scn float $SIZE 0:3)
out="$RENDER_TMP/anim.ppm"
if render_board render_anim "$out" scenes/anim.scn -o "$out" --ncs 4 --size $SIZE \
    --balance dynamic --areas 64 --frames 0:3; then
    for f in 0 1 2 3; do
        render_same render_anim_frame$f "${ref%.ppm}-000$f.ppm" "${out%.ppm}-000$f.ppm"
    done
fi

render_frames_same render_anim_pendulum_float scenes/pendulum.scn float 0:3
render_frames_same render_anim_pendulum_fixed scenes/pendulum.scn fixed 0:3
ball3=$RENDER_TMP/ball3.scn
bash host-tools/gen/make_spin.sh 3 4 "$ball3" ball
render_frames_same render_anim_ball_float "$ball3" float 0:3
