#!/usr/bin/env bash
# Firmware checks that need what the links1 tool never does on purpose: a
# board given too little RAM is refused at boot with both sizes named; on a
# 10-core board damaged frames, unknown commands and malformed payloads get
# a negative LINK_RESULT naming the problem and the board keeps running;
# data abort, prefetch abort, panic and both spinlock misuses on five NCs
# are reported with core, role, kind and address while the others keep
# answering.  The checks are build/tests/fw_board_check (fw_board_check.c).
set -u
cd "$(dirname "$0")/../../.."
FW_DIR=${FW_DIR:-build}
prog=build/tests/fw_board_check
elf=$FW_DIR/links1-float.elf
[ -x "$prog" ] || { echo "FAIL fw_board: $prog is not built (run make)"; exit 1; }
[ -r "$elf" ] || { echo "FAIL fw_board: firmware $elf is not built (run make)"; exit 1; }
exec timeout 300 "$prog" "$elf" 10
