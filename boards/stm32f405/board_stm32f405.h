/* What the STM32F405 board offers beyond the kernel's board interface. */
#ifndef BOARD_STM32F405_H
#define BOARD_STM32F405_H

#include <stdint.h>

#include "boards/include/board.h"

/* The console's receiver on USART1, the board's side of
 * board_console_rx_start (boards/include/board.h): calls fn(byte, flags) in the
 * console's interrupt for every received byte; when fn returns 0, reception
 * pauses (the next byte waits in the USART) until
 * stm32f405_console_rx_resume. NULL: reception off. Returns 0, or -1 when
 * another receiver is attached. */
int stm32f405_console_rx_attach(board_console_rx_sink fn);
void stm32f405_console_rx_resume(void);

/* The simulated part of the board's ports (ports.c). */
struct stm32f405_sim_io {
    uint16_t bio;            /* PDL_BIO_OUT writes, PDL_BIO_IN reads */
    uint8_t binin;           /* PDL_BINARY_IN reads */
    int32_t motor[4];
    int32_t analog_out[8];
    int32_t fast_out[8];
    uint32_t adc_no_eoc;     /* ADC conversions read without EOC (QEMU's model) */
};
extern struct stm32f405_sim_io stm32f405_sim_io;
#endif /* BOARD_STM32F405_H */
