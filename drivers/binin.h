/*
 * The five binary inputs IP1-IP5 (header H7, pull-ups) on the DUART's input
 * port (register IP, the board's board_binary_in_reg; IP0 is the radio's
 * carrier detect and not one of them). A read is one register read: no bus, no waiting.
 */
#ifndef DRIVERS_BININ_H
#define DRIVERS_BININ_H

#include <stdint.h>

#define BININ_FIRST 1u
#define BININ_LAST  5u

int binin_init(void);
/* Level of IPn (n 1..5): 1 = high (open, pulled up), 0 = low; DRV_ERR_CHANNEL. */
int binin_read(unsigned n);
/* IP1..IP5 as bits 0..4. */
uint8_t binin_read_all(void);

#endif /* DRIVERS_BININ_H */
