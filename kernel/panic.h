/* panic.h: stopping one core loudly.
 *
 * panic() and the fault handlers report through the log sink (kernel/klog.h;
 * a LINK_FAULT frame with core, role, kind, address and pc, then a
 * readable LINK_LOG line), mark the core halted and stop it in WFI with interrupts masked.
 * The other cores keep running. */
#ifndef LINKS1_KERNEL_PANIC_H
#define LINKS1_KERNEL_PANIC_H

#include <stdint.h>

void panic(const char *fmt, ...) __attribute__((noreturn, format(printf, 1, 2)));

/* Called by the exception vectors (boot/virt/vectors.S). */
void fault_from_exception(uint32_t kind, const uint32_t *regs, uint32_t pc,
                          uint32_t spsr) __attribute__((noreturn));

/* Stops this core for good (boot/virt/vectors.S). */
void cpu_halt_forever(void) __attribute__((noreturn));

#endif
