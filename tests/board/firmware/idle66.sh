#!/usr/bin/env bash
# A board of 66 cores (DM, RC, 64 NCs, as LINKS-1 was built), idle after
# boot: over 5 s every core must retire almost no guest instructions (it
# sleeps in WFI; counted by the TCG plugin, so the verdict does not depend
# on how busy the host is); then every serial line still answers a ping.
. "$(dirname "$0")/../lib.sh"
board_ready idle66_idle idle66_ping || exit 0
board_selftest idle66 --ncs 64 idle ping
