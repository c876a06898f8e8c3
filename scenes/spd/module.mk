# scenes/spd/: links1-spd, the Standard Procedural Databases (Haines 1987),
# written as the SPD's own programs write them (NFF) and made into scenes
# by the NFF reader (host-tools/scene/nff_read.c).
SPD_GEN_SRCS := scenes/spd/spd_out.c scenes/spd/spd_dbs.c scenes/spd/spd_teapot.c
HOST_TOOLS += links1-spd
links1-spd_SRCS = scenes/spd/spd_main.c $(SPD_GEN_SRCS) $(SCENE_TEXT_SRCS) \
	host-tools/opts/out_file.c host-tools/opts/exit_clean.c
links1-spd_ARITH := double
links1-spd_LIBS = $(SCENE_TEXT_LIBS)

# The NFF reader (entities, errors, hostile files) and the generators
# against the SPD's own output (tests/spd/official/).
HOST_TESTS += test_nff
test_nff_SRCS = tests/host/test_nff.c $(SPD_GEN_SRCS) $(SCENE_TEXT_SRCS)
test_nff_ARITH := double
test_nff_LIBS = $(SCENE_TEXT_LIBS)
BOARD_TESTS += tests/images/spd_official.sh
