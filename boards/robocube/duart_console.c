/* Polled console on MC68681 channel B; see duart_console.h. */
#include "duart_console.h"

#include "boards/robocube/mc68681.h"
#include "kernel/lib/kprintf.h"

/*
 * Baud clock, chosen at build time by CONSOLE_BAUD (duart_console.h):
 * 38400 is the default (duart_console.h says why). 57600, the CubeOS
 * console rate, is not in the MC68681 baud-rate
 * tables, so the counter/timer in timer mode divides the 3.6864 MHz crystal
 * by 2 x CTUR:CTLR = 4 to 921600 Hz = 16 x 57600, and CSRB = 0xDD takes it
 * for receive and transmit. 38400 and 9600 come from baud-rate set 1
 * (ACR bit 7 = 0) and leave the counter/timer stopped.
 * ACR also holds channel A's baud-rate set; the radio driver keeps bit 7
 * and, only when the counter/timer is unused here (bits 6..4 = 000), takes it
 * as channel A's 19200 baud clock (duart_ct_baud_clock in duart.h).
 */
#if CONSOLE_BAUD == 57600
#define CONSOLE_ACR   0xE0u /* BRG set 2, counter/timer = timer from X1 */
#define CONSOLE_CT    2u    /* counter/timer preload */
#define CONSOLE_CSR   0xDDu /* RX and TX clock = counter/timer */
#elif CONSOLE_BAUD == 38400
#define CONSOLE_ACR   0x00u /* BRG set 1, counter/timer unused */
#define CONSOLE_CSR   0xCCu /* set 1 code 0xC = 38400 */
#elif CONSOLE_BAUD == 9600
#define CONSOLE_ACR   0x00u
#define CONSOLE_CSR   0xBBu /* set 1 code 0xB = 9600 */
#else
#error "CONSOLE_BAUD must be 57600, 38400 or 9600"
#endif
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
#ifdef CONSOLE_CT
    DUART_REG(DUART_CTUR) = (uint8_t)(CONSOLE_CT >> 8);
    DUART_REG(DUART_CTLR) = (uint8_t)(CONSOLE_CT & 0xFFu);
    (void)DUART_REG(DUART_START_COUNTER);
#endif
    DUART_REG(DUART_CSRB) = CONSOLE_CSR;
    DUART_REG(DUART_CRB) = DUART_CR_RX_ENABLE | DUART_CR_TX_ENABLE;
    kprintf_set_output(console_putc);
}

uint8_t console_acr(void)
{
    return CONSOLE_ACR;
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
