/* links1.c: the host tool's entry point: one dispatch table of subcommands.
 * The board subcommands live in cmd_*.c, the scene subcommands in scene/. */
#include <stdio.h>
#include <string.h>

#include "host-tools/cli/links1_cmds.h"
#include "host-tools/cli/scene_cmds.h"
#include "host-tools/opts/exit_clean.h"

struct links1_cmd {
    const char *name;
    int (*fn)(int argc, char **argv);
    const char *help;
};

static const struct links1_cmd links1_cmds[] = {
    {"boot", cmd_boot, "boot the board, show every unit computer reporting in, shut down"},
    {"selftest", cmd_selftest, "boot the board and run board checks (ping, imsu, ...)"},
    {"render", cmd_render, "render a scene on the board (links1 render --help)"},
    {"farm", cmd_farm, "render an animation's frames on hosts (GNU parallel or Slurm)"},
    {"board", cmd_board, "start, stop or list boards that keep running between commands"},
    {"replay", cmd_replay, "replay a traced frame on equal-speed unit computers"},
    {"semihost", cmd_semihost, "run a semihosting program on the plain board (1 to 8 cores)"},
    {"compile", scene_cmd_compile, "compile a text scene into the form uploaded to the board"},
    {"ref", scene_cmd_ref, "render a scene on the host (--arith double|float|soft|fixed|auto)"},
    {"import", scene_cmd_import, "a model (OBJ, glTF, PLY, STL, Collada, 3DS, ...) into a scene"},
    {"export-pov", scene_cmd_export_pov, "write a scene for POV-Ray 3.7"},
    {"compare", scene_cmd_compare, "compare two images pixel by pixel"},
};
#define LINKS1_NCMDS (int)(sizeof links1_cmds / sizeof links1_cmds[0])

/* The other programs the project builds beside links1 (each answers --help). */
static const struct {
    const char *name, *help;
} links1_programs[] = {
    {"links1-spd", "write one of Haines's Standard Procedural Databases (NFF or a scene)"},
    {"links1-ref-<arith>", "links1 ref's host renderer: double, float, fixed, fixed12/14/16/18"},
    {"render-clip-stats", "how many clusters the screen clipping keeps, per area"},
};

static void links1_usage(FILE *out)
{
    fprintf(out, "usage: links1 COMMAND [options]   (links1 COMMAND --help for its options)\n"
                 "commands:\n");
    for (int i = 0; i < LINKS1_NCMDS; i++)
        fprintf(out, "  %-11s %s\n", links1_cmds[i].name, links1_cmds[i].help);
    fprintf(out, "programs beside links1 (in the same directory):\n");
    for (size_t i = 0; i < sizeof links1_programs / sizeof links1_programs[0]; i++)
        fprintf(out, "  %-19s %s\n", links1_programs[i].name, links1_programs[i].help);
    fprintf(out, "exit status: 0 done, 1 failed, 2 a usage error; 128 + N ended by signal N\n");
}

int main(int argc, char **argv)
{
    exit_clean_install(); /* a signal leaves no temporary file and no child of ours */
    if (argc < 2) {
        fprintf(stderr, "links1: name a command (see links1 --help)\n");
        return 2;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 ||
        strcmp(argv[1], "help") == 0) {
        links1_usage(stdout);
        return 0;
    }
    for (int i = 0; i < LINKS1_NCMDS; i++)
        if (strcmp(argv[1], links1_cmds[i].name) == 0)
            return links1_cmds[i].fn(argc - 1, argv + 1);
    fprintf(stderr, "links1: unknown command '%s' (see links1 --help)\n", argv[1]);
    return 2;
}
