/*
 * RoboCube I/O side of the machine: creates the TPU, the two PCF8584 I2C
 * controllers with the I/O board (6 x PCF8591, 2 x PCF8574A) on bus A, the
 * three motor models, the 16 fast binary outputs, and the host interface:
 * everything lives under the QOM path /machine/robocube-io (see emu/IO.md).
 */
#include "qemu/osdep.h"
#include "qemu/module.h"
#include "qapi/error.h"
#include "qapi/visitor.h"
#include "hw/qdev-core.h"
#include "hw/sysbus.h"
#include "hw/boards.h"
#include "sysemu/reset.h"
#include "robocube_io.h"
#include "robocube_io_devs.h"

#define TYPE_ROBOCUBE_IO "robocube-io"
OBJECT_DECLARE_SIMPLE_TYPE(RoboCubeIO, ROBOCUBE_IO)

/* I/O board strapping (the facts leave it open; CubeOS probes 0x90..0x9E and
 * 0x70..0x7E, 8-bit): PCF8591 n at 7-bit 0x48+n, PCF8574A n at 0x38+n, all
 * on bus A (jumpers J9/J10 select the bus). */
#define ADC_ADDR0 0x48
#define BIO_ADDR0 0x38
#define MOTOR_STEP_NS (1000 * 1000)     /* motor model integration step */

struct RoboCubeIO {
    Object parent_obj;
    MC68332TpuState *tpu;
    PCF8584State *i2c_a, *i2c_b;
    PCF8591State *adc[RC_ADCS];
    PCF8574AState *bio[RC_BIOS];
    RoboCubeMotor *motor[RC_MOTORS];
    MemoryRegion fastbin_mr;
    uint16_t fastbin;
    QEMUTimer *motor_timer;
};

/* ---- property helpers ---------------------------------------------------- */
typedef struct RcProp {
    RcPropGet get;
    RcPropSet set;
    void *opaque;
    int index;
    int64_t min, max;
} RcProp;

static void rc_prop_visit_get(Object *obj, Visitor *v, const char *name,
                              void *opaque, Error **errp)
{
    RcProp *p = opaque;
    int64_t value = p->get(p->opaque, p->index);
    visit_type_int(v, name, &value, errp);
}

static void rc_prop_visit_set(Object *obj, Visitor *v, const char *name,
                              void *opaque, Error **errp)
{
    RcProp *p = opaque;
    int64_t value;
    if (!visit_type_int(v, name, &value, errp)) {
        return;
    }
    if (value < p->min || value > p->max) {
        error_setg(errp, "%s: %" PRId64 " is out of range [%" PRId64 ", %" PRId64 "]",
                   name, value, p->min, p->max);
        return;
    }
    p->set(p->opaque, p->index, value, errp);
}

static void rc_prop_release(Object *obj, const char *name, void *opaque)
{
    g_free(opaque);
}

void rc_prop_add_int(Object *obj, const char *name, int64_t min, int64_t max,
                     RcPropGet get, RcPropSet set, void *opaque, int index)
{
    RcProp *p = g_new0(RcProp, 1);
    p->get = get;
    p->set = set;
    p->opaque = opaque;
    p->index = index;
    p->min = min;
    p->max = max;
    object_property_add(obj, name, "int", rc_prop_visit_get,
                        set ? rc_prop_visit_set : NULL, rc_prop_release, p);
}

/* ---- fast binary outputs: 74ABT16823 at 0xFE0000 -------------------------- */
static uint64_t fastbin_read(void *opaque, hwaddr off, unsigned size)
{
    /* The real register has no read path; the model returns the latch. */
    RoboCubeIO *io = opaque;
    if (size == 1) {
        return off ? (io->fastbin & 0xFF) : (io->fastbin >> 8);
    }
    return io->fastbin;
}

