/* apu_bench.c: the paper's Table 1 on two cores of the board's CPU.
 *
 * Core 0 is the unit computer (the paper's Z8001), core 1 its APU (the
 * iAPX 86/20).  For each of the four operations core 0 runs APU_N rounds
 *   - locally in soft float (every + and * a call of the EABI soft-float
 *     routines __aeabi_fadd and __aeabi_fmul, what the firmware's soft build
 *     compiles them to), in fixed point (apu_fixed.c) and with VFP;
 *   - handed to core 1: core 0 writes the operands and the operation into
 *     a mailbox in shared memory and raises a sequence number; core 1,
 *     polling it, reads the operands, computes with VFP, writes the result
 *     and answers; core 0, polling the answer, reads the result.
 * Trace marks (proto/insn_mark.h) bracket the work, not the waiting: on
 * core 0 each local block of rounds, and in each hand-off the sending and
 * the reading of the result; on core 1 each request from its arrival to
 * its answer.  bench_apu.sh turns the plugin's counts into instructions per
 * operation.  The results are checked: the APU's equal the local VFP ones
 * bit for bit, soft float's too (IEEE single, the same operations in the
 * same order), fixed point's within 1e-3.  Output: one line per check and
 * "done". */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "proto/insn_mark.h"
#include "tests/bench/apu/apu.h"

#define APU_N 64 /* rounds of each operation and method */

/* The EABI soft-float routines, base procedure call standard. */
float __aeabi_fadd(float, float) __attribute__((pcs("aapcs")));
float __aeabi_fmul(float, float) __attribute__((pcs("aapcs")));

/* The mailbox: one writer per field.  seq and op by core 0, done by core 1. */
struct apu_box {
    volatile uint32_t seq;  /* request number, raised last */
    volatile uint32_t op;
    volatile uint32_t done; /* the request answered, written last */
    uint32_t pad[13];
    float a[9], b[9], r[9];
} __attribute__((aligned(64)));
static struct apu_box box;
uint8_t apu_stack[8192] __attribute__((aligned(16), used)); /* core 1's, set in apu_entry */

static inline void apu_dmb(void) { __asm__ volatile("dmb ish" ::: "memory"); }

static void vfp_op(int op, const float *a, const float *b, float *r)
{
    switch (op) {
    case APU_VADD:
        for (int i = 0; i < 3; i++)
            r[i] = a[i] + b[i];
        break;
    case APU_VDOT:
        r[0] = (a[0] * b[0] + a[1] * b[1]) + a[2] * b[2];
        break;
    case APU_MADD:
        for (int i = 0; i < 9; i++)
            r[i] = a[i] + b[i];
        break;
    case APU_MMUL:
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                r[3 * i + j] = (a[3 * i] * b[j] + a[3 * i + 1] * b[3 + j]) + a[3 * i + 2] * b[6 + j];
        break;
    }
}

/* The same, every + and * a soft-float call. */
static void soft_op(int op, const float *a, const float *b, float *r)
{
#define ADD __aeabi_fadd
#define MUL __aeabi_fmul
    switch (op) {
    case APU_VADD:
        for (int i = 0; i < 3; i++)
            r[i] = ADD(a[i], b[i]);
        break;
    case APU_VDOT:
        r[0] = ADD(ADD(MUL(a[0], b[0]), MUL(a[1], b[1])), MUL(a[2], b[2]));
        break;
    case APU_MADD:
        for (int i = 0; i < 9; i++)
            r[i] = ADD(a[i], b[i]);
        break;
    case APU_MMUL:
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                r[3 * i + j] = ADD(ADD(MUL(a[3 * i], b[j]), MUL(a[3 * i + 1], b[3 + j])),
                                   MUL(a[3 * i + 2], b[6 + j]));
        break;
    }
#undef ADD
#undef MUL
}

/* ---- core 1: the APU ---- */
__attribute__((noreturn)) void apu_main(void)
{
    uint32_t last = 0;
    for (;;) {
        uint32_t s;
        while ((s = box.seq) == last)
            ;
        apu_dmb();
        insn_mark_trace_span_begin();
        uint32_t op = box.op;
        float a[9], b[9], r[9];
        int n = op < APU_OPS ? apu_in_words((int)op) : 0;
        for (int i = 0; i < n; i++) {
            a[i] = box.a[i];
            b[i] = box.b[i];
        }
        if (op < APU_OPS)
            vfp_op((int)op, a, b, r);
        n = op < APU_OPS ? apu_out_words((int)op) : 0;
        for (int i = 0; i < n; i++)
            box.r[i] = r[i];
        apu_dmb();
        box.done = s;
        insn_mark_trace_span_end();
        last = s;
        if (op == APU_STOP)
            for (;;)
                __asm__ volatile("wfi");
    }
}

/* Entered in ARM state by PSCI CPU_ON: a stack, VFP on, then C. */
__attribute__((naked, target("arm"))) void apu_entry(void)
{
    __asm__ volatile("ldr r0, =apu_stack\n"
                     "add r0, r0, #8192\n"
                     "mov sp, r0\n"
                     "mrc p15, 0, r0, c1, c0, 2\n"
                     "orr r0, r0, #(0xf << 20)\n"
                     "mcr p15, 0, r0, c1, c0, 2\n"
                     "isb\n"
                     "mov r0, #0x40000000\n"
                     "vmsr fpexc, r0\n"
                     "ldr r0, =apu_main\n"
                     "bx r0\n");
}

