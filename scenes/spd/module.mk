# scenes/spd/: links1-spd, the Standard Procedural Databases (Haines 1987)
# as text scenes.
HOST_TOOLS += links1-spd
links1-spd_SRCS := scenes/spd/spd_main.c scenes/spd/spd_out.c scenes/spd/spd_dbs.c \
	scenes/spd/spd_teapot.c host-tools/scene/scene_math.c
links1-spd_ARITH := double
links1-spd_LIBS := -lm
