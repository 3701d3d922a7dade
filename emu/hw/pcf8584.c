/*
 * Philips PCF8584 I2C bus controller, master mode, on QEMU's I2C bus core.
 * Two byte registers: A0=0 (offset 0) = S0 data / S0' own address / S2 clock /
 * S3 interrupt vector chosen by the ES bits of S1; A0=1 (offset 1) = S1
 * control (write) / status (read). A byte transfer takes 9 SCL periods of
 * virtual time (SCL from S2); PIN drops to 0 when it is done and, with ENI
 * set, the controller requests its interrupt with the vector in S3.
 * Slave mode, arbitration loss, bus errors, long-distance mode: not modelled
 * (there is no other master on the bus).
 * Fault injection: the host property "bus-stuck" = 1 holds the bus low (as a
 * slave holding SDA would): BB reads busy, a START does nothing and a byte on
 * the wire never completes (PIN stays 1, no interrupt) until it is cleared.
 * Writing S1 with ES0 = 0 (the software reset drivers use) switches the serial
 * interface off and so releases the bus lines: an open transfer is dropped.
 */
#include "qemu/osdep.h"
#include "qemu/log.h"
#include "qemu/module.h"
#include "qapi/error.h"
#include "hw/sysbus.h"
#include "robocube_io_devs.h"

#define S1_PIN 0x80
#define S1_ES0 0x40
#define S1_ES1 0x20
#define S1_ES2 0x10
#define S1_ENI 0x08
#define S1_STA 0x04
#define S1_STO 0x02
#define S1_ACK 0x01

#define ST_LRB 0x08
#define ST_BB  0x01     /* 1 = bus free ("bus busy" is active low) */

/* S3 after reset in 68000 mode: the uninitialised-interrupt vector. */
#define PCF8584_S3_RESET 0x0F

static void pcf_update_irq(PCF8584State *s)
{
    bool active = (s->ctrl & S1_ENI) && (s->ctrl & S1_ES0) && !s->pin;
    robocube_intc_request(s->intc, s->irq_source, active ? s->irq_level : 0,
                          s->vector);
}

/* SCL frequency from S2 bits 1-0 (the clock input bits 4-2 are assumed to
 * match the real oscillator, as on the board: 12 MHz, S2 = 0x1C). */
static int64_t byte_time_ns(PCF8584State *s)
{
    static const uint32_t scl_hz[4] = { 90000, 45000, 11000, 1500 };
    return (int64_t)(9ULL * NANOSECONDS_PER_SECOND / scl_hz[s->clock & 3]);
}

static void pcf_begin_byte(PCF8584State *s)
{
    s->pin = true;
    pcf_update_irq(s);
    timer_mod(s->done_timer, qemu_clock_get_ns(QEMU_CLOCK_VIRTUAL) + byte_time_ns(s));
}

static void pcf_byte_done(void *opaque)
{
    PCF8584State *s = opaque;
    if (s->stuck) {
        /* SCL/SDA held low: the byte never ends; finish when released. */
        s->byte_stalled = true;
        return;
    }
    if (s->rx_pending) {
        s->s0 = s->rx_byte;
        s->rx_pending = false;
    }
    s->pin = false;
    pcf_update_irq(s);
}

static void pcf_close_transfer(PCF8584State *s)
{
    if (s->transfer_open) {
        i2c_end_transfer(s->bus);
        s->transfer_open = false;
    }
}

/* START (or repeated START) followed by the address byte a. */
static void pcf_send_address(PCF8584State *s, uint8_t a)
{
    uint8_t addr7 = a >> 1;
    bool is_recv = a & 1;
    int rc;

    if (s->transfer_open && addr7 != s->cur_addr) {
        pcf_close_transfer(s);
    }
    rc = i2c_start_transfer(s->bus, addr7, is_recv);
    if (rc) {
        /* QEMU ends a failed first start itself; a failed repeated start
         * leaves the old device list, so end it here. */
        if (s->transfer_open) {
            i2c_end_transfer(s->bus);
        }
        s->transfer_open = false;
    } else {
        s->transfer_open = true;
        s->cur_addr = addr7;
    }
    s->lrb = rc != 0;
    s->busy = true;
    s->receiving = is_recv;
    s->repstart_armed = false;
    s->s0 = a;
    pcf_begin_byte(s);
}

