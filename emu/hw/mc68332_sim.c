/*
 * MC68332 System Integration Module (SIM) and TPURAM control block, as used
 * on the RoboCube board.
 *
 * Modelled: SIMCR, SYNCR (clock synthesiser, SLOCK reads 1 at once), RSR
 * (reset cause), port E (PE3 drives the board LED) and port F as plain
 * latches, SYPCR (write-once) with the software watchdog (SWSR 0x55/0xAA
 * service sequence, timeout resets the board with RSR.SW), the periodic
 * interrupt timer (PICR/PITR, virtual time, request cleared by the
 * interrupt-acknowledge cycle), the chip-select registers with the address
 * decoding of CSBOOT (flash) and CS0/CS1 (SRAM), and TPURAM placement by
 * TRAMBAR.  See emu/README.md for what is not modelled.
 */
#include "qemu/osdep.h"
#include "qemu/log.h"
#include "qemu/timer.h"
#include "qapi/error.h"
#include "qapi/visitor.h"
#include "hw/sysbus.h"
#include "hw/qdev-properties.h"
#include "sysemu/runstate.h"
#include "qom/object.h"
#include "robocube_board.h"
#include "robocube_io.h"

OBJECT_DECLARE_SIMPLE_TYPE(MC68332SimState, MC68332_SIM)

/* Byte offsets of the SIM registers from 0xFFFA00. */
enum {
    SIM_SIMCR = 0x00, SIM_SIMTR = 0x02, SIM_SYNCR = 0x04, SIM_RSR = 0x07,
    SIM_SIMTRE = 0x08, SIM_PORTE0 = 0x11, SIM_PORTE1 = 0x13, SIM_DDRE = 0x15,
    SIM_PEPAR = 0x17, SIM_PORTF0 = 0x19, SIM_PORTF1 = 0x1B, SIM_DDRF = 0x1D,
    SIM_PFPAR = 0x1F, SIM_SYPCR = 0x21, SIM_PICR = 0x22, SIM_PITR = 0x24,
    SIM_SWSR = 0x27, SIM_CSPAR0 = 0x44, SIM_CSPAR1 = 0x46, SIM_CSBARBT = 0x48,
    SIM_CSORBT = 0x4A, SIM_CSBAR0 = 0x4C, SIM_CS_END = 0x78,
    SIM_SIZE = 0x80,
};

/* RSR bits. */
#define RSR_EXT 0x80
#define RSR_POW 0x40
#define RSR_SW  0x20

/* SYPCR bits. */
#define SYPCR_SWE 0x80
#define SYPCR_SWP 0x40
#define SYPCR_SWT_SHIFT 4

/* SYNCR bits. */
#define SYNCR_W     0x8000
#define SYNCR_X     0x4000
#define SYNCR_Y_SHIFT 8
#define SYNCR_SLOCK 0x0008
#define SYNCR_WRITABLE 0xFF87   /* W, X, Y, EDIV, RSTEN, STSIM, STEXT */

#define TRAMBAR_RAMDS 0x0001
#define RC_TPURAM_CTRL_SIZE 0x40

/* Chip select index in cs_bar/cs_or: 0 = CSBOOT, 1 + n = CSn (n = 0..10). */
#define CS_BOOT 0
#define CS_N(n) (1 + (n))
#define CS_COUNT 12

struct MC68332SimState {
    SysBusDevice parent_obj;

    MemoryRegion iomem;
    MemoryRegion tram_ctrl;
    MemoryRegion tpuram;
    MemoryRegion flash_alias;
    MemoryRegion sram_alias;
    MemoryRegion *bus;
    MemoryRegion *flash;
    MemoryRegion *sram;
    RoboCubeIntc *intc;

    uint16_t simcr;
    uint16_t syncr;
    uint8_t rsr;
    uint8_t next_rsr;       /* cause recorded for the next reset */
    uint8_t porte, ddre, pepar;
    uint64_t led_changes;   /* LED on/off transitions since reset (host clock-free check) */
    uint8_t portf, ddrf, pfpar;
    uint8_t sypcr;
    bool sypcr_written;
    uint16_t picr, pitr;
    uint8_t swsr_last;      /* last byte written to SWSR */
    uint16_t cspar0, cspar1;
    uint16_t cs_bar[CS_COUNT], cs_or[CS_COUNT];
    uint16_t trammcr, trambar;
    bool trambar_written;

