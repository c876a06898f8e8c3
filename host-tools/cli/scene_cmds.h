/* scene_cmds.h: the `links1` subcommands that work on scene files on the host
 * (compile, ref, export-pov, compare).  Each gets argv[0] = its own name,
 * then its arguments, and returns the process exit status. */
#ifndef LINKS1_HOST_SCENE_CMDS_H
#define LINKS1_HOST_SCENE_CMDS_H

#include <stddef.h>

int scene_cmd_compile(int argc, char **argv);    /* links1 compile SCENE -o OUT.l1s */
int scene_cmd_ref(int argc, char **argv);        /* links1 ref SCENE -o OUT.png [--arith A] */
int scene_cmd_export_pov(int argc, char **argv); /* links1 export-pov SCENE -o OUT.pov */
int scene_cmd_compare(int argc, char **argv);    /* links1 compare A.png B.png [...] */
int scene_cmd_import(int argc, char **argv);     /* links1 import MODEL -o SCENE.scn [...] */

#endif
