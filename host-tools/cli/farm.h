/* farm.h: what `links1 farm` (cmd_farm.c) shares with its Slurm side
 * (farm_slurm.c): the per-host summary and one round of items handed to
 * Slurm as a job array. */
#ifndef LINKS1_HOST_CLI_FARM_H
#define LINKS1_HOST_CLI_FARM_H

#define FARM_MAX_HOSTS 256 /* hosts in the summary */

struct farm_host {
    char name[256];
    long frames, failed;
    double seconds;
};

/* One round of a farm on Slurm: the items (frames, or with bands > 0 the
 * bands of frame `frame`) rendered by `tool render scene ... extra` in dir,
 * one array task an item, the task id the item. */
struct farm_slurm_round {
    const char *tool, *scene, *dir, *ext;
    long frame;
    int bands;
    const char *const *extra;
    int nextra;
    const long *items; /* rising */
    long nitems;
};

/* Whether NAME is an executable file in some directory of $PATH (1 or 0). */
int farm_in_path(const char *name);

/* Submits the round as one job array (`sbatch --wait`), waits for it and
 * adds each task's host, seconds and outcome (from the line its task script
 * writes to its log) into hosts[]; *njobs the tasks logged.  0 once the
 * array has ended (whatever its tasks did: the caller looks for the items),
 * or -1 after saying why it could not be submitted. */
int farm_slurm_run(const struct farm_slurm_round *r, struct farm_host *hosts, int *nhosts,
                   long *njobs);

#endif
