#!/usr/bin/env bash
# A failed RC or DM ends the run cleanly: the board reports it, the host
# names it and exits non-zero, and the frames written before are whole (no
# half-written file).  `links1 render --frames A:B --resume` then starts a
# new board and renders only the frames not yet written: the ones already
# there are not rewritten, and every frame equals the host build's.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready render_resume || exit 0
SIZE=96x72
ref=$(render_ref scenes/anim.scn float $SIZE 0:3)
# resume_case NAME UNIT FRAME: UNIT (dm or rc) fails during FRAME of 0..3.
resume_case() {
    local name=$1 unit=$2 frame=$3 up
    up=$(echo "$unit" | tr a-z A-Z)
    local dir="$RENDER_TMP/$name" log="$RENDER_TMP/$name.log"
    mkdir -p "$dir"
    timeout "$BOARD_RUN_LIMIT_S" "$LINKS1" render --quiet scenes/anim.scn -o "$dir/a.ppm" \
        --ncs 4 --size $SIZE --frames 0:3 --inject-unit-fault "$unit:$frame" >"$log" 2>&1
    local rc=$? written
    sed 's/^/    /' "$log"
    written=$(cd "$dir" && ls | tr '\n' ' ')
    local want_written="" f
    for ((f = 0; f < frame; f++)); do want_written+="a-000$f.ppm "; done
    if [ $rc -ne 0 ] && [ $rc -ne 124 ] && grep -q "the $up (core [01]) failed" "$log" &&
        [ "$written" = "$want_written" ]; then
        echo "PASS ${name}_ends_named"
    else
        echo "FAIL ${name}_ends_named: exit $rc, files '$written' (want '$want_written'), $(grep -c "the $up" "$log") lines naming the $up"
    fi
    local before after
    before=$(cd "$dir" && stat -c '%n %i %Y' * 2>/dev/null | tr '\n' ' '; cat * 2>/dev/null | md5sum)
    render_board ${name}_resume "$dir/a.ppm" scenes/anim.scn -o "$dir/a.ppm" --ncs 4 \
        --size $SIZE --frames 0:3 --resume || return 0
    after=$(cd "$dir" && for f in $want_written; do stat -c '%n %i %Y' "$f"; done | tr '\n' ' '
        cat $want_written 2>/dev/null | md5sum)
    local kept
    kept=$(grep -c 'is there already (--resume): kept' "$RENDER_TMP/${name}_resume.log")
    if [ "$before" = "$after" ] && [ "$kept" = "$frame" ]; then
        echo "PASS ${name}_resume_keeps_written"
    else
        echo "FAIL ${name}_resume_keeps_written: $kept frames kept (want $frame); before '$before', after '$after'"
    fi
    for f in 0 1 2 3; do
        render_same ${name}_frame$f "${ref%.ppm}-000$f.ppm" "$dir/a-000$f.ppm"
    done
}
resume_case render_resume_rc rc 2
resume_case render_resume_dm dm 1
