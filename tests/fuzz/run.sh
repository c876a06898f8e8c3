#!/usr/bin/env bash
# tests/fuzz/run.sh NAME SECONDS: runs the harness build/fuzz/NAME for
# SECONDS on a working copy of its seed corpus (build/fuzz/work/NAME; the
# seeds in tests/fuzz/corpus/NAME stay as they are), then reports one line:
#   fuzz NAME: N executions in S s, coverage C edges (F features), corpus K, crashes X
# A crash leaves its input in build/fuzz/crashes/NAME/ and the exit status 1.
set -u
cd "$(dirname "$0")/../.."
name=$1
seconds=$2
bin=build/fuzz/$name
seeds=tests/fuzz/corpus/$name
work=build/fuzz/work/$name
crashes=build/fuzz/crashes/$name
log=build/fuzz/$name.log
if [ ! -x "$bin" ]; then
    echo "fuzz $name: $bin is missing (make fuzz-build)" >&2
    exit 1
fi
mkdir -p "$work" "$crashes"
[ -d "$seeds" ] && cp -n "$seeds"/* "$work"/ 2>/dev/null
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}"
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$PWD/tests/fuzz/lsan-assimp.supp}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
# -close_fd_mask=3: the code's own prints are not wanted; libFuzzer and the
# sanitizers still report on a copy of stderr.
# a harness over a library that itself crashes or hangs on some inputs
# names flags of its own in module.mk (NAME_RUN_FLAGS, e.g. -fork=1
# -ignore_crashes=1): every crash still leaves its input and is counted
flags=$(sed -n "s/^${name}_RUN_FLAGS := *//p" tests/fuzz/module.mk)
start=$SECONDS
"$bin" $flags -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2560 -print_final_stats=1 \
    -close_fd_mask=3 -artifact_prefix="$crashes/" "$work" >"$log" 2>&1
rc=$?
wall=$((SECONDS - start))
execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
last=$(grep -E '^#[0-9]+' "$log" | tail -1)
[ -z "$execs" ] && execs=$(echo "$last" | sed -n 's/^#\([0-9]*\).*/\1/p') # fork mode
cov=$(echo "$last" | sed -n 's/.* cov: \([0-9]*\).*/\1/p')
ft=$(echo "$last" | sed -n 's/.* ft: \([0-9]*\).*/\1/p')
corp=$(echo "$last" | sed -n 's/.* corp: \([0-9]*\).*/\1/p')
ncrash=$(find "$crashes" -type f \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' \
    -o -name 'oom-*' \) -newer "$bin" | wc -l)
echo "fuzz $name: ${execs:-?} executions in $wall s, coverage ${cov:-?} edges" \
    "(${ft:-?} features), corpus ${corp:-?}, crashes $ncrash (log $log)"
if [ "$rc" -ne 0 ]; then
    grep -E '^(==[0-9]+==ERROR|SUMMARY|.*runtime error)' "$log" | head -5 | sed 's/^/    /'
    exit 1
fi
exit 0
