# host-tools/cli/: the commands.  `links1` and its subcommands (boot,
# selftest, render, farm, board, replay, semihost, compile, ref, import,
# export-pov, compare), and render-clip-stats; each command reads its
# options and calls the rooms that do the work.
HOST_TOOLS += links1
links1_SRCS = host-tools/cli/links1.c host-tools/cli/cmd_boot.c host-tools/cli/cmd_board.c \
	host-tools/cli/cmd_selftest.c host-tools/cli/cmd_semihost.c host-tools/cli/cmd_render.c \
	host-tools/cli/cmd_replay.c host-tools/cli/scene_cmds.c host-tools/cli/cmd_import.c \
	host-tools/cli/cmd_compare.c host-tools/cli/cmd_farm.c host-tools/cli/farm_slurm.c \
	$(BOARD_LAUNCHER_SRCS) $(HT_GIGS_SRCS) $(HT_SELFTEST_SRCS) $(HT_INSN_SRCS) \
	$(HT_TRACE_SRCS) $(HT_REF_AUTO_SRCS) $(HT_IMAGE_COMPARE_SRCS) $(HT_SCENE_POV_SRCS) \
	$(HT_IMAGE_FILM_SRCS) $(SCENE_TEXT_SRCS)
links1_ARITH := double
links1_LIBS = $(SCENE_TEXT_LIBS)

# Work counted per speed-up (Table 2 of the paper): build/render-clip-stats.
HOST_TOOLS += render-clip-stats
render-clip-stats_SRCS = host-tools/cli/clip_stats_main.c $(HT_OPTS_CLI_SRCS) $(SCENE_TEXT_SRCS)
render-clip-stats_ARITH := float
render-clip-stats_LIBS = $(SCENE_TEXT_LIBS)

# Benchmarks of a board's boot, its channels and the host link.
BENCHES += tests/bench/bench_boot.sh tests/bench/bench_channels.sh tests/bench/bench_link.sh
