/*
 * The console shell's command interpreter: one line in, one or more lines
 * of answer out (through k_printf). Every refused line (unknown command, bad
 * argument, driver error) answers exactly one line starting with "error:".
 *
 * shell.c has the interpreter and the commands every board has; the board's
 * part (shell_robocube.c, shell_stm32f405.c: the image's sources per board,
 * app.mk) gives the functions below.
 */
#ifndef APPS_SHELL_SHELL_H
#define APPS_SHELL_SHELL_H

#include <stddef.h>

#include "drivers/cmd.h"

/* The longest command line, characters (longer lines are refused whole). */
#define SHELL_LINE_MAX 80u
/* Words of a command line the interpreter looks at. */
#define SHELL_MAX_ARGS 6u

/* Runs one command line (modified in place). Blank lines do nothing. */
void shell_execute(char *line);

/* Answers "error: ..." (one line). */
void shell_reply_error(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/* ---- the board's part ---- */
/* Its commands: sets *table, returns how many (0: none). */
size_t shell_board_commands(const struct cmd **table);
/* In main, before the kernel starts: the drivers the board's commands need
 * (halts the board when one cannot start). */
void shell_board_setup(void);
/* In the shell's thread, before the first prompt (may print a boot report). */
void shell_board_bring_up(void);
/* exit's first step: makes the board safe before it switches off; returns
 * the line exit prints ("exit: ..., board off\n"). */
const char *shell_board_stop(void);

#endif /* APPS_SHELL_SHELL_H */
