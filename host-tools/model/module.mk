# host-tools/model/: 3-D models made elsewhere (OBJ, glTF 2, PLY, ...) read
# through libassimp in a child process, as plain data; it knows no scene.
HT_MODEL_SRCS := host-tools/model/model_assimp.c host-tools/model/model_child.c \
	host-tools/model/model_wire.c
ARITH_FREE_SRCS += $(HT_MODEL_SRCS)
