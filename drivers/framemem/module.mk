# drivers/framemem/: the data collector (DC) FIFO and the frame memory (FM);
# its live view is the machine's (fm_view.h).
FW_ARITH_FREE_SRCS += drivers/framemem/fm.c drivers/framemem/dc_ring.c drivers/framemem/dc.c \
	drivers/framemem/dc_selftest.c drivers/framemem/dc_selftest_pattern.c
