/*
 * The start-up of a program written as an ordinary C program: apps/NAME/main.c
 * with int main(void). The board (kernel, LED, console, tick) is started here,
 * then main runs as a thread and may use the C library, the kernel and the
 * drivers as any thread does. When main returns, its thread ends and the
 * program's other threads (a PDL program's cycle thread, say) go on, as in
 * Zephyr; exit() or abort() halts the board.
 *
 * apps/apps.mk links this file into every image whose app.mk does not say
 * NAME_BOOT := self (an image whose main starts the board itself).
 */
#include <stddef.h>
#include <stdint.h>

#include "kernel.h"
#include "boards/include/board.h"

#ifndef FW_IMAGE_NAME
#define FW_IMAGE_NAME "main"
#endif
/* The main thread's stack: room for printf with floating point (newlib's
 * vfprintf) and a program's own frames; the worst case is checked by
 * make check-stack. */
#ifndef BOARD_MAIN_STACK
#define BOARD_MAIN_STACK 4096u
#endif
/* Below the B-scheduler thread (K_PRIO_APP_MAX), above the lowest application
 * priority, so a program can have threads of its own on either side. */
#define BOARD_MAIN_PRIO (K_PRIO_APP_MIN + 1u)

int main(void);
void firmware_entry(void);

static struct k_thread main_thread;
K_STACK_DEFINE(main_stack, BOARD_MAIN_STACK);
static int main_status;

static void *main_thread_entry(void *arg)
{
    (void)arg;
    main_status = main();
    if (main_status != 0)
        k_printf("%s: main returned %d\n", FW_IMAGE_NAME, main_status);
    return NULL;
}

void firmware_entry(void)
{
    board_start(FW_IMAGE_NAME);
    if (board_spawn(&main_thread, "main", main_thread_entry, NULL, main_stack, sizeof main_stack,
                    BOARD_MAIN_PRIO) != K_OK)
        board_halt(FW_IMAGE_NAME, "cannot start the main thread\n");
    k_start();
}
