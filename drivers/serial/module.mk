# drivers/serial/: host-link transmit (over the machine's UART, uart.h) and
# the inter-unit lines.
FW_ARITH_FREE_SRCS += drivers/serial/uart.c drivers/serial/hostlink_tx.c \
	drivers/serial/line.c drivers/serial/linemsg.c

test_linemsg_SRCS := tests/host/test_linemsg.c drivers/serial/linemsg.c
test_linemsg_ARITH := double
