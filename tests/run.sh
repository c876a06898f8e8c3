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

# exec_one LABEL CMD...: runs one test into its log and records its exit
# status and seconds beside it.
exec_one() {
    local label=$1; shift
    local log="$log_dir/$(basename "$label").log"
    local start=$SECONDS
    "$@" >"$log" 2>&1
    echo "$? $((SECONDS - start))" >"$log.rc"
}

# report_one LABEL: counts the PASS/FAIL lines of a finished test's log.
report_one() {
    local label=$1
    local log="$log_dir/$(basename "$label").log"
    local rc secs p f
    read -r rc secs <"$log.rc"
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
    echo "  [$label: $p passed, $f failed, $secs s]"
    passed=$((passed + p))
    failed=$((failed + f))
}

# Host tests are independent programs: HOST_JOBS of them run at once (one
# per host core by default); their results are reported in order.  Board
# tests run one at a time: each boots a board that wants the host's cores.
HOST_JOBS=${HOST_JOBS:-$(nproc 2>/dev/null || echo 2)}
host_list=(${HOST_TESTS:-})
next_report=0
for ((i = 0; i < ${#host_list[@]}; i++)); do
    rm -f "$log_dir/$(basename "${host_list[i]}").log.rc" # no stale verdict
    exec_one "${host_list[i]}" "${host_list[i]}" &
    # Keep at most HOST_JOBS running; report finished ones in order.
    while [ "$(jobs -rp | wc -l)" -ge "$HOST_JOBS" ]; do
        wait -n
    done
    while [ $next_report -le $i ] &&
        [ -e "$log_dir/$(basename "${host_list[next_report]}").log.rc" ]; do
        report_one "${host_list[next_report]}"
        next_report=$((next_report + 1))
    done
done
wait
while [ $next_report -lt ${#host_list[@]} ]; do
    report_one "${host_list[next_report]}"
    next_report=$((next_report + 1))
done
for t in ${BOARD_TESTS:-}; do
    exec_one "$t" bash "$t"
    report_one "$t"
done

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
