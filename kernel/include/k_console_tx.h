/*
 * The interrupt-driven console transmitter every board's console glue
 * shares (boards/robocube/k_board_robocube.c on the DUART,
 * boards/stm32f405/k_board_stm32f405.c on a USART): the board gives three
 * small calls on its chip, this gives the writers it registers with
 * k_console_register.
 *
 * Threads put bytes into a ring; the board's transmit interrupt calls
 * k_console_tx_isr, which moves them to the transmitter while it is ready,
 * and the board switches its interrupt off when that says all is sent. A
 * thread that finds the ring full waits on a semaphore the interrupt posts;
 * a handler (or code before k_start) cannot wait, so its surplus is dropped
 * and counted. LF goes out as CR LF.
 */
#ifndef K_CONSOLE_TX_H
#define K_CONSOLE_TX_H

#include <stddef.h>
#include <stdint.h>

#include "kernel.h"

struct k_console_tx {
    struct k_ring ring;
    struct k_sem space;          /* posted by the interrupt when it took bytes */
    int lf_held;                 /* CR sent, LF still to send */
    uint32_t drops;
    int (*ready)(void);          /* the transmitter takes a byte now */
    void (*put)(uint8_t byte);   /* hand it one */
    void (*start)(void);         /* make its interrupt come (interrupts masked) */
};

/* Sets tx up on buf[0..size) (a power of two) with the board's calls.
 * K_OK, or K_EINVAL for a NULL argument or a bad size. */
int k_console_tx_init(struct k_console_tx *tx, uint8_t *buf, size_t size, int (*ready)(void),
                      void (*put)(uint8_t byte), void (*start)(void));

/* The board's transmit interrupt: feeds the transmitter and wakes a writer
 * waiting for room. Returns 1 when everything is sent (the board then masks
 * its transmit interrupt until start), else 0. */
int k_console_tx_isr(struct k_console_tx *tx);

/* The interrupt-driven writer: queues s[0..len), waiting for room where a
 * thread may wait; returns how many bytes were queued (the rest is counted
 * in drops). */
size_t k_console_tx_write(struct k_console_tx *tx, const char *s, size_t len);

/* Sends what is queued by polling, with interrupts masked by the caller:
 * the polled writer's first step, so a fault report comes out in order. */
void k_console_tx_drain(struct k_console_tx *tx);

#endif /* K_CONSOLE_TX_H */
