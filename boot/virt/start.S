/* start.S: where every core begins.
 *
 * Core 0 enters at _start from QEMU's ELF loader; the other cores enter at
 * secondary_entry when core 0 calls PSCI CPU_ON.  Both run core_setup
 * (mode stacks, vectors, MMU and caches, VFP) before any C code, so C always
 * runs with the MMU on: Normal memory for RAM (unaligned accesses and
 * exclusives work) and Device memory for the devices. */
#include "drivers/virt/virt_map.h"

    .syntax unified
    .arch armv7-a
    .arch_extension virt
    .arm

#define MODE_IRQ 0x12
#define MODE_SVC 0x13
#define MODE_ABT 0x17
#define MODE_UND 0x1b

/* MAIR0: attribute 0 Normal write-back read/write-allocate (inner and
 * outer), attribute 1 Device-nGnRE.  boot/virt/mmu_table.c uses these indices. */
#define MAIR0_VALUE 0x000004FF
/* TTBCR: EAE (long descriptors), T0SZ=0 (TTBR0 covers 4 GiB), table walks
 * inner shareable and write-back cacheable, TTBR1 walks disabled. */
#define TTBCR_VALUE ((1 << 31) | (1 << 23) | (3 << 12) | (1 << 10) | (1 << 8))
/* SCTLR: MMU, data cache, branch prediction, instruction cache on;
 * alignment checking off. */
#define SCTLR_SET ((1 << 0) | (1 << 2) | (1 << 11) | (1 << 12))
#define SCTLR_CLEAR ((1 << 1) | (1 << 30)) /* A, TE (exceptions in ARM state) */

    .section .text.boot, "ax"
    .global _start
_start:
    cpsid aif
    bl core_setup               @ r0 = core number
    cmp r0, #0
    bne park                    @ only core 0 starts here (see BOARD-NOTES)
    ldr r1, =__bss_start        @ clear .bss (8-byte aligned, linker-checked)
    ldr r2, =__bss_end
    mov r4, #0
    mov r5, #0
1:  cmp r1, r2
    strdlo r4, r5, [r1], #8
    blo 1b
    blx boot_main               @ C, never returns
    b park

    .global secondary_entry
secondary_entry:
    cpsid aif
    bl core_setup
    blx boot_secondary          @ C, never returns
    b park

park:
    cpsid aif
2:  wfi
    b 2b

/* core_setup: returns the core number in r0.  Uses r0-r3 and only banked
 * registers of other modes; the caller's lr (SVC mode) survives the mode
 * switches. */
core_setup:
    mrc p15, 0, r0, c0, c0, 5   @ MPIDR
    and r1, r0, #0xff           @ Aff0
    ubfx r2, r0, #8, #8         @ Aff1
    add r0, r1, r2, lsl #4      @ core = Aff1 * 16 + Aff0
    ldr r1, =LINKS1_MAX_CORES
    cmp r0, r1
    bhs park                    @ a core the firmware has no room for

    /* Stack block of this core: SVC at the top, then IRQ, ABT, UND. */
    ldr r1, =LINKS1_CORE_STACK
    ldr r2, =__stacks_start
    mla r2, r0, r1, r2
    add r2, r2, r1              @ r2 = top of the block
    ldr r3, =LINKS1_STACK_SVC
    sub r1, r2, r3              @ r1 = top of IRQ stack
    cps #MODE_IRQ
    mov sp, r1
    ldr r3, =LINKS1_STACK_IRQ
    sub r1, r1, r3
    cps #MODE_ABT
    mov sp, r1
    ldr r3, =LINKS1_STACK_ABT
    sub r1, r1, r3
    cps #MODE_UND
    mov sp, r1
    cps #MODE_SVC
    mov sp, r2

    ldr r1, =vectors
    mcr p15, 0, r1, c12, c0, 0  @ VBAR

    /* MMU: LPAE identity map + high redistributor window (memlayout.h). */
    ldr r1, =MAIR0_VALUE
    mcr p15, 0, r1, c10, c2, 0  @ MAIR0
    ldr r1, =TTBCR_VALUE
    mcr p15, 0, r1, c2, c0, 2   @ TTBCR
    ldr r1, =mmu_l1_table
    mov r2, #0
    mcrr p15, 0, r1, r2, c2     @ TTBR0 (64-bit), ASID 0
    mov r1, #0
    mcr p15, 0, r1, c8, c7, 0   @ TLBIALL
    mcr p15, 0, r1, c7, c5, 0   @ ICIALLU
    dsb
    isb
    mrc p15, 0, r1, c1, c0, 0   @ SCTLR
    ldr r2, =SCTLR_SET
    orr r1, r1, r2
    ldr r2, =SCTLR_CLEAR
    bic r1, r1, r2
    mcr p15, 0, r1, c1, c0, 0
    isb

#ifdef __ARM_PCS_VFP
    /* VFP for the hard-float build: CPACR cp10/cp11 full access, then
     * FPEXC.EN.  Must precede any C code, which may use VFP registers. */
    .fpu vfpv4
    mrc p15, 0, r1, c1, c0, 2
    orr r1, r1, #(0xf << 20)
    mcr p15, 0, r1, c1, c0, 2
    isb
    mov r1, #0x40000000
    vmsr fpexc, r1
#endif
    bx lr

/* int psci_call(uint32_t fn, uint32_t a1, uint32_t a2, uint32_t a3):
 * QEMU's virt board implements PSCI at the hypervisor call. */
    .text
    .global psci_call
    .type psci_call, %function
psci_call:
    hvc #0
    bx lr

    .global cpu_halt_forever
    .type cpu_halt_forever, %function
cpu_halt_forever:
    cpsid aif
3:  wfi
    b 3b
