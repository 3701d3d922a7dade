/* The RoboCube's side of the board interface (boards/include/board.h):
 * start-up, halt, power-off and the console's receiver. What every board
 * shares is in boards/common/board_common.c. */
#include "boards/include/board.h"

#include "kernel/arch/cpu32/cpu.h"
#include "k_board.h"
#include "boards/include/board_led.h"
#include "boards/robocube/duart.h"
#include "boards/robocube/duart_console.h"
#include "boards/robocube/mc68332.h"
#include "boards/robocube/mc68681.h"

const char board_name[] = "RoboCube";
const char board_cpu_name[] = "MC68332";
const uint32_t board_cpu_hz = CPU_CLOCK_HZ;
const uint32_t board_console_baud = CONSOLE_BAUD;

void board_halt(const char *image, const char *why)
{
    board_say(image, why);
    cpu32_halt();
}

void board_power_off(const char *image, const char *why)
{
    board_say(image, why);
    for (;;) /* a level-7 interrupt would wake it: off again */
        __asm__ __volatile__("lpstop #0x2700" : : : "memory");
}

/* The console's receiver: DUART channel B's RxRDYB interrupt, attached
 * through the DUART's shared handler (boards/robocube/duart.h). */
#define RX_SR_ERRORS 0xF0u       /* received break, framing, parity, overrun */
static board_console_rx_sink rx_sink;

static void console_rx_isr(uint8_t pending, void *arg)
{
    (void)pending;
    (void)arg;
    for (;;) {
        uint8_t sr = DUART_REG(DUART_SRB);
        unsigned flags = 0;
        if ((sr & DUART_SR_RXRDY) == 0u)
            break;
        if ((sr & RX_SR_ERRORS) != 0u) {
            flags = (sr & DUART_SR_OVERRUN) != 0u ? BOARD_RX_OVERRUN : BOARD_RX_ERROR;
            DUART_REG(DUART_CRB) = DUART_CR_RESET_ERROR;
        }
        if (!rx_sink(DUART_REG(DUART_RBB), flags)) {
            /* full: the rest waits in the FIFO (the host, or the chip, holds it) */
            duart_imr_update(0, DUART_INT_RXRDYB);
            break;
        }
    }
}

int board_console_rx_start(board_console_rx_sink sink)
{
    if (sink == NULL || rx_sink != NULL)
        return -1;
    rx_sink = sink;
    if (duart_irq_attach(DUART_INT_RXRDYB, console_rx_isr, NULL) != 0) {
        rx_sink = NULL;
        return -1;
    }
    duart_imr_update(DUART_INT_RXRDYB, 0);
    return 0;
}

void board_console_rx_resume(void)
{
    duart_imr_update(DUART_INT_RXRDYB, 0);
}
