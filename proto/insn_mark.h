/* insn_mark.h: markers for the instruction-counting plugin
 * (host-tools/insn/insn_count_plugin.c).
 *
 * "Count from here": a core that executes this marker has its count set
 * back to zero, so a benchmark counts the work of rendering and not
 * boot-time waits, whose length varies run to run (a core waiting for a
 * spinlock in WFE keeps executing under QEMU).
 *
 * Trace marks (plugin option trace=FILE, links1 render --trace): a core
 * that executes one has the plugin note the mark's kind and the core's
 * count at that moment.  Two kinds carry one bit each, so a unit computer
 * can write numbers into the trace (insn_mark_trace_bits); the others mark
 * points in the work (docs/trace.md says what each role marks).
 *
 * Every marker is a Thumb-2 instruction HINT #n with n unallocated, which
 * the architecture executes as a NOP, so it costs one instruction without
 * the plugin.  In memory: halfword 0xF3AF, then halfword 0x8000 | n. */
#ifndef LINKS1_PROTO_INSN_MARK_H
#define LINKS1_PROTO_INSN_MARK_H

#include <stdint.h>

#define INSN_MARK_THUMB_HW0 0xF3AFu
#define INSN_MARK_THUMB_HW1 0x8050u /* count from here */

/* Trace mark kinds: HINT #(INSN_MARK_TRACE_HW1_BASE + kind) - 0x8000. */
#define INSN_MARK_TRACE_HW1_BASE 0x8051u
enum insn_mark_trace_kind {
    INSN_TRACE_BIT0 = 0,       /* a 0 bit */
    INSN_TRACE_BIT1 = 1,       /* a 1 bit */
    INSN_TRACE_AREA_BEGIN = 2, /* NC: an area starts (its x, y, w, h written just before) */
    INSN_TRACE_PIXEL = 3,      /* NC: the area's set-up, then each pixel, is done */
    INSN_TRACE_AREA_END = 4,   /* NC: the area's pixels are in the data collector */
    INSN_TRACE_SPAN_BEGIN = 5, /* a span of a role's work starts */
    INSN_TRACE_SPAN_END = 6,   /* ... and ends */
    INSN_TRACE_KINDS = 7,
};

#if defined(__arm__) && defined(__thumb2__)
static inline void insn_mark_count_from_here(void)
{
    __asm__ volatile(".inst.w 0xf3af8050" ::: "memory");
}

#define INSN_MARK_TRACE_ASM(n) __asm__ volatile(".inst.w 0xf3af805" #n ::: "memory")
static inline void insn_mark_trace_bit(uint32_t bit)
{
    if (bit)
        INSN_MARK_TRACE_ASM(2);
    else
        INSN_MARK_TRACE_ASM(1);
}
static inline void insn_mark_trace_area_begin(void) { INSN_MARK_TRACE_ASM(3); }
static inline void insn_mark_trace_pixel(void) { INSN_MARK_TRACE_ASM(4); }
static inline void insn_mark_trace_area_end(void) { INSN_MARK_TRACE_ASM(5); }
static inline void insn_mark_trace_span_begin(void) { INSN_MARK_TRACE_ASM(6); }
static inline void insn_mark_trace_span_end(void) { INSN_MARK_TRACE_ASM(7); }

/* Writes the low n bits of v, most significant first. */
static inline void insn_mark_trace_bits(uint32_t v, int n)
{
    for (int i = n - 1; i >= 0; i--)
        insn_mark_trace_bit((v >> i) & 1u);
}
#endif

#endif
