/*
 * The shared start-up of the firmware images (boards/include/board.h) and the
 * status LED (boards/include/board_led.h) on the MPS2 AN385: the interface
 * every board gives (boards/common/board_common.c has what all share).
 */
#include "boards/include/board.h"
#include "boards/include/board_led.h"

#include "k_board.h"
#include "armv7m.h"
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

void board_halt(const char *image, const char *why)
{
    board_say(image, why);
    armv7m_halt();
}

/* ARM semihosting SYS_EXIT (ADP_Stopped_ApplicationExit): QEMU, started with
 * -semihosting-config enable=on (make run does), ends the emulation; a board
 * without a debugger attached would fault on the BKPT, so it only comes
 * after the message, and the fault handler halts. */
void board_power_off(const char *image, const char *why)
{
    board_say(image, why);
    {
        /* set after the call above, which is free to use r0 and r1 */
        register uint32_t op __asm__("r0") = 0x18u;       /* SYS_EXIT */
        register uint32_t arg __asm__("r1") = 0x20026u;   /* ADP_Stopped_ApplicationExit */
        __asm__ __volatile__("bkpt 0xab" : : "r"(op), "r"(arg) : "memory");
    }
    armv7m_halt();
}

void board_start(const char *image)
{
    k_init();
    led_init();
    if (k_board_init() != 0)
        board_halt(image, "k_board_init failed: no console interrupt or no SysTick rate for K_TICK_HZ\n");
}

int board_console_rx_start(board_console_rx_sink sink)
{
    return sink == NULL ? -1 : mps2_an385_console_rx_attach(sink);
}

void board_console_rx_resume(void)
{
    mps2_an385_console_rx_resume();
}
