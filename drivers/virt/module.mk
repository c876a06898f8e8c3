# drivers/virt/: the virt board's devices: the GICv3 (interrupts and the
# doorbells between cores), the generic timer, the PL011 UART of the host
# link, and the frame memory's live view through fw_cfg + ramfb.
FW_ARITH_FREE_SRCS_virt += drivers/virt/gic.c drivers/virt/virt_cpu.c drivers/virt/timer_generic.c \
	drivers/virt/uart_pl011.c drivers/virt/fwcfg_format.c drivers/virt/fwcfg.c \
	drivers/virt/ramfb.c drivers/virt/relay_none.c
