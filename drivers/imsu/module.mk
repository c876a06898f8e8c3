# drivers/imsu/: the intercomputer memory swapping unit.
FW_ARITH_FREE_SRCS += drivers/imsu/imsu.c drivers/imsu/imsu_board.c

test_imsu_SRCS := tests/host/test_imsu.c drivers/imsu/imsu.c
test_imsu_ARITH := double
