#!/usr/bin/env bash
# Firmware checks on a 10-core board that need deliberately bad frames:
# damaged frames, unknown commands and malformed payloads get a negative
# LINK_RESULT naming the problem and the board keeps running; data abort,
# prefetch abort and panic on three NCs are reported with core, role, kind
# and address while the other unit computers keep answering.
set -u
cd "$(dirname "$0")/../.."
FW_DIR=${FW_DIR:-build}
exec timeout 300 python3 tests/board/fw_board.py "$FW_DIR/links1-float.elf" 10
