# drivers/framemem/: the data collector (DC) FIFO, the frame memory (FM)
# and its live view through fw_cfg + ramfb.
FW_SRCS += drivers/framemem/fm.c drivers/framemem/dc_ring.c drivers/framemem/dc.c \
	drivers/framemem/fwcfg_format.c drivers/framemem/fwcfg.c drivers/framemem/ramfb.c \
	drivers/framemem/dc_selftest.c drivers/framemem/dc_selftest_pattern.c
