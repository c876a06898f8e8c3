# host-tools/launcher/: the board launcher: QEMU started, watched and
# stopped; named boards' state; the board options; the noisy relay.
HT_LAUNCHER_SRCS := host-tools/launcher/qemu.c host-tools/launcher/board_opts.c host-tools/launcher/board_named.c \
	host-tools/launcher/board_state.c \
	host-tools/launcher/link_noise.c host-tools/launcher/link_relay.c
ARITH_FREE_SRCS += $(HT_LAUNCHER_SRCS)

# The go-back-N pieces of proto/link_arq.h, --link-noise's damage and relay.
test_link_arq_SRCS := tests/host/test_link_arq.c host-tools/launcher/link_noise.c \
	host-tools/launcher/link_relay.c
test_link_arq_ARITH := double

# Named boards' state against hostile state (a fake QEMU: this same program).
test_board_named_SRCS = tests/host/test_board_named.c $(BOARD_LAUNCHER_SRCS)
test_board_named_ARITH := double
