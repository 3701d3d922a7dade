/*
 * MC68332 Time Processor Unit: a functional model of the host interface
 * (registers at 0xFFFE00, parameter RAM at 0xFFFF00) and of the standard
 * mask-A time functions the RoboCube uses: PWM (9), DIO (8), ITC (0xA) and
 * QDEC (6). Not a model of the microengine: each function's effect on the
 * parameter RAM, the pins and CISR is computed directly when a host service
 * request, a pin edge or a period timer occurs. Parameter layouts follow the
 * Motorola TPU programming notes (see emu/IO.md).
 */
#include "qemu/osdep.h"
#include "qemu/log.h"
#include "qemu/module.h"
#include "qapi/error.h"
#include "hw/sysbus.h"
#include "robocube_io_devs.h"

/* Register offsets inside the 512-byte TPU block. */
enum {
    R_TPUMCR = 0x00, R_TCR = 0x02, R_DSCR = 0x04, R_DSSR = 0x06, R_TICR = 0x08,
    R_CIER = 0x0A, R_CFSR0 = 0x0C, R_HSQR0 = 0x14, R_HSRR0 = 0x18, R_CPR0 = 0x1C,
    R_CISR = 0x20, R_LR = 0x22, R_SGLR = 0x24, R_DCNR = 0x26, R_PRAM = 0x100,
};

#define TPUMCR_RESET 0x0080     /* SUPV = 1 */
#define PWM_MIN_PERIOD_NS 5000  /* timer floor: faster PWM still reports its duty */

/* Field accessors: CFSR 4 bits/channel (channel 0 in the low nibble of
 * CFSR3), HSQR/HSRR/CPR 2 bits/channel (channels 0-7 in the second register). */
static unsigned cfsr_fn(MC68332TpuState *s, int ch)
{
    return (s->cfsr[3 - ch / 4] >> ((ch % 4) * 4)) & 0xF;
}

static unsigned field2(const uint16_t *regs, int ch)
{
    return (regs[1 - ch / 8] >> ((ch % 8) * 2)) & 3;
}

static void set_field2(uint16_t *regs, int ch, unsigned v)
{
    int shift = (ch % 8) * 2;
    regs[1 - ch / 8] = (uint16_t)((regs[1 - ch / 8] & ~(3u << shift)) | (v << shift));
}

static uint64_t tcr1_hz(MC68332TpuState *s)
{
    unsigned tcr1p = (s->mcr >> 13) & 3;
    unsigned psck_div = (s->mcr & 0x0040) ? 4 : 32;
    /* TCR1 follows the system clock the SIM's SYNCR currently gives. */
    return robocube_sim_system_clock_hz() / psck_div / (1u << tcr1p);
}

uint16_t tpu_tcr1(MC68332TpuState *s)
{
    int64_t now = qemu_clock_get_ns(QEMU_CLOCK_VIRTUAL);
    return (uint16_t)muldiv64((uint64_t)(now - s->tcr1_epoch_ns), tcr1_hz(s),
                              NANOSECONDS_PER_SECOND);
}

static int64_t ticks_to_ns(MC68332TpuState *s, uint32_t ticks)
{
    return (int64_t)muldiv64(ticks, NANOSECONDS_PER_SECOND, tcr1_hz(s));
}

/* Channel interrupts: one request line to the board; channel 15 has the
 * highest priority inside the TPU, so its vector is presented first. */
static void tpu_update_irq(MC68332TpuState *s)
{
    uint16_t pending = s->cisr & s->cier;
    unsigned level = (s->ticr >> 8) & 7;
    if (pending && level) {
        int ch = 31 - clz32(pending);
        uint8_t vector = (uint8_t)((s->ticr & 0xF0) | ch);
        robocube_intc_request(s->intc, RC_IRQ_TPU, level, vector);
    } else {
        robocube_intc_request(s->intc, RC_IRQ_TPU, 0, 0);
    }
}

static void tpu_raise(MC68332TpuState *s, int ch)
{
    s->cisr |= 1u << ch;
    tpu_update_irq(s);
}

