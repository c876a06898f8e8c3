# tests/fuzz/: libFuzzer harnesses (clang -fsanitize=fuzzer,address,undefined),
# one small C file each, and their seed corpora in tests/fuzz/corpus/NAME/.
# For each NAME in FUZZERS: NAME_SRCS (its own sources; the shared code is
# added), NAME_ARITH (the arithmetic of the shared code), NAME_LIBS.
#   make fuzz                 each harness FUZZ_SECONDS (default 600) in turn
#   tests/fuzz/smoke.sh       a short fixed run of each (part of make test)

# The compiled-form loader and the DM's build of a frame from it, in the
# board's main arithmetic.
FUZZERS += fuzz_scene_load
fuzz_scene_load_SRCS = tests/fuzz/fuzz_scene_load.c
fuzz_scene_load_ARITH := float

# The text scene format: tokenizer, parser, compiler, then the loader.
FUZZERS += fuzz_scene_text
fuzz_scene_text_SRCS = tests/fuzz/fuzz_scene_text.c $(SCENE_TEXT_SRCS)
fuzz_scene_text_ARITH := double
fuzz_scene_text_LIBS = $(SCENE_TEXT_LIBS)

# The host-link frame decoder (both sides), the host's frame handling and
# the payload getters.
FUZZERS += fuzz_hostlink
fuzz_hostlink_SRCS = tests/fuzz/fuzz_hostlink.c $(BOARD_LAUNCHER_SRCS)
fuzz_hostlink_ARITH := double

# Image files read as colour and bump maps, then traced.
FUZZERS += fuzz_image_map
fuzz_image_map_SRCS = tests/fuzz/fuzz_image_map.c $(SCENE_TEXT_SRCS)
fuzz_image_map_ARITH := float
fuzz_image_map_LIBS = $(SCENE_TEXT_LIBS)

# Writes fuzz_hostlink's seed frames (with the one encoder).
BOARD_PROGS += seed_frames
seed_frames_SRCS := tests/fuzz/seed_frames.c
seed_frames_ARITH := double

# Model files through libassimp from memory, then the project's importer,
# the text writer and parser, the compiler, the loader and a few pixels.
FUZZERS += fuzz_import
fuzz_import_SRCS = tests/fuzz/fuzz_import.c $(SCENE_TEXT_SRCS)
fuzz_import_ARITH := float
fuzz_import_LIBS = $(SCENE_TEXT_LIBS)
# about 70 inputs a second (the library, then a whole compile and trace):
# and its mutations soon reach one of libassimp's own crashes (where depends
# on every line of the project's code: after 1,190 inputs from seed 1 one
# day, within 1,000 the next), so its smoke run replays the seed corpus and
# the regression inputs only (-runs=0); the 10-minute run mutates, in fork
# mode past libassimp's crashes (see docs/results/fuzzing-and-hostile.md)
fuzz_import_SMOKE_RUNS := 0
# libassimp 5.2 itself aborts or loops on some inputs (tests/fuzz/assimp-crashes/):
# the long run goes on past them in fork mode, keeping each input
fuzz_import_RUN_FLAGS := -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1
