/* assimp_lib.h: libassimp opened when a model is first read (dlopen by
 * the soname the build found, MODEL_LIB_SONAME), not linked: a program
 * that reads no model never loads it, nor the C++ runtime it pulls in
 * (about 8 ms at every start of every host program).  model_assimp.c
 * calls the library through this table alone. */
#ifndef LINKS1_HOST_MODEL_ASSIMP_LIB_H
#define LINKS1_HOST_MODEL_ASSIMP_LIB_H

#include <assimp/cimport.h>
#include <assimp/material.h>
#include <stddef.h>

struct assimp_lib {
    __typeof__(aiImportFileEx) *import_file_ex;
    __typeof__(aiImportFileFromMemory) *import_file_from_memory;
    __typeof__(aiReleaseImport) *release_import;
    __typeof__(aiGetErrorString) *error_string;
    __typeof__(aiGetMaterialTextureCount) *material_texture_count;
    __typeof__(aiGetMaterialTexture) *material_texture;
    __typeof__(aiGetMaterialColor) *material_color;
    __typeof__(aiGetMaterialFloatArray) *material_float_array;
    __typeof__(aiGetMaterialString) *material_string;
    __typeof__(aiMultiplyMatrix4) *multiply_matrix4;
};

/* The library's functions, opened on the first call and kept open.  The
 * table, or NULL with "the model library (SONAME) cannot be loaded: why"
 * in err. */
const struct assimp_lib *assimp_lib(char *err, size_t errlen);

#endif
