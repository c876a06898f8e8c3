#!/usr/bin/env bash
# The counting plugin's profile (links1 render --insn-profile): by default
# the NCs' instructions, among which the renderer's per-pixel functions and
# none of the DM's preparation; with --insn-profile-core 0 the DM's alone,
# with render_prepare and no per-pixel function; on the an521 boards the
# same for the DM (board 0's vCPU 0).  A core the board does not have is
# refused before it boots.  Functions come from tests/bench/insn_funcs.sh.
. "$(dirname "$0")/lib.sh"
. "$(dirname "$0")/render_lib.sh"
CHECKS="insn_profile_ncs insn_profile_dm insn_profile_dm_an521 insn_profile_core_refused"
board_ready $CHECKS || exit 0
T=$RENDER_TMP
ELF=$FW_DIR/links1-float.elf
# funcs PROFILE ELF: "FUNCTION COUNT" lines
funcs() { bash tests/bench/insn_funcs.sh "$1" "$2" 2>&1; }
# has FUNCS NAME: the count of NAME, 0 when absent
has() { awk -v f="$2" '$1 == f { n = $2 } END { print n + 0 }' <<<"$1"; }
profile() { # NAME PROFILE ARGS...
    local name=$1 prof=$2; shift 2
    "$LINKS1" render scenes/demo.scn --size 32x24 -o "$T/$name.png" --insn-profile "$prof" \
        --quiet "$@" >"$T/$name.log" 2>&1
}
if profile ncs "$T/ncs.prof" --ncs 2; then
    f=$(funcs "$T/ncs.prof" "$ELF")
    px=$(has "$f" render_pixel_impl) prep=$(has "$f" render_prepare)
    if [ "$px" -gt 0 ] && [ "$prep" = 0 ]; then
        echo "PASS insn_profile_ncs (render_pixel_impl $px)"
    else
        echo "FAIL insn_profile_ncs: render_pixel_impl $px, render_prepare $prep (want >0 and 0)"
    fi
else
    echo "FAIL insn_profile_ncs: $(tail -n 1 "$T/ncs.log")"
fi
if profile dm "$T/dm.prof" --ncs 2 --insn-profile-core 0; then
    f=$(funcs "$T/dm.prof" "$ELF")
    px=$(has "$f" render_pixel_impl) prep=$(has "$f" render_prepare)
    if [ "$prep" -gt 0 ] && [ "$px" = 0 ]; then
        echo "PASS insn_profile_dm (render_prepare $prep)"
    else
        echo "FAIL insn_profile_dm: render_prepare $prep, render_pixel_impl $px (want >0 and 0)"
    fi
else
    echo "FAIL insn_profile_dm: $(tail -n 1 "$T/dm.log")"
fi
if profile dm521 "$T/dm521.prof" --machine an521 --ncs 2 --insn-profile-core 0; then
    f=$(funcs "$T/dm521.prof" "$FW_DIR/an521/links1-float.elf")
    px=$(has "$f" render_pixel_impl) prep=$(has "$f" render_prepare)
    if [ "$prep" -gt 0 ] && [ "$px" = 0 ]; then
        echo "PASS insn_profile_dm_an521 (render_prepare $prep)"
    else
        echo "FAIL insn_profile_dm_an521: render_prepare $prep, render_pixel_impl $px (want >0 and 0)"
    fi
else
    echo "FAIL insn_profile_dm_an521: $(tail -n 1 "$T/dm521.log")"
fi
if ! profile bad "$T/bad.prof" --ncs 2 --insn-profile-core 4 &&
    grep -q 'insn-profile-core 4 goes with --insn-profile, and the board has cores 0..3' "$T/bad.log"; then
    echo "PASS insn_profile_core_refused"
else
    echo "FAIL insn_profile_core_refused: $(tail -n 1 "$T/bad.log")"
fi
