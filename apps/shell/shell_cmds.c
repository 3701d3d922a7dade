/*
 * Commands of the console shell. The port commands (ad, da, bio, bin,
 * fast, pwm, motor, enc, led) name their channel the way the uniform access
 * layer does ("ad 5" is SAI channel "analog in 5"), so the channel checks,
 * ranges and error codes are SAI's (drivers/sai.h); the shell adds the
 * extras SAI has no room for (a PWM frequency, an encoder's speed).
 */
#include "shell.h"

#include <stdarg.h>
#include <stdint.h>

#include "kernel.h"
#include "drivers/board.h"
#include "drivers/cmd.h"
#include "drivers/console_in.h"
#include "drivers/drv_err.h"
#include "drivers/i2c.h"
#include "drivers/motor.h"
#include "drivers/sai.h"
#include "drivers/tpu.h"
#include "net/net.h"
#include "net/auth.h"

static void reply_error(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
static void reply_error(const char *fmt, ...)
{
    char text[SHELL_LINE_MAX + 64u];
    va_list ap;
    va_start(ap, fmt);
    (void)k_vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    k_printf("error: %s\n", text);
}

/* The channel named by the command's first two words ("ad 5"), parsed by SAI
 * from the line; reports the error itself and returns < 0 when there is none. */
static int channel_of(const char *line, char **argv, struct sai_channel *ch)
{
    const char *rest;
    unsigned k;
    int rc = sai_parse_prefix(line, ch, &rest);
    if (rc >= 0)
        return rc;
    for (k = 0; k < SAI_KIND_COUNT; k++) { /* name the numbers the kind has */
        const struct sai_kind_info *info = sai_kind_info(k);
        if (cmd_same(argv[0], info->short_name)) {
            reply_error("%s %s: no such channel (%s %u..%u)", argv[0], argv[1],
                        info->short_name, info->first, info->last);
            return rc;
        }
    }
    reply_error("%s %s: no such channel", argv[0], argv[1]);
    return rc;
}

/* Prints "SHORT N = V": the answer of every port command. */
static void print_channel(struct sai_channel ch, int32_t value)
{
    k_printf("%s %u = %ld\n", sai_kind_info(ch.kind)->short_name, ch.index, (long)value);
}

static void report_driver_error(const char *what, int rc)
{
    reply_error("%s: %s (%d)", what, drv_strerror(rc), rc);
}

/* ---- port commands through SAI ---- */

/* ad N, bin N, bio N: read. da N V, bio N V, fast N V: write. */
static void cmd_port(int argc, char **argv, const char *line)
{
    struct sai_channel ch;
    int32_t value;
    int rc;
    if (channel_of(line, argv, &ch) < 0)
        return;
    if (argc == 2) {
        rc = sai_read(ch, &value);
        if (rc < 0) {
            report_driver_error(line, rc);
            return;
        }
        print_channel(ch, value);
        return;
    }
    if (!cmd_parse_int(argv[2], &value)) {
        reply_error("%s: '%s' is not a number", argv[0], argv[2]);
        return;
    }
    rc = sai_write(ch, value);
    if (rc == DRV_ERR_RANGE) {
        const struct sai_kind_info *info = sai_kind_info(ch.kind);
        reply_error("%s %s: value %ld out of range %ld..%ld", argv[0], argv[1], (long)value,
                    (long)info->min, (long)info->max);
        return;
    }
    if (rc < 0) {
        report_driver_error(line, rc);
        return;
    }
    print_channel(ch, value);
}

static void cmd_led(int argc, char **argv, const char *line)
{
    struct sai_channel ch;
    int32_t value;
    int rc;
    (void)line;
    if (sai_parse("led", &ch) < 0)
        return;
    if (argc == 2) {
        if (cmd_same(argv[1], "on"))
            value = 1;
        else if (cmd_same(argv[1], "off"))
            value = 0;
        else {
            reply_error("led: '%s': say on or off", argv[1]);
            return;
        }
        rc = sai_write(ch, value);
        if (rc < 0) {
            report_driver_error("led", rc);
            return;
        }
    }
    rc = sai_read(ch, &value);
    if (rc < 0) {
        report_driver_error("led", rc);
        return;
    }
    k_printf("led = %s\n", value != 0 ? "on" : "off");
}

/* pwm CH PERMILLE [HZ] */
static void cmd_pwm(int argc, char **argv, const char *line)
{
    struct sai_channel ch;
    int32_t permille, hz = 0;
    uint32_t hz_now;
    int duty_now, rc;
    if (channel_of(line, argv, &ch) < 0)
        return;
    if (!cmd_parse_int(argv[2], &permille)) {
        reply_error("pwm: '%s' is not a number", argv[2]);
        return;
    }
    if (argc == 4 && !cmd_parse_int(argv[3], &hz)) {
        reply_error("pwm: '%s' is not a number", argv[3]);
        return;
    }
    rc = sai_check_value(ch, permille);
    if (rc == DRV_ERR_RANGE) {
        reply_error("pwm %u: duty %ld out of range 0..1000 per-mille", ch.index, (long)permille);
        return;
    }
    if (argc == 4 && (hz < (int32_t)TPU_PWM_HZ_MIN || hz > (int32_t)TPU_PWM_HZ_MAX)) {
        reply_error("pwm %u: frequency %ld out of range %u..%u Hz", ch.index, (long)hz,
                    TPU_PWM_HZ_MIN, TPU_PWM_HZ_MAX);
        return;
    }
    rc = tpu_pwm(ch.index, (uint32_t)hz, (int)permille);
    if (rc >= 0)
        rc = tpu_pwm_get(ch.index, &hz_now, &duty_now);
    if (rc < 0) {
        report_driver_error("pwm", rc);
        return;
    }
    k_printf("pwm %u = %d per-mille at %lu Hz\n", ch.index, duty_now, (unsigned long)hz_now);
}

/* motor N SPEED: open loop, signed per-mille of full power. */
static void cmd_motor(int argc, char **argv, const char *line)
{
    struct sai_channel ch;
    int32_t permille;
    int rc;
    (void)argc;
    if (channel_of(line, argv, &ch) < 0)
        return;
    if (!cmd_parse_int(argv[2], &permille)) {
        reply_error("motor: '%s' is not a number", argv[2]);
        return;
    }
    rc = sai_write(ch, permille);
    if (rc == DRV_ERR_RANGE) {
        reply_error("motor %u: power %ld out of range -1000..1000 per-mille", ch.index,
                    (long)permille);
        return;
    }
    if (rc < 0) {
        report_driver_error("motor", rc);
        return;
    }
    k_printf("motor %u = %ld per-mille\n", ch.index, (long)permille);
}

/* speed N CPS: closed loop, the motor service's PI controller. */
static void cmd_speed(int argc, char **argv, const char *line)
{
    struct sai_channel ch;
    int32_t cps;
    int rc;
    char name[SHELL_LINE_MAX + 8u];
    (void)argc;
    (void)line;
    (void)k_snprintf(name, sizeof name, "motor %s", argv[1]); /* the channel as SAI names it */
    if (channel_of(name, (char *[]){"motor", argv[1]}, &ch) < 0)
        return;
    if (!cmd_parse_int(argv[2], &cps)) {
        reply_error("speed: '%s' is not a number", argv[2]);
        return;
    }
    rc = motor_set_speed(ch.index, cps);
    if (rc == DRV_ERR_RANGE) {
        reply_error("speed %u: %ld out of range -%ld..%ld counts/s", ch.index, (long)cps,
                    (long)MOTOR_SPEED_MAX, (long)MOTOR_SPEED_MAX);
        return;
    }
    if (rc < 0) {
        report_driver_error("speed", rc);
        return;
    }
    k_printf("speed %u = %ld counts/s\n", ch.index, (long)cps);
}

/* sleep MS: waits, so that a script piped into the shell can let time pass. */
#define SHELL_SLEEP_MAX_MS 60000
static void cmd_sleep(int argc, char **argv, const char *line)
{
    int32_t ms;
    (void)argc;
    (void)line;
    if (!cmd_parse_int(argv[1], &ms) || ms < 0 || ms > SHELL_SLEEP_MAX_MS) {
        reply_error("sleep: '%s': milliseconds 0..%d", argv[1], SHELL_SLEEP_MAX_MS);
        return;
    }
    (void)k_sleep_ticks(k_ms_to_ticks((uint32_t)ms));
    k_printf("slept %ld ms\n", (long)ms);
}

/* enc N: position and speed. */
static void cmd_enc(int argc, char **argv, const char *line)
{
    struct sai_channel ch;
    int32_t position, speed;
    int rc;
    (void)argc;
    (void)argv;
    if (channel_of(line, argv, &ch) < 0)
        return;
    rc = sai_read(ch, &position);
    if (rc >= 0)
        rc = motor_speed(ch.index, &speed);
    if (rc < 0) {
        report_driver_error("enc", rc);
        return;
    }
    k_printf("enc %u = %ld counts, %ld counts/s\n", ch.index, (long)position, (long)speed);
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

static void cmd_i2c(int argc, char **argv, const char *line)
{
    unsigned bus;
    (void)argc;
    (void)line;
    if (!cmd_same(argv[1], "scan")) {
        reply_error("i2c: unknown subcommand '%s' (try i2c scan)", argv[1]);
        return;
    }
    for (bus = 0; bus < I2C_BUS_COUNT; bus++) {
        uint8_t found[16];
        int n = i2c_scan(bus, found, sizeof found), i;
        if (n < 0) {
            k_printf("i2c bus %c: %s (%d)\n", 'A' + bus, drv_strerror(n), n);
            continue;
        }
        k_printf("i2c bus %c: %d device%s", 'A' + bus, n, n == 1 ? "" : "s");
        for (i = 0; i < n && i < (int)sizeof found; i++)
            k_printf(" 0x%02x", found[i]);
        k_printf("\n");
    }
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

/* net: the radio stack's statistics; net start N: join the radio as station N. */
static void cmd_net(int argc, char **argv, const char *line)
{
    static int started;
    int32_t station;
    int rc;
    (void)line;
    if (argc == 1) {
        if (!started)
            k_printf("net: not started (net start STATION)\n");
        else
            (void)net_stats_print();
        return;
    }
    if (argc != 3 || !cmd_same(argv[1], "start")) {
        reply_error("net: unknown subcommand '%s' (try net, or net start STATION)", argv[1]);
        return;
    }
    /* The link layer's station numbers, checked here so that a number out
     * of range is named with the range instead of net_init's bare code. */
    if (!cmd_parse_int(argv[2], &station)) {
        reply_error("net: '%s' is not a station number (0..%u)", argv[2],
                    (unsigned)LINK_MAX_STATIONS - 1u);
        return;
    }
    if (station < 0 || station > (int32_t)LINK_MAX_STATIONS - 1) {
        reply_error("net: station %ld out of range 0..%u", (long)station,
                    (unsigned)LINK_MAX_STATIONS - 1u);
        return;
    }
    if (started) {
        reply_error("net: already started as station %u", (unsigned)net_station());
        return;
    }
    /* The development key (net.h: public, it protects nothing) and the tick
     * count as the epoch: the shell has no boot counter, so a restarted
     * board's epoch grows only if the user starts the network later after
     * boot than the time before (net/README.md, "Threat model"). */
    rc = net_auth_setup(net_auth_dev_key, (uint32_t)(k_ticks() % (AUTH_EPOCH_MAX + 1u)));
    if (rc == K_OK)
        rc = net_init((uint8_t)station, k_ticks());
    if (rc != K_OK) {
        reply_error("net: station %ld refused (%d)", (long)station, rc);
        return;
    }
    started = 1;
    k_printf("net: station %u started\n", (unsigned)net_station());
}

/* exit: every motor to 0 first (open loop, which also ends a speed
 * set-point), so the robot stands still whatever happens to the board, then
 * the board switches itself off (board_power_off: LPSTOP with the interrupt
 * mask at 7), which ends the emulated run: make run returns. */
static void cmd_exit(int argc, char **argv, const char *line)
{
    unsigned m;
    (void)argc;
    (void)argv;
    (void)line;
    for (m = 0; m < MOTOR_COUNT; m++)
        (void)motor_set(m, 0);
    board_power_off("shell", "exit: motors stopped, board off\n");
}

static void cmd_help(int argc, char **argv, const char *line);

static const struct cmd commands[] = {
    {"help", "", "this list", 0, 0, cmd_help},
    {"ad", "N", "read analog input N (0..23)", 1, 1, cmd_port},
    {"da", "N V", "set analog output N (0..5) to V (0..255)", 2, 2, cmd_port},
    {"bio", "N [V]", "binary I/O line N (0..15): read, or latch V (1 = input)", 1, 2, cmd_port},
    {"bin", "N", "read binary input N (1..5, DUART IP1-IP5)", 1, 1, cmd_port},
    {"fast", "N V", "set fast output bit N (0..15) to V (0/1)", 2, 2, cmd_port},
    {"pwm", "CH PERMILLE [HZ]", "TPU channel CH (0..15): PWM duty 0..1000, 17..20000 Hz", 2, 3, cmd_pwm},
    {"motor", "N SPEED", "motor N (0..2) power, signed per-mille (-1000..1000)", 2, 2, cmd_motor},
    {"speed", "N CPS", "motor N closed loop: PI speed set-point in counts/s", 2, 2, cmd_speed},
    {"enc", "N", "motor N's encoder: position (counts), speed (counts/s)", 1, 1, cmd_enc},
    {"led", "on|off", "switch the LED (no argument: show it)", 0, 1, cmd_led},
    {"ps", "", "threads: priority, state, stack used/size, switches", 0, 0, cmd_ps},
    {"uptime", "", "time since boot", 0, 0, cmd_uptime},
    {"sleep", "MS", "wait MS milliseconds (0..60000), for scripts", 1, 1, cmd_sleep},
    {"i2c", "scan", "list the devices that answer on both I2C buses", 1, 1, cmd_i2c},
    {"console", "", "console input counters (bytes, lines, pauses, losses)", 0, 0, cmd_console},
    {"net", "[start STATION]", "radio statistics; net start N (0..15) joins the radio", 0, 2, cmd_net},
    {"exit", "", "stop the motors and switch the board off (ends make run)", 0, 0, cmd_exit},
};
#define COMMAND_COUNT (sizeof commands / sizeof commands[0])

static void cmd_help(int argc, char **argv, const char *line)
{
    unsigned i;
    (void)argc;
    (void)argv;
    (void)line;
    for (i = 0; i < COMMAND_COUNT; i++) {
        char head[32];
        (void)k_snprintf(head, sizeof head, "%s %s", commands[i].name, commands[i].usage);
        k_printf("  %-22s %s\n", head, commands[i].what);
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
    const struct cmd *c;
    int argc;
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
        reply_error("too many arguments");
        return;
    }
    if (argc == 0)
        return;
    switch (cmd_find(commands, COMMAND_COUNT, argc, argv, &c)) {
    case CMD_FOUND:
        c->run(argc, argv, original);
        break;
    case CMD_USAGE:
        reply_error("usage: %s %s", c->name, c->usage);
        break;
    default:
        reply_error("unknown command '%s' (try help)", argv[0]);
        break;
    }
}
