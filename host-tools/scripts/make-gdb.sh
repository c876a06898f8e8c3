#!/usr/bin/env bash
# make-gdb.sh: what `make gdb` does after building (xv6's `make qemu-gdb`):
# starts the named board "gdb" (DM, RC and $GDB_NCS NCs) halted, with QEMU's
# gdb stub on a unix socket in the board's state directory (only this user
# can reach it; no TCP port), through the one launcher (`links1 board start
# --gdb`), and attaches gdb-multiarch to that socket with the firmware's
# symbols.  Every emulated core is a gdb thread.  Render on the board from
# another terminal with `build/links1 render --board gdb SCENE -o OUT.png`.
# When gdb exits the board is stopped.  GDB_ARGS adds gdb arguments (e.g.
# -x FILE).
set -eu
cd "$(dirname "$0")/../.."
LINKS1=${LINKS1:-build/links1}
FW=${FW_DIR:-build}/links1-${GDB_ARITH:-float}.elf
if [ -n "${GDB_PORT:-}" ]; then
    echo "make gdb: GDB_PORT is gone: the gdb stub is a unix socket in your state directory now" >&2
fi
log=$(mktemp /tmp/links1-gdb-start.XXXXXX)
trap 'rm -f "$log"' EXIT
"$LINKS1" board stop gdb >/dev/null 2>&1 || true
"$LINKS1" board start --name gdb --ncs "${GDB_NCS:-2}" --arith "${GDB_ARITH:-float}" \
    --gdb --timeout 3600 > >(tee "$log") 2>&1 &
starter=$!
# The launcher names the socket; QEMU makes it once it is up.
sock=""
for _ in $(seq 100); do
    sock=$(sed -n "s/^links1: QEMU's gdb stub on \(.*\), every core halted.*/\1/p" "$log")
    [ -n "$sock" ] && [ -S "$sock" ] && break
    sleep 0.1
done
rc=0
if [ -n "$sock" ] && [ -S "$sock" ]; then
    gdb-multiarch -q "$FW" -ex "target remote $sock" ${GDB_ARGS:-} || rc=$?
else
    echo "make gdb: the board's gdb socket did not appear" >&2
    rc=1
fi
# A board that never came up (gdb left before the cores ran) still has its
# starter waiting for it.
kill "$starter" 2>/dev/null || true
wait "$starter" 2>/dev/null || true
"$LINKS1" board stop gdb || true
exit $rc