static bool channel_live(MC68332TpuState *s, int ch, unsigned fn)
{
    return s->ch[ch].init_fn == (int)fn && cfsr_fn(s, ch) == fn &&
           field2(s->cpr, ch) != 0;
}

/* ---- PWM (TPUPN17): param0 CHANNEL_CONTROL, 1 OLDRIS, 2 PWMHI, 3 PWMPER,
 * 4 PWMRIS. HSR 10 init, 01 immediate update. Interrupt at every rising edge. */
static void pwm_schedule(TpuChannel *c, int64_t from_ns)
{
    MC68332TpuState *s = c->tpu;
    int64_t period_ns = ticks_to_ns(s, c->pwm_period);
    if (c->pwm_period == 0) {
        timer_del(c->timer);
        return;
    }
    timer_mod(c->timer, from_ns + MAX(period_ns, PWM_MIN_PERIOD_NS));
}

static void pwm_rising_edge(TpuChannel *c, int64_t now_ns)
{
    MC68332TpuState *s = c->tpu;
    uint16_t *p = s->param[c->index];
    /* Normal update: new PWMHI/PWMPER take effect at the next period. */
    c->pwm_high = p[2];
    c->pwm_period = p[3];
    p[1] = p[4];                    /* OLDRIS <- previous rise time */
    p[4] = tpu_tcr1(s);             /* PWMRIS <- this rise time */
    c->pwm_rise_ns = now_ns;
    pwm_schedule(c, now_ns);
    tpu_raise(s, c->index);
}

static void pwm_init(TpuChannel *c, bool immediate_update)
{
    int64_t now = qemu_clock_get_ns(QEMU_CLOCK_VIRTUAL);
    MC68332TpuState *s = c->tpu;
    c->is_output = true;
    if (immediate_update && c->init_fn == TPU_FN_PWM) {
        c->pwm_high = s->param[c->index][2];
        c->pwm_period = s->param[c->index][3];
        pwm_schedule(c, c->pwm_rise_ns);
        return;
    }
    c->init_fn = TPU_FN_PWM;
    pwm_rising_edge(c, now);
}

unsigned tpu_pwm_duty(MC68332TpuState *s, int ch)
{
    TpuChannel *c = &s->ch[ch];
    if (!channel_live(s, ch, TPU_FN_PWM) || c->pwm_period == 0) {
        return 0;
    }
    if (c->pwm_high >= c->pwm_period) {
        return 10000;
    }
    return (unsigned)((uint32_t)c->pwm_high * 10000u / c->pwm_period);
}

static bool pwm_level(MC68332TpuState *s, TpuChannel *c)
{
    int64_t now = qemu_clock_get_ns(QEMU_CLOCK_VIRTUAL);
    if (c->pwm_period == 0 || c->pwm_high == 0) {
        return false;
    }
    if (c->pwm_high >= c->pwm_period) {
        return true;
    }
    return now - c->pwm_rise_ns < ticks_to_ns(s, c->pwm_high);
}

/* ---- DIO (TPUPN18): param0 CHANNEL_CONTROL, 1 PIN_LEVEL (history, newest
 * level in bit 15), 2 MATCH_RATE. HSR 01 drive high, 10 drive low, 11 init
 * as input. HSQ 00: record on transitions, 01: record every MATCH_RATE
 * ticks, 10: record on HSR 11 only. Interrupt on every input record. */
static void dio_record(TpuChannel *c, bool level)
{
    uint16_t *p = c->tpu->param[c->index];
    p[1] = (uint16_t)((p[1] >> 1) | (level ? 0x8000 : 0));
}

static void dio_schedule(TpuChannel *c)
{
    MC68332TpuState *s = c->tpu;
    uint16_t rate = s->param[c->index][2];
    if (field2(s->hsqr, c->index) == 1 && rate != 0) {
        int64_t now = qemu_clock_get_ns(QEMU_CLOCK_VIRTUAL);
        timer_mod(c->timer, now + MAX(ticks_to_ns(s, rate), PWM_MIN_PERIOD_NS));
    } else {
        timer_del(c->timer);
    }
}

