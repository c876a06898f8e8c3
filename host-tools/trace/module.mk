# host-tools/trace/: frame traces (links1 render --trace), decoded from the
# counting plugin's marks, and their replay on equal-speed unit computers.
HT_TRACE_SRCS := host-tools/trace/trace_file.c host-tools/trace/trace_scale.c \
	host-tools/trace/trace_decode.c host-tools/trace/replay.c host-tools/trace/replay_timeline.c
ARITH_FREE_SRCS += $(HT_TRACE_SRCS)

# Frame traces and their replay on equal-speed units.
test_trace_SRCS := tests/host/test_trace.c host-tools/trace/trace_file.c \
	host-tools/trace/trace_scale.c host-tools/trace/replay.c host-tools/trace/replay_timeline.c \
	host-tools/opts/tmp_dir.c host-tools/opts/exit_clean.c
test_trace_ARITH := double
