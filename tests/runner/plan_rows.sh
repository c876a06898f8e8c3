#!/usr/bin/env bash
# Every test the plan (tests/plan.tsv) declares is one some list of the
# build runs (HOST_TESTS, BOARD_TESTS, the test-full lists in the Makefile
# and every module.mk): a declared test no list names would never run,
# and nothing else would say so.
cd "$(dirname "$0")/../.."
lists=$(cat Makefile $(find . -name module.mk -not -path "./build/*"))
missing=
while IFS=$'\t' read -r name _; do
    case $name in '' | '#'*) continue ;; esac
    base=${name%.sh}
    base=${base%_double}; base=${base%_float}; base=${base%_fixed}; base=${base%_soft}
    grep -qw -- "$base" <<<"$lists" || missing+=" $name"
done <tests/plan.tsv
if [ -z "$missing" ]; then
    echo "PASS plan_rows_all_run"
else
    echo "FAIL plan_rows_all_run: declared in tests/plan.tsv, run by no list:$missing"
fi
