/*
 * Driver test image (see app.mk). Reads command lines from the console
 * (polled every tick by a low-priority thread) and answers each with exactly
 * one line starting with '=' (results) or "=err" (bad command). Commands:
 *
 *   ad                 analog_read of the 24 inputs: "=ad v0 .. v23" (value or error code)
 *   da N V             analog_write(N, V): "=da rc"
 *   bi                 bio_read of the 16 lines: "=bi v0 .. v15"
 *   bo N V             bio_write(N, V): "=bo rc"
 *   in                 binin_read(1..5): "=in v1 .. v5"
 *   fo N V             fastout_write(N, V): "=fo rc shadow"
 *   fa V               fastout_write_all(V): "=fa rc shadow"
 *   snap               latest sampler snapshot:
 *                      "=snap seq time_us valid bio binin last_error a0 .. a23"
 *   period MS          sampler_start(MS): "=period rc"
 *   probe BUS ADDR     i2c_probe: "=probe rc"
 *   scan BUS           i2c_scan: "=scan n a1 a2 .."
 *   stats BUS          "=stats done absent arb timeouts resets interrupts"
 *   bench N            N sampler sweeps back to back (sampler paused): virtual
 *                      time per sweep and CPU busy fraction from an idle-loop
 *                      counter, "=bench N ticks us_per_sweep busy_permille failed
 *                      idle_loops busy_loops context_switches i2c_interrupts"
 *   benchrd N          the same with N 64-byte reads (the per-byte cost alone)
 *   benchsamp P N      the sampler thread at P ms for N periods: "=benchsamp P ticks
 *                      sweeps busy_permille cpu_us_per_sweep overruns"
 *   benchsleep N       the same with a sleep of N ticks (checks the method: ~0)
 *   uptime             "=uptime ms"
 *
 * Numbers are decimal or 0x-hex.
 */
#include <stdint.h>

#include "drivers/analog.h"
#include "drivers/bio.h"
#include "drivers/binin.h"
#include "drivers/board_io.h"
#include "drivers/cmd.h"
#include "drivers/drv_err.h"
#include "boards/robocube/duart_console.h"
#include "drivers/fastout.h"
#include "drivers/i2c.h"
#include "drivers/sampler.h"
#include "kernel.h"
#include "boards/include/board.h"

#define IOTEST_LINE 80u
#define IOTEST_SAMPLER_MS 10u
#define IOTEST_MAX_ARGS 4u

static struct k_thread main_thread, spin_thread;
K_STACK_DEFINE(main_stack, 2048u);
/* The spinner's own calls take 292 bytes, the interrupts add 352 (make stack). */
K_STACK_DEFINE(spin_stack, 1024u);

/* ---- idle-loop counter for the CPU busy fraction ------------------------ */
/* Priority 1: runs only when every other thread waits, so its loop count over
 * a span, against the count over an equally long span with nothing else to
 * do, is the fraction of the CPU the rest left idle. */
static volatile uint32_t spin_count;
static volatile uint8_t spin_on;
static struct k_sem spin_go;

static void *spin_main(void *arg)
{
    (void)arg;
    for (;;) {
        (void)k_sem_wait(&spin_go);
        while (spin_on)
            spin_count++;
    }
    return NULL;
}

/* Loop count of the spinner over `ticks` ticks, while the caller runs fn(n). */
static uint32_t spin_over(k_ticks_t *ticks, int (*fn)(unsigned), unsigned n, int *fn_result)
{
    k_ticks_t t0;
    uint32_t c0 = spin_count, c;
    /* Differences only: the spinner may be preempted between loading and
     * storing the counter, so a reset to 0 from here could be undone. */
    spin_on = 1;
    (void)k_sem_post(&spin_go);
    t0 = k_ticks();
    if (fn != NULL) {
        *fn_result = fn(n);
        *ticks = k_ticks() - t0;
    } else {
        (void)k_sleep_until(t0 + *ticks);
    }
    c = spin_count - c0;
    spin_on = 0;
    return c;
}

static int sleeps(unsigned n)
{
    (void)k_sleep_ticks(n);
    return 0;
}

/* n reads of 64 bytes from the first PCF8574A: the per-byte cost alone. */
static int long_reads(unsigned n)
{
    static uint8_t buf[64];
    int failed = 0;
    for (unsigned i = 0; i < n; i++)
        failed += i2c_transfer(I2C_BUS_A, 0x38, NULL, 0, buf, sizeof buf) != DRV_OK;
    return failed;
}

