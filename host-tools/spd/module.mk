# host-tools/spd/: links1-spd, the Standard Procedural Databases (Haines 1987),
# written as the SPD's own programs write them (NFF) and made into scenes
# by the NFF reader (host-tools/scene/nff_read.c).
SPD_GEN_SRCS := host-tools/spd/spd_out.c host-tools/spd/spd_dbs.c host-tools/spd/spd_teapot.c
HOST_TOOLS += links1-spd
links1-spd_SRCS = host-tools/spd/spd_main.c $(SPD_GEN_SRCS) $(SCENE_TEXT_SRCS) \
	$(filter-out $(SCENE_TEXT_SRCS),$(HT_OPTS_CLI_SRCS) $(HT_OPTS_ARGS_SRCS))
links1-spd_ARITH := double
links1-spd_LIBS = $(SCENE_TEXT_LIBS)

# The NFF reader (entities, errors, hostile files) and the generators
# against the SPD's own output (tests/spd/official/).
test_nff_SRCS = tests/host/test_nff.c $(SPD_GEN_SRCS) $(SCENE_TEXT_SRCS)
test_nff_ARITH := double
test_nff_LIBS = $(SCENE_TEXT_LIBS)
