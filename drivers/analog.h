/*
 * Analog inputs and outputs: the I/O board's PCF8591 converters (8-bit ADC
 * with four inputs and one DAC each).
 *
 * analog_init probes the chips as CubeOS did (facts 3.1): 7-bit addresses
 * 0x48..0x4F on bus A, then 0x48..0x4E on bus B; the chips found are numbered
 * in that order, chip n owning inputs 4n..4n+3 and output n. Up to 6 chips are
 * used (24 inputs, 6 outputs). Inputs are single-ended (0..255 = AGND..VREF).
 */
#ifndef DRIVERS_ANALOG_H
#define DRIVERS_ANALOG_H

#include <stdint.h>

#define ANALOG_CHIPS   6u
#define ANALOG_INPUTS  24u
#define ANALOG_OUTPUTS 6u

/* Probes the chips; returns how many were found (0..6), or a bus error. */
int analog_init(void);

/* Input ch (0..23) straight from the bus: 0..255, DRV_ERR_CHANNEL,
 * DRV_ERR_ABSENT (its chip was not found or does not answer), DRV_ERR_TIMEOUT. */
int analog_read(unsigned ch);

/* The four inputs of chip (0..5) in one auto-increment transaction. */
int analog_read_chip(unsigned chip, uint8_t out[4]);

/* Output ch (0..5) to v (0..255); enables the chip's analog output.
 * DRV_OK, DRV_ERR_CHANNEL, DRV_ERR_RANGE, DRV_ERR_ABSENT, DRV_ERR_TIMEOUT. */
int analog_write(unsigned ch, int v);

/* 1 if chip (0..5) was found by analog_init, 0 if not, DRV_ERR_CHANNEL. */
int analog_chip_present(unsigned chip);

/* For the sampler: the bus, address and control byte of a chip's
 * auto-increment read (write control, repeated START, read 5 bytes: the
 * first byte is the previous conversion and is dropped). *control points at
 * the driver's copy, which stays valid and follows analog_write (output
 * enable). DRV_OK, DRV_ERR_CHANNEL, DRV_ERR_ABSENT. */
#define ANALOG_CHIP_READ_LEN 5u
int analog_chip_location(unsigned chip, unsigned *bus, uint8_t *addr7, const uint8_t **control);
/* Changes whenever analog_init has probed again (the locations may differ). */
uint32_t analog_generation(void);

#endif /* DRIVERS_ANALOG_H */
