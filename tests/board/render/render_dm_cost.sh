#!/usr/bin/env bash
# The DM's whole work for a scene's first frame (issue 39): SPD tetra 5
# (1,024 triangles) at 32x24 on 2 NCs with --count-insns, whose render
# summary gives the DM's spans (docs/trace.md): the upload's check, the
# load with the index, frame 0's preparation, and their sum a primitive.
#  - render_dm_cost_spans: the line is there, each span is counted and
#    their sum is within the DM's count;
#  - render_dm_cost_limit: at most DM_COST_LIMIT instructions a primitive
#    (1,490 measured; 3,535 before the word sum and the loader's fast
#    paths).  Guest instructions repeat run to run, so the margin is for
#    changes to the code, not for noise.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready render_dm_cost_spans render_dm_cost_limit || exit 0
DM_COST_LIMIT=1800
SPD="$(dirname "$LINKS1")/links1-spd"
nff="$RENDER_TMP/tetra5.nff" log="$RENDER_TMP/dm_cost.log"
if ! "$SPD" tetra 5 -o "$nff" >"$log" 2>&1; then
    checks_fail "links1-spd tetra 5 failed: $(tail -n 1 "$log")" render_dm_cost_spans \
        render_dm_cost_limit
    exit 0
fi
timeout "$BOARD_RUN_LIMIT_S" "$LINKS1" render "$nff" --size 32x24 --ncs 2 --count-insns \
    -o "$RENDER_TMP/tetra5.ppm" >"$log" 2>&1
rc=$?
echo "--- links1 render tetra5.nff --size 32x24 --ncs 2 --count-insns (exit $rc)"
sed 's/^/    /' "$log"
line=$(grep "^  DM's scene load: " "$log")
dm=$(awk '$1 == "DM" && $2 ~ /^[0-9]+,$/ { sub(",", "", $2); print $2 }' "$log")
read -r check load prep all per prims < <(echo "$line" | sed -E \
    's/.*check ([0-9]+), load and index ([0-9]+), frame 0.s preparation ([0-9]+); ([0-9]+) in all, ([0-9]+) a primitive \(([0-9]+)\).*/\1 \2 \3 \4 \5 \6/')
if [ $rc -ne 0 ] || [ -z "$line" ] || [ -z "$dm" ] || [ -z "${prims:-}" ]; then
    checks_fail "exit $rc, or no DM count or spans line" render_dm_cost_spans render_dm_cost_limit
    exit 0
fi
if [ "$check" -gt 0 ] && [ "$load" -gt 0 ] && [ "$prep" -gt 0 ] && [ "$prims" -eq 1024 ] &&
    [ $((check + load + prep)) -eq "$all" ] && [ "$all" -le "$dm" ]; then
    echo "PASS render_dm_cost_spans (check $check, load $load, preparation $prep of the DM's $dm)"
else
    echo "FAIL render_dm_cost_spans: check $check, load $load, preparation $prep, all $all, $prims primitives (want 1024), the DM's $dm"
fi
if [ "$per" -le "$DM_COST_LIMIT" ]; then
    echo "PASS render_dm_cost_limit ($per a primitive, at most $DM_COST_LIMIT)"
else
    echo "FAIL render_dm_cost_limit: $per instructions a primitive, over $DM_COST_LIMIT"
fi
