/* What the MPS2 AN385 board offers beyond the kernel's board interface. */
#ifndef BOARD_MPS2_AN385_H
#define BOARD_MPS2_AN385_H

#include "boards/include/board.h"

/* The console's receiver on UART0, the board's side of
 * board_console_rx_start (boards/include/board.h): calls fn(byte, flags) in
 * the console's interrupt for every received byte; when fn returns 0,
 * reception pauses (the next byte waits in the UART, which takes no more
 * from the line meanwhile) until mps2_an385_console_rx_resume. NULL:
 * reception off. Returns 0, or -1 when another receiver is attached. */
int mps2_an385_console_rx_attach(board_console_rx_sink fn);
void mps2_an385_console_rx_resume(void);

#endif /* BOARD_MPS2_AN385_H */
