/*
 * The STM32F405's part of the console shell: no commands of its own (the
 * board has no RoboCube I/O board, and QEMU models none of its pins but the
 * USART, the ADC and the timers, which the PDL ports use); the shell's
 * common commands (help, led, ps, uptime, sleep, console, exit) serve.
 */
#include "shell.h"

size_t shell_board_commands(const struct cmd **table)
{
    *table = NULL;
    return 0;
}

void shell_board_setup(void)
{
}

void shell_board_bring_up(void)
{
}

const char *shell_board_stop(void)
{
    return "exit: board off\n";
}
