# host-tools/gigs/: the GIGS render session: the scene up, a frame's
# commands and progress, its pixels down; the planned failures' encoding.
HT_GIGS_SRCS := host-tools/gigs/render_session.c host-tools/gigs/render_faults.c
ARITH_FREE_SRCS += $(HT_GIGS_SRCS)

# A board that sends what it should not (on a socketpair): its text printed
# escaped, a serial frame pull bounded by the frame, no SIGPIPE.
test_board_hostile_SRCS = tests/host/test_board_hostile.c $(HT_GIGS_SRCS) $(BOARD_LAUNCHER_SRCS) \
	$(HT_IMAGE_IO_SRCS)
test_board_hostile_ARITH := double
test_board_hostile_LIBS := -lpng -lm
