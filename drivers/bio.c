/*
 * PCF8574A binary I/O (see bio.h): a one-byte write sets the latch, a
 * one-byte read returns the pin levels.
 */
#include "drivers/bio.h"

#include "drivers/drv_err.h"
#include "drivers/i2c.h"
#include "kernel.h"

#define PCF8574A_ADDR_FIRST 0x38u
#define PCF8574A_ADDR_LAST 0x3Fu

struct bio_chip {
    uint8_t present;
    uint8_t bus;
    uint8_t addr7;
    uint8_t latch;
};

static struct bio_chip bio_chips[BIO_CHIPS];
static uint32_t bio_gen;
/* Serialises the latch read-modify-write of bio_write between threads. */
static struct k_mutex bio_lock;
static uint8_t bio_lock_ready;

int bio_init(void)
{
    unsigned n = 0;
    if (!bio_lock_ready) {
        (void)k_mutex_init(&bio_lock);
        bio_lock_ready = 1;
    }
    bio_gen++;
    for (unsigned i = 0; i < BIO_CHIPS; i++)
        bio_chips[i] = (struct bio_chip){ 0 };
    for (unsigned bus = 0; bus < I2C_BUS_COUNT; bus++) {
        for (uint8_t a = PCF8574A_ADDR_FIRST; a <= PCF8574A_ADDR_LAST && n < BIO_CHIPS; a++) {
            uint8_t all_inputs = 0xFFu;
            int rc = i2c_probe(bus, a);
            if (rc == DRV_OK)   /* every line an input, as after power-on */
                rc = i2c_transfer(bus, a, &all_inputs, 1, NULL, 0);
            if (rc == DRV_OK) {
                bio_chips[n] = (struct bio_chip){ .present = 1, .bus = (uint8_t)bus,
                                                  .addr7 = a, .latch = 0xFFu };
                n++;
            } else if (rc != DRV_ERR_ABSENT && rc != DRV_ERR_STATE) {
                return rc;
            }
        }
    }
    return (int)n;
}

uint32_t bio_generation(void)
{
    return bio_gen;
}

int bio_chip_present(unsigned chip)
{
    if (chip >= BIO_CHIPS)
        return DRV_ERR_CHANNEL;
    return bio_chips[chip].present;
}

int bio_chip_location(unsigned chip, unsigned *bus, uint8_t *addr7)
{
    if (chip >= BIO_CHIPS)
        return DRV_ERR_CHANNEL;
    if (!bio_chips[chip].present)
        return DRV_ERR_ABSENT;
    *bus = bio_chips[chip].bus;
    *addr7 = bio_chips[chip].addr7;
    return DRV_OK;
}

int bio_read_chip(unsigned chip)
{
    unsigned bus;
    uint8_t addr, v;
    int rc = bio_chip_location(chip, &bus, &addr);
    if (rc != DRV_OK)
        return rc;
    rc = i2c_transfer(bus, addr, NULL, 0, &v, 1);
    return rc == DRV_OK ? v : rc;
}

int bio_read(unsigned line)
{
    int v;
    if (line >= BIO_LINES)
        return DRV_ERR_CHANNEL;
    v = bio_read_chip(line / 8u);
    return v < 0 ? v : (v >> (line % 8u)) & 1;
}

int bio_write(unsigned line, int v)
{
    struct bio_chip *c;
    uint8_t latch, bit;
    int rc;
    if (line >= BIO_LINES)
        return DRV_ERR_CHANNEL;
    if (v != 0 && v != 1)
        return DRV_ERR_RANGE;
    c = &bio_chips[line / 8u];
    if (!c->present)
        return DRV_ERR_ABSENT;
    bit = (uint8_t)(1u << (line % 8u));
    if (k_mutex_lock_ticks(&bio_lock, k_ms_to_ticks(1000u)) != K_OK)
        return DRV_ERR_BUSY;
    latch = v ? (uint8_t)(c->latch | bit) : (uint8_t)(c->latch & ~bit);
    rc = i2c_transfer(c->bus, c->addr7, &latch, 1, NULL, 0);
    if (rc == DRV_OK)
        c->latch = latch;
    (void)k_mutex_unlock(&bio_lock);
    return rc;
}

uint16_t bio_latch(void)
{
    return (uint16_t)(bio_chips[0].latch | (bio_chips[1].latch << 8));
}