static void fastbin_write(void *opaque, hwaddr off, uint64_t val, unsigned size)
{
    RoboCubeIO *io = opaque;
    if (size == 1) {
        io->fastbin = off ? (uint16_t)((io->fastbin & 0xFF00) | (val & 0xFF))
                          : (uint16_t)((io->fastbin & 0x00FF) | ((val & 0xFF) << 8));
    } else {
        io->fastbin = (uint16_t)val;
    }
}

static const MemoryRegionOps fastbin_ops = {
    .read = fastbin_read,
    .write = fastbin_write,
    .endianness = DEVICE_BIG_ENDIAN,
    .valid = { .min_access_size = 1, .max_access_size = 2 },
    .impl = { .min_access_size = 1, .max_access_size = 2 },
};

/* ---- motors ------------------------------------------------------------- */
static void motor_tick(void *opaque)
{
    RoboCubeIO *io = opaque;
    int64_t now = qemu_clock_get_ns(QEMU_CLOCK_VIRTUAL);
    uint8_t opr = robocube_duart_opr();
    for (int m = 0; m < RC_MOTORS; m++) {
        robocube_motor_step(io->motor[m], now, opr);
    }
    timer_mod(io->motor_timer, now + MOTOR_STEP_NS);
}

static void robocube_io_reset(void *opaque)
{
    RoboCubeIO *io = opaque;
    io->fastbin = 0;
    for (int m = 0; m < RC_MOTORS; m++) {
        robocube_motor_reset(io->motor[m]);
    }
    timer_mod(io->motor_timer, qemu_clock_get_ns(QEMU_CLOCK_VIRTUAL) + MOTOR_STEP_NS);
}

/* ---- container properties ------------------------------------------------ */
static int64_t prop_fastbin_get(void *opaque, int i)
{
    return ROBOCUBE_IO(opaque)->fastbin;
}

static int64_t prop_bio_in_get(void *opaque, int i)
{
    RoboCubeIO *io = opaque;
    return io->bio[0]->ext | (io->bio[1]->ext << 8);
}

static bool prop_bio_in_set(void *opaque, int i, int64_t v, Error **errp)
{
    RoboCubeIO *io = opaque;
    return object_property_set_int(OBJECT(io->bio[0]), "input", v & 0xFF, errp) &&
           object_property_set_int(OBJECT(io->bio[1]), "input", (v >> 8) & 0xFF, errp);
}

static int64_t prop_bio_out_get(void *opaque, int i)
{
    RoboCubeIO *io = opaque;
    return io->bio[0]->latch | (io->bio[1]->latch << 8);
}

static int64_t prop_bio_pins_get(void *opaque, int i)
{
    RoboCubeIO *io = opaque;
    return pcf8574a_pins(io->bio[0]) | (pcf8574a_pins(io->bio[1]) << 8);
}

static int64_t prop_opr_get(void *opaque, int i)
{
    return robocube_duart_opr();
}

static PCF8584State *make_i2c(RoboCubeIO *io, const char *name, hwaddr base,
                              RoboCubeIntc *intc, int source, unsigned level,
                              MemoryRegion *sysmem)
{
    DeviceState *dev = qdev_new(TYPE_PCF8584);
    PCF8584State *s = PCF8584(dev);
    s->intc = intc;
    s->irq_source = source;
    s->irq_level = level;
    object_property_add_child(OBJECT(io), name, OBJECT(dev));
    sysbus_realize_and_unref(SYS_BUS_DEVICE(dev), &error_fatal);
    memory_region_add_subregion(sysmem, base, &s->iomem);
    return s;
}

