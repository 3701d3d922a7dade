/*
 * Philips PCF8591 8-bit A/D and D/A converter (I2C slave 1001 A2A1A0).
 * Write: first byte = control byte (bit 6 analog output enable, bits 5-4
 * input programming, bit 2 auto-increment, bits 1-0 channel), further bytes
 * = DAC data. Read: every byte sent is the result of the previous conversion,
 * and sending it starts the next conversion of the selected channel (so the
 * first byte after power-on is 0x80 and the first byte of a read is stale).
 * Analog values are host-set 8-bit codes (0..255 = AGND..VREF); differential
 * channels give the two's complement difference, clamped to -128..127.
 * Fault injection: host property "nack" = 1 makes the chip ignore its address
 * (a dead or unplugged chip); it survives a reset.
 */
#include "qemu/osdep.h"
#include "qemu/module.h"
#include "qapi/error.h"
#include "hw/i2c/i2c.h"
#include "robocube_io_devs.h"

#define CTRL_AOUT_ENABLE 0x40
#define CTRL_AUTOINC 0x04
#define RESULT_RESET 0x80

static unsigned mode_channels(uint8_t control)
{
    static const unsigned n[4] = { 4, 3, 3, 2 };
    return n[(control >> 4) & 3];
}

static uint8_t diff(uint8_t a, uint8_t b)
{
    int d = (int)a - (int)b;
    d = MIN(MAX(d, -128), 127);
    return (uint8_t)(int8_t)d;
}

static uint8_t convert(PCF8591State *s, unsigned ch)
{
    const uint8_t *in = s->ain;
    switch ((s->control >> 4) & 3) {
    case 0:                                         /* four single-ended */
        return in[ch];
    case 1:                                         /* three differential vs AIN3 */
        return diff(in[ch], in[3]);
    case 2:                                         /* AIN0, AIN1 single; AIN2-AIN3 */
        return ch < 2 ? in[ch] : diff(in[2], in[3]);
    default:                                        /* AIN0-AIN1, AIN2-AIN3 */
        return ch == 0 ? diff(in[0], in[1]) : diff(in[2], in[3]);
    }
}

static int pcf8591_event(I2CSlave *i2c, enum i2c_event event)
{
    PCF8591State *s = PCF8591(i2c);
    if (s->nack && (event == I2C_START_SEND || event == I2C_START_RECV)) {
        return -1;              /* address not acknowledged */
    }
    if (event == I2C_START_SEND) {
        s->expect_control = true;
    }
    return 0;
}

static int pcf8591_send(I2CSlave *i2c, uint8_t data)
{
    PCF8591State *s = PCF8591(i2c);
    if (s->expect_control) {
        s->expect_control = false;
        s->control = data & 0x77;  /* bits 7 and 3 must be 0 */
        s->channel = data & 3;
    } else {
        s->dac = data;
    }
    return 0;
}

static uint8_t pcf8591_recv(I2CSlave *i2c)
{
    PCF8591State *s = PCF8591(i2c);
    unsigned n = mode_channels(s->control);
    uint8_t out = s->result;
    unsigned ch = s->channel % n;

    s->result = convert(s, ch);
    if (s->control & CTRL_AUTOINC) {
        s->channel = (uint8_t)((ch + 1) % n);
    }
    return out;
}

static void pcf8591_reset(DeviceState *dev)
{
    PCF8591State *s = PCF8591(dev);
    s->control = 0;
    s->dac = 0;
    s->channel = 0;
    s->result = RESULT_RESET;
    s->expect_control = false;
    /* ain[] are external inputs: kept across reset. */
}

static int64_t prop_ain_get(void *opaque, int i)
{
    return PCF8591(opaque)->ain[i];
}

static bool prop_ain_set(void *opaque, int i, int64_t v, Error **errp)
{
    PCF8591(opaque)->ain[i] = (uint8_t)v;
    return true;
}

static int64_t prop_aout_get(void *opaque, int i)
{
    return PCF8591(opaque)->dac;
}

static int64_t prop_aout_en_get(void *opaque, int i)
{
    return (PCF8591(opaque)->control & CTRL_AOUT_ENABLE) != 0;
}

static int64_t prop_control_get(void *opaque, int i)
{
    return PCF8591(opaque)->control;
}

static int64_t prop_addr_get(void *opaque, int i)
{
    return I2C_SLAVE(opaque)->address;
}

static int64_t prop_nack_get(void *opaque, int i)
{
    return PCF8591(opaque)->nack;
}

static bool prop_nack_set(void *opaque, int i, int64_t v, Error **errp)
{
    PCF8591(opaque)->nack = v != 0;
    return true;
}

static void pcf8591_instance_init(Object *obj)
{
    for (int i = 0; i < 4; i++) {
        char name[8];
        snprintf(name, sizeof(name), "ain%d", i);
        rc_prop_add_int(obj, name, 0, 255, prop_ain_get, prop_ain_set, obj, i);
    }
    rc_prop_add_int(obj, "aout", 0, 255, prop_aout_get, NULL, obj, 0);
    rc_prop_add_int(obj, "aout-enabled", 0, 1, prop_aout_en_get, NULL, obj, 0);
    rc_prop_add_int(obj, "control", 0, 255, prop_control_get, NULL, obj, 0);
    rc_prop_add_int(obj, "i2c-address", 0, 127, prop_addr_get, NULL, obj, 0);
    rc_prop_add_int(obj, "nack", 0, 1, prop_nack_get, prop_nack_set, obj, 0);
}

static void pcf8591_class_init(ObjectClass *klass, void *data)
{
    DeviceClass *dc = DEVICE_CLASS(klass);
    I2CSlaveClass *k = I2C_SLAVE_CLASS(klass);
    dc->reset = pcf8591_reset;
    dc->desc = "PCF8591 8-bit A/D and D/A converter";
    k->event = pcf8591_event;
    k->send = pcf8591_send;
    k->recv = pcf8591_recv;
}

static const TypeInfo pcf8591_info = {
    .name = TYPE_PCF8591,
    .parent = TYPE_I2C_SLAVE,
    .instance_size = sizeof(PCF8591State),
    .instance_init = pcf8591_instance_init,
    .class_init = pcf8591_class_init,
};

static void pcf8591_register_types(void)
{
    type_register_static(&pcf8591_info);
}

type_init(pcf8591_register_types)
