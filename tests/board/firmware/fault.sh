#!/usr/bin/env bash
# An undefined instruction injected on NC core 5 of a 10-core board is
# reported with core, role and address; the other cores still answer.
. "$(dirname "$0")/../lib.sh"
board_ready fault_fault || exit 0
board_selftest fault --ncs 8 fault 5
