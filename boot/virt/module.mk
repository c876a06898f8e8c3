# boot/virt/: the virt board's reset entry, exception vectors, MMU table
# and first C code (PSCI starts the other cores).
FW_ARITH_FREE_SRCS_virt += boot/virt/start.S boot/virt/vectors.S boot/virt/mmu_table.c boot/virt/boot.c boot/virt/memory.c
