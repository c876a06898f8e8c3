# host-tools/: the programs that run on the host (docs/layers.md).  Each
# room has its own module.mk listing its sources as HT_<ROOM>_SRCS; the
# programs are put together in host-tools/cli/module.mk.  Rooms use `=` for
# each other's lists: this file is read before theirs.
#
#   cli/       the commands: links1's subcommands, render-clip-stats
#   opts/      option helpers: getopt_long tables, numbers, sizes, own path
#   launcher/  the board launcher: QEMU started and stopped, named boards'
#              state, the board options, the noisy relay
#   link/      the link session: frames, go-back-N, bulk transfers
#   gigs/      the GIGS render session: scene up, frames, pixels down
#   selftest/  links1 selftest's checks
#   insn/      instruction counting: the QEMU plugin and its report
#   trace/     frame traces and their replay on equal-speed unit computers
#   scene/     the scene language, its compiler and bounding hierarchy
#   model/     model files read through libassimp in a child process
#   image/     PNG/PPM reading and writing, image comparison
#   ref/       the host reference renderer and --arith auto
#   scripts/   install-deps.sh, make run's and make gdb's scripts

# Every program that talks to a board links these.
BOARD_LAUNCHER_SRCS = $(HT_LAUNCHER_SRCS) $(HT_LINK_SRCS) $(HT_OPTS_CLI_SRCS)
# Programs that read text scenes link these (and SCENE_TEXT_LIBS); the
# `model` statement's libassimp is opened only when a model is read
# (host-tools/model/assimp_lib.h), not linked.
SCENE_TEXT_SRCS = $(HT_SCENE_SRCS) $(HT_MODEL_SRCS) $(HT_IMAGE_IO_SRCS) $(HT_OPTS_ARGS_SRCS)
SCENE_TEXT_LIBS := -lpng
