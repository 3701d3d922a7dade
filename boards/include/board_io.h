/*
 * Where the board's I/O devices are, for the device drivers in drivers/: the
 * register blocks the drivers address, placed by the board's linker script
 * (the RoboCube's: boards/robocube/robocube.ld), so no driver names a chip's
 * address and an access compiles to the same instruction as a constant
 * address would; and the board's output lines. A board declares only the
 * devices it has: an image that uses a driver for a device its board lacks
 * does not link.
 */
#ifndef BOARD_IO_H
#define BOARD_IO_H

#include <stdint.h>

/* The I2C controllers (PCF8584, drivers/i2c.c): S0 at the block's first
 * byte, S1 at the next. Bus A is the I/O board's. */
extern volatile uint8_t board_i2c_a_regs[];
extern volatile uint8_t board_i2c_b_regs[];

/* The fast binary outputs' write-only 16-bit register (drivers/fastout.c). */
extern volatile uint16_t board_fast_out_reg;

/* The binary inputs' read-only port: bit n = input n (drivers/binin.c). */
extern volatile const uint8_t board_binary_in_reg;

/* The TPU (drivers/tpu.c): its registers (16-bit words from TPUMCR on) and
 * its parameter RAM (8 words a channel). */
extern volatile uint16_t board_tpu_regs[];
extern volatile uint16_t board_tpu_param[];
/* The TPU channels the board support holds for itself (bit n = TPn), which
 * the TPU driver refuses: none until the board takes one (the RoboCube's
 * fine time stamp takes TP15 when it starts, k_timestamp_start). */
extern volatile uint16_t board_tpu_reserved;

/* The board's output lines (the motors' direction bits, drivers/motor.c;
 * on the RoboCube the DUART's output port): bit n set = line n asserted.
 * Each call is one register write, so drivers owning different bits never
 * race; safe from threads and handlers. */
void board_outputs_assert(uint8_t bits);
void board_outputs_negate(uint8_t bits);

#endif /* BOARD_IO_H */
