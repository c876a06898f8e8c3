#!/usr/bin/env bash
# make-gdb.sh: what `make gdb` does after building (xv6's `make qemu-gdb`):
# starts the named board "gdb" (DM, RC and $GDB_NCS NCs) halted, with QEMU's
# gdb stub on 127.0.0.1:$GDB_PORT, through the one launcher (`links1 board
# start --gdb`), and attaches gdb-multiarch with the firmware's symbols.
# Every emulated core is a gdb thread.  Render on the board from another
# terminal with `build/links1 render --board gdb SCENE -o OUT.png`.  When
# gdb exits the board is stopped.  GDB_ARGS adds gdb arguments (e.g. -x FILE).
set -eu
cd "$(dirname "$0")/.."
LINKS1=build/links1
FW=${FW_DIR:-build}/links1-${GDB_ARITH:-float}.elf
PORT=${GDB_PORT:-1234}
"$LINKS1" board stop gdb >/dev/null 2>&1 || true
"$LINKS1" board start --name gdb --ncs "${GDB_NCS:-2}" --arith "${GDB_ARITH:-float}" \
    --gdb "$PORT" --timeout 3600 &
starter=$!
# The stub listens once QEMU is up.
for _ in $(seq 100); do
    (exec 3<>"/dev/tcp/127.0.0.1/$PORT") 2>/dev/null && break
    sleep 0.1
done
rc=0
gdb-multiarch -q "$FW" -ex "target remote 127.0.0.1:$PORT" ${GDB_ARGS:-} || rc=$?
# A board that never came up (gdb left before the cores ran) still has its
# starter waiting for it.
kill "$starter" 2>/dev/null || true
wait "$starter" 2>/dev/null || true
"$LINKS1" board stop gdb || true
exit $rc
