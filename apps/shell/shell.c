/*
 * The console shell's interpreter and the commands every board has: help,
 * led, ps, uptime, sleep, console, exit. The board's own commands come from
 * its part (shell_board_commands: shell_robocube.c, shell_stm32f405.c);
 * lines are parsed by drivers/cmd.c, the parser the test images share.
 */
#include "shell.h"

#include <stdarg.h>
#include <stdint.h>

#include "kernel.h"
#include "boards/include/board.h"
#include "drivers/cmd.h"
#include "drivers/console_in.h"
#include "boards/include/board_led.h"

void shell_reply_error(const char *fmt, ...)
{
    char text[SHELL_LINE_MAX + 64u];
    va_list ap;
    va_start(ap, fmt);
    (void)k_vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    k_printf("error: %s\n", text);
}

/* led [on|off] */
static void cmd_led(int argc, char **argv, const char *line)
{
    (void)line;
    if (argc == 2) {
        if (cmd_same(argv[1], "on"))
            led_set(true);
        else if (cmd_same(argv[1], "off"))
            led_set(false);
        else {
            shell_reply_error("led: '%s': say on or off", argv[1]);
            return;
        }
    }
    k_printf("led = %s\n", led_is_on() ? "on" : "off");
}

/* sleep MS: waits, so that a script piped into the shell can let time pass. */
#define SHELL_SLEEP_MAX_MS 60000
static void cmd_sleep(int argc, char **argv, const char *line)
{
    int32_t ms;
    (void)argc;
    (void)line;
    if (!cmd_parse_int(argv[1], &ms) || ms < 0 || ms > SHELL_SLEEP_MAX_MS) {
        shell_reply_error("sleep: '%s': milliseconds 0..%d", argv[1], SHELL_SLEEP_MAX_MS);
        return;
    }
    (void)k_sleep_ticks(k_ms_to_ticks((uint32_t)ms));
    k_printf("slept %ld ms\n", (long)ms);
}

/* ---- system commands ---- */

static const char *state_name(const struct k_thread_info *t)
{
    if (t->is_current)
        return "run";
    switch (t->state) {
    case K_THREAD_READY:   return "ready";
    case K_THREAD_BLOCKED: return "blocked";
    case K_THREAD_DEAD:    return "dead";
    default:               return "?";
    }
}

#define SHELL_PS_MAX 16u
static void cmd_ps(int argc, char **argv, const char *line)
{
    static struct k_thread_info threads[SHELL_PS_MAX]; /* static: keep the shell's stack small */
    int n = k_thread_list(threads, SHELL_PS_MAX), i;
    uint32_t irq_size, irq_used;
    (void)argc;
    (void)argv;
    (void)line;
    k_printf("%-14s %4s %-8s %13s %8s\n", "thread", "prio", "state", "stack used", "switches");
    for (i = 0; i < n && i < (int)SHELL_PS_MAX; i++) {
        const struct k_thread_info *t = &threads[i];
        /* a thread whose guard words broke (stopped by the kernel) is marked */
        k_printf("%-14s %4u %-8s %6lu/%-6lu %8lu%s\n", t->name, t->prio, state_name(t),
                 (unsigned long)t->stack_used, (unsigned long)t->stack_bytes,
                 (unsigned long)t->switches_in, t->stack_intact ? "" : " STACK OVERFLOW");
    }
    if (n > (int)SHELL_PS_MAX)
        k_printf("(%d more threads not shown)\n", n - (int)SHELL_PS_MAX);
    if (k_irq_stack_usage(&irq_size, &irq_used) == K_OK)
        k_printf("interrupt stack %lu/%lu\n", (unsigned long)irq_used, (unsigned long)irq_size);
}

static void cmd_uptime(int argc, char **argv, const char *line)
{
    uint32_t ms = k_uptime_ms();
    (void)argc;
    (void)argv;
    (void)line;
    k_printf("uptime %lu.%03lu s (%lu ticks at %u Hz)\n", (unsigned long)(ms / 1000u),
             (unsigned long)(ms % 1000u), (unsigned long)k_ticks(), (unsigned)K_TICK_HZ);
}

