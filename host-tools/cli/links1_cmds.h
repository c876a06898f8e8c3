/* links1_cmds.h: the board subcommands of `links1`.  Each takes the
 * arguments after its name (argv[0] is the subcommand's name) and returns the
 * process exit status. */
#ifndef LINKS1_HOST_CMDS_H
#define LINKS1_HOST_CMDS_H

int cmd_boot(int argc, char **argv);     /* links1 boot: boot, report in, shut down */
int cmd_selftest(int argc, char **argv); /* links1 selftest NAME...: board checks */

int cmd_render(int argc, char **argv);   /* links1 render SCENE -o OUT: render on the board */
int cmd_replay(int argc, char **argv);   /* links1 replay TRACE --ncs LIST: equal-speed units */
int cmd_semihost(int argc, char **argv); /* links1 semihost ELF: a semihosting program */
int cmd_farm(int argc, char **argv);     /* links1 farm SCENE -o DIR --hosts FILE: on hosts */
int cmd_board(int argc, char **argv);    /* links1 board start|stop|list: named boards */

/* The arguments args[0..n-1] that links1 farm passes on to `links1 render`
 * on every host, read with render's own option definitions: 0, or -1
 * after saying what is wrong (an option render does not take, a bad value,
 * an operand, or one that the farm sets itself: -o, --frame, --frames,
 * --band, --rows). */
int cmd_render_check_args(int n, const char *const *args);

#endif