    /* Periodic interrupt timer: tick n of the current programming is due at
     * pit_start_ns + n * period, computed exactly from the 32.768 kHz clock. */
    QEMUTimer *pit_timer;
    int64_t pit_start_ns;
    uint64_t pit_ticks;
    bool pit_pending;
    uint64_t pit_count;     /* PIT expiries since reset (host diagnostics) */

    QEMUTimer *watchdog_timer;

    /* Where the chip selects currently put flash and SRAM (for QOM readback). */
    bool flash_mapped, sram_mapped, tpuram_mapped;
};

static MC68332SimState *the_sim;

static uint64_t sim_clock_hz(MC68332SimState *s)
{
    unsigned w = !!(s->syncr & SYNCR_W);
    unsigned x = !!(s->syncr & SYNCR_X);
    unsigned y = (s->syncr >> SYNCR_Y_SHIFT) & 0x3F;

    /* fsys = fref * 4 * (Y + 1) * 2^(2W + X) */
    return (uint64_t)RC_EXTAL_HZ * 4 * (y + 1) << (2 * w + x);
}

uint64_t robocube_sim_system_clock_hz(void)
{
    return the_sim ? sim_clock_hz(the_sim) : 0;
}

/* ---- chip selects ------------------------------------------------------ */

static uint32_t cs_block_size(uint16_t bar)
{
    static const uint32_t sizes[8] = {
        2 * KiB, 8 * KiB, 16 * KiB, 64 * KiB, 128 * KiB, 256 * KiB,
        512 * KiB, 1 * MiB,
    };
    return sizes[bar & 7];
}

static uint32_t cs_base(uint16_t bar)
{
    /* BAR bits 15..3 are A23..A11; a block is aligned to its own size. */
    return ((uint32_t)(bar & 0xFFF8) << 8) & ~(cs_block_size(bar) - 1);
}

/* CSPAR field of chip select @cs: 0x = discrete/alternate, 1x = chip select. */
static unsigned cs_pin_field(MC68332SimState *s, int cs)
{
    if (cs == CS_BOOT) {
        return s->cspar0 & 3;
    }
    if (cs <= CS_N(5)) {
        return (s->cspar0 >> (2 * (cs - CS_N(0)) + 2)) & 3;
    }
    return (s->cspar1 >> (2 * (cs - CS_N(6)))) & 3;
}

static bool cs_enabled(MC68332SimState *s, int cs)
{
    /* A chip select asserts when its pin is assigned to the chip-select
     * function (CSPAR field 1x; CSBOOT is always a chip select, its field
     * only chooses the port size) and its BYTE field in CSOR is not "off". */
    bool pin_is_cs = cs == CS_BOOT || (cs_pin_field(s, cs) & 2);

    return pin_is_cs && ((s->cs_or[cs] >> 13) & 3) != 0;
}

static void sim_place(MemoryRegion *mr, bool on, hwaddr addr, hwaddr offset,
                      uint64_t size)
{
    if (on) {
        memory_region_set_alias_offset(mr, offset);
        memory_region_set_size(mr, size);
        memory_region_set_address(mr, addr);
    }
    memory_region_set_enabled(mr, on);
}

