#!/usr/bin/env bash
# The counting plugin's profile (links1 render --insn-profile): by default
# the NCs' instructions, among which the renderer's per-pixel functions and
# none of the DM's preparation; with --insn-profile-core 0 the DM's alone,
# with render_prepare_parts (every preparation's work) and no per-pixel function; on the an521 boards the
# same for the DM (board 0's vCPU 0).  A core the board does not have is
# refused before it boots.  Functions come from tests/bench/insn_funcs.sh;
# tests/bench/insn_lines.py gives a function's blocks the same total.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
CHECKS="insn_profile_ncs insn_lines_same_total insn_profile_dm insn_profile_dm_an521
    insn_profile_core_refused"
board_ready $CHECKS || exit 0
T=$RENDER_TMP
ELF=$FW_DIR/links1-float.elf
# check NAME ELF WANT ARGS...: render with --insn-profile and ARGS; WANT
# "ncs" wants the per-pixel function and no preparation, "dm" the reverse
# (functions by tests/bench/insn_funcs.sh, kept in $T/NAME.funcs)
check() {
    local name=$1 elf=$2 want=$3 prof=$T/$1.prof f px prep
    shift 3
    if ! "$LINKS1" render scenes/demo.scn --size 32x24 -o "$T/$name.png" --insn-profile "$prof" \
        --quiet "$@" >"$T/$name.log" 2>&1; then
        echo "FAIL $name: $(tail -n 1 "$T/$name.log")"
        return
    fi
    f=$(bash tests/bench/insn_funcs.sh "$prof" "$elf" 2>&1 | tee "$T/$name.funcs")
    px=$(awk '$1 == "render_pixel_impl" { n = $2 } END { print n + 0 }' <<<"$f")
    prep=$(awk '$1 == "render_prepare_parts" { n += $2 } END { print n + 0 }' <<<"$f")
    if [ "$want" = ncs ] && [ "$px" -gt 0 ] && [ "$prep" = 0 ]; then
        echo "PASS $name (render_pixel_impl $px)"
    elif [ "$want" = dm ] && [ "$prep" -gt 0 ] && [ "$px" = 0 ]; then
        echo "PASS $name (render_prepare $prep)"
    else
        echo "FAIL $name: render_pixel_impl $px, render_prepare $prep (want the $want's)"
    fi
}
check insn_profile_ncs "$ELF" ncs --ncs 2
# by line and inlined function: render_pixel_impl's blocks, as many
# instructions as insn_funcs.sh gives its symbol, over two of its lines
# or more
name=insn_lines_same_total
funcs=$(awk '$1 == "render_pixel_impl" { print $2 }' "$T/insn_profile_ncs.funcs" 2>/dev/null)
lines=$(python3 tests/bench/insn_lines.py "$T/insn_profile_ncs.prof" "$ELF" \
    --function render_pixel_impl --top 100 2>&1)
total=$(awk '$1 == "total" { print $2 }' <<<"$lines")
rows=$(awk '/^inclusive$/ { exit } $3 == "render_pixel_impl" { n++ } END { print n + 0 }' <<<"$lines")
if [ -n "$funcs" ] && [ "$funcs" -gt 0 ] && [ "$total" = "$funcs" ] && [ "$rows" -ge 2 ]; then
    echo "PASS $name (render_pixel_impl $total over $rows of its lines)"
else
    echo "FAIL $name: insn_funcs.sh '$funcs', insn_lines.py total '$total' over $rows lines: $(head -n 3 <<<"$lines" | paste -sd' ')"
fi
check insn_profile_dm "$ELF" dm --ncs 2 --insn-profile-core 0
check insn_profile_dm_an521 "$FW_DIR/an521/links1-float.elf" dm --machine an521 --ncs 2 \
    --insn-profile-core 0
if ! "$LINKS1" render scenes/demo.scn --size 32x24 -o "$T/bad.png" --insn-profile "$T/bad.prof" \
    --quiet --ncs 2 --insn-profile-core 4 >"$T/bad.log" 2>&1 &&
    grep -q 'insn-profile-core 4 goes with --insn-profile, and the board has cores 0..3' "$T/bad.log"; then
    echo "PASS insn_profile_core_refused"
else
    echo "FAIL insn_profile_core_refused: $(tail -n 1 "$T/bad.log")"
fi
