/*
 * Console shell image: a command shell on the console, as CubeOS' boot
 * monitor and Zephyr's or NuttX's shells give their users, to poke every
 * port of the board by hand (see apps/shell/README.md). The same sources
 * run on the RoboCube (console on DUART channel B) and the STM32F405
 * (USART1); the board's part (shell.h) adds its commands.
 *
 * Threads (priority: larger is more urgent):
 *   motor    26  the RoboCube's motor service (drivers/motor.c: encoders,
 *                speed control)
 *   i2c      ..  the RoboCube's I2C drivers' own service (drivers/i2c.c)
 *   shell    10  brings the board's part up (the RoboCube's I/O boot
 *                report), then reads command lines and answers them
 *   idle      0
 *
 * The prompt "shell> " is printed when the shell is ready for the next line,
 * so a program driving the shell can wait for it after every command.
 */
#include <stdint.h>

#include "kernel.h"
#include "boards/include/board.h"
#include "shell.h"
#include "drivers/console_in.h"
#include "drivers/drv_err.h"

#define SHELL_PRIO 10u
/* How long one wait for a line lasts; the loop then simply waits again
 * (a bounded wait, so the thread never blocks forever in a driver). */
#define SHELL_READ_TIMEOUT_MS 1000u

static struct k_thread shell_thread;
K_STACK_DEFINE(shell_stack, 4096u);

static void *shell_main(void *arg)
{
    static char line[SHELL_LINE_MAX + 1u];
    int rc;
    (void)arg;
    shell_board_bring_up();
    rc = console_in_init();
    if (rc < 0) {
        k_printf("shell: console input: %s (%d)\n", drv_strerror(rc), rc);
        return NULL;
    }
    k_printf("%s shell: 'help' lists the commands\n", board_name);
    for (;;) {
        k_printf("shell> ");
        do {
            rc = console_read_line(line, sizeof line, SHELL_READ_TIMEOUT_MS);
        } while (rc == DRV_ERR_TIMEOUT);
        if (rc == DRV_ERR_RANGE)
            k_printf("error: line too long (more than %u characters), ignored\n",
                     (unsigned)SHELL_LINE_MAX);
        else if (rc >= 0)
            shell_execute(line);
    }
    return NULL;
}

int main(void)
{
    board_start("shell");
    shell_board_setup();
    if (board_spawn(&shell_thread, "shell", shell_main, NULL, shell_stack, sizeof shell_stack,
                    SHELL_PRIO) != K_OK)
        board_halt("shell", "no shell thread\n");
    k_start();
    return 0;
}