static void sim_update_memory_map(MC68332SimState *s)
{
    uint32_t base;

    memory_region_transaction_begin();

    /* Flash on CSBOOT.  The flash chip decodes A1..A19 itself, so a block
     * at @base shows flash offset (base mod 1 MiB). */
    s->flash_mapped = cs_enabled(s, CS_BOOT);
    base = cs_base(s->cs_bar[CS_BOOT]);
    sim_place(&s->flash_alias, s->flash_mapped, base, base & (RC_FLASH_SIZE - 1),
              MIN(cs_block_size(s->cs_bar[CS_BOOT]), RC_FLASH_SIZE));

    /* SRAM: CS0 strobes the upper byte chip, CS1 the lower byte chip; the
     * board puts both on the same block, so SRAM appears when both chip
     * selects are enabled on the same base and block size. */
    s->sram_mapped = cs_enabled(s, CS_N(0)) && cs_enabled(s, CS_N(1)) &&
                     s->cs_bar[CS_N(0)] == s->cs_bar[CS_N(1)];
    base = cs_base(s->cs_bar[CS_N(0)]);
    sim_place(&s->sram_alias, s->sram_mapped, base, base & (RC_SRAM_SIZE - 1),
              MIN(cs_block_size(s->cs_bar[CS_N(0)]), RC_SRAM_SIZE));

    /* TPURAM: on-chip, above any external chip select. */
    s->tpuram_mapped = !(s->trambar & TRAMBAR_RAMDS);
    if (s->tpuram_mapped) {
        memory_region_set_address(&s->tpuram, ((uint32_t)s->trambar & 0xFFF8) << 8);
    }
    memory_region_set_enabled(&s->tpuram, s->tpuram_mapped);

    memory_region_transaction_commit();
}

/* ---- periodic interrupt timer ------------------------------------------ */

/* Period numerator in units of 1/32768 s: PITM * 4 (* 512 with PTP). */
static uint64_t pit_period_extal(MC68332SimState *s)
{
    uint64_t pitm = s->pitr & 0xFF;

    return pitm * 4 * ((s->pitr & 0x100) ? 512 : 1);
}

static int64_t pit_due_ns(MC68332SimState *s, uint64_t tick)
{
    return s->pit_start_ns +
           (int64_t)muldiv64(tick * pit_period_extal(s), NANOSECONDS_PER_SECOND,
                             RC_EXTAL_HZ);
}

static void pit_update_irq(MC68332SimState *s)
{
    unsigned level = (s->picr >> 8) & 7;

    robocube_intc_request(s->intc, RC_IRQ_PIT, s->pit_pending ? level : 0,
                          s->picr & 0xFF);
}

static void pit_restart(MC68332SimState *s)
{
    s->pit_start_ns = qemu_clock_get_ns(QEMU_CLOCK_VIRTUAL);
    s->pit_ticks = 0;
    if (pit_period_extal(s) == 0) {
        timer_del(s->pit_timer);
    } else {
        timer_mod(s->pit_timer, pit_due_ns(s, 1));
    }
}

static void pit_expire(void *opaque)
{
    MC68332SimState *s = opaque;

    s->pit_ticks++;
    s->pit_count++;
    /* The request stays asserted until the CPU acknowledges it; with
     * PIRQL = 0 the timer runs but requests nothing. */
    s->pit_pending = true;
    pit_update_irq(s);
    timer_mod(s->pit_timer, pit_due_ns(s, s->pit_ticks + 1));
}

static void pit_iack(void *opaque)
{
    MC68332SimState *s = opaque;

    s->pit_pending = false;
    pit_update_irq(s);
}

/* ---- software watchdog --------------------------------------------------- */

static void watchdog_restart(MC68332SimState *s)
{
    unsigned swt = (s->sypcr >> SYPCR_SWT_SHIFT) & 3;
    unsigned shift = ((s->sypcr & SYPCR_SWP) ? 18 : 9) + 2 * swt;

    if (!(s->sypcr & SYPCR_SWE)) {
        timer_del(s->watchdog_timer);
        return;
    }
    timer_mod(s->watchdog_timer, qemu_clock_get_ns(QEMU_CLOCK_VIRTUAL) +
              (int64_t)muldiv64(1ULL << shift, NANOSECONDS_PER_SECOND,
                                RC_EXTAL_HZ));
}

static void watchdog_expire(void *opaque)
{
    MC68332SimState *s = opaque;

    qemu_log_mask(LOG_GUEST_ERROR,
                  "mc68332-sim: software watchdog timeout, resetting\n");
    s->next_rsr = RSR_SW;
    qemu_system_reset_request(SHUTDOWN_CAUSE_GUEST_RESET);
}