/* ---- ITC (TPUPN08): param0 CHANNEL_CONTROL (PAC bits 4-2 select the edge),
 * 1 START_LINK/LINK_COUNT/BANK (links not modelled), 2 MAX_COUNT,
 * 3 TRANS_COUNT, 4 FINAL_TRANS_TIME, 5 LAST_TRANS_TIME. HSR 01 init.
 * HSQ bit 0: 0 single-shot, 1 continuous. */
static bool pac_matches(uint16_t channel_control, bool new_level)
{
    unsigned pac = (channel_control >> 2) & 7;
    switch (pac) {
    case 1: return new_level;           /* rising */
    case 2: return !new_level;          /* falling */
    case 3: return true;                /* either */
    default: return false;              /* 000 no detection, 1xx no change */
    }
}

static void itc_edge(TpuChannel *c, bool level)
{
    MC68332TpuState *s = c->tpu;
    uint16_t *p = s->param[c->index];
    if (!c->itc_armed || !pac_matches(p[0], level)) {
        return;
    }
    p[5] = tpu_tcr1(s);
    p[3]++;
    if (p[3] >= p[2]) {
        p[4] = p[5];
        if (field2(s->hsqr, c->index) & 1) {
            p[3] = 0;
        } else {
            c->itc_armed = false;
        }
        tpu_raise(s, c->index);
    }
}

/* ---- QDEC (TPUPN20): per channel param0 EDGE_TIME, 1 POSITION_COUNT
 * (both used in the channel EDGE_TIME_LSB_ADDR points to), 2 TCR1_VALUE,
 * 3 CHAN_PINSTATE, 4 CORR_PINSTATE_ADDR (byte address of the partner's
 * CHAN_PINSTATE), 5 EDGE_TIME_LSB_ADDR (byte address of the LSB of the
 * shared EDGE_TIME). The lower-numbered channel is the primary; the count
 * goes up when the primary leads the secondary. HSR 11 init, HSR 01 copies
 * TCR1 into TCR1_VALUE. No interrupts. */
static uint16_t *pram_word(MC68332TpuState *s, uint16_t byte_addr)
{
    return &s->param[(byte_addr >> 4) & 0xF][(byte_addr >> 1) & 7];
}

static void qdec_edge(TpuChannel *c, bool level)
{
    MC68332TpuState *s = c->tpu;
    uint16_t *p = s->param[c->index];
    int partner = (p[4] >> 4) & 0xF;
    bool partner_level = *pram_word(s, p[4]) != 0;
    uint16_t *edge_time = pram_word(s, (uint16_t)(p[5] & ~1u));
    uint16_t *count = pram_word(s, (uint16_t)((p[5] & ~1u) + 2));
    bool up;

    p[3] = level ? 1 : 0;
    if (c->index < partner) {
        up = level != partner_level;    /* primary edge */
    } else {
        up = level == partner_level;    /* secondary edge */
    }
    *count = (uint16_t)(*count + (up ? 1 : -1));
    *edge_time = tpu_tcr1(s);
}

/* ---- host service requests ---------------------------------------------- */
static void tpu_service(MC68332TpuState *s, int ch)
{
    TpuChannel *c = &s->ch[ch];
    unsigned hsr = field2(s->hsrr, ch);
    unsigned fn = cfsr_fn(s, ch);
    uint16_t *p = s->param[ch];

    if (hsr == 0 || field2(s->cpr, ch) == 0) {
        return;     /* disabled channels keep their request pending */
    }
    set_field2(s->hsrr, ch, 0);

    if (c->init_fn != (int)fn) {
        timer_del(c->timer);
        c->is_output = false;
        c->itc_armed = false;
    }
    switch (fn) {
    case TPU_FN_PWM:
        if (hsr == 2 || hsr == 1) {
            pwm_init(c, hsr == 1);
        }
        break;
    case TPU_FN_DIO:
        if (hsr == 1 || hsr == 2) {
            c->init_fn = TPU_FN_DIO;
            c->is_output = true;
            c->out_level = hsr == 1;
            dio_record(c, c->out_level);
            timer_del(c->timer);
        } else {
            c->init_fn = TPU_FN_DIO;
            c->is_output = false;
            dio_record(c, c->in_level);
            dio_schedule(c);
            tpu_raise(s, ch);
        }
        break;
    case TPU_FN_ITC:
        if (hsr == 1) {
            c->init_fn = TPU_FN_ITC;
            c->is_output = false;
            c->itc_armed = true;
            p[3] = 0;
        }
        break;
    case TPU_FN_QDEC:
        if (hsr == 3) {
            c->init_fn = TPU_FN_QDEC;
            c->is_output = false;
            p[3] = c->in_level ? 1 : 0;
        } else if (hsr == 1) {
            p[2] = tpu_tcr1(s);
        }
        break;
    default:
        qemu_log_mask(LOG_UNIMP, "mc68332-tpu: function %u on channel %d "
                      "not modelled (HSR %u ignored)\n", fn, ch, hsr);
        c->init_fn = (int)fn;
        break;
    }
}

