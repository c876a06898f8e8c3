#!/usr/bin/env bash
# tests/run.sh: runs every host unit test and board test, counts the
# "PASS name" / "FAIL name: ..." lines they print, and ends with the summary
# line "N passed, N failed".
#
# A check that cannot run here (it needs root to make a second account)
# prints "SKIP name: why"; it counts as run, and the summary line ends
# ", N skipped" when any was.
#
# Every test is declared in tests/plan.tsv: its path (as the lists give it),
# how many checks it runs, the seconds it may take, and its suite: "host"
# for one that boots no board, "board" for one that does, "full" for one
# of `make test-full`.  Host and board
# tests run TEST_JOBS at a time (one per host core by default: a board's
# idle unit computers sleep, and a small test's time is mostly the host's
# own work), longest first by their last run (or their limit); full tests run one at
# a time.  A test fails (one failure more, named) when it
#   - is not declared there, or runs another number of checks than declared
#     (one that ends early prints fewer);
#   - exits non-zero without printing a FAIL line (a crash, a sanitizer
#     report), or leaves no exit status;
#   - runs past its time limit (it is killed, its name printed).
# Each test's exit status is written to a file beside its log atomically
# (written aside, then renamed), and read back only once the test ended.
#
# Environment (set by the Makefile from the plan): HOST_TESTS (programs),
# BOARD_TESTS (scripts), FW_DIR; TEST_JOBS (tests at once, default nproc);
# TEST_START_DELAY (seconds each test waits before it starts: the runner's
# own tests); TEST_TIME_SCALE multiplies every limit (default 1); TEST_PLAN and
# TEST_LOG_DIR name another plan and log folder (tests/runner/ tests the
# runner itself with them).
set -u
cd "$(dirname "$0")/.."
export FW_DIR="${FW_DIR:-build}"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
plan=${TEST_PLAN:-tests/plan.tsv}
scale=${TEST_TIME_SCALE:-1}
case $scale in
    '' | *[!0-9]*) echo "tests/run.sh: TEST_TIME_SCALE must be a whole number, not '$scale'" >&2
        exit 2 ;;
esac

passed=0
failed=0
skipped=0
log_dir=${TEST_LOG_DIR:-build/test-logs}
mkdir -p "$log_dir"

# plan_of PATH: "CHECKS LIMIT" from the plan, or nothing.
plan_of() {
    awk -F'\t' -v n="$1" '$1 == n && NF >= 3 { print $2, $3; exit }' "$plan"
}
# pooled PATH: true when the plan's suite of the test lets it run beside
# others ("host" or "board").
pooled() {
    awk -F'\t' -v n="$1" '$1 == n && ($4 == "host" || $4 == "board") { found = 1; exit }
        END { exit !found }' "$plan"
}
# last_secs PATH: the seconds its last run here took; before any, an
# eighth of its limit (the plan sets limits at about eight times a run).
last_secs() {
    local rc secs limit checks plimit
    read -r rc secs limit 2>/dev/null <"$log_dir/$(basename "$1").log.rc" || true
    case ${secs:-} in
    '' | *[!0-9]*)
        read -r checks plimit < <(plan_of "$1")
        echo $(( ${plimit:-0} / 8 )) ;;
    *) echo "$secs" ;;
    esac
}

# exec_one LABEL CMD...: runs one test into its log under its time limit
# and records "STATUS SECONDS" beside it (status 124: killed at the limit).
exec_one() {
    local label=$1; shift
    local name log limit checks
    name=$(basename "$label")
    log="$log_dir/$name.log"
    read -r checks limit < <(plan_of "$label")
    limit=$(( ${limit:-60} * scale ))
    local start=$SECONDS
    timeout --kill-after=10 "$limit" "$@" >"$log" 2>&1
    local rc=$?
    echo "$rc $((SECONDS - start)) $limit" >"$log.rc.part" && mv "$log.rc.part" "$log.rc"
}

