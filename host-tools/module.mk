# host-tools/: the links1 host tool, the instruction-counting QEMU plugin,
# `make run`'s script.  (host-tools/scene/ adds its own sources.)
HOST_TOOLS += links1
# The launcher: every program that starts a board links these.
BOARD_LAUNCHER_SRCS := host-tools/board.c host-tools/board_frames.c \
	host-tools/board_opts.c host-tools/cli_opt.c host-tools/board_named.c \
	host-tools/link_noise.c host-tools/link_relay.c
# These host-side sources know no num_t (Makefile: ARITH_FREE_SRCS).
ARITH_FREE_SRCS += $(BOARD_LAUNCHER_SRCS) host-tools/render_faults.c host-tools/link_transfer.c \
	host-tools/link_shared.c host-tools/link_arq_sim.c host-tools/trace_file.c host-tools/trace_scale.c \
	host-tools/replay.c
links1_SRCS := host-tools/links1.c $(BOARD_LAUNCHER_SRCS) \
	host-tools/cmd_boot.c host-tools/cmd_selftest.c host-tools/selftest_checks.c \
	host-tools/selftest_link.c host-tools/link_transfer.c host-tools/link_shared.c host-tools/insn_report.c \
	host-tools/cmd_semihost.c host-tools/selftest_idle.c
links1_SRCS += host-tools/cmd_render.c host-tools/render_session.c host-tools/cmd_board.c \
	host-tools/render_faults.c host-tools/trace_file.c host-tools/trace_scale.c host-tools/trace_decode.c host-tools/replay.c \
	host-tools/cmd_replay.c
links1_ARITH := double

# The TCG plugin is loaded into QEMU: a plain shared object, no sanitizers.
INSN_PLUGIN := $(B)/insn-count.so
$(INSN_PLUGIN): host-tools/insn_count_plugin.c
	$(call say,HOSTSO,$@)
	$(Q)mkdir -p $(@D)
	$(Q)$(HOST_CC) $(HOST_CFLAGS) -fPIC -shared -fvisibility=hidden $< -o $@
-include $(INSN_PLUGIN:.so=.d)
host-tools: $(INSN_PLUGIN)

# Host unit tests of the link framing and message encodings.
HOST_TESTS += test_hostlink
test_hostlink_SRCS := tests/host/test_hostlink.c
test_hostlink_ARITH := double
HOST_TESTS += test_hostlink_msgs
test_hostlink_msgs_SRCS := tests/host/test_hostlink_msgs.c $(BOARD_LAUNCHER_SRCS)
test_hostlink_msgs_ARITH := double
HOST_TESTS += test_hostlink_transfer
test_hostlink_transfer_SRCS := tests/host/test_hostlink_transfer.c $(BOARD_LAUNCHER_SRCS) \
	host-tools/link_transfer.c
test_hostlink_transfer_ARITH := double
test_hostlink_transfer_LIBS := -lpthread
# The host side of the shared-memory path against a fake board and RAM.
HOST_TESTS += test_link_shared
test_link_shared_SRCS := tests/host/test_link_shared.c $(BOARD_LAUNCHER_SRCS) \
	host-tools/link_shared.c
test_link_shared_ARITH := double
# The argument reader of every command and the board options.
HOST_TESTS += test_cli_opt
test_cli_opt_SRCS := tests/host/test_cli_opt.c host-tools/board_opts.c host-tools/cli_opt.c \
	host-tools/link_noise.c
test_cli_opt_ARITH := double
HOST_TESTS += test_hostlink_session
test_hostlink_session_SRCS := tests/host/test_hostlink_session.c $(BOARD_LAUNCHER_SRCS)
test_hostlink_session_ARITH := double

# Work counted per speed-up (Table 2 of the paper): build/render-clip-stats.
HOST_TOOLS += render-clip-stats
render-clip-stats_SRCS = host-tools/clip_stats_main.c host-tools/cli_opt.c $(SCENE_TEXT_SRCS)
render-clip-stats_ARITH := float
render-clip-stats_LIBS = $(SCENE_TEXT_LIBS)

# Board tests (tests/board/lib.sh is their shared helper, not a test).
BOARD_TESTS += tests/board/boot_smp.sh tests/board/channels.sh tests/board/idle66.sh \
	tests/board/fault.sh

BENCHES += tests/bench/bench_boot.sh tests/bench/bench_channels.sh tests/bench/bench_link.sh

# Stop-and-wait retransmission of the host link through --link-noise's damage.
HOST_TESTS += test_link_arq
test_link_arq_SRCS := tests/host/test_link_arq.c host-tools/link_noise.c host-tools/link_relay.c \
	host-tools/link_arq_sim.c
test_link_arq_ARITH := double
# The retransmission's goodput through simulated noise (make bench).
HOST_TOOLS += bench-link-arq
bench-link-arq_SRCS := host-tools/arq_bench_main.c host-tools/link_arq_sim.c \
	host-tools/link_noise.c
bench-link-arq_ARITH := double
