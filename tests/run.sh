#!/usr/bin/env bash
# tests/run.sh: runs every host unit test and board test, counts the
# "PASS name" / "FAIL name: ..." lines they print, and ends with the summary
# line "N passed, N failed".  A program that exits non-zero without printing a
# FAIL line (a crash, a sanitizer report, a timeout) counts as one failure.
#
# Environment (set by the Makefile): HOST_TESTS, BOARD_TESTS, FW_DIR.
set -u
cd "$(dirname "$0")/.."
export FW_DIR="${FW_DIR:-build}"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"

passed=0
failed=0
log_dir=build/test-logs
mkdir -p "$log_dir"

run_one() { # $1 = label, rest = command
    local label=$1; shift
    local log="$log_dir/$(basename "$label").log"
    local start=$SECONDS
    "$@" >"$log" 2>&1
    local rc=$?
    local p f
    p=$(grep -c '^PASS ' "$log")
    f=$(grep -c '^FAIL ' "$log")
    grep -E '^(PASS|FAIL|  also) ' "$log"
    if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
        echo "FAIL $label: exited with status $rc without naming a failed check; last lines:"
        tail -n 15 "$log" | sed 's/^/    /'
        f=1
    elif [ "$f" -gt 0 ]; then
        echo "  (full log: $log)"
    fi
    if [ "$p" -eq 0 ] && [ "$f" -eq 0 ]; then
        echo "FAIL $label: ran no check"
        f=1
    fi
    echo "  [$label: $p passed, $f failed, $((SECONDS - start)) s]"
    passed=$((passed + p))
    failed=$((failed + f))
}

for t in ${HOST_TESTS:-}; do
    run_one "$t" "$t"
done
for t in ${BOARD_TESTS:-}; do
    run_one "$t" bash "$t"
done

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
