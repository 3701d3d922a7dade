/*
 * Philips PCF8574A remote 8-bit I/O expander (I2C slave 0111 A2A1A0).
 * Quasi-bidirectional pins: a written 1 is a weak pull-up the outside may pull
 * low, a written 0 drives the pin low. Reading returns the pin levels.
 * /INT is asserted when a pin level changes from the one seen at the last
 * read or write and released by the next read or write; the board routes it
 * to /IRQ2 through a jumper, which this model leaves open (state visible as a
 * host property only).
 * Fault injection: host property "nack" = 1 makes the chip ignore its address.
 */
#include "qemu/osdep.h"
#include "qemu/module.h"
#include "qapi/error.h"
#include "hw/i2c/i2c.h"
#include "robocube_io_devs.h"

uint8_t pcf8574a_pins(PCF8574AState *s)
{
    return s->latch & s->ext;
}

static int pcf8574a_event(I2CSlave *i2c, enum i2c_event event)
{
    PCF8574AState *s = PCF8574A(i2c);
    if (s->nack && (event == I2C_START_SEND || event == I2C_START_RECV)) {
        return -1;              /* address not acknowledged */
    }
    return 0;
}

static int pcf8574a_send(I2CSlave *i2c, uint8_t data)
{
    PCF8574AState *s = PCF8574A(i2c);
    s->latch = data;
    s->last_seen = pcf8574a_pins(s);
    s->int_pending = false;
    return 0;
}

static uint8_t pcf8574a_recv(I2CSlave *i2c)
{
    PCF8574AState *s = PCF8574A(i2c);
    s->last_seen = pcf8574a_pins(s);
    s->int_pending = false;
    return s->last_seen;
}

static void pcf8574a_reset(DeviceState *dev)
{
    PCF8574AState *s = PCF8574A(dev);
    s->latch = 0xFF;
    s->last_seen = pcf8574a_pins(s);
    s->int_pending = false;
}

static int64_t prop_input_get(void *opaque, int i)
{
    return PCF8574A(opaque)->ext;
}

static bool prop_input_set(void *opaque, int i, int64_t v, Error **errp)
{
    PCF8574AState *s = PCF8574A(opaque);
    s->ext = (uint8_t)v;
    if (pcf8574a_pins(s) != s->last_seen) {
        s->int_pending = true;
    }
    return true;
}

static int64_t prop_output_get(void *opaque, int i)
{
    return PCF8574A(opaque)->latch;
}

static int64_t prop_pins_get(void *opaque, int i)
{
    return pcf8574a_pins(PCF8574A(opaque));
}

static int64_t prop_int_get(void *opaque, int i)
{
    return PCF8574A(opaque)->int_pending;
}

static int64_t prop_addr_get(void *opaque, int i)
{
    return I2C_SLAVE(opaque)->address;
}

static int64_t prop_nack_get(void *opaque, int i)
{
    return PCF8574A(opaque)->nack;
}

static bool prop_nack_set(void *opaque, int i, int64_t v, Error **errp)
{
    PCF8574A(opaque)->nack = v != 0;
    return true;
}

static void pcf8574a_instance_init(Object *obj)
{
    PCF8574AState *s = PCF8574A(obj);
    s->ext = 0xFF;      /* nothing connected: the pull-ups win */
    rc_prop_add_int(obj, "input", 0, 255, prop_input_get, prop_input_set, obj, 0);
    rc_prop_add_int(obj, "output", 0, 255, prop_output_get, NULL, obj, 0);
    rc_prop_add_int(obj, "pins", 0, 255, prop_pins_get, NULL, obj, 0);
    rc_prop_add_int(obj, "int", 0, 1, prop_int_get, NULL, obj, 0);
    rc_prop_add_int(obj, "i2c-address", 0, 127, prop_addr_get, NULL, obj, 0);
    rc_prop_add_int(obj, "nack", 0, 1, prop_nack_get, prop_nack_set, obj, 0);
}

static void pcf8574a_class_init(ObjectClass *klass, void *data)
{
    DeviceClass *dc = DEVICE_CLASS(klass);
    I2CSlaveClass *k = I2C_SLAVE_CLASS(klass);
    dc->reset = pcf8574a_reset;
    dc->desc = "PCF8574A 8-bit quasi-bidirectional I/O expander";
    k->event = pcf8574a_event;
    k->send = pcf8574a_send;
    k->recv = pcf8574a_recv;
}

static const TypeInfo pcf8574a_info = {
    .name = TYPE_PCF8574A,
    .parent = TYPE_I2C_SLAVE,
    .instance_size = sizeof(PCF8574AState),
    .instance_init = pcf8574a_instance_init,
    .class_init = pcf8574a_class_init,
};

static void pcf8574a_register_types(void)
{
    type_register_static(&pcf8574a_info);
}

type_init(pcf8574a_register_types)
