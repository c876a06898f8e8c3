/* exit_clean.h: what a program leaves when SIGINT, SIGTERM or SIGHUP ends
 * it: nothing.  Each program's main installs the handlers once; whatever
 * makes a temporary file or directory, or starts a child, registers it
 * here and drops it once it is gone.  The handler (async-signal-safe work
 * only) sends SIGTERM to every registered child and waits for them a few
 * seconds (SIGKILL after that), runs every registered command (waited for
 * as long, its note on stderr), removes every registered path (a
 * directory with everything under it, never following a link), then
 * dies of the same signal with its default action, so a shell sees
 * 128 + N.  A child of this program that has not exec'ed yet runs the
 * default action (the registry is its parent's).  Nothing can clean up
 * after SIGKILL: the children go too (exit_clean_in_child: the
 * parent-death signal), and tmp_dir_make's directories are swept by a
 * later run (tmp_dir.h).  SIGTSTP (^Z) stops every registered process
 * group (exit_clean_add_group: out of the terminal's reach) and then the
 * program; when the program is continued, so are they. */
#ifndef LINKS1_HOST_OPTS_EXIT_CLEAN_H
#define LINKS1_HOST_OPTS_EXIT_CLEAN_H

#include <signal.h>
#include <sys/types.h>

#define EXIT_CLEAN_MAX_PATHS 32
#define EXIT_CLEAN_MAX_CHILDREN 48      /* an an521 run's 33 QEMUs, ffmpeg, ... */
#define EXIT_CLEAN_CHILD_WAIT_MS 5000   /* a child's own clean-up (a links1 render's) */
#define EXIT_CLEAN_MAX_COMMANDS 4
#define EXIT_CLEAN_COMMAND_WORDS 15     /* argv's words */
#define EXIT_CLEAN_COMMAND_BYTES 1024   /* its words and notes, each with its 0 */

enum exit_clean_kind {
    EXIT_CLEAN_FILE, /* unlinked */
    EXIT_CLEAN_DIR,  /* removed with everything under it */
};

/* The handlers for SIGINT, SIGTERM, SIGHUP and SIGTSTP (a signal ignored
 * when the program started, e.g. SIGHUP under nohup, stays ignored). */
void exit_clean_install(void);

/* path removed if a signal ends the program.  0, or -1 (the registry is
 * full or path too long: it is then only not cleaned on a signal). */
int exit_clean_add(const char *path, enum exit_clean_kind kind);
/* path no longer removed on a signal (call after removing it). */
void exit_clean_drop(const char *path);

/* pid sent SIGTERM (and waited for) if a signal ends the program. */
void exit_clean_add_child(pid_t pid);
/* The same for a child that leads a process group of its own
 * (exit_clean_in_child_group, or setsid): its whole group is signalled,
 * so what it started without exec (a $QEMU wrapper script's emulator)
 * ends with it.  Dropped by exit_clean_drop_child(pid). */
void exit_clean_add_group(pid_t pid);
void exit_clean_drop_child(pid_t pid);
/* sig to pid's process group when pid leads one, else to pid alone (a
 * group not made yet: the child has not reached setpgid or setsid).
 * kill's result. */
int exit_clean_kill(pid_t pid, int sig);

/* argv (NULL-ended) run if a signal ends the program, once the children
 * are stopped and before the paths go: forked and started with execvp,
 * waited for up to EXIT_CLEAN_CHILD_WAIT_MS (then SIGKILL); done, or failed
 * when it did not exit 0, written to stderr as a line.  Its slot for
 * exit_clean_drop_command, or -1 (the registry is full or the words too
 * many or too long: nothing is then run). */
int exit_clean_add_command(const char *const *argv, const char *done, const char *failed);
/* The command of slot no longer run on a signal (-1: nothing). */
void exit_clean_drop_command(int slot);

/* In a child of the program (the process that called exit_clean_install)
 * right after fork: the handlers back to the default, SIGTERM when the
 * parent dies (PR_SET_PDEATHSIG), and _exit(1) at once when it died
 * already (getppid() is not the program). */
void exit_clean_in_child(void);
/* exit_clean_in_child, and the child leads a process group of its own
 * (its parent registers it with exit_clean_add_group and signals it with
 * exit_clean_kill).  A terminal's ^C and ^Z then reach the program, not
 * the child: the program's handler stops it. */
void exit_clean_in_child_group(void);

/* The three signals held (between making a file and registering it) and
 * let go again. */
void exit_clean_hold(sigset_t *old);
void exit_clean_release(const sigset_t *old);

#endif
