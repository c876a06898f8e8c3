#!/usr/bin/env bash
# A panic before the other cores start still reaches the host: core 0 checks
# the board's RAM (boot/boot.c) right after it has registered the host link
# as the kernel's log sink; a board given 256 MiB must report that panic as a
# LINK_FAULT naming both sizes, and the boot must fail.
. "$(dirname "$0")/lib.sh"
board_ready early_panic || exit 0
out=$(timeout "$BOARD_RUN_LIMIT_S" "$LINKS1" boot --smp 3 --ram 256 --timeout 3 2>&1)
rc=$?
echo "--- $LINKS1 boot --smp 3 --ram 256 --timeout 3 (exit $rc)"
echo "$out" | sed 's/^/    /'
want='core 0 DM FAULT: panic .*the board has 256 MiB of RAM .*links1 needs 512 MiB'
if [ $rc -ne 0 ] && echo "$out" | grep -q "$want"; then
    echo "PASS early_panic"
else
    echo "FAIL early_panic: exit $rc, no LINK_FAULT from core 0 naming 256 and 512 MiB"
fi
