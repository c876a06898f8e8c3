#!/usr/bin/env bash
# The terminal's progress line (links1 render on a terminal: `script` gives
# it one): a bar with the share of pixels in the frame memory, never going
# back, ending at 100% and "done"; the estimate of the time left comes from
# pixels ("about N s left").
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready render_progress_bar render_progress_monotonic || exit 0
log="$RENDER_TMP/progress.log"
timeout "$BOARD_RUN_LIMIT_S" script -qec "$LINKS1 render --quiet --ncs 2 scenes/demo.scn \
    --size 160x120 -o $RENDER_TMP/p.ppm" /dev/null | tr '\r' '\n' >"$log"
rc=${PIPESTATUS[0]}
echo "--- links1 render on a terminal (exit $rc)"; sed 's/^/    /' "$log"
lines=$(grep '^frame 0 \[' "$log")
if [ "$rc" -eq 0 ] && echo "$lines" | grep -q '\[##############################\] 100%.*, done' &&
    echo "$lines" | grep -q 'about [0-9.]* s left'; then
    echo "PASS render_progress_bar"
else
    echo "FAIL render_progress_bar: exit $rc, no full bar ending 'done' or no 'about N s left' estimate"
fi
# The percentages never go down.
pcts=$(echo "$lines" | sed 's/.*\] *\([0-9]*\)%.*/\1/')
if [ -n "$pcts" ] && [ "$pcts" = "$(echo "$pcts" | sort -n)" ]; then
    echo "PASS render_progress_monotonic"
else
    echo "FAIL render_progress_monotonic: the bar's percentages were: $(echo $pcts)"
fi
