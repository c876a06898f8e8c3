# render/: the ray tracer, built for every arithmetic; it knows nothing of
# cores, drivers or messages.
SHARED_SRCS += render/arena.c render/xform.c render/prim.c render/prim_cone.c render/prepare.c \
	render/shade.c render/maps.c render/trace.c render/precision.c render/haze.c \
	render/lightbuf.c
# The arena and the word loops know no num_t: one host build for every
# arithmetic.
ARITH_FREE_SRCS += render/arena.c

# Renderer tests, once per arithmetic.
test_prim_double_SRCS := tests/host/test_prim.c
test_prim_double_ARITH := double
test_prim_float_SRCS := tests/host/test_prim.c
test_prim_float_ARITH := float
test_prim_fixed_SRCS := tests/host/test_prim.c
test_prim_fixed_ARITH := fixed
test_shade_double_SRCS := tests/host/test_shade.c
test_shade_double_ARITH := double
test_shade_float_SRCS := tests/host/test_shade.c
test_shade_float_ARITH := float
test_shade_fixed_SRCS := tests/host/test_shade.c
test_shade_fixed_ARITH := fixed
test_haze_double_SRCS := tests/host/test_haze.c
test_haze_double_ARITH := double
test_haze_float_SRCS := tests/host/test_haze.c
test_haze_float_ARITH := float
test_haze_fixed_SRCS := tests/host/test_haze.c
test_haze_fixed_ARITH := fixed
test_render_double_SRCS := tests/host/test_render.c
test_render_double_ARITH := double
test_render_float_SRCS := tests/host/test_render.c
test_render_float_ARITH := float
test_render_fixed_SRCS := tests/host/test_render.c
test_render_fixed_ARITH := fixed

# Blobs that travel through the IMSU (load + prepare into one block,
# relocation after a copy) and the NC's screen clipping.
SHARED_SRCS += render/relocate.c render/blob.c render/clip.c render/layout.c

# Blob relocation and screen clipping tests, once per arithmetic; they
# compile the scenes of scenes/ with the host scene compiler.
$(foreach a,double float fixed,$(eval test_blob_$(a)_SRCS = tests/host/test_blob.c $$(SCENE_TEXT_SRCS)))
$(foreach a,double float fixed,$(eval test_blob_$(a)_ARITH := $(a)))
$(foreach a,double float fixed,$(eval test_blob_$(a)_LIBS = $$(SCENE_TEXT_LIBS)))
$(foreach a,double float fixed,$(eval test_clip_$(a)_SRCS = tests/host/test_clip.c tests/host/render_fixture.c $$(SCENE_TEXT_SRCS)))
$(foreach a,double float fixed,$(eval test_clip_$(a)_ARITH := $(a)))
$(foreach a,double float fixed,$(eval test_clip_$(a)_LIBS = $$(SCENE_TEXT_LIBS)))
$(foreach a,double float fixed,$(eval test_lightbuf_$(a)_SRCS = tests/host/test_lightbuf.c $$(SCENE_TEXT_SRCS)))
$(foreach a,double float fixed,$(eval test_lightbuf_$(a)_ARITH := $(a)))
$(foreach a,double float fixed,$(eval test_lightbuf_$(a)_LIBS = $$(SCENE_TEXT_LIBS)))
# Anti-aliasing (render/trace.c): areas, corner means, cuts.
$(foreach a,double float fixed,$(eval test_aa_$(a)_SRCS = tests/host/test_aa.c tests/host/render_fixture.c $$(SCENE_TEXT_SRCS)))
$(foreach a,double float fixed,$(eval test_aa_$(a)_ARITH := $(a)))
$(foreach a,double float fixed,$(eval test_aa_$(a)_LIBS = $$(SCENE_TEXT_LIBS)))

# Escalation (render/wide.h): float and fixed with the wide copy linked in.
$(foreach a,float fixed,$(eval test_wide_$(a)_SRCS = tests/host/test_wide.c $$(SCENE_TEXT_SRCS)))
$(foreach a,float fixed,$(eval test_wide_$(a)_ARITH := $(a)))
$(foreach a,float fixed,$(eval test_wide_$(a)_LIBS = $$(SCENE_TEXT_LIBS)))
$(foreach a,float fixed,$(eval test_wide_$(a)_WIDE := 1))

# The scene's static structure once a load (render_scene_index), each arithmetic.
$(foreach a,double float fixed,$(eval test_scene_index_$(a)_SRCS = tests/host/test_scene_index.c $$(SCENE_TEXT_SRCS)))
$(foreach a,double float fixed,$(eval test_scene_index_$(a)_ARITH := $(a)))
$(foreach a,double float fixed,$(eval test_scene_index_$(a)_LIBS = $$(SCENE_TEXT_LIBS)))
