/*
 * The 16 fast binary outputs: a write-only 16-bit register, the board's
 * board_fast_out_reg (0xFE0000, a 74ABT16823, on the v2 board). The driver keeps a shadow, so single bits can
 * be changed and the state read back.
 */
#ifndef DRIVERS_FASTOUT_H
#define DRIVERS_FASTOUT_H

#include <stdint.h>

#define FASTOUT_BITS 16u

/* Bit (0..15) to v (0/1): DRV_OK, DRV_ERR_CHANNEL, DRV_ERR_RANGE. */
int fastout_write(unsigned bit, int v);
/* All 16 at once. DRV_OK. */
int fastout_write_all(uint16_t v);
/* The shadow: what the register holds. */
uint16_t fastout_get(void);

#endif /* DRIVERS_FASTOUT_H */