static void tpu_service_all(MC68332TpuState *s)
{
    for (int ch = 0; ch < RC_TPU_CHANNELS; ch++) {
        tpu_service(s, ch);
    }
}

static void tpu_timer_cb(void *opaque)
{
    TpuChannel *c = opaque;
    MC68332TpuState *s = c->tpu;
    int64_t now = qemu_clock_get_ns(QEMU_CLOCK_VIRTUAL);
    if (channel_live(s, c->index, TPU_FN_PWM)) {
        pwm_rising_edge(c, now);
    } else if (channel_live(s, c->index, TPU_FN_DIO) && !c->is_output) {
        dio_record(c, c->in_level);
        dio_schedule(c);
        tpu_raise(s, c->index);
    }
}

void tpu_set_input(MC68332TpuState *s, int ch, bool level)
{
    TpuChannel *c = &s->ch[ch];
    if (c->in_level == level) {
        return;
    }
    c->in_level = level;
    if (c->is_output) {
        return;
    }
    if (channel_live(s, ch, TPU_FN_ITC)) {
        itc_edge(c, level);
    } else if (channel_live(s, ch, TPU_FN_QDEC)) {
        qdec_edge(c, level);
    } else if (channel_live(s, ch, TPU_FN_DIO) && field2(s->hsqr, ch) == 0) {
        dio_record(c, level);
        tpu_raise(s, ch);
    }
}

bool tpu_pin_level(MC68332TpuState *s, int ch)
{
    TpuChannel *c = &s->ch[ch];
    if (c->is_output && channel_live(s, ch, TPU_FN_PWM)) {
        return pwm_level(s, c);
    }
    if (c->is_output) {
        return c->out_level;
    }
    return c->in_level;
}

/* ---- register interface -------------------------------------------------- */
static uint16_t *tpu_reg(MC68332TpuState *s, hwaddr off)
{
    switch (off & ~1) {
    case R_TPUMCR: return &s->mcr;
    case R_TCR: return &s->tcr;
    case R_DSCR: return &s->dscr;
    case R_DSSR: return &s->dssr;
    case R_TICR: return &s->ticr;
    case R_CIER: return &s->cier;
    case R_CFSR0: case R_CFSR0 + 2: case R_CFSR0 + 4: case R_CFSR0 + 6:
        return &s->cfsr[((off & ~1) - R_CFSR0) / 2];
    case R_HSQR0: case R_HSQR0 + 2: return &s->hsqr[((off & ~1) - R_HSQR0) / 2];
    case R_HSRR0: case R_HSRR0 + 2: return &s->hsrr[((off & ~1) - R_HSRR0) / 2];
    case R_CPR0: case R_CPR0 + 2: return &s->cpr[((off & ~1) - R_CPR0) / 2];
    case R_CISR: return &s->cisr;
    case R_LR: return &s->lr;
    case R_SGLR: return &s->sglr;
    case R_DCNR: return &s->dcnr;
    default: return NULL;
    }
}

static uint64_t tpu_read(void *opaque, hwaddr off, unsigned size)
{
    MC68332TpuState *s = opaque;
    uint16_t word;
    if (off >= R_PRAM) {
        word = s->param[(off - R_PRAM) >> 4][((off - R_PRAM) >> 1) & 7];
    } else {
        uint16_t *r = tpu_reg(s, off);
        word = r ? *r : 0;
    }
    if (size == 1) {
        return (off & 1) ? (word & 0xFF) : (word >> 8);
    }
    return word;
}

