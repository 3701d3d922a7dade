/*
 * The console shell's command interpreter: one line in, one or more lines
 * of answer out (through k_printf). Every refused line (unknown command, bad
 * argument, driver error) answers exactly one line starting with "error:".
 */
#ifndef APPS_SHELL_SHELL_H
#define APPS_SHELL_SHELL_H

/* The longest command line, characters (longer lines are refused whole). */
#define SHELL_LINE_MAX 80u
/* Words of a command line the interpreter looks at. */
#define SHELL_MAX_ARGS 6u

/* Runs one command line (modified in place). Blank lines do nothing. */
void shell_execute(char *line);

#endif /* APPS_SHELL_SHELL_H */
