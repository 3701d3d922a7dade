/*
 * The RoboCube's part of the console shell: the commands of its I/O board.
 * The port commands (ad, da, bio, bin, fast, pwm, motor, enc) name their
 * channel the way the uniform access layer does ("ad 5" is SAI channel
 * "analog in 5"), so the channel checks, ranges and error codes are SAI's
 * (drivers/sai.h); the shell adds the extras SAI has no room for (a PWM
 * frequency, an encoder's speed). Also the I2C scan and the radio.
 */
#include "shell.h"

#include <stdint.h>

#include "kernel.h"
#include "boards/include/board.h"
#include "drivers/board_io.h"
#include "drivers/cmd.h"
#include "drivers/drv_err.h"
#include "drivers/i2c.h"
#include "drivers/motor.h"
#include "drivers/sai.h"
#include "drivers/tpu.h"
#include "net/net.h"
#include "net/auth.h"

#define reply_error shell_reply_error

/* The channel named by the command's first two words ("ad 5"), parsed by SAI
 * from the line; reports the error itself and returns < 0 when there is none. */
static int channel_of(const char *line, char **argv, struct sai_channel *ch)
{
    const char *rest;
    unsigned k;
    int rc = sai_parse_prefix(line, ch, &rest);
    if (rc >= 0)
        return rc;
    for (k = 0; k < BOARD_PORT_KINDS; k++) { /* name the numbers the kind has */
        const struct sai_kind_info *info = sai_kind_info(k);
        if (cmd_same(argv[0], info->port->short_name)) {
            reply_error("%s %s: no such channel (%s %u..%u)", argv[0], argv[1],
                        info->port->short_name, info->port->first, info->port->last);
            return rc;
        }
    }
    reply_error("%s %s: no such channel", argv[0], argv[1]);
    return rc;
}

/* Prints "SHORT N = V": the answer of every port command. */
static void print_channel(struct sai_channel ch, int32_t value)
{
    k_printf("%s %u = %ld\n", sai_kind_info(ch.kind)->port->short_name, ch.index, (long)value);
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
                    (long)info->port->min, (long)info->port->max);
        return;
    }
    if (rc < 0) {
        report_driver_error(line, rc);
        return;
    }
    print_channel(ch, value);
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

static const struct cmd robocube_commands[] = {
    {"ad", "N", "read analog input N (0..23)", 1, 1, cmd_port},
    {"da", "N V", "set analog output N (0..5) to V (0..255)", 2, 2, cmd_port},
    {"bio", "N [V]", "binary I/O line N (0..15): read, or latch V (1 = input)", 1, 2, cmd_port},
    {"bin", "N", "read binary input N (1..5, DUART IP1-IP5)", 1, 1, cmd_port},
    {"fast", "N V", "set fast output bit N (0..15) to V (0/1)", 2, 2, cmd_port},
    {"pwm", "CH PERMILLE [HZ]", "TPU channel CH (0..15): PWM duty 0..1000, 17..20000 Hz", 2, 3, cmd_pwm},
    {"motor", "N SPEED", "motor N (0..2) power, signed per-mille (-1000..1000)", 2, 2, cmd_motor},
    {"speed", "N CPS", "motor N closed loop: PI speed set-point in counts/s", 2, 2, cmd_speed},
    {"enc", "N", "motor N's encoder: position (counts), speed (counts/s)", 1, 1, cmd_enc},
    {"i2c", "scan", "list the devices that answer on both I2C buses", 1, 1, cmd_i2c},
    {"net", "[start STATION]", "radio statistics; net start N (0..15) joins the radio", 0, 2, cmd_net},
};

size_t shell_board_commands(const struct cmd **table)
{
    *table = robocube_commands;
    return sizeof robocube_commands / sizeof robocube_commands[0];
}

/* The TPU and the motor service (its thread: encoders, speed control). */
void shell_board_setup(void)
{
    if (tpu_init() < 0)
        board_halt("shell", "tpu_init failed\n");
    if (motor_init() < 0)
        board_halt("shell", "motor_init failed\n");
}

/* The I2C devices, with the boot report of which answered on which bus. */
void shell_board_bring_up(void)
{
    int rc = board_io_init();
    if (rc < 0)
        k_printf("shell: board I/O: %s (%d); the other ports still work\n", drv_strerror(rc), rc);
}

/* exit: every motor to 0 first (open loop, which also ends a speed
 * set-point), so the robot stands still whatever happens to the board. */
const char *shell_board_stop(void)
{
    unsigned m;
    for (m = 0; m < MOTOR_COUNT; m++)
        (void)motor_set(m, 0);
    return "exit: motors stopped, board off\n";
}
