# roles/: the programs of the unit computers (DM, RC, NC).
FW_SRCS += roles/unit.c roles/dm.c roles/rc.c roles/nc.c roles/selftest.c
