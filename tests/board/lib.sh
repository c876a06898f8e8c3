# tests/board/lib.sh: helpers for the board test scripts (sourced, not run).
# Every check prints one line "PASS name" or "FAIL name: why", which
# tests/run.sh counts.  The tool's full output stays in the test log.
set -u
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
LINKS1=${LINKS1:-build/links1}
export FW_DIR=${FW_DIR:-build}
# A run that hangs past this is killed (QEMU dies with the tool).
BOARD_RUN_LIMIT_S=${BOARD_RUN_LIMIT_S:-300}

# checks_fail WHY NAME...: FAILs every named check for the same reason
# (a script that cannot run its checks still prints one line each).
checks_fail() {
    local why=$1 name
    shift
    for name in "$@"; do echo "FAIL $name: $why"; done
}

# board_ready: FAILs every named check when the tool or firmware is missing.
board_ready() { # $@ = check names that cannot run
    local why=""
    [ -x "$LINKS1" ] || why="$LINKS1 is not built (run make)"
    [ -z "$why" ] && [ ! -r "$FW_DIR/links1-float.elf" ] &&
        why="firmware $FW_DIR/links1-float.elf is not built (run make)"
    [ -z "$why" ] && return 0
    checks_fail "$why" "$@"
    return 1
}

# board_selftest PREFIX [links1 selftest arguments...]: runs the checks in one
# boot and turns each "selftest NAME: ok|FAILED: ..." line into
# "PASS PREFIX_NAME" or "FAIL PREFIX_NAME: ...".  Checks named on the
# command line that never reported (the board died first) FAIL too.
board_selftest() {
    local prefix=$1; shift
    local out rc
    out=$(timeout "$BOARD_RUN_LIMIT_S" "$LINKS1" selftest --quiet "$@" 2>&1)
    rc=$?
    echo "--- $LINKS1 selftest $* (exit $rc)"
    echo "$out" | sed 's/^/    /'
    local names=(boot shutdown link-errors) a
    for a in "$@"; do
        case $a in
        status|ping|imsu|stress|link-sink|link-source|fault|idle|latency) names+=("$a") ;;
        esac
    done
    local n line
    for n in "${names[@]}"; do
        line=$(echo "$out" | grep -m1 "^selftest $n: ")
        case $line in
        "selftest $n: ok"*) echo "PASS ${prefix}_$n" ;;
        "selftest $n: FAILED: "*) echo "FAIL ${prefix}_$n: ${line#"selftest $n: FAILED: "}" ;;
        *)
            [ $rc -eq 124 ] && line="killed after ${BOARD_RUN_LIMIT_S} s" ||
                line="no verdict (exit $rc): $(echo "$out" | grep 'links1' | tail -n 1)"
            echo "FAIL ${prefix}_$n: $line"
            ;;
        esac
    done
}