/* ---- register access ---------------------------------------------------- */

static uint8_t hi(uint16_t v)
{
    return v >> 8;
}

static uint8_t lo(uint16_t v)
{
    return v & 0xFF;
}

static void set_hi(uint16_t *r, uint8_t v)
{
    *r = (*r & 0x00FF) | (v << 8);
}

static void set_lo(uint16_t *r, uint8_t v)
{
    *r = (*r & 0xFF00) | v;
}

static uint64_t sim_read(void *opaque, hwaddr addr, unsigned size)
{
    MC68332SimState *s = opaque;

    if (addr >= SIM_CSBARBT && addr < SIM_CS_END) {
        unsigned idx = (addr - SIM_CSBARBT) / 4;
        uint16_t v = ((addr - SIM_CSBARBT) & 2) ? s->cs_or[idx] : s->cs_bar[idx];
        return (addr & 1) ? lo(v) : hi(v);
    }
    switch (addr) {
    case SIM_SIMCR: return hi(s->simcr);
    case SIM_SIMCR + 1: return lo(s->simcr);
    case SIM_SYNCR: return hi(s->syncr);
    case SIM_SYNCR + 1: return lo(s->syncr) | SYNCR_SLOCK;
    case SIM_RSR: return s->rsr;
    case SIM_PORTE0: case SIM_PORTE1: return s->porte;
    case SIM_DDRE: return s->ddre;
    case SIM_PEPAR: return s->pepar;
    case SIM_PORTF0: case SIM_PORTF1: return s->portf;
    case SIM_DDRF: return s->ddrf;
    case SIM_PFPAR: return s->pfpar;
    case SIM_SYPCR: return s->sypcr;
    case SIM_PICR: return hi(s->picr);
    case SIM_PICR + 1: return lo(s->picr);
    case SIM_PITR: return hi(s->pitr);
    case SIM_PITR + 1: return lo(s->pitr);
    case SIM_CSPAR0: return hi(s->cspar0);
    case SIM_CSPAR0 + 1: return lo(s->cspar0);
    case SIM_CSPAR1: return hi(s->cspar1);
    case SIM_CSPAR1 + 1: return lo(s->cspar1);
    default:
        /* SWSR reads 0; test registers and reserved bytes read 0. */
        return 0;
    }
}

/* PE3 as output port pin driving the LED (high = on). */
static bool sim_led_on(MC68332SimState *s)
{
    return (s->ddre & 0x08) && !(s->pepar & 0x08) && (s->porte & 0x08);
}

/* A write to one of port E's registers; counts LED transitions so the host
 * can check blink rates against virtual time, not against its own clock. */
static void sim_port_e_write(MC68332SimState *s, uint8_t *reg, uint8_t v)
{
    bool was_on = sim_led_on(s);

    *reg = v;
    if (sim_led_on(s) != was_on) {
        s->led_changes++;
    }
}

