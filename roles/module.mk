# roles/: the programs of the unit computers (DM, RC, NC).
FW_SRCS += roles/unit.c roles/dm.c roles/dm_checks.c roles/dm_transfer.c roles/dm_bulk.c roles/rc.c roles/nc.c roles/selftest.c \
	roles/dm_render.c roles/rc_render.c roles/rc_nc.c roles/nc_render.c

# tests/board/firmware/fw_board.sh's checks (damaged frames, bad commands,
# injected faults), a program built into build/tests/.
BOARD_PROGS += fw_board_check
fw_board_check_SRCS = tests/board/firmware/fw_board_check.c $(BOARD_LAUNCHER_SRCS)
fw_board_check_ARITH := double
