# drivers/an521/: an an521 board's devices: the NVIC, timer 0 and SysTick,
# the CMSDK UART of the host link, the board's number and the shared file's
# header, the NC boards' relay of host-link messages; no display.
FW_ARITH_FREE_SRCS_an521 += drivers/an521/an521_board.c drivers/an521/nvic.c drivers/an521/timer.c \
	drivers/an521/uart_cmsdk.c drivers/an521/relay.c drivers/an521/fm_view_none.c
