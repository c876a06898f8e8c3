#!/usr/bin/env bash
# runner.sh: tests/run.sh counts what it says it counts.  Fake tests (small
# scripts in a temporary folder, with a plan of their own) that pass, fail,
# hang, crash after printing PASS lines, end early, exit non-zero silently,
# or are missing from the plan: each must be counted as the runner's header
# says, and the summary line must add them up; a verdict an earlier run
# left is not taken for this run's.  Two scripts the plan marks
# "host" run beside each other: each waits for the other to start.
set -u
cd "$(dirname "$0")/../.."
tmp=$(mktemp -d /tmp/links1-runner.XXXXXX)
trap 'rm -rf "$tmp"' EXIT

fake() { # NAME BODY
    printf '#!/usr/bin/env bash\n%s\n' "$2" >"$tmp/$1.sh"
}
fake good 'echo "PASS good_a"; echo "PASS good_b"'
fake bad 'echo "PASS bad_a"; echo "FAIL bad_b: as it should"; exit 1'
fake hang 'echo "PASS hang_a"; sleep 30; echo "PASS hang_b"'
fake crash 'echo "PASS crash_a"; echo "PASS crash_b"; kill -SEGV $$'
fake early 'echo "PASS early_a"; exit 0'
fake silent 'exit 3'
fake unplanned 'echo "PASS unplanned_a"'
fake skips 'echo "PASS skips_a"; echo "SKIP skips_b: needs root"'
meet() { # ME OTHER: a script that starts, then waits up to 20 s for OTHER to
    fake "host$1" "touch '$tmp/$1.started'
for i in \$(seq 200); do
    [ -e '$tmp/$2.started' ] && { echo 'PASS host$1_met'; exit 0; }
    sleep 0.1
done
echo 'FAIL host$1_met: host$2 did not start while it ran'; exit 1"
}
meet a b
meet b a
# solo (suite full): runs one at a time, once nothing of the pool is left running
fake solo "for i in \$(seq 10); do
    if pgrep -f '$tmp/(host[ab]|good|bad|hang|crash|early|silent|skips)\.sh' >/dev/null; then
        echo 'FAIL solo_alone: a pooled test runs beside it'; exit 1
    fi
    sleep 0.1
done
echo 'PASS solo_alone'"
# The plan's rows: path, checks, seconds, suite (as tests/plan.tsv's).
row() { printf '%s\t%s\t%s\t%s\n' "$tmp/$1.sh" "$2" "$3" "$4" >>"$tmp/plan.tsv"; }
row good 2 10 board; row bad 2 10 board; row hang 2 2 board; row crash 3 10 board
row early 3 10 board; row silent 1 10 board; row skips 2 10 board
row hosta 1 30 host; row hostb 1 30 board; row solo 1 30 full
# a row of another path of the same name is no row of this test
printf 'unplanned.sh\t1\t10\tboard\n' >>"$tmp/plan.tsv"
list=""
for t in solo good bad hang crash early silent unplanned skips hosta hostb; do list="$list $tmp/$t.sh"; done
out=$(TEST_PLAN="$tmp/plan.tsv" TEST_LOG_DIR="$tmp/logs" HOST_TESTS= BOARD_TESTS="$list" \
    TEST_JOBS=2 TEST_TIME_SCALE=1 bash tests/run.sh 2>&1)
rc=$?

# expect NAME PATTERN: the runner's output holds a line matching PATTERN
expect() {
    if grep -qE "$2" <<<"$out"; then
        echo "PASS runner_$1"
    else
        echo "FAIL runner_$1: no line matching '$2' in:"
        sed 's/^/    /' <<<"$out" | head -40
    fi
}
expect counts_a_good_test "good.sh: 2 passed, 0 failed"
expect counts_a_failed_check "bad.sh: 1 passed, 1 failed"
expect kills_a_hung_test "FAIL .*hang.sh: did not finish within its limit of 2 s"
expect crash_after_pass_lines_fails "FAIL .*crash.sh: exited with status [0-9]+ without naming a failed check"
expect crash_counts_short "FAIL .*crash.sh: ran 2 checks, .* declares 3"
expect early_exit_fails "FAIL .*early.sh: ran 1 checks, .* declares 3"
expect silent_exit_fails "FAIL .*silent.sh: exited with status 3 without naming a failed check"
expect unplanned_test_fails "FAIL .*unplanned.sh: not declared in"
expect counts_a_skipped_check "skips.sh: 1 passed, 0 failed, 1 skipped"
if grep -q "hosta.sh: 1 passed, 0 failed" <<<"$out" && grep -q "hostb.sh: 1 passed, 0 failed" <<<"$out"; then
    echo "PASS runner_host_and_board_tests_run_beside_each_other"
else
    echo "FAIL runner_host_and_board_tests_run_beside_each_other: $(grep -E 'host[ab]' <<<"$out" | tr '\n' ' ')"
fi
expect solo_runs_alone "solo.sh: 1 passed, 0 failed"
# good 2 + bad 1 + hang 1 + crash 2 + early 1 + unplanned 1 + skips 1 +
# hosta 1 + hostb 1 + solo 1 passed; skips 1 skipped; failed:
# bad 1, hang 1, crash 2, early 1, silent 1 (+ its count? it ran 0 of 1:
# counted), unplanned 1
expect summary_adds_up "^12 passed, 9 failed, 1 skipped$"
if [ $rc -ne 0 ]; then
    echo "PASS runner_exit_status_says_failed"
else
    echo "FAIL runner_exit_status_says_failed: the runner exited 0 with failures"
fi
# A verdict left by an earlier run is not read as this run's, though the
# test starts late (TEST_START_DELAY): the runner looks for a finished
# test's status file right after starting it.
fake flip 'echo "PASS flip_new"'
printf '%s\t1\t60\tboard\n' "$tmp/flip.sh" >"$tmp/plan-flip.tsv"
mkdir -p "$tmp/logs-flip"
echo "FAIL flip_old: the earlier run's" >"$tmp/logs-flip/flip.sh.log"
echo "1 1 60" >"$tmp/logs-flip/flip.sh.log.rc"
out=$(TEST_PLAN="$tmp/plan-flip.tsv" TEST_LOG_DIR="$tmp/logs-flip" HOST_TESTS= \
    BOARD_TESTS="$tmp/flip.sh" TEST_JOBS=2 TEST_START_DELAY=1 bash tests/run.sh 2>&1)
if grep -q "flip.sh: 1 passed, 0 failed" <<<"$out" && ! grep -q flip_old <<<"$out"; then
    echo "PASS runner_stale_verdict_not_read"
else
    echo "FAIL runner_stale_verdict_not_read: $(tr '\n' ' ' <<<"$out")"
fi
