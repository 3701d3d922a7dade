/* Polled console on MC68681 channel B; see duart_console.h. */
#include "duart_console.h"

#include "drivers/mc68681.h"
#include "kernel/lib/kprintf.h"

/*
 * Baud clock: the counter/timer in timer mode divides the 3.6864 MHz
 * crystal; its output toggles every CTUR:CTLR clocks, so it runs at
 * 3686400 / (2 * 2) = 921600 Hz = 16 x 57600 baud, and CSRB = 0xDD picks it
 * for receive and transmit. ACR = 0xE0 also selects baud-rate set 2 for
 * the standard rates channel A (radio) uses.
 */
#define CONSOLE_ACR   0xE0u /* BRG set 2, counter/timer = timer from X1 */
#define CONSOLE_CT    2u    /* counter/timer preload */
#define CONSOLE_CSR   0xDDu /* RX and TX clock = counter/timer */
#define CONSOLE_MR1   0x13u /* no parity, 8 data bits, RxRDY interrupt, no RTS control */
#define CONSOLE_MR2   0x07u /* normal mode, 1 stop bit */

void console_init(void)
{
    DUART_REG(DUART_IMR) = 0x00;
    DUART_REG(DUART_CRB) = DUART_CR_RESET_RX | DUART_CR_RX_DISABLE | DUART_CR_TX_DISABLE;
    DUART_REG(DUART_CRB) = DUART_CR_RESET_TX | DUART_CR_RX_DISABLE | DUART_CR_TX_DISABLE;
    DUART_REG(DUART_CRB) = DUART_CR_RESET_ERROR;
    DUART_REG(DUART_CRB) = DUART_CR_RESET_MR;
    DUART_REG(DUART_MRB) = CONSOLE_MR1;
    DUART_REG(DUART_MRB) = CONSOLE_MR2;
    DUART_REG(DUART_ACR) = CONSOLE_ACR;
    DUART_REG(DUART_CTUR) = (uint8_t)(CONSOLE_CT >> 8);
    DUART_REG(DUART_CTLR) = (uint8_t)(CONSOLE_CT & 0xFFu);
    (void)DUART_REG(DUART_START_COUNTER);
    DUART_REG(DUART_CSRB) = CONSOLE_CSR;
    DUART_REG(DUART_CRB) = DUART_CR_RX_ENABLE | DUART_CR_TX_ENABLE;
    kprintf_set_output(console_putc);
}

static void console_send(char c)
{
    while ((DUART_REG(DUART_SRB) & DUART_SR_TXRDY) == 0) {
        /* the transmit holding register empties within one character time */
    }
    DUART_REG(DUART_TBB) = (uint8_t)c;
}

void console_putc(char c)
{
    if (c == '\n') {
        console_send('\r');
    }
    console_send(c);
}

void console_write(const char *s, size_t len)
{
    size_t i;
    for (i = 0; i < len; i++) {
        console_putc(s[i]);
    }
}

void console_puts(const char *s)
{
    while (*s != '\0') {
        console_putc(*s++);
    }
}

int console_getc_nonblocking(void)
{
    uint8_t status = DUART_REG(DUART_SRB);
    if (status & (DUART_SR_OVERRUN | 0x70u)) {
        /* overrun, parity or framing error: clear it, keep the character */
        DUART_REG(DUART_CRB) = DUART_CR_RESET_ERROR;
    }
    if ((status & DUART_SR_RXRDY) == 0) {
        return -1;
    }
    return DUART_REG(DUART_RBB);
}
