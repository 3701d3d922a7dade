/* What the STM32F405 board offers beyond the kernel's board interface. */
#ifndef BOARD_STM32F405_H
#define BOARD_STM32F405_H

#include <stdint.h>

/* Calls fn(byte) in the console's interrupt for every received byte
 * (NULL: reception off). */
void stm32f405_console_rx_attach(void (*fn)(uint8_t byte));

#endif /* BOARD_STM32F405_H */