static int sweeps(unsigned n)
{
    struct sensor_snapshot s;
    int failed = 0;
    for (unsigned i = 0; i < n; i++)
        failed += sampler_sweep(&s);
    return failed;
}

/* ---- commands ------------------------------------------------------------- */
static int parse_num(const char *s, long *out)
{
    long v = 0;
    int neg = 0, base = 10, digits = 0;
    if (*s == '-') {
        neg = 1;
        s++;
    }
    if (s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
        base = 16;
        s += 2;
    }
    for (; *s; s++) {
        int d;
        if (*s >= '0' && *s <= '9')
            d = *s - '0';
        else if (base == 16 && *s >= 'a' && *s <= 'f')
            d = *s - 'a' + 10;
        else if (base == 16 && *s >= 'A' && *s <= 'F')
            d = *s - 'A' + 10;
        else
            return -1;
        v = v * base + d;
        digits++;
        if (v > 0x7FFFFFFL / 16)
            return -1;
    }
    if (digits == 0)
        return -1;
    *out = neg ? -v : v;
    return 0;
}

static void cmd_bench(long n, int (*fn)(unsigned))
{
    k_ticks_t calib_ticks, run_ticks = 0;
    uint32_t idle, busy_count;
    int failed = 0;
    uint32_t busy_permille, us;

    sampler_stop();
    (void)k_sleep_ticks(k_ms_to_ticks(50u));     /* let a running sweep end */
    struct i2c_stats st0, st1;
    uint32_t sw0 = k_stats.context_switches, sw1;
    (void)i2c_get_stats(I2C_BUS_A, &st0);
    run_ticks = 0;
    busy_count = spin_over(&run_ticks, fn, (unsigned)n, &failed);
    sw1 = k_stats.context_switches;
    (void)i2c_get_stats(I2C_BUS_A, &st1);
    calib_ticks = run_ticks;
    idle = spin_over(&calib_ticks, NULL, 0, NULL);
    busy_permille = idle == 0 ? 1000u
        : (uint32_t)(1000u - (uint32_t)(((uint64_t)busy_count * 1000u) / idle));
    us = (uint32_t)(((uint64_t)run_ticks * 1000000u) / K_TICK_HZ / (uint32_t)n);
    k_printf("=bench %ld %lu %lu %lu %d %lu %lu %lu %lu\n", n, (unsigned long)run_ticks,
             (unsigned long)us, (unsigned long)busy_permille, failed, (unsigned long)idle,
             (unsigned long)busy_count, (unsigned long)(sw1 - sw0),
             (unsigned long)(st1.interrupts - st0.interrupts));
    (void)sampler_start(IOTEST_SAMPLER_MS);
}

/* The sampler thread at period_ms for `periods` periods: CPU per sweep from
 * the idle-loop deficit over the whole window (thread start, interrupt
 * handler, publication):
 * "=benchsamp period_ms ticks sweeps busy_permille cpu_us_per_sweep overruns" */
static void cmd_benchsamp(unsigned period_ms, unsigned periods)
{
    struct sensor_snapshot s0, s1;
    k_ticks_t window = k_ms_to_ticks(period_ms * periods), calib;
    uint32_t busy_count, idle, over0 = sampler_overruns(), busy_permille, sweeps_done, cpu_us;

    (void)sampler_start(period_ms);
    (void)k_sleep_ticks(k_ms_to_ticks(3u * period_ms));  /* settle into the period */
    sampler_read(&s0);
    busy_count = spin_over(&window, NULL, 0, NULL);
    sampler_read(&s1);
    (void)sampler_start(IOTEST_SAMPLER_MS);
    sampler_stop();
    (void)k_sleep_ticks(k_ms_to_ticks(50u));
    calib = window;
    idle = spin_over(&calib, NULL, 0, NULL);
    (void)sampler_start(IOTEST_SAMPLER_MS);
    sweeps_done = s1.seq - s0.seq;
    busy_permille = idle == 0 || busy_count > idle ? 1000u
        : (uint32_t)(1000u - (uint32_t)(((uint64_t)busy_count * 1000u) / idle));
    cpu_us = sweeps_done == 0 ? 0
        : (uint32_t)(((uint64_t)window * 1000000u / K_TICK_HZ) * busy_permille / 1000u / sweeps_done);
    k_printf("=benchsamp %u %lu %lu %lu %lu %lu\n", period_ms, (unsigned long)window,
             (unsigned long)sweeps_done, (unsigned long)busy_permille, (unsigned long)cpu_us,
             (unsigned long)(sampler_overruns() - over0));
}

