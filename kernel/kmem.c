/* kmem.c: per-unit-computer private memory (see kmem.h). */
#include "kernel/kmem.h"

#include "kernel/cpu.h"
#include "kernel/machine.h"
#include "kernel/panic.h"
#include "proto/hostlink.h"

void kmem_init(uint32_t core, uint32_t ncores)
{
    struct cpu *c = cpu_of(core);
    machine_private_memory(core, ncores, &c->mem_base, &c->mem_size);
    c->mem_used = 0;
    c->mem_high = 0;
}

void *kmem_alloc(size_t n, const char *what)
{
    struct cpu *c = mycpu();
    size_t need = (n + 7u) & ~(size_t)7u;
    if (need > c->mem_size - c->mem_used)
        panic("kmem: %s %u out of private memory for %s: asked %u bytes, %u of %u left",
              unit_role_name(c->role), (unsigned)c->core, what, (unsigned)n,
              (unsigned)(c->mem_size - c->mem_used), (unsigned)c->mem_size);
    void *p = c->mem_base + c->mem_used;
    c->mem_used += need;
    if (c->mem_used > c->mem_high)
        c->mem_high = c->mem_used;
    return p;
}

size_t kmem_size(void)
{
    return mycpu()->mem_size;
}

size_t kmem_high_water(void)
{
    return mycpu()->mem_high;
}

size_t kmem_mark(void)
{
    return mycpu()->mem_used;
}

void kmem_release_to(size_t mark)
{
    struct cpu *c = mycpu();
    if (mark > c->mem_used)
        panic("kmem: release to %u, but only %u bytes are in use", (unsigned)mark,
              (unsigned)c->mem_used);
    c->mem_used = mark;
}

size_t kmem_free(void)
{
    struct cpu *c = mycpu();
    return c->mem_size - c->mem_used;
}
