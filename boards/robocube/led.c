/* The status LED (boards/include/board_led.h) on the RoboCube: the green LED
 * on SIM port E bit 3 (PE3, the /RMC pin), output 1 = LED on. Making PE3 a
 * general-purpose output leaves the other port E pins their bus functions. */
#include "boards/include/board_led.h"

#include "boards/robocube/mc68332.h"

#define LED_BIT 0x08u /* PE3 */

void led_init(void)
{
    SIM_PORTE = (uint8_t)(SIM_PORTE & ~LED_BIT);
    SIM_DDRE = (uint8_t)(SIM_DDRE | LED_BIT);
    SIM_PEPAR = (uint8_t)(SIM_PEPAR & ~LED_BIT);
}

void led_set(bool on)
{
    if (on) {
        SIM_PORTE = (uint8_t)(SIM_PORTE | LED_BIT);
    } else {
        SIM_PORTE = (uint8_t)(SIM_PORTE & ~LED_BIT);
    }
}

void led_toggle(void)
{
    SIM_PORTE = (uint8_t)(SIM_PORTE ^ LED_BIT);
}

bool led_is_on(void)
{
    return (SIM_PORTE & LED_BIT) != 0u;
}
