#!/usr/bin/env bash
# tests/fuzz/smoke.sh: a short fixed run of each fuzz harness (no board):
# first every seed of tests/fuzz/corpus/NAME (the regression inputs of the
# crashes found so far among them), then FUZZ_SMOKE_RUNS mutated inputs from
# a fixed seed.  PASS when the harness ends without a crash, a leak or a
# sanitizer report.
set -u
cd "$(dirname "$0")/../.."
runs=${FUZZ_SMOKE_RUNS:-10000}
names=$(sed -n 's/^FUZZERS += //p' tests/fuzz/module.mk)
for name in $names; do
    check=fuzz_smoke_${name#fuzz_}
    bin=build/fuzz/$name
    if [ ! -x "$bin" ]; then
        echo "FAIL $check: $bin is missing (make fuzz-build)"
        continue
    fi
    # a slow harness names its own count in module.mk (NAME_SMOKE_RUNS)
    own=$(sed -n "s/^${name}_SMOKE_RUNS := *//p" tests/fuzz/module.mk)
    n_runs=${own:-$runs}
    [ -n "${FUZZ_SMOKE_RUNS:-}" ] && n_runs=$FUZZ_SMOKE_RUNS
    seeds=tests/fuzz/corpus/$name
    nseeds=$(ls "$seeds" 2>/dev/null | wc -l)
    if [ "$nseeds" -eq 0 ]; then
        echo "FAIL $check: no seed corpus in $seeds"
        continue
    fi
    work=$(mktemp -d)
    art=$(mktemp -d)
    log=build/test-logs/$check.fuzz.log
    mkdir -p build/test-logs
    cp "$seeds"/* "$work"/
    LSAN_OPTIONS=suppressions=$PWD/tests/fuzz/lsan-assimp.supp ASAN_OPTIONS=detect_leaks=1 "$bin" -seed=1 -runs="$n_runs" -timeout=20 \
        -rss_limit_mb=2560 -close_fd_mask=3 -artifact_prefix="$art/" "$work" >"$log" 2>&1
    rc=$?
    done_line=$(grep -E '^Done [0-9]+ runs' "$log" | tail -1)
    if [ $rc -eq 0 ] && [ -n "$done_line" ] && [ -z "$(ls "$art")" ]; then
        echo "PASS $check ($nseeds seeds; $done_line)"
    else
        echo "FAIL $check: exit $rc, $(ls "$art" | head -3 | tr '\n' ' ')" \
            "$(grep -E 'ERROR|runtime error' "$log" | head -2 | tr '\n' ' ') (log $log)"
    fi
    rm -rf "$work" "$art"
done
