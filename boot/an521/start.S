/* start.S: where both cores of an an521 board begin, the vector table,
 * the fault entries and the task context switch (Thumb: the M33 has no
 * other state).
 *
 * Core 0 starts at reset; core 1 is held (the SSE-200's CPUWAIT) until
 * core 0 lets it go, and finds the same vector table (INITSVTOR1 resets to
 * 0x10000000, where the image starts).  Both take the table's initial
 * stack, so each first moves to its own before touching memory. */
#include "drivers/an521/an521_map.h"

    .syntax unified
    .arch armv8-m.main
    .thumb

/* enum link_fault_kind of proto/hostlink.h (kernel/fault.c checks these). */
#define FAULT_UNDEF 1
#define FAULT_DATA_ABORT 3
#define FAULT_PANIC 4

/* Coprocessor access control: CP10 and CP11 (the FPU) full access. */
#define SCB_CPACR 0xE000ED88
#define CPACR_FPU (0xF << 20)

    .section .text.boot, "ax"
    .align 8                    /* VTOR: 64 entries of 4 bytes */
    .global vectors
vectors:
    .word __an521_initial_sp    /* core 0's stack (linker/an521-memory.ld) */
    .word _start
    .word vec_panic             /* NMI */
    .word vec_hardfault
    .word vec_memmanage
    .word vec_busfault
    .word vec_usagefault
    .word vec_panic             /* SecureFault */
    .word 0, 0, 0
    .word vec_panic             /* SVCall: the firmware makes no supervisor calls */
    .word vec_panic             /* DebugMonitor */
    .word 0
    .word vec_panic             /* PendSV */
    .word an521_irq_entry       /* SysTick */
    .rept AN521_VECTOR_IRQS
    .word an521_irq_entry
    .endr

    .global _start
    .type _start, %function
    .thumb_func
_start:                         /* the ELF's entry; the core takes the table's */
    cpsid i
    ldr r0, =AN521_CPUID
    ldr r0, [r0]                /* 0 or 1 */
    ldr r1, =LINKS1_CORE_STACK
    ldr r2, =__stacks_start
    mla r2, r0, r1, r2
    add r2, r2, r1
    mov sp, r2                  /* this core's own stack */
#ifdef __ARM_PCS_VFP
    /* FPU on before any C code, which may use it. */
    ldr r1, =SCB_CPACR
    ldr r2, [r1]
    orr r2, r2, #CPACR_FPU
    str r2, [r1]
    dsb
    isb
#endif
    cmp r0, #0
    bne 2f
    ldr r1, =__bss_start        /* core 0 clears .bss (8-byte aligned) */
    ldr r2, =__bss_end
    movs r4, #0
    movs r5, #0
1:  cmp r1, r2
    itt lo
    strdlo r4, r5, [r1], #8
    blo 1b
    bl boot_main                /* C, never returns */
    b cpu_halt_forever
2:  bl boot_secondary           /* C, never returns */
    b cpu_halt_forever

/* Faults: the hardware stacked r0-r3, r12, lr, pc, xPSR on the stack in
 * use (always MSP here); kernel/fault.c gets that frame as its registers,
 * the stacked pc and xPSR. */
    .macro fault_entry name, kind
    .thumb_func
\name:
    mov r1, sp
    ldr r2, [r1, #24]
    ldr r3, [r1, #28]
    movs r0, #\kind
    bl fault_from_exception
    b cpu_halt_forever
    .endm

    fault_entry vec_hardfault, FAULT_DATA_ABORT
    fault_entry vec_memmanage, FAULT_DATA_ABORT
    fault_entry vec_busfault, FAULT_DATA_ABORT
    fault_entry vec_usagefault, FAULT_UNDEF
    fault_entry vec_panic, FAULT_PANIC

/* void task_switch_context(struct task_ctx *from, struct task_ctx *to)
 * Saves the callee-saved registers of the running code in *from and
 * resumes *to where it last called task_switch_context (or at its entry). */
    .text
    .global task_switch_context
    .type task_switch_context, %function
    .thumb_func
task_switch_context:
    stmia r0, {r4-r11}
    mov r2, sp
    str r2, [r0, #32]
    str lr, [r0, #36]
#ifdef __ARM_PCS_VFP
    add r2, r0, #40
    vstmia r2, {d8-d15}
    add r2, r1, #40
    vldmia r2, {d8-d15}
#endif
    ldmia r1, {r4-r11}
    ldr r2, [r1, #32]
    mov sp, r2
    ldr lr, [r1, #36]
    bx lr

/* First code of a new task: task_create put the function in r4 and its
 * argument in r5. */
    .global task_entry_trampoline
    .type task_entry_trampoline, %function
    .thumb_func
task_entry_trampoline:
    mov r0, r5
    blx r4
    bl task_exit_current

    .global cpu_halt_forever
    .type cpu_halt_forever, %function
    .thumb_func
cpu_halt_forever:
    cpsid i
3:  wfi
    b 3b
