# host-tools/scene/: the scene language (tokenizer, parser, transforms), its
# compiler to the board's form with the bounding hierarchy, models turned
# into scene records, the text writer and the POV-Ray exporter.
#
# The loader of the compiled form is shared code (the board's DM runs it).
SHARED_SRCS += render/scene_load.c

HT_SCENE_SRCS := host-tools/scene/scene_lex.c host-tools/scene/scene_parse.c \
	host-tools/scene/scene_parse_looks.c host-tools/scene/scene_parse_objects.c \
	host-tools/scene/scene_parse_model.c host-tools/scene/scene_parse_view.c \
	host-tools/scene/scene_math.c \
	host-tools/scene/scene_compile.c host-tools/scene/scene_bvh.c \
	host-tools/scene/scene_board.c host-tools/scene/scene_file.c host-tools/scene/scene_optdefs.c \
	host-tools/scene/scene_import.c host-tools/scene/scene_import_view.c \
	host-tools/scene/scene_map_image.c host-tools/scene/scene_texture.c \
	host-tools/scene/scene_write.c host-tools/scene/nff_read.c \
	host-tools/scene/scene_paper.c host-tools/scene/scene_mem.c
HT_SCENE_POV_SRCS := host-tools/scene/scene_pov.c
# All but the board conversion (scene_board.c) know no num_t: one host build
# serves every arithmetic (Makefile: ARITH_FREE_SRCS).
ARITH_FREE_SRCS += $(filter-out host-tools/scene/scene_board.c,$(HT_SCENE_SRCS)) $(HT_SCENE_POV_SRCS)

# Host tests of the format, the parser and the loader (ASan + UBSan).
test_scene_load_SRCS = tests/host/test_scene_load.c $(SCENE_TEXT_SRCS)
test_scene_load_ARITH := double
test_scene_load_LIBS = $(SCENE_TEXT_LIBS)
test_scene_parse_SRCS = tests/host/test_scene_parse.c $(SCENE_TEXT_SRCS)
test_scene_parse_ARITH := double
test_scene_parse_LIBS = $(SCENE_TEXT_LIBS)

# Paper mode: what it sets in the scene, the compiled bytes and the render
# arguments (scene_paper.c).
test_scene_paper_SRCS = tests/host/test_scene_paper.c $(SCENE_TEXT_SRCS)
test_scene_paper_ARITH := double
test_scene_paper_LIBS = $(SCENE_TEXT_LIBS)

# How ref and render both read a scene file (scene_file.c).
test_scene_file_SRCS = tests/host/test_scene_file.c $(SCENE_TEXT_SRCS)
test_scene_file_ARITH := double
test_scene_file_LIBS = $(SCENE_TEXT_LIBS)

# The loader once more in the other two arithmetics it runs in on the board.
test_scene_load_float_SRCS = $(test_scene_load_SRCS)
test_scene_load_float_ARITH := float
test_scene_load_float_LIBS = $(SCENE_TEXT_LIBS)
test_scene_load_fixed_SRCS = $(test_scene_load_SRCS)
test_scene_load_fixed_ARITH := fixed
test_scene_load_fixed_LIBS = $(SCENE_TEXT_LIBS)

# Models made elsewhere: each format, the material mapping, bad models,
# the model statement (tests/models/).
test_scene_import_SRCS = tests/host/test_scene_import.c $(SCENE_TEXT_SRCS)
test_scene_import_ARITH := double
test_scene_import_LIBS = $(SCENE_TEXT_LIBS)

# The automatic hierarchy: tree invariants and the same image on and off,
# in each arithmetic of the shared renderer.
$(foreach a,double float fixed,$(eval test_auto_hierarchy_$(a)_SRCS = tests/host/test_auto_hierarchy.c $$(SCENE_TEXT_SRCS)))
$(foreach a,double float fixed,$(eval test_auto_hierarchy_$(a)_ARITH := $(a)))
$(foreach a,double float fixed,$(eval test_auto_hierarchy_$(a)_LIBS = $$(SCENE_TEXT_LIBS)))

# Smooth triangles (`model { smooth on }`), each arithmetic.
$(foreach a,double float fixed,$(eval test_smooth_$(a)_SRCS = tests/host/test_smooth.c $$(SCENE_TEXT_SRCS)))
$(foreach a,double float fixed,$(eval test_smooth_$(a)_ARITH := $(a)))
$(foreach a,double float fixed,$(eval test_smooth_$(a)_LIBS = $$(SCENE_TEXT_LIBS)))

# The model library in a child process: the same models as in this
# process, the wire form cut and damaged, children that crash, abort, exit
# badly, hang, send too much or send a malformed model, and libassimp's own
# crashes (tests/fuzz/assimp-crashes/).
test_model_child_SRCS = tests/host/test_model_child.c $(SCENE_TEXT_SRCS)
test_model_child_ARITH := double
test_model_child_LIBS = $(SCENE_TEXT_LIBS)

# A model's texture paths: confined to its directory (or one the user
# allows), regular files only, never a blocking read.
test_textures_SRCS = tests/host/test_textures.c $(SCENE_TEXT_SRCS) host-tools/opts/tmp_dir.c \
	host-tools/opts/exit_clean.c
test_textures_ARITH := double
test_textures_LIBS = $(SCENE_TEXT_LIBS)
# Large arrays on transparent huge pages (scene_mem.c).
test_scene_mem_SRCS := tests/host/test_scene_mem.c host-tools/scene/scene_mem.c
test_scene_mem_ARITH := double
