/*
 * Board I/O bring-up: both I2C buses, the analog and binary I/O chips, the
 * binary inputs, the fast outputs (cleared). Prints the boot report: which
 * I2C devices answered on which bus, and what the drivers made of them.
 */
#ifndef DRIVERS_BOARD_IO_H
#define DRIVERS_BOARD_IO_H

/* Call from a thread after k_start. Returns DRV_OK, or the first error of a
 * controller that failed (the other parts are still brought up). */
int board_io_init(void);

#endif /* DRIVERS_BOARD_IO_H */