static void sim_write(void *opaque, hwaddr addr, uint64_t value, unsigned size)
{
    MC68332SimState *s = opaque;
    uint8_t v = value;

    if (addr >= SIM_CSBARBT && addr < SIM_CS_END) {
        unsigned idx = (addr - SIM_CSBARBT) / 4;
        uint16_t *r = ((addr - SIM_CSBARBT) & 2) ? &s->cs_or[idx] : &s->cs_bar[idx];
        if (addr & 1) {
            set_lo(r, v);
        } else {
            set_hi(r, v);
        }
        sim_update_memory_map(s);
        return;
    }
    switch (addr) {
    case SIM_SIMCR:
        /* EXOFF, FRZSW, FRZBM, SHEN, SUPV writable; SLVEN read-only. */
        set_hi(&s->simcr, (v & 0xE3) | (hi(s->simcr) & 0x08));
        break;
    case SIM_SIMCR + 1:
        /* SUPV, MM (MM is accepted but the registers stay at 0xFFFxxx), IARB */
        set_lo(&s->simcr, v & 0xCF);
        break;
    case SIM_SYNCR:
        set_hi(&s->syncr, v);
        break;
    case SIM_SYNCR + 1:
        set_lo(&s->syncr, v & lo(SYNCR_WRITABLE));
        break;
    case SIM_PORTE0: case SIM_PORTE1: sim_port_e_write(s, &s->porte, v); break;
    case SIM_DDRE: sim_port_e_write(s, &s->ddre, v); break;
    case SIM_PEPAR: sim_port_e_write(s, &s->pepar, v); break;
    case SIM_PORTF0: case SIM_PORTF1: s->portf = v; break;
    case SIM_DDRF: s->ddrf = v; break;
    case SIM_PFPAR: s->pfpar = v; break;
    case SIM_SYPCR:
        /* Write-once after reset (MC68332 SIM): later writes are ignored. */
        if (!s->sypcr_written) {
            s->sypcr = v;
            s->sypcr_written = true;
            watchdog_restart(s);
        } else {
            qemu_log_mask(LOG_GUEST_ERROR,
                          "mc68332-sim: SYPCR is write-once, write ignored\n");
        }
        break;
    case SIM_PICR:
        set_hi(&s->picr, v & 0x07);
        pit_update_irq(s);
        break;
    case SIM_PICR + 1:
        set_lo(&s->picr, v);
        pit_update_irq(s);
        break;
    case SIM_PITR:
        set_hi(&s->pitr, v & 0x01);
        pit_restart(s);
        break;
    case SIM_PITR + 1:
        set_lo(&s->pitr, v);
        pit_restart(s);
        break;
    case SIM_SWSR:
        /* Service sequence: 0x55 then 0xAA restarts the watchdog. */
        if (v == 0xAA && s->swsr_last == 0x55) {
            watchdog_restart(s);
        }
        s->swsr_last = v;
        break;
    case SIM_CSPAR0:
        set_hi(&s->cspar0, v & 0x3F);
        sim_update_memory_map(s);
        break;
    case SIM_CSPAR0 + 1:
        set_lo(&s->cspar0, v);
        sim_update_memory_map(s);
        break;
    case SIM_CSPAR1:
        set_hi(&s->cspar1, v & 0x03);
        sim_update_memory_map(s);
        break;
    case SIM_CSPAR1 + 1:
        set_lo(&s->cspar1, v);
        sim_update_memory_map(s);
        break;
    default:
        qemu_log_mask(LOG_UNIMP, "mc68332-sim: write 0x%02x to +0x%02x ignored\n",
                      v, (unsigned)addr);
        break;
    }
}

static const MemoryRegionOps sim_ops = {
    .read = sim_read,
    .write = sim_write,
    .endianness = DEVICE_BIG_ENDIAN,
    .impl = { .min_access_size = 1, .max_access_size = 1 },
    .valid = { .min_access_size = 1, .max_access_size = 4 },
};

/* TPURAM module control: TRAMMCR +0, TRAMTST +2, TRAMBAR +4 (write-once). */
static uint64_t tram_read(void *opaque, hwaddr addr, unsigned size)
{
    MC68332SimState *s = opaque;

    switch (addr) {
    case 0: return hi(s->trammcr);
    case 1: return lo(s->trammcr);
    case 4: return hi(s->trambar);
    case 5: return lo(s->trambar);
    default: return 0;
    }
}

static void tram_write(void *opaque, hwaddr addr, uint64_t value, unsigned size)
{
    MC68332SimState *s = opaque;
    uint8_t v = value;

    switch (addr) {
    case 0:
        set_hi(&s->trammcr, v & 0x81);   /* STOP, RASP */
        break;
    case 4:
    case 5:
        if (s->trambar_written) {
            qemu_log_mask(LOG_GUEST_ERROR,
                          "mc68332-sim: TRAMBAR is write-once, write ignored\n");
            return;
        }
        if (addr == 4) {
            set_hi(&s->trambar, v);
        } else {
            set_lo(&s->trambar, v & 0xF9);
            /* The low byte completes a word write: lock the register. */
            s->trambar_written = true;
        }
        sim_update_memory_map(s);
        break;
    default:
        break;
    }
}

