/* The part of the board interface (boards/include/board.h) that is the same
 * on every board: each board's own boards/NAME/board.c gives the rest. */
#include "boards/include/board.h"

#include "boards/include/board_led.h"
#include "k_board.h"
#include "kernel/lib/kstring.h"

void board_say(const char *image, const char *why)
{
    k_console_write_sync(image, strlen(image));
    k_console_write_sync(": ", 2u);
    k_console_write_sync(why, strlen(why));
}

int board_spawn(struct k_thread *t, const char *name, k_thread_fn entry, void *arg,
                uint32_t *stack, size_t stack_bytes, unsigned prio)
{
    int rc = k_thread_create(t, name, entry, arg, stack, stack_bytes, prio);
    if (rc != K_OK)
        k_printf("cannot create thread '%s': error %d\n", name, rc);
    return rc;
}

void board_start(const char *image)
{
    k_init();
    led_init();
    if (k_board_init() != 0)
        board_halt(image, "k_board_init failed: no console interrupt or no tick at K_TICK_HZ\n");
}
