#!/usr/bin/env bash
# The DM's whole work for a scene's first frame (issue 39): SPD tetra 5
# (1,024 triangles) at 32x24 on 2 NCs with --count-insns, whose render
# summary gives the DM's spans (docs/trace.md): the upload's check, the
# load with the index, frame 0's preparation, and their sum a primitive.
# The default boots the escalating firmware: the load and the preparation
# hold the double copy's too.
#  - render_dm_cost_spans: the line is there, each span is counted and
#    their sum is within the DM's count;
#  - render_dm_cost_whole: the spans hold at least 90% of the DM's count;
#  - render_dm_cost_trace: the same run's --trace gives dm_prepare (the
#    frame's preprocessing, the DM's last span) equal to frame 0's
#    preparation, narrow and wide blob alike;
#  - render_dm_cost_limit: at most DM_COST_LIMIT instructions a primitive
#    (1,805 measured, the double copy's load and preparation included);
#  - render_dm_cost_narrow: --no-escalate (the firmware without the double
#    copy), at most DM_NARROW_LIMIT (1,012 measured).
# Guest instructions repeat run to run, so the margins are for changes to
# the code, not for noise.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
CHECKS=(render_dm_cost_spans render_dm_cost_whole render_dm_cost_trace render_dm_cost_limit
    render_dm_cost_narrow)
board_ready "${CHECKS[@]}" || exit 0
DM_COST_LIMIT=1900 DM_NARROW_LIMIT=1070
SPD="$(dirname "$LINKS1")/links1-spd"
nff="$RENDER_TMP/tetra5.nff" log="$RENDER_TMP/dm_cost.log" trace="$RENDER_TMP/tetra5.trace"
if ! "$SPD" tetra 5 -o "$nff" >"$log" 2>&1; then
    checks_fail "links1-spd tetra 5 failed: $(tail -n 1 "$log")" "${CHECKS[@]}"
    exit 0
fi

# dm_cost_run LOG ARGS...: one render of tetra5.nff counted; sets rc, dm
# (the DM's count) and check load prep all per prims from the spans line.
dm_cost_run() {
    local log=$1; shift
    timeout "$BOARD_RUN_LIMIT_S" "$LINKS1" render "$nff" --size 32x24 --ncs 2 --count-insns \
        -o "$RENDER_TMP/tetra5.ppm" "$@" >"$log" 2>&1
    rc=$?
    echo "--- links1 render tetra5.nff --size 32x24 --ncs 2 --count-insns $* (exit $rc)"
    sed 's/^/    /' "$log"
    line=$(grep "^  DM's scene load: " "$log")
    dm=$(awk '$1 == "DM" && $2 ~ /^[0-9]+,$/ { sub(",", "", $2); print $2 }' "$log")
    prims=
    read -r check load prep all per prims < <(echo "$line" | sed -E \
        's/.*check ([0-9]+), load and index ([0-9]+), frame 0.s preparation ([0-9]+); ([0-9]+) in all, ([0-9]+) a primitive \(([0-9]+)\).*/\1 \2 \3 \4 \5 \6/')
    [ $rc -eq 0 ] && [ -n "$line" ] && [ -n "$dm" ] && [ -n "${prims:-}" ]
}

if ! dm_cost_run "$log" --trace "$trace"; then
    checks_fail "exit $rc, or no DM count or spans line" render_dm_cost_spans \
        render_dm_cost_whole render_dm_cost_trace render_dm_cost_limit
else
    if [ "$check" -gt 0 ] && [ "$load" -gt 0 ] && [ "$prep" -gt 0 ] && [ "$prims" -eq 1024 ] &&
        [ $((check + load + prep)) -eq "$all" ] && [ "$all" -le "$dm" ]; then
        echo "PASS render_dm_cost_spans (check $check, load $load, preparation $prep of the DM's $dm)"
    else
        echo "FAIL render_dm_cost_spans: check $check, load $load, preparation $prep, all $all, $prims primitives (want 1024), the DM's $dm"
    fi
    if [ $((all * 10)) -ge $((dm * 9)) ]; then
        echo "PASS render_dm_cost_whole (the spans hold $all of the DM's $dm)"
    else
        echo "FAIL render_dm_cost_whole: the spans hold $all of the DM's $dm, under 90%"
    fi
    traced=$(awk '$1 == "dm_prepare" { print $2 }' "$trace" 2>/dev/null)
    if [ "${traced:-x}" = "$prep" ]; then
        echo "PASS render_dm_cost_trace (dm_prepare $traced)"
    else
        echo "FAIL render_dm_cost_trace: the trace's dm_prepare '${traced:-}', frame 0's preparation $prep"
    fi
    if [ "$per" -le "$DM_COST_LIMIT" ]; then
        echo "PASS render_dm_cost_limit ($per a primitive, at most $DM_COST_LIMIT)"
    else
        echo "FAIL render_dm_cost_limit: $per instructions a primitive, over $DM_COST_LIMIT"
    fi
fi

if ! dm_cost_run "$RENDER_TMP/dm_narrow.log" --no-escalate; then
    checks_fail "--no-escalate: exit $rc, or no DM count or spans line" render_dm_cost_narrow
elif [ "$per" -le "$DM_NARROW_LIMIT" ] && [ "$prims" -eq 1024 ]; then
    echo "PASS render_dm_cost_narrow ($per a primitive, at most $DM_NARROW_LIMIT)"
else
    echo "FAIL render_dm_cost_narrow: $per instructions a primitive ($prims primitives), over $DM_NARROW_LIMIT"
fi