/* The numeric arguments of the line being run (hex with 0x), for the commands below. */
static long a[IOTEST_MAX_ARGS];

static void c_ad(int argc, char **argv, const char *line)
{
    (void)argc; (void)argv; (void)line;
    k_printf("=ad");
    for (unsigned ch = 0; ch < ANALOG_INPUTS; ch++)
        k_printf(" %d", analog_read(ch));
    k_printf("\n");
}

static void c_da(int argc, char **argv, const char *line)
{
    (void)argc; (void)argv; (void)line;
    k_printf("=da %d\n", analog_write((unsigned)a[0], (int)a[1]));
}

static void c_bi(int argc, char **argv, const char *line)
{
    (void)argc; (void)argv; (void)line;
    k_printf("=bi");
    for (unsigned l = 0; l < BIO_LINES; l++)
        k_printf(" %d", bio_read(l));
    k_printf("\n");
}

static void c_bo(int argc, char **argv, const char *line)
{
    (void)argc; (void)argv; (void)line;
    k_printf("=bo %d\n", bio_write((unsigned)a[0], (int)a[1]));
}

static void c_in(int argc, char **argv, const char *line)
{
    (void)argc; (void)argv; (void)line;
    k_printf("=in");
    for (unsigned n = 0; n <= BININ_LAST + 1u; n++) {
        if (n >= BININ_FIRST && n <= BININ_LAST)
            k_printf(" %d", binin_read(n));
    }
    k_printf(" %d %d\n", binin_read(0), binin_read(6));   /* both DRV_ERR_CHANNEL */
}

static void c_fo(int argc, char **argv, const char *line)
{
    (void)argc; (void)argv; (void)line;
    int rc = fastout_write((unsigned)a[0], (int)a[1]);
    k_printf("=fo %d %u\n", rc, (unsigned)fastout_get());
}

static void c_fa(int argc, char **argv, const char *line)
{
    (void)argc; (void)argv; (void)line;
    int rc = fastout_write_all((uint16_t)a[0]);
    k_printf("=fa %d %u\n", rc, (unsigned)fastout_get());
}

static void c_snap(int argc, char **argv, const char *line)
{
    struct sensor_snapshot s;
    (void)argc; (void)argv; (void)line;
    sampler_read(&s);
    k_printf("=snap %lu %lu %lu %u %u %d", (unsigned long)s.seq, (unsigned long)s.time_us,
             (unsigned long)s.valid, (unsigned)s.bio, (unsigned)s.binin, s.last_error);
    for (unsigned ch = 0; ch < ANALOG_INPUTS; ch++)
        k_printf(" %u", (unsigned)s.analog[ch]);
    k_printf("\n");
}

static void c_period(int argc, char **argv, const char *line)
{
    (void)argc; (void)argv; (void)line;
    k_printf("=period %d\n", a[0] < 0 ? DRV_ERR_RANGE : sampler_start((unsigned)a[0]));
}

static void c_probe(int argc, char **argv, const char *line)
{
    (void)argc; (void)argv; (void)line;
    k_printf("=probe %d\n", i2c_probe((unsigned)a[0], (uint8_t)a[1]));
}

static void c_scan(int argc, char **argv, const char *line)
{
    uint8_t found[16];
    (void)argc; (void)argv; (void)line;
    int n = i2c_scan((unsigned)a[0], found, 16u);
    k_printf("=scan %d", n);
    for (int i = 0; i < n && i < 16; i++)
        k_printf(" %u", (unsigned)found[i]);
    k_printf("\n");
}

static void c_stats(int argc, char **argv, const char *line)
{
    struct i2c_stats st;
    (void)argc; (void)argv; (void)line;
    int rc = i2c_get_stats((unsigned)a[0], &st);
    if (rc != DRV_OK) {
        k_printf("=stats %d\n", rc);
        return;
    }
    k_printf("=stats %lu %lu %lu %lu %lu %lu\n", (unsigned long)st.done,
             (unsigned long)st.absent, (unsigned long)st.arb, (unsigned long)st.timeouts,
             (unsigned long)st.resets, (unsigned long)st.interrupts);
}

static void c_bench(int argc, char **argv, const char *line)
{
    (void)argc; (void)argv; (void)line;
    if (a[0] < 1 || a[0] > 1000) {
        k_printf("=err bench 1..1000\n");
        return;
    }
    cmd_bench(a[0], sweeps);
}

