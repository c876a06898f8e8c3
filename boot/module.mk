# boot/: reset entry, exception vectors, MMU table, first C code.
FW_SRCS += boot/start.S boot/vectors.S boot/mmu_table.c boot/boot.c
