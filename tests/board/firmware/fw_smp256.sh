#!/usr/bin/env bash
# The full LINKS-1 design on a 256-core board (DM, RC, 254 NCs): every
# serial line answers a ping (doorbell SGIs reach cores 123..255 through the
# high redistributor window), IMSU swap and broadcast reach all 254 NCs, and
# 64 MiB cross the inter-unit lines.
. "$(dirname "$0")/../lib.sh"
board_ready fw_smp256_ping fw_smp256_imsu fw_smp256_stress || exit 0
board_selftest fw_smp256 --ncs 254 --quiet ping imsu stress