static const MemoryRegionOps tram_ops = {
    .read = tram_read,
    .write = tram_write,
    .endianness = DEVICE_BIG_ENDIAN,
    .impl = { .min_access_size = 1, .max_access_size = 1 },
    .valid = { .min_access_size = 1, .max_access_size = 4 },
};

/* ---- QOM --------------------------------------------------------------- */

static void sim_reset(DeviceState *dev)
{
    MC68332SimState *s = MC68332_SIM(dev);
    int i;

    s->rsr = s->next_rsr;
    s->next_rsr = RSR_EXT;  /* any later reset not caused by us is external */
    s->simcr = 0x00CF;
    s->syncr = 0x3F00;      /* W=0 X=0 Y=63: 8.388608 MHz from 32.768 kHz */
    s->porte = s->ddre = 0;
    s->led_changes = 0;
    s->pepar = 0xFF;
    s->portf = s->ddrf = 0;
    s->pfpar = 0xFF;
    s->sypcr = SYPCR_SWE;   /* watchdog on, 2^9 / 32768 Hz = 15.6 ms */
    s->sypcr_written = false;
    s->picr = 0x000F;
    s->pitr = 0x0000;
    s->swsr_last = 0;
    s->cspar0 = 0x3FFF;     /* data bus pulled up at reset: 16-bit chip selects */
    s->cspar1 = 0x03FF;
    for (i = 0; i < CS_COUNT; i++) {
        s->cs_bar[i] = 0;
        s->cs_or[i] = 0;
    }
    s->cs_bar[CS_BOOT] = 0x0007;    /* flash at 0, 1 MiB block */
    s->cs_or[CS_BOOT] = 0x7870;     /* both bytes, R/W, AS, 13 wait, S/U */
    s->trammcr = 0x0100;
    s->trambar = TRAMBAR_RAMDS;
    s->trambar_written = false;
    s->pit_pending = false;
    s->pit_count = 0;
    timer_del(s->pit_timer);
    pit_update_irq(s);
    watchdog_restart(s);
    sim_update_memory_map(s);
}

static void sim_get_u64(Object *obj, Visitor *v, const char *name,
                        void *opaque, Error **errp)
{
    MC68332SimState *s = MC68332_SIM(obj);
    uint64_t value;

    if (!strcmp(name, "system-clock-hz")) {
        value = sim_clock_hz(s);
    } else if (!strcmp(name, "pit-count")) {
        value = s->pit_count;
    } else if (!strcmp(name, "led-changes")) {
        value = s->led_changes;
    } else if (!strcmp(name, "virtual-time-ns")) {
        value = qemu_clock_get_ns(QEMU_CLOCK_VIRTUAL);
    } else if (!strcmp(name, "pit-period-ns")) {
        value = muldiv64(pit_period_extal(s), NANOSECONDS_PER_SECOND, RC_EXTAL_HZ);
    } else if (!strcmp(name, "pit-start-ns")) {
        value = s->pit_start_ns;     /* tick n is due at pit-start-ns + n * period */
    } else if (!strcmp(name, "flash-base")) {
        value = s->flash_mapped ? cs_base(s->cs_bar[CS_BOOT]) : UINT64_MAX;
    } else if (!strcmp(name, "sram-base")) {
        value = s->sram_mapped ? cs_base(s->cs_bar[CS_N(0)]) : UINT64_MAX;
    } else {
        value = s->tpuram_mapped ? ((uint32_t)s->trambar & 0xFFF8) << 8 : UINT64_MAX;
    }
    visit_type_uint64(v, name, &value, errp);
}

static bool sim_get_led(Object *obj, Error **errp)
{
    return sim_led_on(MC68332_SIM(obj));
}

