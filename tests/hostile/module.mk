# tests/hostile/: hostile scenes, each class refused with an error naming
# the problem: on the host (test_hostile) and on the board, which then
# renders the next scene (tests/board/render/render_hostile.sh, with the files
# make_hostile writes).
HOSTILE_SRCS := tests/hostile/hostile.c
ARITH_FREE_SRCS += $(HOSTILE_SRCS)

test_hostile_SRCS = tests/hostile/test_hostile.c $(HOSTILE_SRCS) $(SCENE_TEXT_SRCS)
test_hostile_ARITH := float
test_hostile_LIBS = $(SCENE_TEXT_LIBS)

BOARD_PROGS += make_hostile
make_hostile_SRCS = tests/hostile/make_hostile.c $(HOSTILE_SRCS) $(SCENE_TEXT_SRCS)
make_hostile_ARITH := double
make_hostile_LIBS = $(SCENE_TEXT_LIBS)

