/* Console command tables: splitting, lookup, argument counts; see cmd.h. */
#include "drivers/cmd.h"

static int is_blank(char c)
{
    return c == ' ' || c == '\t';
}

int cmd_split(char *line, char **argv, int max)
{
    int argc = 0;
    char *p = line;
    while (is_blank(*p))
        p++;
    while (*p != '\0') {
        if (argc == max)
            return -1;
        argv[argc++] = p;
        while (*p != '\0' && !is_blank(*p))
            p++;
        if (*p != '\0')
            *p++ = '\0';
        while (is_blank(*p))
            p++;
    }
    return argc;
}

int cmd_same(const char *a, const char *b)
{
    while (*a != '\0' && *a == *b) {
        a++;
        b++;
    }
    return *a == *b;
}

int cmd_parse_int(const char *s, int32_t *out)
{
    uint32_t v = 0, limit = 0x7FFFFFFFu;
    int neg = 0;
    if (*s == '-' || *s == '+') {
        neg = (*s == '-');
        s++;
    }
    if (neg)
        limit = 0x80000000u;
    if (*s == '\0')
        return 0;
    for (; *s != '\0'; s++) {
        uint32_t d;
        if (*s < '0' || *s > '9')
            return 0;
        d = (uint32_t)(*s - '0');
        if (v > (limit - d) / 10u)
            return 0;
        v = v * 10u + d;
    }
    *out = neg ? (int32_t)(0u - v) : (int32_t)v;
    return 1;
}

int cmd_find(const struct cmd *table, size_t count, int argc, char **argv, const struct cmd **found)
{
    size_t i;
    *found = NULL;
    for (i = 0; i < count; i++) {
        if (cmd_same(argv[0], table[i].name)) {
            *found = &table[i];
            if (argc - 1 < (int)table[i].min_args || argc - 1 > (int)table[i].max_args)
                return CMD_USAGE;
            return CMD_FOUND;
        }
    }
    return CMD_UNKNOWN;
}
