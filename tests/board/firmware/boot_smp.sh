#!/usr/bin/env bash
# Boots the board with 3, 10, 66 and 256 cores (1, 8, 64 and 254 NCs): every
# unit computer must report in with its role (a line each under --verbose),
# the board must shut down on command, and no frame may be damaged or lost.
# Without --verbose bringing the board up prints one line, not one per core.
. "$(dirname "$0")/../lib.sh"
names=()
for n in 3 10 66 256; do names+=("boot_smp$n"); done
names+=(boot_summary_line)
board_ready "${names[@]}" || exit 0
for n in 3 10 66 256; do
    out=$(timeout "$BOARD_RUN_LIMIT_S" "$LINKS1" boot --ncs "$((n - 2))" --verbose 2>&1)
    rc=$?
    echo "--- $LINKS1 boot --ncs $((n - 2)) --verbose (exit $rc)"
    echo "$out" | sed 's/^/    /'
    reported=$(echo "$out" | grep -c '^core [0-9]* \(DM\|RC\|NC\) reported in')
    roles_ok=$(echo "$out" | grep -c -E '^core (0 DM|1 RC|([2-9]|[1-9][0-9]+) NC) reported in')
    if [ $rc -eq 0 ] && [ "$reported" -eq "$n" ] && [ "$roles_ok" -eq "$n" ]; then
        echo "PASS boot_smp$n"
    else
        why=$(echo "$out" | grep '^links1: ' | grep -v 'booting' | tail -n 2 | tr '\n' ' ')
        echo "FAIL boot_smp$n: exit $rc, $reported of $n reported in ($roles_ok with the right role) $why"
    fi
done
out=$(timeout "$BOARD_RUN_LIMIT_S" "$LINKS1" boot --ncs 8 2>&1)
rc=$?
echo "--- $LINKS1 boot --ncs 8 (exit $rc)"
echo "$out" | sed 's/^/    /'
if [ $rc -eq 0 ] && echo "$out" | grep -q '^links1: board up: 10 unit computers in [0-9.]* s$' &&
    ! echo "$out" | grep -q 'reported in (mpidr'; then
    echo "PASS boot_summary_line"
else
    echo "FAIL boot_summary_line: exit $rc, no 'board up: 10 unit computers in T s' line, or per-core lines without --verbose"
fi
