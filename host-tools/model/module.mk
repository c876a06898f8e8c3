# host-tools/model/: 3-D models made elsewhere (OBJ, glTF 2, PLY, ...) read
# through libassimp in a child process, as plain data; it knows no scene.
HT_MODEL_SRCS := host-tools/model/model_assimp.c host-tools/model/assimp_lib.c \
	host-tools/model/model_child.c host-tools/model/model_wire.c
# libassimp is opened by its soname when a model is first read (assimp_lib.h),
# not linked; the soname is the installed library's (found when the file is
# compiled, after `make deps`).
MODEL_LIB_SONAME = $(or $(shell objdump -p "$$($(HOST_CC) -print-file-name=libassimp.so)" \
	2>/dev/null | sed -n 's/^ *SONAME *//p'),$(error libassimp.so not found: `make deps` \
	installs libassimp-dev))
host-tools/model/assimp_lib.c_CFLAGS = -DMODEL_LIB_SONAME='"$(MODEL_LIB_SONAME)"'
ARITH_FREE_SRCS += $(HT_MODEL_SRCS)
