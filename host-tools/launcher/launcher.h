/* launcher.h: the board launcher.  It starts qemu-system-arm (always with
 * -nodefaults) with the board's UART on one end of a socketpair (QEMU's
 * "-chardev socket,fd=N": no file-system path to clean up, no race to
 * connect, and a socket gives both sides back-pressure, so a slow reader
 * slows the writer instead of losing bytes; when QEMU exits the socket
 * reads end-of-file), and its RAM a memfd mapped here too (the
 * shared-memory path of proto/hostlink.h); then opens a link session on
 * it (host-tools/link/board.h).  Named boards run on between commands,
 * their state in a directory only their owner can reach. */
#ifndef LINKS1_HOST_LAUNCHER_H
#define LINKS1_HOST_LAUNCHER_H

#include <stddef.h>

#include "host-tools/link/board.h"
#include "host-tools/opts/cli_opt.h"
#include "proto/board_map.h"
#include "proto/units.h"

#define BOARD_DEFAULT_CORES 10
#define BOARD_DEFAULT_RAM_MB BOARD_RAM_MB /* what the firmware carves */
/* The least RAM a board is started with and a record may hold (a test of
 * the firmware's own refusal of too little starts one below the next). */
#define BOARD_MIN_RAM_MB 64
/* The least --ram takes: what the firmware carves (linker/virt-memory.ld
 * lays its memory out up to 0x80000000; given less, the DM panics at boot). */
#define BOARD_FIRMWARE_RAM_MB BOARD_RAM_MB
#define BOARD_MAX_RAM_MB 2048 /* the virt board's 32-bit RAM window below 4 GiB */
/* Default seconds to wait for every unit computer to report in.  256 cores
 * start one after another under emulation on two host cores, so this is
 * generous. */
#define BOARD_DEFAULT_TIMEOUT_S 60
#define BOARD_MAX_TIMEOUT_S 3600
/* A session on a named board waits this long for the board's first answer
 * (it may be finishing a command of a session that went away). */
#define BOARD_SESSION_WAIT_MS 60000
/* Clean stop: wait this long for QEMU to exit after CMD_SHUTDOWN, then send
 * SIGTERM and wait again, and only then SIGKILL. */
#define BOARD_SHUTDOWN_WAIT_MS 5000
#define BOARD_TERM_WAIT_MS 3000
/* --link-noise: the send buffer of each socket towards the board around the
 * relay (the kernel doubles it). */
#define BOARD_RELAY_SNDBUF 4096

/* QEMU's option syntax ("-chardev socket,path=P,server=on", "-plugin
 * SO,out=F") ends a value at a ',' and takes ",," as a comma of the value:
 * value with each ',' doubled, into out, which it returns (cap at least
 * 2 * strlen(value) + 1 holds it whole; else it ends early, never in the
 * middle of a doubled comma).  Every path put into a QEMU option string
 * goes through this; -kernel takes a plain path and does not. */
const char *qemu_opt_escape(const char *value, char *out, size_t cap);

/* Fills o with the defaults (BOARD_DEFAULT_*). */
void board_opts_init(struct board_opts *o);

/* The board options every command that starts a board takes (--ncs,
 * --machine, --arith, --firmware, --timeout, --ram, --quiet, --verbose,
 * --gdb, --view, --link, --link-noise), defined once: board_optdefs, for each
 * command's getopt table and --help. */
enum board_opt_code {
    BOARD_OPT_NCS = CLI_BOARD_CODES,
    BOARD_OPT_ARITH,
    BOARD_OPT_FIRMWARE,
    BOARD_OPT_TIMEOUT,
    BOARD_OPT_RAM,
    BOARD_OPT_QUIET,
    BOARD_OPT_LINK,
    BOARD_OPT_VERBOSE,
    BOARD_OPT_GDB,
    BOARD_OPT_LINK_NOISE,
    BOARD_OPT_MACHINE,
    BOARD_OPT_VIEW,
};
extern const struct cli_optdef board_optdefs[];

/* Takes the board option cli_next() returned as code into o.  Returns 1
 * when it took it, 0 when code is not a board option, -1 after printing
 * what is wrong with its value. */
int board_opt(struct board_opts *o, const struct cli *c, int code);

/* Resolves the firmware ELF into out: opts->firmware, else
 * $FW_DIR/links1-<arith>.elf, else links1-<arith>.elf next to this program
 * (links1-<arith>-esc.elf when opts->escalate).
 * Returns 0, or -1 after printing where it looked. */
int board_find_firmware(const struct board_opts *o, char *out, size_t cap);

/* Starts QEMU, its RAM a memfd mapped here too (b->ram: the shared-memory
 * path of proto/hostlink.h), and says so ("links1: booting ...").
 * Returns 0, or -1 after printing why. */
int board_start(struct board *b, const struct board_opts *o);
/* board_start's two steps: the start, which says nothing unless it fails,
 * and its "booting" line (none with --quiet).  links1 render starts the
 * board so while it compiles the scene, and says it once the scene is
 * taken. */
