# host-tools/scene/: the text scene format, its compiler, the host reference
# renderer and the POV-Ray exporter.
#
# The loader of the compiled form is shared code (the board's DM runs it).
SHARED_SRCS += render/scene_load.c

# Models made elsewhere into scene records (`links1 import`, `model`).
SCENE_MODEL_SRCS := host-tools/scene/model_assimp.c host-tools/scene/model_child.c \
	host-tools/scene/model_wire.c host-tools/scene/scene_import.c \
	host-tools/scene/scene_import_view.c host-tools/scene/scene_map_image.c \
	host-tools/scene/scene_write.c host-tools/scene/scene_parse_model.c

# The text form: tokenizer, parser, transforms, compiler, image files.
SCENE_TEXT_SRCS := host-tools/scene/scene_lex.c host-tools/scene/scene_parse.c \
	host-tools/scene/scene_parse_looks.c host-tools/scene/scene_parse_objects.c \
	host-tools/scene/scene_math.c host-tools/scene/scene_compile.c host-tools/scene/scene_bvh.c \
	host-tools/scene/scene_board.c \
	host-tools/scene/image_io.c host-tools/scene/cli_args.c host-tools/scene/scene_file.c \
	host-tools/scene/nff_read.c \
	$(SCENE_MODEL_SRCS)
# All but the board conversion (scene_board.c) know no num_t: one host build
# serves every arithmetic (Makefile: ARITH_FREE_SRCS).
ARITH_FREE_SRCS += $(filter-out host-tools/scene/scene_board.c,$(SCENE_TEXT_SRCS))
# Programs that read text scenes link these: the `model` statement reads
# model files through libassimp (model_assimp.c, the only file that knows it).
SCENE_TEXT_LIBS := -lpng -lassimp

# Sources of the scene subcommands of `links1` (compile, ref, export-pov,
# compare); the links1 tool adds them to its own sources and SCENE_CMD_LIBS
# to its libraries.
SCENE_CMD_SRCS := host-tools/scene/scene_cmds.c host-tools/scene/scene_pov.c \
	host-tools/scene/arith_auto.c \
	host-tools/scene/image_compare.c host-tools/scene/import_cmd.c $(SCENE_TEXT_SRCS)
SCENE_CMD_LIBS := $(SCENE_TEXT_LIBS)

# The host reference renderer, one executable per arithmetic of the shared
# renderer; `links1 ref --arith A` runs the one asked for.
SCENE_REF_SRCS := host-tools/scene/ref_main.c host-tools/cli_opt.c $(SCENE_TEXT_SRCS)
HOST_TOOLS += links1-ref-double links1-ref-float links1-ref-fixed
links1-ref-double_SRCS := $(SCENE_REF_SRCS)
links1-ref-double_ARITH := double
links1-ref-double_LIBS := $(SCENE_TEXT_LIBS)
links1-ref-float_SRCS := $(SCENE_REF_SRCS)
links1-ref-float_ARITH := float
links1-ref-float_LIBS := $(SCENE_TEXT_LIBS)
links1-ref-fixed_SRCS := $(SCENE_REF_SRCS)
links1-ref-fixed_ARITH := fixed
links1-ref-fixed_LIBS := $(SCENE_TEXT_LIBS)
# The same renderer in other fixed formats (links1-ref-fixedN: Q(31-N).N),
# candidates of `links1 ref --arith auto` (arith_auto.c finds them next to
# links1; the board's firmware stays Q12.19, fixed/num.h's default).
REF_FIXED_BITS := 14 16 18
HOST_EXTRA_ARITHS += $(addprefix fixed,$(REF_FIXED_BITS))
$(foreach f,$(REF_FIXED_BITS),$(eval ARITH_DEF_fixed$(f) := -DLINKS1_NUM_FIXED -DNUM_FRAC_BITS=$(f)))
$(foreach f,$(REF_FIXED_BITS),$(eval HOST_TOOLS += links1-ref-fixed$(f)))
$(foreach f,$(REF_FIXED_BITS),$(eval links1-ref-fixed$(f)_SRCS = $$(SCENE_REF_SRCS)))
$(foreach f,$(REF_FIXED_BITS),$(eval links1-ref-fixed$(f)_ARITH := fixed$(f)))
$(foreach f,$(REF_FIXED_BITS),$(eval links1-ref-fixed$(f)_LIBS = $$(SCENE_TEXT_LIBS)))

