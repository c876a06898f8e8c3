# host-tools/launcher/: the board launcher: QEMU started, watched and
# stopped; named boards' state; the board options; the noisy relay.
HT_LAUNCHER_SRCS := host-tools/launcher/qemu.c host-tools/launcher/board_opts.c host-tools/launcher/board_named.c \
	host-tools/launcher/board_state.c \
	host-tools/launcher/link_noise.c host-tools/launcher/link_relay.c
ARITH_FREE_SRCS += $(HT_LAUNCHER_SRCS)

# The go-back-N pieces of proto/link_arq.h, --link-noise's damage and relay.
HOST_TESTS += test_link_arq
test_link_arq_SRCS := tests/host/test_link_arq.c host-tools/launcher/link_noise.c \
	host-tools/launcher/link_relay.c
test_link_arq_ARITH := double

# Named boards' state against hostile state (a fake QEMU: this same program).
HOST_TESTS += test_board_named
test_board_named_SRCS = tests/host/test_board_named.c $(BOARD_LAUNCHER_SRCS)
test_board_named_ARITH := double
# What only the user may reach on a real board: the gdb stub's unix socket,
# a board dying in `render --board`, render's output files.
BOARD_TESTS += tests/board/boards/board_owner.sh
# A reused pid of another user's is a board gone (as root, with a second
# account); paths with commas doubled in QEMU's options, on a board and
# against a fake QEMU with bad sizes, --ram and -o refused before one starts.
BOARD_TESTS += tests/board/boards/other_user_boards.sh tests/board/boards/comma_paths.sh \
	tests/board/boards/refused_early.sh
