/*
 * The RoboCube's green status LED on SIM port E bit 3 (PE3, the /RMC pin):
 * output 1 = LED on.
 */
#ifndef DRIVERS_LED_H
#define DRIVERS_LED_H

#include <stdbool.h>

/* Makes PE3 a general-purpose output (other port E pins keep their bus
 * functions) and switches the LED off. */
void led_init(void);
void led_set(bool on);
void led_toggle(void);
bool led_is_on(void);

#endif /* DRIVERS_LED_H */
