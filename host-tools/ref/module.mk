# host-tools/ref/: the host reference renderer (links1-ref-<arith>, one
# executable per arithmetic of the shared renderer; `links1 ref --arith A`
# runs the one asked for) and --arith auto's choice among them.
HT_REF_AUTO_SRCS := host-tools/ref/arith_auto.c host-tools/ref/ref_program.c host-tools/ref/ref_opts.c \
	host-tools/scene/scene_opts.c
# (arith_auto.c reads render/render.h: built in the links1 tool's double)

SCENE_REF_SRCS = host-tools/ref/ref_main.c host-tools/ref/ref_opts.c host-tools/scene/scene_opts.c \
	$(HT_OPTS_CLI_SRCS) \
	$(HT_IMAGE_FILM_SRCS) $(SCENE_TEXT_SRCS)
HOST_TOOLS += links1-ref-double links1-ref-float links1-ref-fixed
$(foreach a,double float fixed,$(eval links1-ref-$(a)_SRCS = $$(SCENE_REF_SRCS)))
$(foreach a,double float fixed,$(eval links1-ref-$(a)_ARITH := $(a)))
$(foreach a,double float fixed,$(eval links1-ref-$(a)_LIBS = $$(SCENE_TEXT_LIBS)))
# float and fixed escalate (--escalate): they carry the wide renderer
# (render/wide.h, the Makefile's wide_object).
links1-ref-float_WIDE := 1
links1-ref-fixed_WIDE := 1
# The same renderer in other fixed formats (links1-ref-fixedN: Q(31-N).N),
# candidates of `links1 ref --arith auto` (arith_auto.c finds them next to
# links1; the board's firmware stays Q12.19, fixed/num.h's default).
REF_FIXED_BITS := 12 14 16 18
HOST_EXTRA_ARITHS += $(addprefix fixed,$(REF_FIXED_BITS))
$(foreach f,$(REF_FIXED_BITS),$(eval ARITH_DEF_fixed$(f) := -DLINKS1_NUM_FIXED -DNUM_FRAC_BITS=$(f)))
$(foreach f,$(REF_FIXED_BITS),$(eval HOST_TOOLS += links1-ref-fixed$(f)))
$(foreach f,$(REF_FIXED_BITS),$(eval links1-ref-fixed$(f)_SRCS = $$(SCENE_REF_SRCS)))
$(foreach f,$(REF_FIXED_BITS),$(eval links1-ref-fixed$(f)_ARITH := fixed$(f)))
$(foreach f,$(REF_FIXED_BITS),$(eval links1-ref-fixed$(f)_LIBS = $$(SCENE_TEXT_LIBS)))
$(foreach f,$(REF_FIXED_BITS),$(eval links1-ref-fixed$(f)_WIDE := 1))
