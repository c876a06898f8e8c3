# boot/an521/: an an521 board's vector table, reset, fault entries, task
# switch and first C code (the board joins the others through the shared
# file; core 0 lets core 1 go).
FW_ARITH_FREE_SRCS_an521 += boot/an521/start.S boot/an521/boot.c
