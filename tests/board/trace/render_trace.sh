#!/usr/bin/env bash
# links1 render --trace on the board, then links1 replay of the trace:
#  - the traced image is the host build's (tracing changes no pixel);
#  - the marks account for the NCs' work: each NC's set-up and areas in the
#    trace add up to at least 98% of what the plugin counted on that NC for
#    the frame;
#  - replayed with static balancing on the board's NC count, each NC's
#    areas cost what the trace counted, exactly (as a set: which NC drew
#    which static area depends on timing on the board, and in the replay);
#  - replayed with dynamic and decreasing balancing on other NC counts, the
#    handout is legal (links1 replay --check);
#  - the RC's instructions to serve each request are in the trace: every
#    area has its own figure, above zero and below RC_REQUEST_MAX (issue
#    39's lines moving whole words: 823 to 896 here; 1,064 to 1,136 before
#    it, 1,700 before issue 10's cheap request path), and the RC's
#    traced spans add up to no more than the plugin counted on the RC.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
board_ready render_trace || exit 0
SIZE=64x48
RC_REQUEST_MAX=1000
ref=$(render_ref scenes/demo.scn float $SIZE)
out="$RENDER_TMP/trace.ppm"
tr="$RENDER_TMP/demo.trace"
if render_board render_trace "$out" scenes/demo.scn -o "$out" --ncs 4 --size $SIZE \
    --balance static --count-insns --trace "$tr"; then
    render_same render_trace_image "$ref" "$out"
    log="$RENDER_TMP/render_trace.log"
    # Per NC: the plugin's count (cores 2..5) and the trace's area totals.
    board=$(awk '$1 == "core" && $3 == "NC" { print $4 }' "$log")
    areas=$(awk '$1 == "area" { s[$7] += $15 } END { for (n = 0; n < 4; n++) print s[n] + 0 }' "$tr")
    traced=$(awk '$1 == "nc" && $3 == "setup" { s[$2] += $4 }
                  $1 == "area" { s[$7] += $15 } END { for (n = 0; n < 4; n++) print s[n] + 0 }' "$tr")
    if [ "$(echo "$board" | wc -l)" = 4 ] &&
        paste <(echo "$board") <(echo "$traced") |
        awk '{ if ($2 <= 0 || $2 > $1 || $2 < 0.98 * $1) bad = 1 } END { exit bad }'; then
        echo "PASS render_trace_covers_nc_work"
    else
        echo "FAIL render_trace_covers_nc_work: plugin per NC '$(echo $board)', trace per NC '$(echo $traced)'"
    fi
    rc_board=$(awk '$1 == "core" && $3 == "RC" { print $4 }' "$log")
    rc_check=$(awk -v max=$RC_REQUEST_MAX -v board="$rc_board" '
        $1 == "area" { n++; s += $NF; if ($(NF - 1) != "rc" || $NF <= 0 || $NF > max) bad++ }
        $1 == "broadcast" { s += $NF } $1 == "rc_other" { s += $2 }
        END { printf "%d areas, %d out of (0, %d], RC spans %d of the plugin'"'"'s %s", n, bad, max, s, board
              exit !(n > 0 && bad == 0 && board != "" && s <= board) }' "$tr")
    if [ $? = 0 ]; then
        echo "PASS render_trace_rc_per_request: $rc_check"
    else
        echo "FAIL render_trace_rc_per_request: $rc_check"
    fi
    rep="$RENDER_TMP/replay.txt"
    if "$LINKS1" replay "$tr" --ncs 4 --balance static --per-nc --check >"$rep" 2>&1 &&
        [ "$(awk '$1 == "nc" && $3 == "insns" { print $4 }' "$rep" | sort -n)" = \
          "$(echo "$areas" | sort -n)" ] && grep -q 'exact 4/4' "$rep"; then
        echo "PASS render_trace_static_replay_exact"
    else
        echo "FAIL render_trace_static_replay_exact: board's areas per NC '$(echo $areas)'; replay: $(tr '\n' ' ' <"$rep")"
    fi
    legal=1
    for bal in dynamic decreasing; do
        "$LINKS1" replay "$tr" --ncs 1,3,16 --balance $bal --areas 64 --check >"$rep" 2>&1 &&
            [ "$(grep -c 'legal handout' "$rep")" = 3 ] || legal=0
    done
    "$LINKS1" replay "$tr" --ncs 5 --balance decreasing --prefetch --check >"$rep" 2>&1 &&
        grep -q 'legal handout' "$rep" || legal=0
    if [ $legal = 1 ]; then
        echo "PASS render_trace_dynamic_replay_legal"
    else
        echo "FAIL render_trace_dynamic_replay_legal: $(tr '\n' ' ' <"$rep")"
    fi
fi
# The trace records the schedule the board ran, and replay --check finds the
# board's own handout to be that schedule, in its order: the default (K and
# factor by NC count, NCs asking ahead, escalating; recorded as 0 0 and
# flags 128, LINK_RENDER_ESCALATE), and
# the paper's rule with a given K and factor.  A replay without what-if
# options says it replays what the board does, with the board's rule.
rep="$RENDER_TMP/replay.txt"
for run in default paper; do
    tr="$RENDER_TMP/$run.trace"
    out="$RENDER_TMP/$run.ppm"
    extra=() want_run="run ncs 4 balance decreasing k 0 guided 0 flags 128" want_ask=ahead
    [ $run = paper ] && extra=(--ask finished --areas 512 --guided 3) &&
        want_run="run ncs 4 balance decreasing k 512 guided 3 flags 192" want_ask=finished
    if render_board render_trace_$run "$out" scenes/demo.scn -o "$out" --ncs 4 --size $SIZE \
        --trace "$tr" "${extra[@]}" &&
        grep -qx "$want_run" "$tr" && cmp -s "$ref" "$out" &&
        "$LINKS1" replay "$tr" --ncs 4,16 --check >"$rep" 2>&1 &&
        grep -q "board handout: the schedule's" "$rep" && grep -q "what the board does" "$rep" &&
        [ "$(grep -c "ask $want_ask\$" "$rep")" = 2 ] && [ "$(grep -c 'legal handout' "$rep")" = 2 ]; then
        echo "PASS render_trace_records_schedule_$run"
    else
        echo "FAIL render_trace_records_schedule_$run: run line '$(grep '^run' "$tr" 2>/dev/null)'; $(tr '\n' ' ' <"$rep" 2>/dev/null)"
    fi
done
