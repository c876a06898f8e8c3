# host-tools/link/: the link session with a board: frames decoded and
# queued, go-back-N, the windowed and the shared-memory bulk transfers.
HT_LINK_SRCS := host-tools/link/board.c host-tools/link/board_frames.c host-tools/link/board_text.c \
	host-tools/link/link_transfer.c host-tools/link/link_shared.c
ARITH_FREE_SRCS += $(HT_LINK_SRCS)

# Host unit tests of the link framing, the message encodings, the session.
test_hostlink_SRCS := tests/host/test_hostlink.c
test_hostlink_ARITH := double
test_hostlink_msgs_SRCS = tests/host/test_hostlink_msgs.c $(BOARD_LAUNCHER_SRCS)
test_hostlink_msgs_ARITH := double
test_hostlink_transfer_SRCS = tests/host/test_hostlink_transfer.c $(BOARD_LAUNCHER_SRCS)
test_hostlink_transfer_ARITH := double
test_hostlink_transfer_LIBS := -lpthread
# The host side of the shared-memory path against a fake board and RAM.
test_link_shared_SRCS = tests/host/test_link_shared.c $(BOARD_LAUNCHER_SRCS)
test_link_shared_ARITH := double
test_hostlink_session_SRCS = tests/host/test_hostlink_session.c $(BOARD_LAUNCHER_SRCS)
test_hostlink_session_ARITH := double
