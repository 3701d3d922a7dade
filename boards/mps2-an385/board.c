/*
 * The shared start-up of the firmware images (boards/include/board.h) and the
 * status LED (boards/include/board_led.h) on the MPS2 AN385: the interface
 * every board gives (boards/common/board_common.c has what every board shares,
 * board_armv7m.c what the ARMv7-M boards do).
 */
#include "boards/include/board.h"
#include "boards/include/board_led.h"

#include "mps2_an385.h"
#include "boards/mps2-an385/board_mps2_an385.h"

const char board_name[] = "MPS2 AN385";
const char board_cpu_name[] = "Cortex-M3 (MPS2 AN385)";
const uint32_t board_cpu_hz = MPS2_AN385_CPU_HZ;
const uint32_t board_console_baud = 115200u;

/* LED0 of the FPGA's LED register, which QEMU models: it reads back what was written. */
void led_init(void)
{
    led_set(false);
}

void led_set(bool on)
{
    FPGAIO_LED = on ? (FPGAIO_LED | 1u) : (FPGAIO_LED & ~1u);
}

void led_toggle(void)
{
    FPGAIO_LED ^= 1u;
}

bool led_is_on(void)
{
    return (FPGAIO_LED & 1u) != 0u;
}

int board_console_rx_start(board_console_rx_sink sink)
{
    return sink == NULL ? -1 : mps2_an385_console_rx_attach(sink);
}

void board_console_rx_resume(void)
{
    mps2_an385_console_rx_resume();
}