static void tpu_write(void *opaque, hwaddr off, uint64_t val, unsigned size)
{
    MC68332TpuState *s = opaque;
    uint16_t old, word;
    uint16_t *r;

    if (off >= R_PRAM) {
        r = &s->param[(off - R_PRAM) >> 4][((off - R_PRAM) >> 1) & 7];
    } else {
        r = tpu_reg(s, off);
        if (!r) {
            qemu_log_mask(LOG_GUEST_ERROR, "mc68332-tpu: write to reserved "
                          "offset 0x%" HWADDR_PRIx "\n", off);
            return;
        }
    }
    old = *r;
    if (size == 1) {
        word = (off & 1) ? (uint16_t)((old & 0xFF00) | (val & 0xFF))
                         : (uint16_t)((old & 0x00FF) | ((val & 0xFF) << 8));
    } else {
        word = (uint16_t)val;
    }
    if (off >= R_PRAM) {
        *r = word;
        return;
    }
    switch (off & ~1) {
    case R_HSRR0:
    case R_HSRR0 + 2: {
        /* Writing 00 to a field does not cancel a pending request. */
        uint16_t merged = old;
        for (int f = 0; f < 8; f++) {
            unsigned v = (word >> (f * 2)) & 3;
            if (v) {
                merged = (uint16_t)((merged & ~(3u << (f * 2))) | (v << (f * 2)));
            }
        }
        *r = merged;
        tpu_service_all(s);
        break;
    }
    case R_CPR0:
    case R_CPR0 + 2:
        *r = word;
        tpu_service_all(s);
        break;
    case R_CISR:
        /* Flags are cleared by writing 0; writing 1 has no effect. */
        *r = old & word;
        tpu_update_irq(s);
        break;
    case R_TICR:
    case R_CIER:
        *r = word;
        tpu_update_irq(s);
        break;
    case R_TPUMCR:
        *r = word;
        break;
    default:
        *r = word;
        break;
    }
}

static const MemoryRegionOps tpu_ops = {
    .read = tpu_read,
    .write = tpu_write,
    .endianness = DEVICE_BIG_ENDIAN,
    .valid = { .min_access_size = 1, .max_access_size = 4 },
    .impl = { .min_access_size = 1, .max_access_size = 2 },
};

static void tpu_reset(DeviceState *dev)
{
    MC68332TpuState *s = MC68332_TPU(dev);
    s->mcr = TPUMCR_RESET;
    s->tcr = s->dscr = s->dssr = s->ticr = s->cier = s->cisr = 0;
    s->lr = s->sglr = s->dcnr = 0;
    memset(s->cfsr, 0, sizeof(s->cfsr));
    memset(s->hsqr, 0, sizeof(s->hsqr));
    memset(s->hsrr, 0, sizeof(s->hsrr));
    memset(s->cpr, 0, sizeof(s->cpr));
    s->tcr1_epoch_ns = qemu_clock_get_ns(QEMU_CLOCK_VIRTUAL);
    for (int ch = 0; ch < RC_TPU_CHANNELS; ch++) {
        TpuChannel *c = &s->ch[ch];
        timer_del(c->timer);
        c->init_fn = -1;
        c->is_output = false;
        c->out_level = false;
        c->itc_armed = false;
        c->pwm_high = c->pwm_period = 0;
        /* in_level is an external input: it survives a CPU reset. */
    }
    if (s->intc) {
        tpu_update_irq(s);
    }
}

static void tpu_realize(DeviceState *dev, Error **errp)
{
    MC68332TpuState *s = MC68332_TPU(dev);
    memory_region_init_io(&s->iomem, OBJECT(dev), &tpu_ops, s,
                          "mc68332-tpu", 0x200);
    sysbus_init_mmio(SYS_BUS_DEVICE(dev), &s->iomem);
    for (int ch = 0; ch < RC_TPU_CHANNELS; ch++) {
        s->ch[ch].tpu = s;
        s->ch[ch].index = ch;
        s->ch[ch].timer = timer_new_ns(QEMU_CLOCK_VIRTUAL, tpu_timer_cb, &s->ch[ch]);
    }
}

