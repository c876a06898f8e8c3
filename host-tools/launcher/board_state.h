/* board_state.h: the state of named boards on the disk, private to the
 * launcher (board_named.c uses it).  Only its owner can touch it:
 *
 *   - the base directory ($LINKS1_BOARDS, else $XDG_RUNTIME_DIR/links1-boards,
 *     else /dev/shm/links1-UID, else /tmp/links1-UID) is refused unless it
 *     is a real directory (not a symbolic link) owned by this user with no
 *     group or other access; it is made 0700 when missing;
 *   - each board's directory below it is checked the same way, and every
 *     file in it is opened relative to it (openat, O_NOFOLLOW, O_CLOEXEC,
 *     O_EXCL where made);
 *   - every value read back from the record is range-checked;
 *   - nothing is removed while the board's lock is held by someone else
 *     (a board starting, or a session), and a board counts as running only
 *     when its recorded pid is a process of this user's (real and
 *     effective uid) whose command line names exactly its directory: a
 *     pid reused by another user's process, whatever its command line,
 *     is a board gone.
 * Each function that fails prints a message naming the path and the
 * problem. */
#ifndef LINKS1_HOST_LAUNCHER_BOARD_STATE_H
#define LINKS1_HOST_LAUNCHER_BOARD_STATE_H

#include <stddef.h>

#include "proto/board_map_an521.h"

/* The longest path of the base directory taken (a board's UART socket
 * below it must fit a unix socket's path anyway). */
#define BOARD_STATE_BASE_MAX 2048
/* The record file's most bytes. */
#define BOARD_STATE_RECORD_MAX 1024
/* The subdirectory of $XDG_RUNTIME_DIR that holds the boards' state. */
#define BOARD_STATE_XDG_DIR "links1-boards"
/* Bytes of a QEMU command line read to check that it is the board's. */
#define BOARD_STATE_CMDLINE_MAX 65536

/* What a board's directory records of it.  pid is the QEMU with the
 * board's UART (an521: board 0's); an an521 set of boards also records
 * its machine and the QEMU of each NC board (nc_pid[1..boards - 1]). */
struct board_record {
    int pid, ncores, ram_mb;
    char arith[16];
    int machine; /* enum machine_id */
    int nc_pid[AN521_MAX_BOARDS];
    int wide;    /* 1: its firmware escalates (links1-<arith>-esc.elf; the
                    record's optional "wide 1", absent in older records) */
};

/* The base directory opened (made 0700 when create and missing) and
 * checked; its path into path.  The directory's fd; -1 after printing why;
 * -2 (nothing printed) when it is missing and create is 0. */
int board_state_base(int create, char *path, size_t cap);

/* NAME (1..64 of [A-Za-z0-9_.-], not starting with '.' or '-': an option
 * such as --help is never taken for a name) checked: 0, or -1
 * after printing what a name may be. */
int board_state_name_ok(const char *name);

/* The directory name below base_fd opened and checked like the base (base
 * is its path, for messages).  Its fd; -2 (nothing printed) when there is
 * none; -1 after printing what it is instead (a symbolic link, not a
 * directory, another's, open to others). */
int board_state_dir(int base_fd, const char *base, const char *name);

/* A new board directory name below base_fd, made under a hidden name and
 * moved into place only once its lock is taken (so that no one ever sees
 * it unlocked), *lock_fd its lock.  Its fd, or -1 after printing why (one
 * of that name appeared meanwhile). */
int board_state_make(int base_fd, const char *base, const char *name, int *lock_fd);

/* The record of board name in dir_fd into *r, every value range-checked
 * (pid > 1, ncores in UNITS_MIN_CORES..UNITS_MAX_CORES, ram_mb in
 * BOARD_MIN_RAM_MB..BOARD_MAX_RAM_MB, an arithmetic the board runs; an
 * an521 set: ncores a whole number of boards, ram_mb AN521_SHARED_MB,
 * one pid > 1 for each NC board).
 * 0; -2 (nothing printed) when there is no record; -1 after printing
 * what is wrong with it (a symbolic link, not a regular file, a value out
 * of range). */
int board_state_read(int dir_fd, const char *dir, const char *name, struct board_record *r);

/* The record made (O_EXCL) in dir_fd.  0, or -1 after printing why. */
int board_state_write(int dir_fd, const char *dir, const struct board_record *r);

/* The board's lock taken without waiting.  Its fd; -2 when another
 * process holds it; -3 when there is no lock file (nothing printed for
 * either); -1 after printing why (a symbolic link, ...). */
int board_state_lock(int dir_fd, const char *dir);

/* A file of the board's directory made (O_CREAT | O_EXCL | O_NOFOLLOW),
 * flags added to O_CLOEXEC.  Its fd, or -1 (errno set). */
int board_state_create(int dir_fd, const char *file, int flags);

/* A file of the board's directory opened (O_NOFOLLOW | O_CLOEXEC): the
 * RAM file, checked a regular file of exactly size bytes.  Its fd, or -1
 * after printing why. */
int board_state_open_ram(int dir_fd, const char *dir, size_t size);

/* The board's UART chardev as QEMU is given it (the path's commas
 * doubled, qemu_opt_escape): its command line holds this exact argument,
 * and only this board's QEMU does. */
void board_state_chardev(const char *dir, char *out, size_t cap);

/* 1 when pid runs as this user (real and effective uid) and its command
 * line holds an argument equal to the chardev of dir (a pid reused by
 * another program or another user's process, or the QEMU of a board whose
 * directory merely begins with dir, does not count). */
int board_state_alive(const char *dir, int pid);

/* The real uid pid runs as, or -1 when there is no such process. */
long board_state_pid_uid(int pid);

/* An an521 NC board's QEMU of a named set has no UART; it is known by its
 * -name argument, this (board k of the set in dir). */
void board_state_nc_name(const char *dir, int k, char *out, size_t cap);
/* 1 when pid runs and is NC board k of the set in dir (its command line
 * holds board_state_nc_name's argument). */
int board_state_nc_alive(const char *dir, int k, int pid);

/* Every file of the board's directory and then the directory itself
 * removed (unlinkat: nothing followed).  0, or -1 after printing what was
 * left. */
int board_state_remove(int base_fd, int dir_fd, const char *dir, const char *name);

#endif
