# host-tools/opts/: option helpers every command shares.
HT_OPTS_CLI_SRCS := host-tools/opts/cli_opt.c host-tools/opts/self_path.c host-tools/opts/out_file.c \
	host-tools/opts/tmp_dir.c host-tools/opts/private_path.c \
	host-tools/opts/exit_clean.c
HT_OPTS_ARGS_SRCS := host-tools/opts/cli_args.c
ARITH_FREE_SRCS += $(HT_OPTS_CLI_SRCS) $(HT_OPTS_ARGS_SRCS)

# The argument reader of every command and the board options.
test_cli_opt_SRCS = tests/host/test_cli_opt.c $(BOARD_LAUNCHER_SRCS)
test_cli_opt_ARITH := double

# Output files written whole through mkstemp beside them (out_file.c).
test_out_file_SRCS := tests/host/test_out_file.c host-tools/opts/out_file.c host-tools/opts/tmp_dir.c host-tools/opts/private_path.c \
	host-tools/opts/exit_clean.c
test_out_file_ARITH := double
# A file or directory only you (or root) can change (private_path.c).
test_private_path_SRCS := tests/host/test_private_path.c host-tools/opts/private_path.c \
	host-tools/opts/tmp_dir.c host-tools/opts/exit_clean.c
test_private_path_ARITH := double
# What a signal leaves (exit_clean.c): nothing registered, the link inside
# not followed, the children ended, stale directories of a dead run swept.
test_exit_clean_SRCS := tests/host/test_exit_clean.c host-tools/opts/exit_clean.c \
	host-tools/opts/tmp_dir.c host-tools/opts/out_file.c
test_exit_clean_ARITH := double
