/* fault.c: panics and CPU exceptions end here: report through the log sink
 * (kernel/klog.h), then halt this core only (see panic.h). */
#include "kernel/panic.h"

#include <stdarg.h>

#include "kernel/arch.h"
#include "kernel/cpu.h"
#include "kernel/klog.h"
#include "kernel/machine.h"
#include "kernel/spinlock.h"
#include "proto/hostlink.h"
#include "proto/textfmt.h"

/* boot/virt/vectors.S passes the kind as a number. */
_Static_assert(FAULT_UNDEF == 1 && FAULT_PREFETCH_ABORT == 2 && FAULT_DATA_ABORT == 3 &&
                   FAULT_PANIC == 4,
               "boot/virt/vectors.S fault kinds differ from enum link_fault_kind");

/* Set once per core: a fault while reporting a fault halts silently
 * rather than recursing. */
static volatile uint8_t fault_in_progress[UNITS_MAX_CORES];

static const char *fault_kind_name(uint32_t kind)
{
    switch (kind) {
    case FAULT_UNDEF: return "undefined instruction";
    case FAULT_PREFETCH_ABORT: return "prefetch abort";
    case FAULT_DATA_ABORT: return "data abort";
    case FAULT_PANIC: return "panic";
    }
    return "unknown exception";
}

static void fault_report(uint32_t kind, uint32_t addr, uint32_t pc, uint32_t status,
                         const char *text)
{
    struct cpu *c = mycpu();
    uint32_t core = c ? c->core : machine_core_id();
    if (core >= UNITS_MAX_CORES || fault_in_progress[core])
        cpu_halt_forever();
    fault_in_progress[core] = 1;
    uint8_t role = unit_role_of_core(core);
    if (c) {
        c->halted = 1;
        /* Drop what this core held (the link's transmit lock among them):
         * it will never release them otherwise. */
        spin_release_all_mine();
    }

    uint8_t p[LINK_FAULT_FIXED_SIZE + KLOG_MAX];
    struct link_fault f = {(uint16_t)core, role, (uint8_t)kind, addr, pc, status};
    link_fault_put(p, &f);
    int n = fmt_snprintf((char *)p + LINK_FAULT_FIXED_SIZE, KLOG_MAX, "%s", text);
    if (n >= KLOG_MAX)
        n = KLOG_MAX - 1;
    klog_emit(LINK_FAULT, p, LINK_FAULT_FIXED_SIZE + (size_t)n);

    char line[KLOG_MAX];
    n = fmt_snprintf(line, sizeof line,
                     "core %u %s halted: %s at pc 0x%08x, address 0x%08x, status 0x%x: %s",
                     (unsigned)core, unit_role_name(role), fault_kind_name(kind),
                     (unsigned)pc, (unsigned)addr, (unsigned)status, text);
    if (n >= (int)sizeof line)
        n = (int)sizeof line - 1;
    klog_emit(LINK_LOG, line, (size_t)n);
}

void panic(const char *fmt, ...)
{
    arch_irq_disable();
    char text[KLOG_MAX];
    va_list ap;
    va_start(ap, fmt);
    fmt_vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    uint32_t pc = (uint32_t)(uintptr_t)__builtin_return_address(0);
    fault_report(FAULT_PANIC, 0, pc, 0, text);
    cpu_halt_forever();
}

void fault_from_exception(uint32_t kind, const uint32_t *regs, uint32_t pc, uint32_t spsr)
{
    uint32_t addr = pc, status = 0;
    arch_fault_info(kind, &addr, &status);
    char text[KLOG_MAX];
    /* regs: r0..r12 as the vector pushed them. */
    fmt_snprintf(text, sizeof text,
                 "%s in task '%s' (cpsr 0x%x, r0 0x%x, r1 0x%x, r2 0x%x)",
                 fault_kind_name(kind), mycpu() ? task_current_name() : "boot",
                 (unsigned)spsr, (unsigned)regs[0], (unsigned)regs[1],
                 (unsigned)regs[2]);
    fault_report(kind, addr, pc, status, text);
    cpu_halt_forever();
}
