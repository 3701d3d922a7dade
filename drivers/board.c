/* The shared start-up of the firmware images; see board.h. */
#include "drivers/board.h"

#include "kernel/arch/cpu32/cpu.h"
#include "k_board.h"
#include "kernel/lib/kstring.h"
#include "drivers/led.h"
#include "boards/robocube/duart_console.h"
#include "boards/robocube/mc68332.h"

const char board_name[] = "RoboCube";
const char board_cpu_name[] = "MC68332";
const uint32_t board_cpu_hz = CPU_CLOCK_HZ;
const uint32_t board_console_baud = CONSOLE_BAUD;

void board_halt(const char *image, const char *why)
{
    k_console_write_sync(image, strlen(image));
    k_console_write_sync(": ", 2u);
    k_console_write_sync(why, strlen(why));
    cpu32_halt();
}

void board_power_off(const char *image, const char *why)
{
    k_console_write_sync(image, strlen(image));
    k_console_write_sync(": ", 2u);
    k_console_write_sync(why, strlen(why));
    for (;;) /* a level-7 interrupt would wake it: off again */
        __asm__ __volatile__("lpstop #0x2700" : : : "memory");
}

void board_start(const char *image)
{
    k_init();
    led_init();
    if (k_board_init() != 0)
        board_halt(image, "k_board_init failed: no console interrupt or no PIT rate for K_TICK_HZ\n");
}

int board_spawn(struct k_thread *t, const char *name, k_thread_fn entry, void *arg,
                uint32_t *stack, size_t stack_bytes, unsigned prio)
{
    int rc = k_thread_create(t, name, entry, arg, stack, stack_bytes, prio);
    if (rc != K_OK)
        k_printf("cannot create thread '%s': error %d\n", name, rc);
    return rc;
}
