/* board_opts.c: the board options every board subcommand takes, and where
 * the firmware ELF is found (see board.h). */
#include "host-tools/launcher/launcher.h"
#include "host-tools/opts/self_path.h"

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "host-tools/launcher/link_noise.h"
#include "proto/arith.h"

const struct cli_optdef board_optdefs[] = {
    {"ncs", "N", BOARD_OPT_NCS, "node computers: the board has N + 2 cores, the DM and the\n"
                                "RC besides (1..254, default 8; an521: even, 2..64)"},
    {"machine", "M", BOARD_OPT_MACHINE,
     "virt (one board, a core per unit computer, default) or an521\n"
     "(dual Cortex-M33 boards, one QEMU each)"},
    {"arith", "A", BOARD_OPT_ARITH, "firmware arithmetic: float (default), soft, fixed or double"},
    {"firmware", "ELF", BOARD_OPT_FIRMWARE,
     "firmware to boot (default: links1-<arith>.elf in $FW_DIR, else\n"
     "next to this program)"},
    {"timeout", "S", BOARD_OPT_TIMEOUT,
     "seconds to wait for every unit computer to report in (default 60)"},
    {"ram", "MB", BOARD_OPT_RAM, "board memory in MiB (1024..2048, default 1024)"},
    {"quiet", NULL, BOARD_OPT_QUIET, "print nothing but errors"},
    {"verbose", NULL, BOARD_OPT_VERBOSE,
     "print each unit computer reporting in (render: and each frame's\n"
     "pixels escalated to double)"},
    {"gdb", "", BOARD_OPT_GDB,
     "start halted, QEMU's gdb stub on a unix socket in your state\n"
     "directory (its path printed; make gdb)"},
    {"view", NULL, BOARD_OPT_VIEW, "show the frame memory live (-device ramfb, a display)"},
    {"link", "L", BOARD_OPT_LINK,
     "bulk bytes through shared memory (fast, default) or the serial\n"
     "link (serial); commands and results always go serially"},
    {"link-noise", "RATE[:SEED]", BOARD_OPT_LINK_NOISE,
     "test hook: a relay flips, drops, duplicates and inserts bytes at\n"
     "RATE per byte both ways"},
    CLI_OPTDEF_END,
};

void board_opts_init(struct board_opts *o)
{
    memset(o, 0, sizeof *o);
    o->ncores = BOARD_DEFAULT_CORES;
    o->arith = "float";
    o->ram_mb = BOARD_DEFAULT_RAM_MB;
    o->timeout_s = BOARD_DEFAULT_TIMEOUT_S;
    o->link = LINK_PATH_SHARED;
    o->insn_profile_core = -1;
}

/* --gdb takes no value: the stub is a unix socket only this user can
 * reach, never a TCP port any local user could attach to first.  The old
 * form (--gdb PORT, --gdb=PORT) is refused with a word on the new one. */
static int board_opt_gdb(struct board_opts *o, const struct cli *c)
{
    const char *next = optind < c->argc ? c->argv[optind] : NULL;
    const char *port = c->arg ? c->arg
                       : next && *next && strspn(next, "0123456789") == strlen(next) ? next
                                                                                      : NULL;
    if (port) {
        return cli_usage_error(c->prog, "--gdb takes no port (given '%s'): QEMU's gdb stub is "
                               "a unix socket in your state directory, its path printed at "
                               "start; attach with gdb-multiarch's `target remote PATH` (make "
                               "gdb does)", port);
    }
    o->gdb = 1;
    return 1;
}

/* --ram MB: at least what the firmware carves, refused here rather than
 * by the DM's panic at boot. */
static int board_opt_ram(struct board_opts *o, const struct cli *c)
{
    long mb;
    if (cli_long(c, 10, 0, BOARD_MAX_RAM_MB, &mb) < 0)
        return -1;
    if (mb < BOARD_FIRMWARE_RAM_MB) {
        char want[160];
        snprintf(want, sizeof want, "at least %d: the firmware lays out %d MiB of RAM "
                 "(linker/virt-memory.ld) and stops at boot with less; at most %d",
                 BOARD_FIRMWARE_RAM_MB, BOARD_FIRMWARE_RAM_MB, BOARD_MAX_RAM_MB);
        return cli_bad_value(c, want);
    }
    o->ram_mb = (int)mb;
    return 1;
}