static void sim_init(Object *obj)
{
    MC68332SimState *s = MC68332_SIM(obj);

    memory_region_init_io(&s->iomem, obj, &sim_ops, s, "mc68332.sim", SIM_SIZE);
    memory_region_init_io(&s->tram_ctrl, obj, &tram_ops, s, "mc68332.tpuram-ctrl",
                          RC_TPURAM_CTRL_SIZE);
    memory_region_init_ram(&s->tpuram, obj, "mc68332.tpuram", RC_TPURAM_SIZE,
                           &error_fatal);
    s->pit_timer = timer_new_ns(QEMU_CLOCK_VIRTUAL, pit_expire, s);
    s->watchdog_timer = timer_new_ns(QEMU_CLOCK_VIRTUAL, watchdog_expire, s);
    s->next_rsr = RSR_POW | RSR_EXT;
    object_property_add_bool(obj, "led", sim_get_led, NULL);
    object_property_add(obj, "system-clock-hz", "uint64", sim_get_u64, NULL, NULL, NULL);
    object_property_add(obj, "pit-count", "uint64", sim_get_u64, NULL, NULL, NULL);
    object_property_add(obj, "led-changes", "uint64", sim_get_u64, NULL, NULL, NULL);
    object_property_add(obj, "virtual-time-ns", "uint64", sim_get_u64, NULL, NULL, NULL);
    object_property_add(obj, "pit-period-ns", "uint64", sim_get_u64, NULL, NULL, NULL);
    object_property_add(obj, "pit-start-ns", "uint64", sim_get_u64, NULL, NULL, NULL);
    object_property_add(obj, "flash-base", "uint64", sim_get_u64, NULL, NULL, NULL);
    object_property_add(obj, "sram-base", "uint64", sim_get_u64, NULL, NULL, NULL);
    object_property_add(obj, "tpuram-base", "uint64", sim_get_u64, NULL, NULL, NULL);
    object_property_add_uint8_ptr(obj, "rsr", &s->rsr, OBJ_PROP_FLAG_READ);
    object_property_add_uint8_ptr(obj, "porte", &s->porte, OBJ_PROP_FLAG_READ);
}

static void sim_class_init(ObjectClass *klass, void *data)
{
    DeviceClass *dc = DEVICE_CLASS(klass);

    dc->reset = sim_reset;
    dc->desc = "MC68332 system integration module";
}

static const TypeInfo sim_info = {
    .name = TYPE_MC68332_SIM,
    .parent = TYPE_SYS_BUS_DEVICE,
    .instance_size = sizeof(MC68332SimState),
    .instance_init = sim_init,
    .class_init = sim_class_init,
};

static void sim_register_types(void)
{
    type_register_static(&sim_info);
}

type_init(sim_register_types)

DeviceState *mc68332_sim_create(MemoryRegion *bus, MemoryRegion *flash,
                                MemoryRegion *sram, RoboCubeIntc *intc)
{
    DeviceState *dev = qdev_new(TYPE_MC68332_SIM);
    MC68332SimState *s = MC68332_SIM(dev);

    s->bus = bus;
    s->flash = flash;
    s->sram = sram;
    s->intc = intc;
    the_sim = s;
    /* Created once, moved and resized by the chip-select decoding. */
    memory_region_init_alias(&s->flash_alias, OBJECT(s), "robocube.flash-cs",
                             flash, 0, RC_FLASH_SIZE);
    memory_region_init_alias(&s->sram_alias, OBJECT(s), "robocube.sram-cs",
                             sram, 0, RC_SRAM_SIZE);
    memory_region_set_enabled(&s->flash_alias, false);
    memory_region_set_enabled(&s->sram_alias, false);
    memory_region_set_enabled(&s->tpuram, false);
    memory_region_add_subregion_overlap(bus, 0, &s->flash_alias, 2);
    memory_region_add_subregion_overlap(bus, 0, &s->sram_alias, 1);
    memory_region_add_subregion_overlap(bus, 0, &s->tpuram, 3);
    robocube_intc_set_iack_handler(intc, RC_IRQ_PIT, pit_iack, s);
    object_property_add_child(qdev_get_machine(), "sim", OBJECT(dev));
    sysbus_realize_and_unref(SYS_BUS_DEVICE(dev), &error_fatal);
    memory_region_add_subregion_overlap(bus, RC_SIM_BASE, &s->iomem, 4);
    memory_region_add_subregion_overlap(bus, RC_TPURAM_CTRL_BASE, &s->tram_ctrl, 4);
    return dev;
}
