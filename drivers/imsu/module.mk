# drivers/imsu/: the intercomputer memory swapping unit.
FW_SRCS += drivers/imsu/imsu.c