# report_one LABEL: counts the PASS/FAIL lines of a finished test's log.
report_one() {
    local label=$1
    local name log rc secs limit p f s checks plimit
    name=$(basename "$label")
    log="$log_dir/$name.log"
    rc= secs= limit=
    [ -e "$log.rc" ] && read -r rc secs limit <"$log.rc"
    p=$(grep -c '^PASS ' "$log" 2>/dev/null)
    f=$(grep -c '^FAIL ' "$log" 2>/dev/null)
    s=$(grep -c '^SKIP ' "$log" 2>/dev/null)
    p=${p:-0} f=${f:-0} s=${s:-0}
    local ran=$((p + f + s))
    grep -E '^(PASS|FAIL|SKIP|  also) ' "$log" 2>/dev/null
    read -r checks plimit < <(plan_of "$label")
    case $rc in
        '' | *[!0-9]*)
            echo "FAIL $label: left no exit status"
            f=$((f + 1)) ;;
        124 | 137)
            echo "FAIL $label: did not finish within its limit of $limit s (tests/plan.tsv); last lines:"
            tail -n 15 "$log" | sed 's/^/    /'
            f=$((f + 1)) ;;
        0) ;;
        *)
            if [ "$f" -eq 0 ]; then
                echo "FAIL $label: exited with status $rc without naming a failed check; last lines:"
                tail -n 15 "$log" | sed 's/^/    /'
                f=1
            fi ;;
    esac
    if [ -z "${checks:-}" ]; then
        echo "FAIL $label: not declared in $plan (path, checks, seconds, suite)"
        f=$((f + 1))
    elif [ "$ran" -ne "$checks" ]; then
        echo "FAIL $label: ran $ran checks, $plan declares $checks"
        f=$((f + 1))
    fi
    [ "$f" -gt 0 ] && echo "  (full log: $log)"
    local skips=""
    [ "$s" -gt 0 ] && skips=", $s skipped"
    echo "  [$label: $p passed, $f failed$skips, ${secs:-?} s]"
    passed=$((passed + p))
    failed=$((failed + f))
    skipped=$((skipped + s))
}

# The pool: host programs and the scripts of suites host and board, longest
# (by their last run) first, TEST_JOBS at a time; results are reported in
# the pool's order as each is known.  Then the full scripts, one at a time.
TEST_JOBS=${TEST_JOBS:-${HOST_JOBS:-$(nproc 2>/dev/null || echo 2)}}
pool_in=()
alone_list=()
for t in ${HOST_TESTS:-}; do pool_in+=("$t"); done
for t in ${BOARD_TESTS:-}; do
    if pooled "$t"; then
        pool_in+=("$t")
    else
        alone_list+=("$t")
    fi
done
pool=()
if [ ${#pool_in[@]} -gt 0 ]; then
    mapfile -t pool < <(for t in "${pool_in[@]}"; do
        printf '%s\t%s\n' "$(last_secs "$t")" "$t"
    done | sort -t$'\t' -k1,1nr -s | cut -f2)
fi
# run_one PATH: runs a test (a script by its interpreter, a program as it
# is) and reports nothing yet.  Its earlier verdict is gone already
# (forget_verdict, before it starts: the pool looks for a finished test's
# status file as soon as it has started one, however late that one gets
# going on a busy host; TEST_START_DELAY seconds model such a late start
# for tests/runner/).
run_one() {
    [ -n "${TEST_START_DELAY:-}" ] && sleep "$TEST_START_DELAY"
    case $1 in
    *.sh) exec_one "$1" bash "$1" ;;
    *.py) exec_one "$1" python3 "$1" ;;
    *) exec_one "$1" "$1" ;;
    esac
}
# forget_verdict PATH: the status file an earlier run of PATH left.
forget_verdict() {
    rm -f "$log_dir/$(basename "$1").log.rc"
}
next_report=0
for ((i = 0; i < ${#pool[@]}; i++)); do
    forget_verdict "${pool[i]}"
    run_one "${pool[i]}" &
    # Keep at most TEST_JOBS running; report finished ones in order.
    while [ "$(jobs -rp | wc -l)" -ge "$TEST_JOBS" ]; do
        wait -n
    done
    while [ $next_report -le $i ] &&
        [ -e "$log_dir/$(basename "${pool[next_report]}").log.rc" ]; do
        report_one "${pool[next_report]}"
        next_report=$((next_report + 1))
    done
done
wait
while [ $next_report -lt ${#pool[@]} ]; do
    report_one "${pool[next_report]}"
    next_report=$((next_report + 1))
done
for t in "${alone_list[@]}"; do
    forget_verdict "$t"
    run_one "$t"
    report_one "$t"
done

if [ "$skipped" -gt 0 ]; then
    echo "$passed passed, $failed failed, $skipped skipped"
else
    echo "$passed passed, $failed failed"
fi
[ "$failed" -eq 0 ]
