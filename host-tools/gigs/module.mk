# host-tools/gigs/: the GIGS render session: the scene up, a frame's
# commands and progress, its pixels down; the planned failures' encoding.
HT_GIGS_SRCS := host-tools/gigs/render_session.c host-tools/gigs/render_faults.c
ARITH_FREE_SRCS += $(HT_GIGS_SRCS)
