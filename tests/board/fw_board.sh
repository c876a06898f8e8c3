#!/usr/bin/env bash
# Firmware checks that need what the links1 tool never does on purpose: a
# board given too little RAM is refused at boot with both sizes named; on a
# 10-core board damaged frames, unknown commands and malformed payloads get
# a negative LINK_RESULT naming the problem and the board keeps running;
# data abort, prefetch abort, panic and both spinlock misuses on five NCs
# are reported with core, role, kind and address while the others keep
# answering.
set -u
cd "$(dirname "$0")/../.."
FW_DIR=${FW_DIR:-build}
exec timeout 300 python3 tests/board/fw_board.py "$FW_DIR/links1-float.elf" 10
