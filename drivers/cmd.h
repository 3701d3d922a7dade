/*
 * Console command tables: the one command-line parser of the shell
 * (apps/shell) and the test images (apps/iotest, apps/motiontest). A line is
 * split into words in place, the first word is looked up in the image's
 * table, and the number of words after it is checked against the entry; the
 * image runs the entry and words its own answers and errors. No libc.
 */
#ifndef DRIVERS_CMD_H
#define DRIVERS_CMD_H

#include <stddef.h>
#include <stdint.h>

struct cmd {
    const char *name;
    const char *usage;      /* the arguments, for help texts and usage errors */
    const char *what;       /* one line of help ("" for test images) */
    uint8_t min_args, max_args; /* words after the name */
    void (*run)(int argc, char **argv, const char *line);
};

/* Splits line in place into words separated by blanks (space, tab) into
 * argv[0..]; returns the word count (0 for a blank line), or -1 when the line
 * has more than max words (argv then holds the first max). */
int cmd_split(char *line, char **argv, int max);

/* Whole-string equality. */
int cmd_same(const char *a, const char *b);

/* A signed decimal int32 ("-12", "+5", "300"): 1 and *out if s is exactly
 * one (no overflow), else 0 and *out untouched. */
int cmd_parse_int(const char *s, int32_t *out);

/* Results of cmd_find. */
#define CMD_FOUND    0
#define CMD_UNKNOWN (-1)   /* argv[0] names no command of the table */
#define CMD_USAGE   (-2)   /* the command takes another number of words */

/* Looks argv[0] up in table[0..count) and checks argc - 1 against its
 * min_args..max_args. Returns CMD_FOUND, CMD_UNKNOWN or CMD_USAGE and sets
 * *found to the entry (NULL for CMD_UNKNOWN). argc >= 1. */
int cmd_find(const struct cmd *table, size_t count, int argc, char **argv, const struct cmd **found);

#endif /* DRIVERS_CMD_H */