/* ---- host properties: pins, PWM outputs ----------------------------------- */
static int64_t prop_pins_get(void *opaque, int index)
{
    MC68332TpuState *s = opaque;
    int64_t v = 0;
    for (int ch = 0; ch < RC_TPU_CHANNELS; ch++) {
        v |= (int64_t)tpu_pin_level(s, ch) << ch;
    }
    return v;
}

static int64_t prop_inputs_get(void *opaque, int index)
{
    MC68332TpuState *s = opaque;
    int64_t v = 0;
    for (int ch = 0; ch < RC_TPU_CHANNELS; ch++) {
        v |= (int64_t)s->ch[ch].in_level << ch;
    }
    return v;
}

static bool prop_inputs_set(void *opaque, int index, int64_t value, Error **errp)
{
    MC68332TpuState *s = opaque;
    for (int ch = 0; ch < RC_TPU_CHANNELS; ch++) {
        tpu_set_input(s, ch, (value >> ch) & 1);
    }
    return true;
}

static int64_t prop_ch_pin_get(void *opaque, int ch)
{
    return tpu_pin_level(opaque, ch);
}

static bool prop_ch_pin_set(void *opaque, int ch, int64_t value, Error **errp)
{
    tpu_set_input(opaque, ch, value != 0);
    return true;
}

static int64_t prop_duty_get(void *opaque, int ch)
{
    return tpu_pwm_duty(opaque, ch);
}

static int64_t prop_high_get(void *opaque, int ch)
{
    MC68332TpuState *s = opaque;
    return channel_live(s, ch, TPU_FN_PWM) ? s->ch[ch].pwm_high : 0;
}

static int64_t prop_period_get(void *opaque, int ch)
{
    MC68332TpuState *s = opaque;
    return channel_live(s, ch, TPU_FN_PWM) ? s->ch[ch].pwm_period : 0;
}

static int64_t prop_tcr1_hz_get(void *opaque, int index)
{
    return (int64_t)tcr1_hz(opaque);
}

void tpu_add_host_properties(MC68332TpuState *s)
{
    Object *o = OBJECT(s);
    rc_prop_add_int(o, "pins", 0, 0xFFFF, prop_pins_get, NULL, s, 0);
    rc_prop_add_int(o, "inputs", 0, 0xFFFF, prop_inputs_get, prop_inputs_set, s, 0);
    rc_prop_add_int(o, "tcr1-hz", 0, INT64_MAX, prop_tcr1_hz_get, NULL, s, 0);
    for (int ch = 0; ch < RC_TPU_CHANNELS; ch++) {
        char name[32];
        snprintf(name, sizeof(name), "ch%d-pin", ch);
        rc_prop_add_int(o, name, 0, 1, prop_ch_pin_get, prop_ch_pin_set, s, ch);
        snprintf(name, sizeof(name), "ch%d-duty", ch);
        rc_prop_add_int(o, name, 0, 10000, prop_duty_get, NULL, s, ch);
        snprintf(name, sizeof(name), "ch%d-pwm-high", ch);
        rc_prop_add_int(o, name, 0, 0xFFFF, prop_high_get, NULL, s, ch);
        snprintf(name, sizeof(name), "ch%d-pwm-period", ch);
        rc_prop_add_int(o, name, 0, 0xFFFF, prop_period_get, NULL, s, ch);
    }
}

static void tpu_class_init(ObjectClass *klass, void *data)
{
    DeviceClass *dc = DEVICE_CLASS(klass);
    dc->realize = tpu_realize;
    dc->reset = tpu_reset;
    dc->desc = "MC68332 Time Processor Unit (functional model)";
    dc->user_creatable = false;
}

static const TypeInfo tpu_info = {
    .name = TYPE_MC68332_TPU,
    .parent = TYPE_SYS_BUS_DEVICE,
    .instance_size = sizeof(MC68332TpuState),
    .class_init = tpu_class_init,
};

static void tpu_register_types(void)
{
    type_register_static(&tpu_info);
}

type_init(tpu_register_types)
