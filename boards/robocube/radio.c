/*
 * The RoboCube's radio channel (boards/include/board_radio.h): the BiM-433
 * radio module on DUART channel A (facts 4.2). OP0 = RX select, OP1 = TX
 * select (through duart.h, which owns OPR), IP0 = carrier detect (low =
 * carrier). Interrupt-driven: RxRDYA hands every character to the network's
 * receiver, TxRDYA asks it for the next one.
 */
#include <stddef.h>

#include "boards/include/board_radio.h"
#include "boards/robocube/duart.h"
#include "boards/robocube/duart_console.h"
#include "boards/robocube/mc68681.h"

#define RADIO_OP_RX 0x01u     /* OP0 */
#define RADIO_OP_TX 0x02u     /* OP1 */
#define RADIO_IP_CD 0x01u     /* IP0, low while a carrier is heard */
#define RADIO_CT_PRELOAD 6u   /* counter/timer: 3.6864 MHz / (2 x 6) = 16 x 19200 */

static board_radio_rx_fn radio_rx;
static board_radio_tx_fn radio_tx;
static uint32_t radio_baud_rate;

int board_radio_carrier(void)
{
    return (DUART_REG(DUART_IP) & RADIO_IP_CD) == 0u;
}

static void radio_rx_chars(void)
{
    uint8_t sr;
    while (((sr = DUART_REG(DUART_SRA)) & DUART_SR_RXRDY) != 0u) {
        uint8_t b = DUART_REG(DUART_RBA);
        int overrun = (sr & DUART_SR_OVERRUN) != 0u;
        if (overrun)
            DUART_REG(DUART_CRA) = DUART_CR_RESET_ERROR;
        radio_rx(b, overrun);
    }
}

static void radio_tx_chars(void)
{
    while ((DUART_REG(DUART_SRA) & DUART_SR_TXRDY) != 0u) {
        int b = radio_tx();
        if (b >= 0) {
            DUART_REG(DUART_TBA) = (uint8_t)b;
            continue;
        }
        /* The last byte is out: back to receive. */
        duart_imr_update(0, DUART_INT_TXRDYA);
        board_outputs_negate(RADIO_OP_TX);
        board_outputs_assert(RADIO_OP_RX);
        break;
    }
}

static void radio_isr(uint8_t pending, void *arg)
{
    (void)arg;
    if ((pending & DUART_INT_RXRDYA) != 0u)
        radio_rx_chars();
    if ((pending & DUART_INT_TXRDYA) != 0u)
        radio_tx_chars();
}

/* 19200 baud (the radio's default, net/README.md) for channel A: baud-rate set 2 has it
 * (code 0xC) when the console chose set 2; set 1 has not, so then the
 * counter/timer clocks channel A (CSR code 0xD, preload 6: X1 / 12 =
 * 16 x 19200). Only if the counter/timer is taken as well, 9600 from set 1. */
static uint8_t radio_csr(void)
{
    radio_baud_rate = 19200u;
    if ((console_acr() & 0x80u) != 0u)
        return 0xCCu;
    if (duart_ct_baud_clock(RADIO_CT_PRELOAD) == 0)
        return 0xDDu;
    radio_baud_rate = 9600u;
    return 0xBBu;
}

uint32_t board_radio_baud(void)
{
    return radio_baud_rate;
}

int board_radio_start(board_radio_rx_fn rx, board_radio_tx_fn tx)
{
    radio_rx = rx;
    radio_tx = tx;
    DUART_REG(DUART_CRA) = DUART_CR_RESET_RX | DUART_CR_RX_DISABLE | DUART_CR_TX_DISABLE;
    DUART_REG(DUART_CRA) = DUART_CR_RESET_TX | DUART_CR_RX_DISABLE | DUART_CR_TX_DISABLE;
    DUART_REG(DUART_CRA) = DUART_CR_RESET_ERROR;
    DUART_REG(DUART_CRA) = DUART_CR_RESET_MR;
    DUART_REG(DUART_MRA) = 0x13u;       /* 8 data bits, no parity, RxRDY interrupt */
    DUART_REG(DUART_MRA) = 0x07u;       /* normal mode, 1 stop bit */
    DUART_REG(DUART_CSRA) = radio_csr();
    DUART_REG(DUART_CRA) = DUART_CR_RX_ENABLE | DUART_CR_TX_ENABLE;
    board_outputs_negate(RADIO_OP_TX);
    board_outputs_assert(RADIO_OP_RX);
    if (duart_irq_attach(DUART_INT_RXRDYA | DUART_INT_TXRDYA, radio_isr, NULL) != 0)
        return -1;
    duart_imr_update(DUART_INT_RXRDYA, 0);
    return 0;
}

void board_radio_transmit(void)
{
    board_outputs_negate(RADIO_OP_RX);
    board_outputs_assert(RADIO_OP_TX);
    duart_imr_update(DUART_INT_TXRDYA, 0);
}
