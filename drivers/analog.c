/*
 * PCF8591 analog inputs/outputs (see analog.h). Control byte: bit 6 analog
 * output enable, bits 5-4 input mode (00: four single-ended), bit 2
 * auto-increment, bits 1-0 first channel. Every read byte is the previous
 * conversion, so a chip read is: write control (auto-increment from channel
 * 0), repeated START, read 5 bytes, drop the first.
 */
#include "drivers/analog.h"

#include "drivers/drv_err.h"
#include "drivers/i2c.h"

#define PCF8591_ADDR_FIRST 0x48u
#define PCF8591_ADDR_LAST_A 0x4Fu
#define PCF8591_ADDR_LAST_B 0x4Eu     /* CubeOS probed 7 slots on bus B */
#define PCF8591_AOUT_ENABLE 0x40u
#define PCF8591_AUTOINC 0x04u

struct analog_chip {
    uint8_t present;
    uint8_t bus;
    uint8_t addr7;
    uint8_t control;    /* for reads: auto-increment from AIN0, + output enable
                           once a write enabled the DAC (a read must not turn
                           it off: the control byte carries that bit) */
};

static struct analog_chip analog_chips[ANALOG_CHIPS];
static uint32_t analog_gen;

static int probe_bus(unsigned bus, uint8_t last, unsigned *n)
{
    for (uint8_t a = PCF8591_ADDR_FIRST; a <= last && *n < ANALOG_CHIPS; a++) {
        int rc = i2c_probe(bus, a);
        if (rc == DRV_OK) {
            analog_chips[*n] = (struct analog_chip){ .present = 1, .bus = (uint8_t)bus, .addr7 = a,
                                                     .control = PCF8591_AUTOINC };
            (*n)++;
        } else if (rc != DRV_ERR_ABSENT && rc != DRV_ERR_STATE) {
            return rc;
        }
    }
    return DRV_OK;
}

int analog_init(void)
{
    unsigned n = 0;
    int rc;
    analog_gen++;
    for (unsigned i = 0; i < ANALOG_CHIPS; i++)
        analog_chips[i] = (struct analog_chip){ 0 };
    rc = probe_bus(I2C_BUS_A, PCF8591_ADDR_LAST_A, &n);
    if (rc == DRV_OK)
        rc = probe_bus(I2C_BUS_B, PCF8591_ADDR_LAST_B, &n);
    return rc == DRV_OK ? (int)n : rc;
}

uint32_t analog_generation(void)
{
    return analog_gen;
}

int analog_chip_location(unsigned chip, unsigned *bus, uint8_t *addr7, const uint8_t **control)
{
    if (chip >= ANALOG_CHIPS)
        return DRV_ERR_CHANNEL;
    if (!analog_chips[chip].present)
        return DRV_ERR_ABSENT;
    *bus = analog_chips[chip].bus;
    *addr7 = analog_chips[chip].addr7;
    *control = &analog_chips[chip].control;
    return DRV_OK;
}

int analog_read_chip(unsigned chip, uint8_t out[4])
{
    unsigned bus;
    uint8_t addr, raw[ANALOG_CHIP_READ_LEN];
    const uint8_t *control;
    int rc = analog_chip_location(chip, &bus, &addr, &control);
    if (rc != DRV_OK)
        return rc;
    rc = i2c_transfer(bus, addr, control, 1, raw, sizeof(raw));
    if (rc != DRV_OK)
        return rc;
    for (unsigned i = 0; i < 4u; i++)
        out[i] = raw[i + 1u];
    return DRV_OK;
}

int analog_read(unsigned ch)
{
    uint8_t v[4];
    int rc;
    if (ch >= ANALOG_INPUTS)
        return DRV_ERR_CHANNEL;
    rc = analog_read_chip(ch / 4u, v);
    return rc == DRV_OK ? v[ch % 4u] : rc;
}

int analog_write(unsigned ch, int v)
{
    struct analog_chip *c;
    uint8_t msg[2];
    if (ch >= ANALOG_OUTPUTS)
        return DRV_ERR_CHANNEL;
    if (v < 0 || v > 255)
        return DRV_ERR_RANGE;
    c = &analog_chips[ch];
    if (!c->present)
        return DRV_ERR_ABSENT;
    c->control |= PCF8591_AOUT_ENABLE;
    msg[0] = c->control;
    msg[1] = (uint8_t)v;
    return i2c_transfer(c->bus, c->addr7, msg, sizeof(msg), NULL, 0);
}

int analog_chip_present(unsigned chip)
{
    if (chip >= ANALOG_CHIPS)
        return DRV_ERR_CHANNEL;
    return analog_chips[chip].present;
}
