/*
 * The board's status LED, which every board has one of (the RoboCube's green
 * LED on SIM port E bit 3, boards/robocube/led.c; the STM32F405's PA10,
 * boards/stm32f405/board.c).
 */
#ifndef BOARD_LED_H
#define BOARD_LED_H

#include <stdbool.h>

/* Makes the LED's pin an output (the pin's other functions on the chip are
 * left as they are) and switches the LED off. */
void led_init(void);
void led_set(bool on);
void led_toggle(void);
bool led_is_on(void);

#endif /* BOARD_LED_H */
