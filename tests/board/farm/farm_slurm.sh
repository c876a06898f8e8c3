#!/usr/bin/env bash
# links1 farm --slurm on a throw-away one-node Slurm cluster on this machine
# (tests/board/farm/farm_slurm_cluster.sh): frames 0..3 of scenes/anim.scn farmed
# as one job array into a DIR named with spaces, quotes and $ equal one
# board's `links1 render --frames 0:3` byte for byte, and the summary names
# the node; with frame 2 deleted, a second farm submits only that task and
# leaves the other frames untouched; one still frame in 3 bands, stitched,
# is the board's; a task killed while it renders is handed out again in the
# next round and its frame arrives; tasks that fail every round leave their
# frames reported missing, with a failing exit.  Needs root and Slurm.
. "$(dirname "$0")/../lib.sh"
. "$(dirname "$0")/../render_lib.sh"
. "$(dirname "$0")/farm_slurm_cluster.sh"
CHECKS="farm_slurm_frames farm_slurm_summary farm_slurm_resume_one_task farm_slurm_resume_kept
        farm_slurm_bands farm_slurm_killed_mid_frame farm_slurm_kill_frames farm_slurm_failing"
board_ready $CHECKS || exit 0
why=$(farm_slurm_why)
if [ -n "$why" ]; then
    checks_fail "$why" $CHECKS
    exit 0
fi
SIZE=48x36
T=$RENDER_TMP
trap 'farm_slurm_stop; rm -rf "$RENDER_TMP"' EXIT
if ! farm_slurm_start "$T/slurm" >"$T/slurm_start.log" 2>&1; then
    cat "$T/slurm_start.log"
    checks_fail "$(tail -n 1 "$T/slurm_start.log")" $CHECKS
    exit 0
fi
render_board farm_slurm_ref "$T/ref.ppm" scenes/anim.scn -o "$T/ref.ppm" --size $SIZE \
    --frames 0:3 || exit 0

# 1. the whole animation as one job array, into a hostile DIR
D="$T/out 'q' \"\$x\""
farm farm_slurm_run scenes/anim.scn --frames 0:3 -o "$D" --slurm --ext ppm -- --size $SIZE
farm_frames_same farm_slurm_frames "$D"
if grep -q 'host farmnode: 4 frame(s)' "$T/farm_slurm_run.log" &&
    grep -q '4 frame(s) rendered now, 0 kept from before, 0 missing' "$T/farm_slurm_run.log"; then
    echo "PASS farm_slurm_summary"
else
    echo "FAIL farm_slurm_summary: $(grep 'links1 farm: ' "$T/farm_slurm_run.log" | tail -n 2 | tr '\n' ' ')"
fi

# 2. resume: only the missing frame is submitted
stamp() { stat -c '%i %Y' "$D/frame-0000.ppm" "$D/frame-0001.ppm" "$D/frame-0003.ppm"; }
before=$(stamp)
rm -f "$D/frame-0002.ppm"
sleep 1
farm farm_slurm_resume scenes/anim.scn --frames 0:3 -o "$D" --slurm --ext ppm -- --size $SIZE
if grep -q '3 in .* already, 1 to render' "$T/farm_slurm_resume.log" &&
    grep -q 'ended (sbatch exit 0): 1 task(s)' "$T/farm_slurm_resume.log" &&
    cmp -s "$T/ref-0002.ppm" "$D/frame-0002.ppm"; then
    echo "PASS farm_slurm_resume_one_task"
else
    echo "FAIL farm_slurm_resume_one_task: $(grep 'links1 farm: ' "$T/farm_slurm_resume.log" | head -n 2 | tr '\n' ' ')"
fi
if [ "$(stamp)" = "$before" ]; then
    echo "PASS farm_slurm_resume_kept"
else
    echo "FAIL farm_slurm_resume_kept: frames 0, 1, 3 were rewritten"
fi

# 3. one still frame in bands, stitched
farm farm_slurm_bands_run scenes/anim.scn --frames 1:1 --bands 3 -o "$T/bands" --slurm \
    --ext ppm -- --size $SIZE
if cmp -s "$T/ref-0001.ppm" "$T/bands/frame-0001.ppm"; then
    echo "PASS farm_slurm_bands"
else
    echo "FAIL farm_slurm_bands: 3 bands as Slurm tasks did not stitch into the board's frame 1"
fi

# 4. a task's links1 killed while it renders: handed out again next round
killer() {
    local p
    for _ in $(seq 600); do
        # slurmd runs the batch script as a copy named slurm_script
        p=$(pgrep -x links1 -P "$(pgrep -d, -f 'slurm_script' || echo 1)" 2>/dev/null | head -n 1)
        if [ -n "$p" ]; then
            kill -9 "$p" && echo "killed links1 $p under a Slurm task" >"$T/killed"
            return
        fi
        sleep 0.05
    done
}
killer &
killer_pid=$!
farm farm_slurm_kill scenes/anim.scn --frames 0:3 -o "$T/kill" --slurm --ext ppm --retries 3 \
    -- --size $SIZE
rc=$?
wait $killer_pid
if [ -e "$T/killed" ] && grep -q 'handing them out again (round 2' "$T/farm_slurm_kill.log"; then
    echo "PASS farm_slurm_killed_mid_frame ($(cat "$T/killed"))"
else
    echo "FAIL farm_slurm_killed_mid_frame: $(cat "$T/killed" 2>/dev/null || echo 'no task was killed'); $(grep 'round' "$T/farm_slurm_kill.log")"
fi
if [ $rc -eq 0 ]; then farm_frames_same farm_slurm_kill_frames "$T/kill"
else echo "FAIL farm_slurm_kill_frames: exit $rc"; fi

# 5. tasks that fail in every round (render arguments the farm accepts, a
# firmware the nodes do not have): frames missing, a failing exit
farm farm_slurm_fail scenes/anim.scn --frames 0:1 -o "$T/fail" --slurm --retries 2 \
    -- --firmware "$T/no-such-firmware.elf"
rc=$?
if [ $rc -ne 0 ] && grep -q '2 frame(s) missing' "$T/farm_slurm_fail.log" &&
    grep -q 'retries: 4 task(s) failed' "$T/farm_slurm_fail.log"; then
    echo "PASS farm_slurm_failing"
else
    echo "FAIL farm_slurm_failing: exit $rc: $(grep -E 'missing|retries' "$T/farm_slurm_fail.log" | tr '\n' ' ')"
fi
