/*
 * The 16 binary I/O lines BIO0-15 on the I/O board's two PCF8574A expanders
 * (line 8c+k = chip c, pin k). Quasi-bidirectional: writing 1 releases the
 * line (weak pull-up), so it can be read as an input; writing 0 drives it low.
 * bio_init probes as CubeOS did (facts 3.2): 7-bit 0x38..0x3F on bus A, then
 * on bus B; the first two chips found are numbered 0 and 1.
 */
#ifndef DRIVERS_BIO_H
#define DRIVERS_BIO_H

#include <stdint.h>

#define BIO_CHIPS 2u
#define BIO_LINES 16u

/* Probes, sets every line to 1 (input). Returns the chips found (0..2). */
int bio_init(void);
/* Level of line (0..15): 0/1, DRV_ERR_CHANNEL, DRV_ERR_ABSENT, DRV_ERR_TIMEOUT. */
int bio_read(unsigned line);
/* Latch of line to v (0/1; 1 = input). DRV_OK, DRV_ERR_CHANNEL, DRV_ERR_RANGE, ... */
int bio_write(unsigned line, int v);
/* The 8 levels of chip (0..1) in one read: 0..255 or an error. */
int bio_read_chip(unsigned chip);
/* The latch shadow of all 16 lines (what was last written). */
uint16_t bio_latch(void);
/* 1 if chip was found, 0 if not, DRV_ERR_CHANNEL. */
int bio_chip_present(unsigned chip);
/* For the sampler: where chip lives. DRV_OK or DRV_ERR_ABSENT / DRV_ERR_CHANNEL. */
int bio_chip_location(unsigned chip, unsigned *bus, uint8_t *addr7);
/* Changes whenever bio_init has probed again. */
uint32_t bio_generation(void);

#endif /* DRIVERS_BIO_H */
