/*
 * Console shell image: a command shell on the console (DUART channel B), as
 * CubeOS' boot monitor and Zephyr's or NuttX's shells give their users, to
 * poke every port of the board by hand (see apps/shell/README.md).
 *
 * Threads (priority: larger is more urgent):
 *   motor    26  the motor service (drivers/motor.c: encoders, speed control)
 *   i2c      ..  the I2C drivers' own service (drivers/i2c.c)
 *   shell    10  brings the board I/O up (boot report), then reads command
 *                lines and answers them
 *   idle      0
 *
 * The prompt "shell> " is printed when the shell is ready for the next line,
 * so a program driving the shell can wait for it after every command.
 */
#include <stdint.h>

#include "kernel.h"
#include "drivers/board.h"
#include "shell.h"
#include "drivers/board_io.h"
#include "drivers/console_in.h"
#include "drivers/drv_err.h"
#include "drivers/motor.h"
#include "drivers/tpu.h"

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
    rc = board_io_init(); /* prints which I2C devices answered on which bus */
    if (rc < 0)
        k_printf("shell: board I/O: %s (%d); the other ports still work\n", drv_strerror(rc), rc);
    rc = console_in_init();
    if (rc < 0) {
        k_printf("shell: console input: %s (%d)\n", drv_strerror(rc), rc);
        return NULL;
    }
    k_printf("RoboCube shell: 'help' lists the commands\n");
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
    if (tpu_init() < 0)
        board_halt("shell", "tpu_init failed\n");
    if (motor_init() < 0)
        board_halt("shell", "motor_init failed\n");
    if (board_spawn(&shell_thread, "shell", shell_main, NULL, shell_stack, sizeof shell_stack,
                    SHELL_PRIO) != K_OK)
        board_halt("shell", "no shell thread\n");
    k_start();
    return 0;
}
