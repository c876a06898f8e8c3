# host-tools/selftest/: the checks of `links1 selftest` on a running board.
HT_SELFTEST_SRCS := host-tools/selftest/selftest_checks.c host-tools/selftest/selftest_idle.c \
	host-tools/selftest/selftest_link.c
ARITH_FREE_SRCS += $(HT_SELFTEST_SRCS)
