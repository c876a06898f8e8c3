#!/usr/bin/env bash
# The plan (tests/plan.tsv) against the tree.  The Makefile makes every list
# of what runs from the plan, so a test is run exactly when it has a row;
# these checks hold the rows and the tree to each other:
#   plan_rows_well_formed     every row is path, checks, seconds and suite
#                             (host, board or full), numbers where numbers
#                             go, and no two rows share a file name (the
#                             runner's logs and mutants' try: lines use it)
#   plan_rows_exist           a script's row names a file that exists; a
#                             build/tests/NAME row a C test with a build rule
#                             (a NAME_SRCS in some module.mk)
#   plan_scripts_all_planned  every test script under tests/ has a row: each
#                             .sh or .py but the benchmarks (tests/bench/) and
#                             the helpers another file of tests/, the
#                             Makefile or a module.mk runs or sources by name
#   plan_c_tests_all_planned  every C test with a build rule (test_NAME_SRCS)
#                             has its build/tests/NAME row
cd "$(dirname "$0")/../.."
plan=tests/plan.tsv
rows=$(awk -F'\t' '!/^#/ && NF' "$plan")

# verdict NAME PROBLEMS: PASS when PROBLEMS is empty.
verdict() {
    if [ -z "$2" ]; then
        echo "PASS $1"
    else
        echo "FAIL $1:$2"
    fi
}

bad=$(awk -F'\t' '!/^#/ && NF {
        if (NF != 4 || $2 !~ /^[0-9]+$/ || $3 !~ /^[1-9][0-9]*$/ || $4 !~ /^(host|board|full)$/)
            printf " line %d: \"%s\";", NR, $0
        n = $1; sub(/.*\//, "", n)
        if (n in seen) printf " %s and %s share a name;", seen[n], $1
        seen[n] = $1
    }' "$plan")
verdict plan_rows_well_formed "$bad"

# (its own make, apart from the one that runs the tests: no MAKEFLAGS)
rules=$(env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make -s --no-print-directory test-progs-with-rules)
bad=
while IFS=$'\t' read -r path _; do
    case $path in
    build/tests/*) grep -qxF -- "${path#build/tests/}" <<<"$rules" ||
        bad+=" $path (no ${path#build/tests/}_SRCS in a module.mk)" ;;
    *) [ -f "$path" ] || bad+=" $path (no such file)" ;;
    esac
done <<<"$rows"
verdict plan_rows_exist "$bad"

# A helper: a script whose file name another file of tests/, the Makefile
# or a module.mk names (the tests that source or run it).
named_elsewhere() {
    git grep -lwF -- "$(basename "$1")" -- Makefile '*module.mk' 'tests/*' \
        ":!$1" ":!$plan" | grep -q .
}
bad=
for f in $(git ls-files -co --exclude-standard -- 'tests/*.sh' 'tests/*.py'); do
    case $f in tests/bench/*) continue ;; esac
    grep -qF -- "$f"$'\t' <<<"$rows" && continue
    named_elsewhere "$f" || bad+=" $f"
done
verdict plan_scripts_all_planned "${bad:+ scripts nothing runs, with no row:$bad}"

bad=
for name in $rules; do
    grep -q "^build/tests/$name"$'\t' <<<"$rows" || bad+=" build/tests/$name"
done
verdict plan_c_tests_all_planned "${bad:+ C tests with a build rule and no row:$bad}"