static void pcf_stop(PCF8584State *s)
{
    pcf_close_transfer(s);
    s->busy = false;
    s->receiving = false;
    s->repstart_armed = false;
    timer_del(s->done_timer);
    if (s->rx_pending) {
        s->s0 = s->rx_byte;
        s->rx_pending = false;
    }
    s->pin = true;
}

static uint8_t *pcf_select_reg0(PCF8584State *s)
{
    if (s->ctrl & S1_ES2) {
        return &s->vector;
    }
    if (s->ctrl & S1_ES1) {
        return &s->clock;
    }
    return (s->ctrl & S1_ES0) ? &s->s0 : &s->own_addr;
}

static uint64_t pcf_read(void *opaque, hwaddr off, unsigned size)
{
    PCF8584State *s = opaque;
    uint8_t *reg;
    uint8_t v;

    if (off & 1) {
        if (!(s->ctrl & S1_ES0)) {
            /* Serial interface off: S1 reads back the control bits. */
            return (s->pin ? S1_PIN : 0) | (s->ctrl & 0x7F);
        }
        return (s->pin ? S1_PIN : 0) | (s->lrb ? ST_LRB : 0) |
               (s->busy || s->stuck ? 0 : ST_BB);
    }
    reg = pcf_select_reg0(s);
    v = *reg;
    if (reg == &s->s0) {
        /* Reading S0 releases PIN; in master-receiver mode it also starts
         * the reception of the next byte, ACKed as the ACK bit says. */
        s->pin = true;
        if (s->busy && s->receiving && !s->repstart_armed) {
            s->rx_byte = s->transfer_open ? i2c_recv(s->bus) : 0xFF;
            if (!(s->ctrl & S1_ACK) && s->transfer_open) {
                i2c_nack(s->bus);
            }
            s->lrb = !(s->ctrl & S1_ACK);
            s->rx_pending = true;
            pcf_begin_byte(s);
        } else {
            pcf_update_irq(s);
        }
    }
    return v;
}

static void pcf_write_control(PCF8584State *s, uint8_t v)
{
    bool sta = v & S1_STA, sto = v & S1_STO;

    s->ctrl = v & (S1_ES0 | S1_ES1 | S1_ES2 | S1_ENI | S1_ACK);
    if (v & S1_PIN) {
        s->pin = true;
    }
    if (!(v & S1_ES0)) {
        /* Serial interface off: the controller lets go of the bus. */
        if (s->busy) {
            pcf_stop(s);
        }
        s->byte_stalled = false;
        pcf_update_irq(s);
        return;
    }
    if (sto) {
        if (s->busy) {
            pcf_stop(s);
        }
    }
    if (sta) {
        if (s->stuck && !s->busy) {
            /* The bus is not free: no START condition can be generated. */
            pcf_update_irq(s);
            return;
        }
        if (!s->busy) {
            pcf_send_address(s, s->s0);
            return;
        }
        /* Repeated START: sent together with the next address written to S0. */
        s->repstart_armed = true;
    }
    pcf_update_irq(s);
}