static void cmd_console(int argc, char **argv, const char *line)
{
    struct console_in_stats st;
    (void)argc;
    (void)argv;
    (void)line;
    console_in_stats(&st);
    k_printf("console: %lu bytes, %lu lines, %lu too long, ring full %lu times, "
             "%lu overruns, %lu errors\n",
             (unsigned long)st.bytes, (unsigned long)st.lines, (unsigned long)st.too_long,
             (unsigned long)st.ring_full, (unsigned long)st.overruns, (unsigned long)st.errors);
}

/* exit: the board's part makes the board safe (the RoboCube stops its
 * motors), then the board switches itself off (board_power_off), which ends
 * the emulated run: make run returns. */
static void cmd_exit(int argc, char **argv, const char *line)
{
    (void)argc;
    (void)argv;
    (void)line;
    board_power_off("shell", shell_board_stop());
}

static void cmd_help(int argc, char **argv, const char *line);

/* help first, the board's commands, then these (exit last). */
static const struct cmd head_commands[] = {
    {"help", "", "this list", 0, 0, cmd_help},
};
static const struct cmd common_commands[] = {
    {"led", "on|off", "switch the LED (no argument: show it)", 0, 1, cmd_led},
    {"ps", "", "threads: priority, state, stack used/size, switches", 0, 0, cmd_ps},
    {"uptime", "", "time since boot", 0, 0, cmd_uptime},
    {"sleep", "MS", "wait MS milliseconds (0..60000), for scripts", 1, 1, cmd_sleep},
    {"console", "", "console input counters (bytes, lines, pauses, losses)", 0, 0, cmd_console},
    {"exit", "", "stop what moves and switch the board off (ends make run)", 0, 0, cmd_exit},
};
#define COUNT(a) (sizeof (a) / sizeof (a)[0])

/* The command tables in the order help lists them. */
static size_t tables(const struct cmd *table[3], size_t count[3])
{
    table[0] = head_commands;
    count[0] = COUNT(head_commands);
    count[1] = shell_board_commands(&table[1]);
    table[2] = common_commands;
    count[2] = COUNT(common_commands);
    return 3u;
}

static void cmd_help(int argc, char **argv, const char *line)
{
    const struct cmd *table[3];
    size_t count[3], t, n = tables(table, count), i;
    (void)argc;
    (void)argv;
    (void)line;
    for (t = 0; t < n; t++) {
        for (i = 0; i < count[t]; i++) {
            char head[32];
            (void)k_snprintf(head, sizeof head, "%s %s", table[t][i].name, table[t][i].usage);
            k_printf("  %-22s %s\n", head, table[t][i].what);
        }
    }
}

static int is_blank(char c)
{
    return c == ' ' || c == '\t';
}

void shell_execute(char *line)
{
    char original[SHELL_LINE_MAX + 1u];
    char *argv[SHELL_MAX_ARGS + 1u];
    const struct cmd *table[3], *c = NULL;
    size_t count[3], t, n;
    int argc, found = CMD_UNKNOWN;
    unsigned i;
    char *p = line;
    /* the line as typed (blanks trimmed) is kept for SAI; the words are split in place */
    while (is_blank(*p))
        p++;
    for (i = 0; p[i] != '\0' && i < SHELL_LINE_MAX; i++)
        original[i] = p[i];
    while (i > 0u && is_blank(original[i - 1u]))
        i--;
    original[i] = '\0';
    argc = cmd_split(p, argv, (int)SHELL_MAX_ARGS + 1);
    if (argc < 0) {
        shell_reply_error("too many arguments");
        return;
    }
    if (argc == 0)
        return;
    n = tables(table, count);
    for (t = 0; t < n && found == CMD_UNKNOWN; t++)
        found = cmd_find(table[t], count[t], argc, argv, &c);
    switch (found) {
    case CMD_FOUND:
        c->run(argc, argv, original);
        break;
    case CMD_USAGE:
        shell_reply_error("usage: %s %s", c->name, c->usage);
        break;
    default:
        shell_reply_error("unknown command '%s' (try help)", argv[0]);
        break;
    }
}
