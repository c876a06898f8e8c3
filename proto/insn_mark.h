/* insn_mark.h: "count from here" for the instruction-counting plugin
 * (host-tools/insn_count_plugin.c).  A core that executes the marker has
 * its count set back to zero, so a benchmark counts the work of rendering
 * and not boot-time waits, whose length varies run to run (a core waiting
 * for a spinlock in WFE keeps executing under QEMU).
 *
 * The marker is the Thumb-2 instruction HINT #0x50: an unallocated hint,
 * which the architecture executes as a NOP, so it costs nothing without
 * the plugin.  In memory: halfword 0xF3AF, then halfword 0x8050. */
#ifndef LINKS1_PROTO_INSN_MARK_H
#define LINKS1_PROTO_INSN_MARK_H

#define INSN_MARK_THUMB_HW0 0xF3AFu
#define INSN_MARK_THUMB_HW1 0x8050u

#if defined(__arm__) && defined(__thumb2__)
static inline void insn_mark_count_from_here(void)
{
    __asm__ volatile(".inst.w 0xf3af8050" ::: "memory");
}
#endif

#endif