static void pcf_write(void *opaque, hwaddr off, uint64_t val, unsigned size)
{
    PCF8584State *s = opaque;
    uint8_t v = (uint8_t)val;
    uint8_t *reg;

    if (off & 1) {
        pcf_write_control(s, v);
        return;
    }
    reg = pcf_select_reg0(s);
    if (reg != &s->s0) {
        *reg = v;
        if (reg == &s->vector) {
            pcf_update_irq(s);
        }
        return;
    }
    if (s->repstart_armed) {
        pcf_send_address(s, v);
        return;
    }
    s->s0 = v;
    if (s->busy && !s->receiving) {
        int rc = s->transfer_open ? i2c_send(s->bus, v) : 1;
        s->lrb = rc != 0;
        pcf_begin_byte(s);
    } else {
        s->pin = true;
        pcf_update_irq(s);
    }
}

/* 8-bit port on D15-D8: the CPU32's dynamic bus sizing turns a word access
 * into two byte cycles (S0 side first), which the memory core reproduces by
 * splitting at impl.max_access_size. */
static const MemoryRegionOps pcf_ops = {
    .read = pcf_read,
    .write = pcf_write,
    .endianness = DEVICE_BIG_ENDIAN,
    .valid = { .min_access_size = 1, .max_access_size = 2 },
    .impl = { .min_access_size = 1, .max_access_size = 1 },
};

static void pcf_reset(DeviceState *dev)
{
    PCF8584State *s = PCF8584(dev);
    timer_del(s->done_timer);
    pcf_close_transfer(s);
    s->s0 = s->own_addr = s->clock = 0;
    s->vector = PCF8584_S3_RESET;
    s->ctrl = 0;
    s->pin = true;
    s->busy = s->lrb = s->receiving = s->repstart_armed = s->rx_pending = false;
    s->byte_stalled = false;    /* "bus-stuck" is external: kept across reset */
    if (s->intc) {
        pcf_update_irq(s);
    }
}

static void pcf_realize(DeviceState *dev, Error **errp)
{
    PCF8584State *s = PCF8584(dev);
    memory_region_init_io(&s->iomem, OBJECT(dev), &pcf_ops, s, "pcf8584", 2);
    sysbus_init_mmio(SYS_BUS_DEVICE(dev), &s->iomem);
    s->bus = i2c_init_bus(dev, "i2c");
    s->done_timer = timer_new_ns(QEMU_CLOCK_VIRTUAL, pcf_byte_done, s);
}

static int64_t prop_s3_get(void *opaque, int index)
{
    return PCF8584(opaque)->vector;
}

static int64_t prop_level_get(void *opaque, int index)
{
    return PCF8584(opaque)->irq_level;
}

static int64_t prop_stuck_get(void *opaque, int index)
{
    return PCF8584(opaque)->stuck;
}

static bool prop_stuck_set(void *opaque, int index, int64_t v, Error **errp)
{
    PCF8584State *s = PCF8584(opaque);
    s->stuck = v != 0;
    if (!s->stuck && s->byte_stalled) {
        s->byte_stalled = false;
        pcf_byte_done(s);       /* released: the stalled byte completes */
    }
    return true;
}

static void pcf_instance_init(Object *obj)
{
    rc_prop_add_int(obj, "bus-stuck", 0, 1, prop_stuck_get, prop_stuck_set, obj, 0);
    rc_prop_add_int(obj, "vector", 0, 255, prop_s3_get, NULL, obj, 0);
    rc_prop_add_int(obj, "irq-level", 0, 7, prop_level_get, NULL, obj, 0);
}

static void pcf_class_init(ObjectClass *klass, void *data)
{
    DeviceClass *dc = DEVICE_CLASS(klass);
    dc->realize = pcf_realize;
    dc->reset = pcf_reset;
    dc->desc = "PCF8584 I2C bus controller";
    dc->user_creatable = false;
}

static const TypeInfo pcf_info = {
    .name = TYPE_PCF8584,
    .parent = TYPE_SYS_BUS_DEVICE,
    .instance_size = sizeof(PCF8584State),
    .instance_init = pcf_instance_init,
    .class_init = pcf_class_init,
};

static void pcf_register_types(void)
{
    type_register_static(&pcf_info);
}

type_init(pcf_register_types)
