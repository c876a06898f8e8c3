/* gic.c: GICv3 distributor, redistributors and CPU interface; the virt
 * board's doorbells (kernel/machine.h) are its SGIs. */
#include "drivers/virt/gic.h"

#include "drivers/virt/virt_cpu.h"
#include "drivers/virt/virt_map.h"
#include "drivers/virt/virt_sysreg.h"
#include "kernel/arch.h"
#include "kernel/cpu.h"
#include "kernel/irq.h"
#include "kernel/machine.h"
#include "kernel/panic.h"

/* Each core's redistributor (virtual address), found by gic_cpu_init. */
static uintptr_t gic_redist[UNITS_MAX_CORES];

/* Distributor registers (offsets from GICD_BASE). */
#define GICD_CTLR 0x0000u
#define GICD_CTLR_ENABLE_GRP0 (1u << 0)
#define GICD_CTLR_ENABLE_GRP1 (1u << 1)
#define GICD_CTLR_ARE (1u << 4)
#define GICD_CTLR_RWP (1u << 31)
#define GICD_IGROUPR(n) (0x0080u + 4u * (n))
#define GICD_ISENABLER(n) (0x0100u + 4u * (n))
#define GICD_IPRIORITYR(n) (0x0400u + (n)) /* byte per interrupt */
#define GICD_IROUTER(n) (0x6000u + 8u * (n))

/* Redistributor RD_base frame. */
#define GICR_WAKER 0x0014u
#define GICR_WAKER_PROCESSOR_SLEEP (1u << 1)
#define GICR_WAKER_CHILDREN_ASLEEP (1u << 2)
#define GICR_TYPER_LO 0x0008u
#define GICR_TYPER_HI 0x000Cu /* Affinity: Aff3.Aff2.Aff1.Aff0 */
#define GICR_TYPER_LAST (1u << 4)
/* SGI_base frame, 64 KiB after RD_base. */
#define GICR_SGI_OFFSET 0x10000u
#define GICR_IGROUPR0 (GICR_SGI_OFFSET + 0x0080u)
#define GICR_ISENABLER0 (GICR_SGI_OFFSET + 0x0100u)
#define GICR_ICPENDR0 (GICR_SGI_OFFSET + 0x0280u)
#define GICR_IPRIORITYR(n) (GICR_SGI_OFFSET + 0x0400u + (n))

#define GIC_PRIORITY_DEFAULT 0x80u
#define GIC_PMR_ALLOW_ALL 0xFFu
#define ICC_SRE_SRE (1u << 0)

/* ICC_SGI1R fields. */
#define SGI1R_TARGETS_SHIFT 0
#define SGI1R_AFF1_SHIFT 16
#define SGI1R_INTID_SHIFT 24

static void gicd_wait_rwp(void)
{
    while (mmio_read32(GICD_BASE + GICD_CTLR) & GICD_CTLR_RWP)
        ;
}

void gic_dist_init(void)
{
    mmio_write32(GICD_BASE + GICD_CTLR, 0);
    gicd_wait_rwp();
    mmio_write32(GICD_BASE + GICD_CTLR,
                 GICD_CTLR_ARE | GICD_CTLR_ENABLE_GRP1 | GICD_CTLR_ENABLE_GRP0);
    gicd_wait_rwp();
}

/* Walks one redistributor region looking for the frame whose affinity
 * matches mpidr; returns its address or 0. */
static uintptr_t gic_find_redist(uintptr_t base, uint32_t size, uint32_t aff)
{
    for (uint32_t off = 0; off + GICR_FRAME_SIZE <= size; off += GICR_FRAME_SIZE) {
        uintptr_t rd = base + off;
        if (mmio_read32(rd + GICR_TYPER_HI) == aff)
            return rd;
        if (mmio_read32(rd + GICR_TYPER_LO) & GICR_TYPER_LAST)
            break;
    }
    return 0;
}