# Host tests of the format, the parser and the loader (ASan + UBSan).
HOST_TESTS += test_scene_load test_scene_parse
test_scene_load_SRCS := tests/host/test_scene_load.c $(SCENE_TEXT_SRCS)
test_scene_load_ARITH := double
test_scene_load_LIBS := $(SCENE_TEXT_LIBS)
test_scene_parse_SRCS := tests/host/test_scene_parse.c $(SCENE_TEXT_SRCS)
test_scene_parse_ARITH := double
test_scene_parse_LIBS := $(SCENE_TEXT_LIBS)

# How ref and render both read a scene file (scene_file.c).
HOST_TESTS += test_scene_file
test_scene_file_SRCS := tests/host/test_scene_file.c $(SCENE_TEXT_SRCS)
test_scene_file_ARITH := double
test_scene_file_LIBS := $(SCENE_TEXT_LIBS)

# The scene subcommands are part of the links1 tool (host-tools/module.mk).
links1_SRCS += $(SCENE_CMD_SRCS)
links1_LIBS += $(SCENE_CMD_LIBS)

# Image tests: POV-Ray agreement and arithmetic accuracy.
BOARD_TESTS += tests/images/scenes.sh tests/images/pov.sh tests/images/accuracy.sh tests/images/adaptive.sh \
	tests/images/import.sh tests/board/render_import.sh

HOST_TESTS += test_scene_image
test_scene_image_SRCS := tests/host/test_scene_image.c host-tools/scene/image_io.c \
	host-tools/scene/image_compare.c host-tools/cli_opt.c
test_scene_image_ARITH := double
test_scene_image_LIBS := -lpng -lm

# The loader once more in the other two arithmetics it runs in on the board.
HOST_TESTS += test_scene_load_float test_scene_load_fixed
test_scene_load_float_SRCS := $(test_scene_load_SRCS)
test_scene_load_float_ARITH := float
test_scene_load_float_LIBS := $(SCENE_TEXT_LIBS)
test_scene_load_fixed_SRCS := $(test_scene_load_SRCS)
test_scene_load_fixed_ARITH := fixed
test_scene_load_fixed_LIBS := $(SCENE_TEXT_LIBS)

# Models made elsewhere: each format, the material mapping, bad models,
# the model statement (tests/models/).
HOST_TESTS += test_scene_import
test_scene_import_SRCS := tests/host/test_scene_import.c $(SCENE_TEXT_SRCS)
test_scene_import_ARITH := double
test_scene_import_LIBS := $(SCENE_TEXT_LIBS)

# The automatic hierarchy: tree invariants and the same image on and off,
# in each arithmetic of the shared renderer.
HOST_TESTS += test_auto_hierarchy_double test_auto_hierarchy_float test_auto_hierarchy_fixed
$(foreach a,double float fixed,$(eval test_auto_hierarchy_$(a)_SRCS = tests/host/test_auto_hierarchy.c $$(SCENE_TEXT_SRCS)))
$(foreach a,double float fixed,$(eval test_auto_hierarchy_$(a)_ARITH := $(a)))
$(foreach a,double float fixed,$(eval test_auto_hierarchy_$(a)_LIBS = $$(SCENE_TEXT_LIBS)))

# Smooth triangles (`model { smooth on }`), each arithmetic.
HOST_TESTS += test_smooth_double test_smooth_float test_smooth_fixed
$(foreach a,double float fixed,$(eval test_smooth_$(a)_SRCS = tests/host/test_smooth.c $$(SCENE_TEXT_SRCS)))
$(foreach a,double float fixed,$(eval test_smooth_$(a)_ARITH := $(a)))
$(foreach a,double float fixed,$(eval test_smooth_$(a)_LIBS = $$(SCENE_TEXT_LIBS)))

# The model library in a child process: the same models as in this
# process, the wire form cut and damaged, children that crash, abort, exit
# badly, hang, send too much or send a malformed model, and libassimp's own
# crashes (tests/fuzz/assimp-crashes/).
HOST_TESTS += test_model_child
test_model_child_SRCS := tests/host/test_model_child.c $(SCENE_TEXT_SRCS)
test_model_child_ARITH := double
test_model_child_LIBS := $(SCENE_TEXT_LIBS)
