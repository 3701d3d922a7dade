/*
 * Binary inputs IP1-IP5 on the DUART input port (see binin.h), the board's
 * binary input port (board_binary_in_reg, boards/include/board_io.h). It is
 * read-only and has no side effects, so reading it needs no shared state with
 * the other DUART users; the input change interrupt (ACR/IMR) is not used.
 */
#include "drivers/binin.h"

#include "boards/include/board_io.h"
#include "drivers/drv_err.h"

#define DUART_IP_REG board_binary_in_reg
#define BININ_MASK 0x3Eu     /* IP1..IP5; IP0 is the radio's carrier detect */

int binin_init(void)
{
    return DRV_OK;
}

uint8_t binin_read_all(void)
{
    return (uint8_t)((DUART_IP_REG & BININ_MASK) >> 1);
}

int binin_read(unsigned n)
{
    if (n < BININ_FIRST || n > BININ_LAST)
        return DRV_ERR_CHANNEL;
    return (DUART_IP_REG >> n) & 1;
}