static void c_benchrd(int argc, char **argv, const char *line)
{
    (void)argc; (void)argv; (void)line;
    cmd_bench(a[0], long_reads);
}

static void c_benchsamp(int argc, char **argv, const char *line)
{
    (void)argc; (void)argv; (void)line;
    if (a[0] < 1 || a[0] > 1000 || a[1] < 1 || a[1] > 1000) {
        k_printf("=err benchsamp 1..1000 1..1000\n");
        return;
    }
    cmd_benchsamp((unsigned)a[0], (unsigned)a[1]);
}

static void c_benchsleep(int argc, char **argv, const char *line)
{
    (void)argc; (void)argv; (void)line;
    cmd_bench(a[0], sleeps);
}

static void c_uptime(int argc, char **argv, const char *line)
{
    (void)argc; (void)argv; (void)line;
    k_printf("=uptime %lu\n", (unsigned long)k_uptime_ms());
}

/* Every command takes exactly min_args numbers. */
static const struct cmd commands[] = {
    {"ad", "", "", 0, 0, c_ad},             {"da", "CH V", "", 2, 2, c_da},
    {"bi", "", "", 0, 0, c_bi},             {"bo", "LINE V", "", 2, 2, c_bo},
    {"in", "", "", 0, 0, c_in},             {"fo", "BIT V", "", 2, 2, c_fo},
    {"fa", "BITS", "", 1, 1, c_fa},         {"snap", "", "", 0, 0, c_snap},
    {"period", "MS", "", 1, 1, c_period},   {"probe", "BUS ADDR", "", 2, 2, c_probe},
    {"scan", "BUS", "", 1, 1, c_scan},      {"stats", "BUS", "", 1, 1, c_stats},
    {"bench", "N", "", 1, 1, c_bench},      {"benchrd", "N", "", 1, 1, c_benchrd},
    {"benchsamp", "MS N", "", 2, 2, c_benchsamp},
    {"benchsleep", "N", "", 1, 1, c_benchsleep},
    {"uptime", "", "", 0, 0, c_uptime},
};

static void execute(char *line)
{
    char *argv[IOTEST_MAX_ARGS + 1u];
    const struct cmd *c;
    int argc = cmd_split(line, argv, (int)IOTEST_MAX_ARGS + 1);
    if (argc < 0) {
        k_printf("=err too many arguments\n");
        return;
    }
    if (argc == 0)
        return;
    for (int i = 1; i < argc; i++) {
        if (parse_num(argv[i], &a[i - 1]) != 0) {
            k_printf("=err bad number '%s'\n", argv[i]);
            return;
        }
    }
    switch (cmd_find(commands, sizeof commands / sizeof commands[0], argc, argv, &c)) {
    case CMD_FOUND:
        c->run(argc, argv, line);
        break;
    case CMD_USAGE:
        k_printf("=err %s takes %u arguments\n", c->name, (unsigned)c->min_args);
        break;
    default:
        k_printf("=err unknown command '%s'\n", argv[0]);
        break;
    }
}

static void *main_fn(void *arg)
{
    char line[IOTEST_LINE];
    unsigned len = 0;
    int overlong = 0;
    (void)arg;

    (void)k_sem_init(&spin_go, 0u, 1u);
    (void)k_thread_create(&spin_thread, "spin", spin_main, NULL, spin_stack, sizeof spin_stack,
                          K_PRIO_APP_MIN);
    k_printf("board_io_init: %s\n", drv_strerror(board_io_init()));
    k_printf("sampler: %d\n", sampler_start(IOTEST_SAMPLER_MS));
    k_printf("iotest ready\n");
    for (;;) {
        int c = console_getc_nonblocking();
        if (c < 0) {
            (void)k_sleep_ticks(1u);
            continue;
        }
        if (c == '\r' || c == '\n') {
            line[len] = '\0';
            if (overlong)
                k_printf("=err line too long\n");
            else
                execute(line);
            len = 0;
            overlong = 0;
        } else if (len + 1u < sizeof line) {
            line[len++] = (char)c;
        } else {
            overlong = 1;
        }
    }
    return NULL;
}

int main(void)
{
    board_start("iotest");
    k_printf("\nRoboCube iotest: board I/O drivers\n");
    (void)board_spawn(&main_thread, "iotest", main_fn, NULL, main_stack, sizeof main_stack, 5u);
    k_start();
    return 0;
}
