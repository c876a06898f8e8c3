/* insn_report.h: reads the instruction-counting plugin's output (one line
 * "vcpu K INSNS" per emulated core, see insn_count_plugin.c) and prints it
 * per unit computer. */
#ifndef LINKS1_HOST_INSN_REPORT_H
#define LINKS1_HOST_INSN_REPORT_H

/* Prints the counts of cores 0..ncores-1 from path: DM, RC, every NC, and
 * the NC total/min/max.  Returns 0, or -1 after printing what is wrong with
 * the file. */
int insn_report_print(const char *path, int ncores);

#endif
