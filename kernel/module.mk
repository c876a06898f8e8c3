# kernel/: the cooperative kernel every unit computer runs.
FW_SRCS += kernel/cpu.c kernel/spinlock.c kernel/task.c kernel/ktime.c \
	kernel/irq.c kernel/kmem.c kernel/klog.c kernel/fault.c \
	kernel/ringbuf.c kernel/fdt.c

# Host unit tests of the hardware-free pieces.
HOST_TESTS += test_ringbuf test_fdt
test_ringbuf_SRCS := tests/host/test_ringbuf.c kernel/ringbuf.c
test_ringbuf_ARITH := double
test_fdt_SRCS := tests/host/test_fdt.c kernel/fdt.c
test_fdt_ARITH := double

# Idle boots do the same work every time: no core waits by looping.
BOARD_TESTS += tests/board/firmware/idle_insns.sh
