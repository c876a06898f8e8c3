/* vectors.S: exception vectors, the IRQ entry, fault entries and the task
 * context switch.  ARM state (SCTLR.TE = 0); the C they call is Thumb. */
    .syntax unified
    .arch armv7-a
    .arm

/* enum link_fault_kind of proto/hostlink.h (kernel/fault.c checks these). */
#define FAULT_UNDEF 1
#define FAULT_PREFETCH_ABORT 2
#define FAULT_DATA_ABORT 3
#define FAULT_PANIC 4

#define MODE_IRQ 0x12
#define MODE_ABT 0x17
#define MODE_UND 0x1b
#define CPSR_T (1 << 5)

    .section .vectors, "ax"
    .align 5
    .global vectors
vectors:
    b vec_unexpected    @ reset (never taken: cores start at their entries)
    b vec_undef
    b vec_unexpected    @ SVC: the firmware makes no supervisor calls
    b vec_pabt
    b vec_dabt
    b vec_unexpected    @ unused
    b vec_irq
    b vec_unexpected    @ FIQ: nothing is routed to FIQ

/* Fault entries build a frame on the mode's stack: SRS (lr, spsr), then
 * r0-r12 and lr; r1 points at r0 of it for the C handler. */
vec_undef:
    srsdb sp!, #MODE_UND
    push {r0-r12, lr}
    mrs r3, spsr
    tst r3, #CPSR_T
    subne r2, lr, #2            @ Thumb: lr = instruction + 2
    subeq r2, lr, #4            @ ARM: lr = instruction + 4
    mov r0, #FAULT_UNDEF
    mov r1, sp
    blx fault_from_exception

vec_pabt:
    srsdb sp!, #MODE_ABT
    push {r0-r12, lr}
    mrs r3, spsr
    sub r2, lr, #4
    mov r0, #FAULT_PREFETCH_ABORT
    mov r1, sp
    blx fault_from_exception

vec_dabt:
    srsdb sp!, #MODE_ABT
    push {r0-r12, lr}
    mrs r3, spsr
    sub r2, lr, #8
    mov r0, #FAULT_DATA_ABORT
    mov r1, sp
    blx fault_from_exception

vec_unexpected:
    srsdb sp!, #MODE_ABT
    push {r0-r12, lr}
    mrs r3, spsr
    mov r2, lr
    mov r0, #FAULT_PANIC
    mov r1, sp
    blx fault_from_exception

/* IRQ: save what AAPCS lets a C call clobber (and the VFP state in the
 * hard-float build, since the interrupted task may be mid-calculation),
 * dispatch, return.  Runs on the core's IRQ stack with IRQs masked. */
vec_irq:
    sub lr, lr, #4
    srsdb sp!, #MODE_IRQ
    push {r0-r3, r12, lr}       @ 8 + 24 bytes: stack stays 8-byte aligned
#ifdef __ARM_PCS_VFP
    .fpu vfpv4
    vmrs r0, fpscr
    push {r0, r1}
    vpush {d0-d7}
    vpush {d16-d31}
#endif
    blx gic_irq_dispatch
#ifdef __ARM_PCS_VFP
    vpop {d16-d31}
    vpop {d0-d7}
    pop {r0, r1}
    vmsr fpscr, r0
#endif
    pop {r0-r3, r12, lr}
    rfeia sp!

/* void task_switch_context(struct task_ctx *from, struct task_ctx *to)
 * Saves the callee-saved registers of the running code in *from and
 * resumes *to where it last called task_switch_context (or at its entry). */
    .text
    .global task_switch_context
    .type task_switch_context, %function
task_switch_context:
    stmia r0, {r4-r11}
    str sp, [r0, #32]
    str lr, [r0, #36]
#ifdef __ARM_PCS_VFP
    add r2, r0, #40
    vstmia r2, {d8-d15}
    add r2, r1, #40
    vldmia r2, {d8-d15}
#endif
    ldmia r1, {r4-r11}
    ldr sp, [r1, #32]
    ldr lr, [r1, #36]
    bx lr

/* First code of a new task: task_create put the function in r4 and its
 * argument in r5. */
    .global task_entry_trampoline
    .type task_entry_trampoline, %function
task_entry_trampoline:
    mov r0, r5
    blx r4
    blx task_exit_current
