/* scene_cmds.c: `links1 compile`, `links1 ref` and `links1 export-pov`
 * (`links1 compare` is in image_compare.c). */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "host-tools/scene/scene_cmds.h"
#include "host-tools/scene/scene_desc.h"
#include "proto/arith.h"

/* Finds "SCENE -o OUT" among the arguments; extra flags are left to the
 * caller through *rest.  0, or -1 after printing the usage. */
static int cmd_in_out(int argc, char **argv, const char *usage, const char **in,
                      const char **out)
{
    *in = *out = NULL;
    for (int i = 0; i < argc; i++) {
        if (strcmp(argv[i], "-o") == 0 && i + 1 < argc)
            *out = argv[++i];
        else if (argv[i][0] != '-' && !*in)
            *in = argv[i];
    }
    if (!*in || !*out) {
        fprintf(stderr, "usage: %s\n", usage);
        return -1;
    }
    return 0;
}

/* Writes len bytes to path through a temporary file, so a failed run never
 * leaves a half-written output. */
static int cmd_write_file(const char *path, const void *data, size_t len)
{
    char tmp[PATH_MAX];
    snprintf(tmp, sizeof tmp, "%s.tmp%ld", path, (long)getpid());
    FILE *f = fopen(tmp, "wb");
    if (!f) {
        fprintf(stderr, "links1: %s: %s\n", tmp, strerror(errno));
        return -1;
    }
    int ok = fwrite(data, 1, len, f) == len;
    if (fclose(f) != 0)
        ok = 0;
    if (!ok || rename(tmp, path) != 0) {
        fprintf(stderr, "links1: writing %s: %s\n", path, strerror(errno));
        remove(tmp);
        return -1;
    }
    return 0;
}

int scene_cmd_compile(int argc, char **argv)
{
    argc--, argv++; /* argv[0] is the subcommand's name */
    const char *in, *out;
    if (cmd_in_out(argc, argv, "links1 compile SCENE.scn -o OUT.l1s", &in, &out))
        return 2;
    struct sd_scene s;
    char err[SD_ERR_MAX];
    if (sd_parse_file(in, &s, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    uint8_t *buf;
    size_t len;
    int rc = sd_compile(&s, &buf, &len, err, sizeof err);
    sd_free(&s);
    if (rc != 0) {
        fprintf(stderr, "%s: %s\n", in, err);
        return 1;
    }
    rc = cmd_write_file(out, buf, len);
    free(buf);
    if (rc == 0)
        printf("%s: %zu bytes\n", out, len);
    return rc ? 1 : 0;
}

int scene_cmd_export_pov(int argc, char **argv)
{
    argc--, argv++; /* argv[0] is the subcommand's name */
    const char *in, *out;
    if (cmd_in_out(argc, argv,
                   "links1 export-pov SCENE.scn -o OUT.pov [--frame N] [--strict]", &in, &out))
        return 2;
    int strict = 0, frame = 0;
    for (int i = 0; i < argc; i++) {
        if (strcmp(argv[i], "--strict") == 0)
            strict = 1;
        else if (strcmp(argv[i], "--frame") == 0 && i + 1 < argc)
            frame = atoi(argv[++i]);
    }
    struct sd_scene s;
    char err[SD_ERR_MAX];
    if (sd_parse_file(in, &s, err, sizeof err) != 0) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    char tmp[PATH_MAX];
    snprintf(tmp, sizeof tmp, "%s.tmp%ld", out, (long)getpid());
    int rc = sd_export_pov(&s, frame, strict, tmp, err, sizeof err);
    sd_free(&s);
    if (rc != 0) {
        fprintf(stderr, "%s: %s\n", in, err);
        remove(tmp);
        return 1;
    }
    if (rename(tmp, out) != 0) {
        fprintf(stderr, "links1: writing %s: %s\n", out, strerror(errno));
        remove(tmp);
        return 1;
    }
    return 0;
}

/* links1 ref: runs links1-ref-<arith> from the directory of this program. */
int scene_cmd_ref(int argc, char **argv)
{
    argc--, argv++; /* argv[0] is the subcommand's name */
    const char *arith = "double";
    char *args[64];
    int n = 1;
    for (int i = 0; i < argc; i++) {
        if (strcmp(argv[i], "--arith") == 0 && i + 1 < argc) {
            arith = argv[++i];
        } else if (n < 62) {
            args[n++] = argv[i];
        }
    }
    args[n] = NULL;
    const char *build = arith;
    int code = arith_from_name(arith);
    if (code == ARITH_SOFT) {
        /* Software float differs from hardware float only in who executes
         * the IEEE operations; on the host both are the float build. */
        fprintf(stderr, "links1 ref: --arith soft on the host is the float build\n");
        build = "float";
    } else if (code < 0) {
        fprintf(stderr, "links1 ref: --arith must be double, float, soft or fixed, not '%s'\n",
                arith);
        return 2;
    }
    char self[PATH_MAX];
    ssize_t k = readlink("/proc/self/exe", self, sizeof self - 1);
    if (k < 0) {
        fprintf(stderr, "links1 ref: cannot find my own directory: %s\n", strerror(errno));
        return 1;
    }
    self[k] = 0;
    char *slash = strrchr(self, '/');
    if (slash)
        slash[1] = 0;
    char prog[PATH_MAX + 32];
    snprintf(prog, sizeof prog, "%slinks1-ref-%s", self, build);
    args[0] = prog;
    execv(prog, args);
    fprintf(stderr, "links1 ref: cannot run %s: %s (build it with make)\n", prog,
            strerror(errno));
    return 1;
}
