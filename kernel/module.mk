# kernel/: the cooperative kernel every unit computer runs.
FW_ARITH_FREE_SRCS += kernel/cpu.c kernel/spinlock.c kernel/task.c kernel/ktime.c \
	kernel/irq.c kernel/kmem.c kernel/klog.c kernel/fault.c \
	kernel/ringbuf.c kernel/fdt.c kernel/mem.c

# Host unit tests of the hardware-free pieces.
test_ringbuf_SRCS := tests/host/test_ringbuf.c kernel/ringbuf.c
test_ringbuf_ARITH := double
test_fdt_SRCS := tests/host/test_fdt.c kernel/fdt.c
test_fdt_ARITH := double