void robocube_io_init(MemoryRegion *sysmem, RoboCubeIntc *intc)
{
    RoboCubeIO *io = ROBOCUBE_IO(object_new(TYPE_ROBOCUBE_IO));
    Object *o = OBJECT(io);
    DeviceState *dev;
    char name[32];

    object_property_add_child(qdev_get_machine(), "robocube-io", o);
    object_unref(o);

    dev = qdev_new(TYPE_MC68332_TPU);
    io->tpu = MC68332_TPU(dev);
    io->tpu->intc = intc;
    object_property_add_child(o, "tpu", OBJECT(dev));
    sysbus_realize_and_unref(SYS_BUS_DEVICE(dev), &error_fatal);
    memory_region_add_subregion(sysmem, RC_TPU_BASE, &io->tpu->iomem);
    tpu_add_host_properties(io->tpu);

    io->i2c_b = make_i2c(io, "i2c-b", RC_I2C_B_BASE, intc, RC_IRQ_I2C_B, 1, sysmem);
    io->i2c_a = make_i2c(io, "i2c-a", RC_I2C_A_BASE, intc, RC_IRQ_I2C_A, 3, sysmem);

    for (int i = 0; i < RC_ADCS; i++) {
        I2CSlave *slave = i2c_slave_new(TYPE_PCF8591, ADC_ADDR0 + i);
        snprintf(name, sizeof(name), "adc%d", i);
        object_property_add_child(o, name, OBJECT(slave));
        i2c_slave_realize_and_unref(slave, io->i2c_a->bus, &error_fatal);
        io->adc[i] = PCF8591(slave);
        for (int k = 0; k < 4; k++) {
            char target[8], alias[8];
            snprintf(target, sizeof(target), "ain%d", k);
            snprintf(alias, sizeof(alias), "ain%d", i * 4 + k);
            object_property_add_alias(o, alias, OBJECT(slave), target);
        }
        snprintf(name, sizeof(name), "aout%d", i);
        object_property_add_alias(o, name, OBJECT(slave), "aout");
        snprintf(name, sizeof(name), "aout%d-enabled", i);
        object_property_add_alias(o, name, OBJECT(slave), "aout-enabled");
    }
    for (int i = 0; i < RC_BIOS; i++) {
        I2CSlave *slave = i2c_slave_new(TYPE_PCF8574A, BIO_ADDR0 + i);
        snprintf(name, sizeof(name), "bio%d", i);
        object_property_add_child(o, name, OBJECT(slave));
        i2c_slave_realize_and_unref(slave, io->i2c_a->bus, &error_fatal);
        io->bio[i] = PCF8574A(slave);
    }
    for (int m = 0; m < RC_MOTORS; m++) {
        RoboCubeMotor *motor = ROBOCUBE_MOTOR(object_new(TYPE_ROBOCUBE_MOTOR));
        snprintf(name, sizeof(name), "motor%d", m);
        object_property_add_child(o, name, OBJECT(motor));
        object_unref(OBJECT(motor));
        robocube_motor_setup(motor, io->tpu, m);
        io->motor[m] = motor;
    }

    memory_region_init_io(&io->fastbin_mr, o, &fastbin_ops, io, "robocube-fastbin", 2);
    memory_region_add_subregion(sysmem, RC_FASTBIN_BASE, &io->fastbin_mr);

    rc_prop_add_int(o, "fastbin", 0, 0xFFFF, prop_fastbin_get, NULL, io, 0);
    rc_prop_add_int(o, "bio-in", 0, 0xFFFF, prop_bio_in_get, prop_bio_in_set, io, 0);
    rc_prop_add_int(o, "bio-out", 0, 0xFFFF, prop_bio_out_get, NULL, io, 0);
    rc_prop_add_int(o, "bio-pins", 0, 0xFFFF, prop_bio_pins_get, NULL, io, 0);
    rc_prop_add_int(o, "duart-opr", 0, 0xFF, prop_opr_get, NULL, io, 0);

    io->motor_timer = timer_new_ns(QEMU_CLOCK_VIRTUAL, motor_tick, io);
    qemu_register_reset(robocube_io_reset, io);
    robocube_io_reset(io);
}

static const TypeInfo robocube_io_info = {
    .name = TYPE_ROBOCUBE_IO,
    .parent = TYPE_OBJECT,
    .instance_size = sizeof(RoboCubeIO),
};

static void robocube_io_register_types(void)
{
    type_register_static(&robocube_io_info);
}

type_init(robocube_io_register_types)
