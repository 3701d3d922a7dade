/*
 * The shared start-up of the firmware images (boards/include/board.h) and the
 * status LED (boards/include/board_led.h) on the STM32F405: the same interface
 * the RoboCube's boards/robocube/board.c and led.c give
 * (boards/common/board_common.c has what every board shares, board_armv7m.c what
 * the ARMv7-M boards do), so an image that uses only the kernel, the console
 * (output and line input, drivers/console_in.h) and the LED builds for
 * every board.
 */
#include "boards/include/board.h"
#include "boards/include/board_led.h"

#include "stm32f405.h"
#include "boards/stm32f405/board_stm32f405.h"

const char board_name[] = "STM32F405";
const char board_cpu_name[] = "Cortex-M4 (STM32F405)";
const uint32_t board_cpu_hz = STM32F405_CPU_HZ;
const uint32_t board_console_baud = CONSOLE_BAUD_STM32;

/* QEMU does not model the GPIO ports (writes are ignored): the LED's state
 * is kept here too, so led_is_on tells what the pin was set to. */
static bool led_on;

void led_init(void)
{
    RCC_AHB1ENR |= RCC_AHB1ENR_GPIOAEN;
    GPIO_MODER(GPIOA_BASE) = (GPIO_MODER(GPIOA_BASE) & ~(3u << (2u * LED_PIN))) |
                             (1u << (2u * LED_PIN)); /* output */
    led_set(false);
}

void led_set(bool on)
{
    led_on = on;
    GPIO_BSRR(GPIOA_BASE) = on ? (1u << LED_PIN) : (1u << (LED_PIN + 16u));
}

void led_toggle(void)
{
    led_set(!led_on);
}

bool led_is_on(void)
{
    return led_on;
}

int board_console_rx_start(board_console_rx_sink sink)
{
    return sink == NULL ? -1 : stm32f405_console_rx_attach(sink);
}

void board_console_rx_resume(void)
{
    stm32f405_console_rx_resume();
}