int board_start_unannounced(struct board *b, const struct board_opts *o);
void board_say_booting(const struct board *b);
/* A board started and not wanted after all (its scene refused before it
 * reported in): QEMU killed at once, no shutdown asked, then board_stop's
 * cleaning up; nothing is printed for a board killed so. */
void board_abandon(struct board *b);

/* Runs a semihosting program (not the firmware: one core, no link) on the
 * plain virt board, its console output on our stdout, until it ends the
 * emulator (semihosting SYS_EXIT).  Returns QEMU's exit status, or -1 after
 * printing why. */
int board_run_semihost(const char *elf, int ram_mb);
/* The same on cores cores of the board (1..8: the program starts the others
 * itself, PSCI CPU_ON), with the instruction-counting plugin writing each
 * core's trace marks (proto/insn_mark.h) to trace_out when it is not NULL. */
int board_run_semihost_smp(const char *elf, int ram_mb, int cores, const char *trace_out);

/* The link ended (board.process_gone): what became of QEMU, into desc (a
 * named board by its name). */
void board_qemu_gone(struct board *b, char *desc, size_t cap);

/* Shuts the board down: CMD_SHUTDOWN, wait for QEMU to exit, SIGTERM, and
 * SIGKILL only as a last resort.  Returns 0 when QEMU exited by itself after
 * the command, 1 when it had to be signalled, -1 on error.  Safe to call
 * twice and after QEMU died. */
int board_stop(struct board *b);

/* ---- named boards (host-tools/launcher/board_named.c) ----
 * `links1 board start --name NAME` leaves a board running for later
 * sessions (`links1 render --board NAME`).  Its state directory
 * ($LINKS1_BOARDS, else $XDG_RUNTIME_DIR/links1-boards, else
 * /dev/shm/links1-UID, else /tmp/links1-UID, then NAME/) holds QEMU's pid
 * and the board's shape (BOARD_STATE_INFO), the UART as a listening
 * socket, the shared RAM file, QEMU's own output, the gdb stub's socket
 * (--gdb) and a lock that one session at a time holds.  Only its owner can
 * touch it (board_state.h: the base and each board's directory refused
 * unless they are real directories of this user's with no group or other
 * access, every file opened relative to them without following links,
 * every value read back range-checked).  A board whose QEMU is gone and
 * whose lock no one holds leaves a stale directory: found, reported and
 * removed by start, stop, list and status.  An an521 named board is the
 * set of QEMUs (board 0's, then one per NC board, each recorded and each
 * known by its command line) on the directory's RAM file; stop and a stale
 * set's removal end every one of them. */
#define BOARD_STATE_INFO "board"
#define BOARD_STATE_SOCKET "link.sock"
#define BOARD_STATE_RAM "ram"
#define BOARD_STATE_LOG "qemu.log"
#define BOARD_STATE_LOCK "lock"
#define BOARD_STATE_GDB "gdb.sock"
#define BOARD_DEFAULT_NAME "default"
#define BOARD_NAME_MAX 64 /* characters of a board's name */

/* Starts QEMU as the named board and waits for every unit computer to
 * report in; the board then runs on without this tool.  0, or -1 after
 * printing why (a board of that name already running, QEMU failing). */
int board_start_named(struct board *b, const struct board_opts *o, const char *name,
                      int timeout_ms);
/* A session on the named board: maps its RAM, connects to its UART, opens
 * the session (LINK_FLAG_SESSION) and checks that every unit computer is up.
 * o gives quiet and link; the shape comes from the board.  0, or -1 after
 * printing why. */
int board_connect(struct board *b, const struct board_opts *o, const char *name);
/* Shuts the named board down and removes its state.  0, or -1. */
int board_stop_named(const char *name);
/* Prints every named board: running (pid, cores) or stale (then removed).
 * Returns the number running, or -1 after printing why the state
 * directory was refused (another's, open to others, a link). */
int board_list_named(void);
/* Prints named board name as board list does.  0 when it runs, -1 when
 * it does not (said why; a stale one reported and removed). */
int board_status_named(const char *name);
/* The machine (enum machine_id) of named board name, from its record, and
 * into *wide whether its firmware escalates; -1 after printing why there
 * is none. */
int board_named_machine(const char *name, int *wide);
/* board_start_named's steps (qemu.c starts the process between them):
 * the state directory made (a stale one removed first) with its lock
 * taken; the record written and the UART socket connected (returns its
 * fd); everything undone after a failure. */
int board_named_prepare(struct board *b, const char *name);
int board_named_started(struct board *b, int timeout_ms);
void board_named_abandon(struct board *b); /* (an an521 set's NC boards too) */
/* In QEMU's child process: its output into the state directory. */
void board_named_redirect(const struct board *b);
/* The named board's UART chardev argument for QEMU (board_state.h). */
void board_named_chardev(const struct board *b, char *out, size_t cap);
/* The named board's RAM file mapped into b (board_start_named creates it
 * with create = 1, and keeps it open in b->ram_fd for QEMU; a session
 * checks it is a regular file of exactly the recorded size).  0, or -1
 * after printing why. */
int board_named_map_ram(struct board *b, int create);

#endif