/* PSCI CPU_ON through the hypervisor call (QEMU's virt board). */
__attribute__((target("arm"), noinline)) static int32_t psci_cpu_on(uint32_t mpidr, uint32_t entry)
{
    register uint32_t r0 __asm__("r0") = 0x84000003u;
    register uint32_t r1 __asm__("r1") = mpidr;
    register uint32_t r2 __asm__("r2") = entry;
    register uint32_t r3 __asm__("r3") = 0;
    __asm__ volatile(".arch_extension virt\n hvc #0" : "+r"(r0) : "r"(r1), "r"(r2), "r"(r3) : "memory");
    return (int32_t)r0;
}

/* ---- core 0: the unit computer ---- */
static uint32_t seq;

/* One hand-off: the work of sending and of reading the result is marked,
 * the waiting between is not. */
static void offload(int op, const float *a, const float *b, float *r)
{
    insn_mark_trace_span_begin();
    int n = apu_in_words(op);
    for (int i = 0; i < n; i++) {
        box.a[i] = a[i];
        box.b[i] = b[i];
    }
    box.op = (uint32_t)op;
    apu_dmb();
    box.seq = ++seq;
    insn_mark_trace_span_end();
    while (box.done != seq)
        ;
    apu_dmb();
    insn_mark_trace_span_begin();
    n = apu_out_words(op);
    for (int i = 0; i < n; i++)
        r[i] = box.r[i];
    insn_mark_trace_span_end();
}

static int failures;

/* Semihosting SYS_EXIT (0x18) with ADP_Stopped_ApplicationExit: ends QEMU
 * (picolibc's exit does not here; the checks above are the verdict). */
static void apu_exit(void)
{
    fflush(stdout);
    register int r0 __asm__("r0") = 0x18;
    register int r1 __asm__("r1") = 0x20026;
    __asm__ volatile("svc 0xab" : : "r"(r0), "r"(r1) : "memory");
}

static void check(const char *what, const char *op, int ok)
{
    printf("%s apu_%s_%s\n", ok ? "PASS" : "FAIL", what, op);
    failures += !ok;
}

int main(void)
{
    static const char *const names[APU_OPS] = {"vadd", "vdot", "madd", "mmul"};
    float a[9], b[9], rv[9], rs[9], ro[9];
    int32_t fa[9], fb[9], rf[9];
    float one = (float)apu_fixed_one();
    for (int i = 0; i < 9; i++) { /* values a fixed format holds: x/64, |x| < 4 */
        a[i] = (float)(i * 13 % 17 - 8) / 64.0f * 3.0f;
        b[i] = (float)(i * 7 % 11 - 5) / 64.0f * 5.0f;
        fa[i] = (int32_t)(a[i] * one); /* exact: multiples of 3/64 and 5/64 */
        fb[i] = (int32_t)(b[i] * one);
    }
    if (psci_cpu_on(1, (uint32_t)(uintptr_t)apu_entry) != 0) {
        printf("FAIL apu_start: PSCI CPU_ON of core 1 refused\n");
        apu_exit();
        return 1;
    }
    for (int op = 0; op < APU_OPS; op++) {
        /* local: soft float, fixed point, VFP; APU_N rounds each */
        insn_mark_trace_span_begin();
        for (int k = 0; k < APU_N; k++) {
            soft_op(op, a, b, rs);
            __asm__ volatile("" ::: "memory");
        }
        insn_mark_trace_span_end();
        insn_mark_trace_span_begin();
        for (int k = 0; k < APU_N; k++) {
            apu_fixed(op, fa, fb, rf);
            __asm__ volatile("" ::: "memory");
        }
        insn_mark_trace_span_end();
        insn_mark_trace_span_begin();
        for (int k = 0; k < APU_N; k++) {
            vfp_op(op, a, b, rv);
            __asm__ volatile("" ::: "memory");
        }
        insn_mark_trace_span_end();
        for (int k = 0; k < APU_N; k++)
            offload(op, a, b, ro);
        int n = apu_out_words(op), same = 1, soft_same = 1, near = 1;
        for (int i = 0; i < n; i++) {
            same &= memcmp(&ro[i], &rv[i], sizeof(float)) == 0;
            soft_same &= memcmp(&rs[i], &rv[i], sizeof(float)) == 0;
            float d = (float)rf[i] / one - rv[i];
            near &= d < 1e-3f && d > -1e-3f;
        }
        check("offload_equals_vfp", names[op], same);
        check("soft_equals_vfp", names[op], soft_same);
        check("fixed_near_vfp", names[op], near);
    }
    box.op = APU_STOP;
    apu_dmb();
    box.seq = ++seq;
    while (box.done != seq)
        ;
    printf("rounds %d\ndone\n", APU_N);
    apu_exit();
    return failures ? 1 : 0;
}
