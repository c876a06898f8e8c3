#!/usr/bin/env bash
# The soft-float and fixed-point firmware builds (no VFP instruction in
# them) boot and move data like the float build: status, ping, IMSU and a
# 64 MiB line stress on a 3-core board (DM, RC, one NC).
. "$(dirname "$0")/../lib.sh"
for v in soft fixed; do
    if [ ! -r "$FW_DIR/links1-$v.elf" ]; then
        echo "FAIL fw_$v: firmware $FW_DIR/links1-$v.elf is not built (run make)"
        continue
    fi
    board_ready "fw_${v}_status" || continue
    board_selftest "fw_$v" --ncs 1 --arith "$v" status ping imsu stress
done
