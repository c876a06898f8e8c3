/* assimp_lib.c: libassimp's functions found once with dlopen and dlsym
 * (assimp_lib.h). */
#include <dlfcn.h>
#include <stdio.h>
#include <string.h>

#include "host-tools/model/assimp_lib.h"

#ifndef MODEL_LIB_SONAME
#error "MODEL_LIB_SONAME (libassimp's soname) comes from host-tools/model/module.mk"
#endif

#define ASSIMP_FN(field, symbol) {offsetof(struct assimp_lib, field), #symbol}
static const struct {
    size_t at;
    const char *symbol;
} assimp_fns[] = {
    ASSIMP_FN(import_file_ex, aiImportFileEx),
    ASSIMP_FN(import_file_from_memory, aiImportFileFromMemory),
    ASSIMP_FN(release_import, aiReleaseImport),
    ASSIMP_FN(error_string, aiGetErrorString),
    ASSIMP_FN(material_texture_count, aiGetMaterialTextureCount),
    ASSIMP_FN(material_texture, aiGetMaterialTexture),
    ASSIMP_FN(material_color, aiGetMaterialColor),
    ASSIMP_FN(material_float_array, aiGetMaterialFloatArray),
    ASSIMP_FN(material_string, aiGetMaterialString),
    ASSIMP_FN(multiply_matrix4, aiMultiplyMatrix4),
};
_Static_assert(sizeof assimp_fns / sizeof assimp_fns[0] ==
                   sizeof(struct assimp_lib) / sizeof(void (*)(void)),
               "every function of struct assimp_lib is looked up");

const struct assimp_lib *assimp_lib(char *err, size_t errlen)
{
    static struct assimp_lib lib;
    static int opened;
    if (opened)
        return &lib;
    void *h = dlopen(MODEL_LIB_SONAME, RTLD_NOW | RTLD_LOCAL);
    if (!h) {
        snprintf(err, errlen, "the model library (%s) cannot be loaded: %s", MODEL_LIB_SONAME,
                 dlerror());
        return NULL;
    }
    for (size_t i = 0; i < sizeof assimp_fns / sizeof assimp_fns[0]; i++) {
        void *fn = dlsym(h, assimp_fns[i].symbol);
        if (!fn) {
            snprintf(err, errlen, "the model library (%s) has no %s: %s", MODEL_LIB_SONAME,
                     assimp_fns[i].symbol, dlerror());
            return NULL;
        }
        /* POSIX: a function's address from dlsym is used through its type */
        memcpy((char *)&lib + assimp_fns[i].at, &fn, sizeof fn);
    }
    opened = 1;
    return &lib;
}