int board_opt(struct board_opts *o, const struct cli *c, int code)
{
    switch (code) {
    case BOARD_OPT_NCS: {
        int ncs;
        if (cli_int(c, UNITS_MIN_CORES - 2, UNITS_MAX_CORES - 2, &ncs) < 0)
            return -1;
        o->ncores = ncs + 2;
        return 1;
    }
    case BOARD_OPT_TIMEOUT:
        return cli_int(c, 1, BOARD_MAX_TIMEOUT_S, &o->timeout_s) < 0 ? -1 : 1;
    case BOARD_OPT_RAM:
        return board_opt_ram(o, c);
    case BOARD_OPT_QUIET:
        o->quiet = 1;
        return 1;
    case BOARD_OPT_VERBOSE:
        o->verbose = 1;
        return 1;
    case BOARD_OPT_GDB:
        return board_opt_gdb(o, c);
    case BOARD_OPT_VIEW:
        o->view = 1;
        return 1;
    case BOARD_OPT_LINK:
        if (strcmp(c->arg, "fast") != 0 && strcmp(c->arg, "serial") != 0)
            return cli_bad_value(c, "fast or serial");
        o->link = strcmp(c->arg, "fast") == 0 ? LINK_PATH_SHARED : LINK_PATH_SERIAL;
        return 1;
    case BOARD_OPT_LINK_NOISE: {
        char why[200];
        if (link_noise_parse(c->arg, &o->link_noise, &o->link_noise_seed, why, sizeof why) < 0)
            return cli_usage_error(c->prog, "%s %s", c->name, why);
        o->link_noise_on = 1;
        return 1;
    }
    case BOARD_OPT_MACHINE:
        if ((o->machine = machine_by_name(c->arg)) < 0)
            return cli_bad_value(c, "virt or an521");
        return 1;
    case BOARD_OPT_FIRMWARE:
        o->firmware = c->arg;
        return 1;
    case BOARD_OPT_ARITH:
        if (board_arith_code(c->arg) < 0)
            return cli_bad_value(c, "float, soft, fixed, double or (render) auto");
        o->arith = c->arg;
        return 1;
    }
    return 0;
}

static int board_file_readable(const char *path)
{
    return access(path, R_OK) == 0;
}

/* QEMU boots anything given to -kernel (a non-ELF file as a raw image that
 * then never reports in), so check the ELF magic first. */
static int board_firmware_is_elf(const char *path)
{
    unsigned char magic[4] = {0};
    FILE *f = fopen(path, "rb");
    size_t n = f ? fread(magic, 1, sizeof magic, f) : 0;
    if (f)
        fclose(f);
    if (n == sizeof magic && memcmp(magic, "\177ELF", 4) == 0)
        return 1;
    fprintf(stderr, "links1: firmware %s is not an ELF file\n", path);
    return 0;
}

/* The firmware's file name under a firmware directory: links1-A.elf for
 * the virt board, an521/links1-A.elf for the an521 boards. */
static const char *board_machine_subdir(const struct board_opts *o)
{
    return o->machine == MACHINE_AN521 ? "an521/" : "";
}

/* "-esc" for the firmware that escalates (the Makefile's float-esc and
 * fixed-esc), "" otherwise. */
static const char *board_variant_suffix(const struct board_opts *o)
{
    return o->escalate ? "-esc" : "";
}

int board_find_firmware(const struct board_opts *o, char *out, size_t cap)
{
    if (o->firmware) {
        if (!board_file_readable(o->firmware)) {
            fprintf(stderr, "links1: firmware %s: %s\n", o->firmware, strerror(errno));
            return -1;
        }
        snprintf(out, cap, "%s", o->firmware);
        return board_firmware_is_elf(out) ? 0 : -1;
    }
    const char *fw_dir = getenv("FW_DIR");
    if (fw_dir && *fw_dir) {
        snprintf(out, cap, "%s/%slinks1-%s%s.elf", fw_dir, board_machine_subdir(o), o->arith,
                 board_variant_suffix(o));
        if (board_file_readable(out))
            return board_firmware_is_elf(out) ? 0 : -1;
        fprintf(stderr, "links1: firmware %s not found ($FW_DIR is set; run make, or "
                "give --firmware ELF)\n", out);
        return -1;
    }
    char self[PATH_MAX];
    if (self_dir(self, sizeof self) < 0) {
        fprintf(stderr, "links1: cannot find this program's directory: %s\n", strerror(errno));
        return -1;
    }
    snprintf(out, cap, "%s/%slinks1-%s%s.elf", self, board_machine_subdir(o), o->arith,
             board_variant_suffix(o));
    if (board_file_readable(out))
        return board_firmware_is_elf(out) ? 0 : -1;
    fprintf(stderr, "links1: firmware %s not found (run make, set $FW_DIR, or give "
            "--firmware ELF)\n", out);
    return -1;
}