void gic_cpu_init(void)
{
    struct cpu *c = mycpu();
    /* System registers first: from here this core can ring doorbells, so
     * a panic below still wakes the cores waiting for the link's lock. */
    arch_write_icc_sre(arch_read_icc_sre() | ICC_SRE_SRE);
    if (!(arch_read_icc_sre() & ICC_SRE_SRE))
        panic("gic: core %u cannot use the GICv3 system register interface",
              (unsigned)c->core);
    uint32_t aff = c->hwid & 0x00FFFFFFu;
    uintptr_t rd = gic_find_redist(GICR_LOW_BASE, GICR_LOW_SIZE, aff);
    if (!rd)
        rd = gic_find_redist(GICR_HIGH_VIRT, GICR_HIGH_SIZE, aff);
    if (!rd)
        panic("gic: no redistributor for core %u (mpidr 0x%x) in the low region "
              "or the high window", (unsigned)c->core, (unsigned)c->hwid);
    gic_redist[c->core] = rd;

    /* Wake the redistributor: clear ProcessorSleep, wait for the children. */
    mmio_write32(rd + GICR_WAKER,
                 mmio_read32(rd + GICR_WAKER) & ~GICR_WAKER_PROCESSOR_SLEEP);
    while (mmio_read32(rd + GICR_WAKER) & GICR_WAKER_CHILDREN_ASLEEP)
        ;
    /* SGIs and PPIs: Group 1, default priority; enable the doorbell, the
     * lock turn and the timer. */
    mmio_write32(rd + GICR_IGROUPR0, 0xFFFFFFFFu);
    for (uint32_t i = 0; i < 32; i += 4)
        mmio_write32(rd + GICR_IPRIORITYR(i), GIC_PRIORITY_DEFAULT * 0x01010101u);
    mmio_write32(rd + GICR_ISENABLER0,
                 (1u << SGI_DOORBELL) | (1u << SGI_LOCK_TURN) | (1u << TIMER_INTID));

    /* CPU interface: all priorities, Group 1 on. */
    arch_write_icc_pmr(GIC_PMR_ALLOW_ALL);
    arch_write_icc_bpr1(0);
    arch_write_icc_igrpen1(1);
    c->wake_ready = 1; /* a doorbell now wakes this core from WFI */
}

void gic_route_spi(uint32_t intid, uint32_t core)
{
    uint32_t mpidr = virt_mpidr_of_core(core);
    uint32_t reg = intid / 32, bit = 1u << (intid % 32);
    mmio_write32(GICD_BASE + GICD_IGROUPR(reg),
                 mmio_read32(GICD_BASE + GICD_IGROUPR(reg)) | bit);
    /* IPRIORITYR is byte-accessible; write the whole word to stay simple. */
    uint32_t pword = GICD_IPRIORITYR(intid & ~3u);
    uint32_t shift = (intid & 3u) * 8u;
    uint32_t p = mmio_read32(GICD_BASE + pword);
    p = (p & ~(0xFFu << shift)) | (GIC_PRIORITY_DEFAULT << shift);
    mmio_write32(GICD_BASE + pword, p);
    /* IROUTER: Aff1.Aff0 in the low word, Aff3 in the high word. */
    mmio_write32(GICD_BASE + GICD_IROUTER(intid), mpidr & 0x00FFFFFFu);
    mmio_write32(GICD_BASE + GICD_IROUTER(intid) + 4u, 0);
    mmio_write32(GICD_BASE + GICD_ISENABLER(reg), bit);
    gicd_wait_rwp();
}

void gic_send_sgi(uint32_t core, uint32_t intid)
{
    uint32_t mpidr = virt_mpidr_of_core(core);
    uint64_t v = ((uint64_t)(1u << (mpidr & 0xFu)) << SGI1R_TARGETS_SHIFT) |
                 ((uint64_t)((mpidr >> 8) & 0xFFu) << SGI1R_AFF1_SHIFT) |
                 ((uint64_t)(intid & 0xFu) << SGI1R_INTID_SHIFT);
    /* The DSB makes the shared-memory writes the doorbell announces visible
     * before the receiver can take the interrupt. */
    arch_dsb();
    arch_write_icc_sgi1r(v);
}

void gic_clear_sgi(uint32_t intid)
{
    mmio_write32(gic_redist[mycpu()->core] + GICR_ICPENDR0, 1u << intid);
}

/* The IRQ entry (boot/virt/vectors.S): acknowledges and handles every
 * pending interrupt. */
void gic_irq_dispatch(void)
{
    for (;;) {
        uint32_t id = arch_read_icc_iar1() & 0xFFFFFFu;
        if (id >= GIC_INTID_SPURIOUS_MIN)
            break;
        irq_handle(id, id != SGI_LOCK_TURN);
        arch_write_icc_eoir1(id);
    }
}

void machine_doorbell(uint32_t core)
{
    gic_send_sgi(core, SGI_DOORBELL);
}

void machine_lock_turn(uint32_t core)
{
    gic_send_sgi(core, SGI_LOCK_TURN);
}

void machine_lock_turn_seen(void)
{
    gic_clear_sgi(SGI_LOCK_TURN);
}
