#!/usr/bin/env bash
# runner.sh: tests/run.sh counts what it says it counts.  Fake tests (small
# scripts in a temporary folder, with a plan of their own) that pass, fail,
# hang, crash after printing PASS lines, end early, exit non-zero silently,
# or are missing from the plan: each must be counted as the runner's header
# says, and the summary line must add them up.
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
printf 'good.sh\t2\t10\nbad.sh\t2\t10\nhang.sh\t2\t2\ncrash.sh\t3\t10\nearly.sh\t3\t10\nsilent.sh\t1\t10\n' \
    >"$tmp/plan.tsv"
list=""
for t in good bad hang crash early silent unplanned; do list="$list $tmp/$t.sh"; done
out=$(TEST_PLAN="$tmp/plan.tsv" TEST_LOG_DIR="$tmp/logs" HOST_TESTS= BOARD_TESTS="$list" \
    bash tests/run.sh 2>&1)
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
# good 2 + bad 1 + hang 1 + crash 2 + early 1 + unplanned 1 passed; failed:
# bad 1, hang 1, crash 2, early 1, silent 1 (+ its count? it ran 0 of 1:
# counted), unplanned 1
expect summary_adds_up "^8 passed, 9 failed$"
if [ $rc -ne 0 ]; then
    echo "PASS runner_exit_status_says_failed"
else
    echo "FAIL runner_exit_status_says_failed: the runner exited 0 with failures"
fi
