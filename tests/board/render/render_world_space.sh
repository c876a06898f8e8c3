#!/usr/bin/env bash
# --world-space (options { world_space on }, render_frame_t.world): the DM
# leaves the scene in world coordinates and the NCs turn the camera rays.
# The board's frames equal the host build's bit for bit, in float and
# fixed (and on the an521 boards in float), over an animation whose camera
# and lights move (fly.scn: every frame after the first keeps the world
# part), one where most clusters move (anim.scn: prepared whole) and two
# where a few move (pendulum.scn, and SPD tetra 3 with a ball passing in
# front of it: only they are prepared again), with escalation too.  The
# double build's image is the eye-space one's within 1/255 on every pixel.
# On the board a later frame's preparation keeps what did not move: on SPD
# tetra 5 with a moving camera, and with a moving ball (in world space and
# in eye space, where the camera stands still), the DM's preprocessing of
# frame 2 (the trace's dm_prepare) is under a tenth of the eye-space
# preprocessing of frame 2 with the camera moving (the whole frame
# prepared again).  And the RC forwards a
# world-space frame whose world part the broadcast block holds by its
# header alone: on SPD tetra 7 with a moving camera its instructions for
# frames 1 and 2 are under half the eye-space ones.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready render_world_fly_float render_world_fly_fixed render_world_fly_an521 render_world_anim_float render_world_fly_escalate \
    render_world_pendulum_float render_world_pendulum_fixed render_world_ball_float render_world_double_is_eye render_world_dm_keeps render_world_dm_moved \
    render_eye_dm_moved \
    render_world_rc_header || exit 0
SIZE=96x72

render_frames_same render_world_fly_float scenes/fly.scn float 0:3 --world-space
render_frames_same render_world_fly_fixed scenes/fly.scn fixed 0:2 --world-space
# the an521 boards: the DM's blocks lie at other addresses on each board
BOARD_ONLY="--machine an521" render_frames_same render_world_fly_an521 scenes/fly.scn float 0:2 --world-space
render_frames_same render_world_anim_float scenes/anim.scn float 0:2 --world-space
render_frames_same render_world_pendulum_float scenes/pendulum.scn float 0:3 --world-space
render_frames_same render_world_pendulum_fixed scenes/pendulum.scn fixed 0:3 --world-space
ball3=$RENDER_TMP/ball3.scn
bash host-tools/gen/make_spin.sh 3 3 "$ball3" ball
render_frames_same render_world_ball_float "$ball3" float 0:2 --world-space
# escalation: the DM's wide blob keeps its world part the same way
render_frames_same render_world_fly_escalate scenes/fly.scn float 0:2 --world-space --escalate

# double: the world-space image is the eye-space one's within 1/255
eye=$RENDER_TMP/eye-double.png world=$RENDER_TMP/world-double.png
"$LINKS1" ref scenes/demo.scn --arith double --size 160x120 -o "$eye" >/dev/null 2>&1
"$LINKS1" ref scenes/demo.scn --arith double --size 160x120 --world-space -o "$world" >/dev/null 2>&1
if "$LINKS1" compare "$eye" "$world" --within 1 --min-fraction 1 >"$RENDER_TMP/cmp.log" 2>&1; then
    echo "PASS render_world_double_is_eye"
else
    echo "FAIL render_world_double_is_eye: $(grep -m1 'within' "$RENDER_TMP/cmp.log")"
fi

# the DM's preprocessing of a later frame against a whole one
# (--no-escalate: the upload prepares frame 0 without the wide blob, which
# an escalating frame 2 would then load whole)
prep() { # SCENE MODE-ARGS...: dm_prepare of frame 2 (the upload prepared frame 0 in the same block)
    local scene=$1
    shift
    local tr=$RENDER_TMP/prep-$#.trace
    "$LINKS1" render "$scene" --frame 2 --ncs 2 --size 64x48 --quiet --no-escalate --trace "$tr" \
        -o "$RENDER_TMP/prep-$#.ppm" "$@" >/dev/null 2>&1 &&
        awk '$1 == "dm_prepare" { print $2 }' "$tr"
}
orbit=$RENDER_TMP/orbit.scn ball5=$RENDER_TMP/ball5.scn
bash host-tools/gen/make_spin.sh 5 3 "$orbit" camera
bash host-tools/gen/make_spin.sh 5 3 "$ball5" ball
whole=$(prep "$orbit") # eye space, the camera moving: every triangle again
# dm_tenth NAME SCENE WHAT MODE-ARGS...: frame 2's preparation under a tenth of whole's
dm_tenth() {
    local name=$1 scene=$2 what=$3 insns
    shift 3
    insns=$(prep "$scene" "$@")
    if [ -n "$whole" ] && [ -n "$insns" ] && [ "$whole" -gt 0 ] && [ $((insns * 10)) -lt "$whole" ]; then
        echo "PASS $name ($what: $insns against $whole instructions)"
    else
        echo "FAIL $name: $what: frame 2's preparation ${insns:-none} instructions ($*) against ${whole:-none} for the whole frame (want under a tenth)"
    fi
}
dm_tenth render_world_dm_keeps "$orbit" "world space, the camera moves" --world-space
dm_tenth render_world_dm_moved "$ball5" "world space, a ball moves" --world-space
dm_tenth render_eye_dm_moved "$ball5" "eye space, a ball moves"

# the RC's instructions for frames 1 and 2 of a camera animation: those of
# frames 0..2 less those of frame 0 alone
rc_insns() { # FRAMES MODE-ARGS...; the render's output kept in rc-*.log
    local fr=$1 log
    shift
    log="$RENDER_TMP/rc-${fr/:/-}${1:+-world}.log"
    "$LINKS1" render "$orbit7" --frames "$fr" --ncs 2 --size 32x24 --count-insns \
        -o "$RENDER_TMP/rc.ppm" "$@" >"$log" 2>&1
    awk '$1 == "core" && $3 == "RC" { print $4 }' "$log"
}
orbit7=$RENDER_TMP/orbit7.scn
bash host-tools/gen/make_spin.sh 7 3 "$orbit7" camera
rc_later() { # MODE-ARGS...
    local all one
    all=$(rc_insns 0:2 "$@")
    one=$(rc_insns 0:0 "$@")
    [ -n "$all" ] && [ -n "$one" ] && echo $((all - one))
}
eye_rc=$(rc_later)
world_rc=$(rc_later --world-space)
if [ -n "$eye_rc" ] && [ -n "$world_rc" ] && [ "$eye_rc" -gt 0 ] && [ $((world_rc * 2)) -lt "$eye_rc" ]; then
    echo "PASS render_world_rc_header (frames 1 and 2: $world_rc against $eye_rc instructions)"
else
    echo "FAIL render_world_rc_header: the RC's frames 1 and 2 took ${world_rc:-none} instructions in world space against ${eye_rc:-none} in eye space (want under half); the renders' last lines: $(tail -q -n 1 "$RENDER_TMP"/rc-*.log | tr '\n' ' ')"
fi
