/*
 * Test firmware of the motion drivers. Reads one command a line from the
 * console (polling the DUART's channel B receiver once a tick: there is no
 * console input driver in this image) and answers one line, "ok ..." or
 * "err CODE". Commands (numbers are decimal, may be negative):
 *
 *   pwm CH HZ PERMILLE     tpu_pwm                 pwmget CH -> ok HZ PERMILLE
 *   ticks CH HIGH PERIOD   tpu_pwm_ticks
 *   dout CH V              tpu_dio_write           din CH -> ok V
 *   itc CH EDGES           tpu_itc_start           itcget CH -> ok COUNT    itcclr CH
 *   qdec A B               tpu_qdec_start          qpos A -> ok POS         qset A POS
 *   irq CH                 count CH's interrupts   irqget CH -> ok COUNT (tpu_irq_count too)
 *   irqwait CH MS          -> ok (CH's interrupts during MS ms)
 *   release CH             tpu_release
 *   motor M PERMILLE       motor_set               enc M -> ok POS SPEED POWER
 *   speed M V              motor_set_speed         off M   gains M KP KI
 *   period MS              motor_control_start     stats -> ok PERIODS PERIOD_MS LATE
 *   wait MS                sleeps MS (virtual time)
 *   step M V MS            motor_set_speed, then one "T_US SPEED POWER" sample per
 *                          service period for MS ms -> ok N T0_US then N lines
 *                          (T0_US: the tick time of the set-point change)
 *   odo MMPC BASE          odometry_init over motors 0 (left) and 2 (right), geometry Q16 mm
 *   odoget                 odometry_update from the motor positions -> ok X Y HEADING
 *   cpuload MS             -> ok TURNS of a lowest-priority busy loop during MS ms
 *   time                   -> ok UPTIME_MS
 *   stamp                  k_timestamp_start -> ok HZ (the fine counter's rate) or err CODE
 */
#include <stdint.h>

#include "kernel.h"
#include "boards/include/board.h"
#include "drivers/cmd.h"
#include "drivers/drv_err.h"
#include "boards/robocube/mc68681.h"
#include "drivers/motor.h"
#include "drivers/odometry.h"
#include "drivers/tpu.h"

#define LINE_MAX 80u
#define ARGS_MAX 4u

static struct k_thread test_thread;
K_STACK_DEFINE(test_stack, 2048u);
static volatile uint32_t irq_counts[TPU_CHANNELS];
/* Odometry over motor 0 (left wheel) and motor 2 (right), as CubeOS' icontrol. */
static struct odometry odo;
#define ODO_LEFT 0u
#define ODO_RIGHT 2u

static void reply(int r)
{
    if (r < 0)
        k_printf("err %d\n", r);
    else
        k_printf("ok\n");
}

/* CPU load: a lowest-priority thread counts loop turns while the test
 * thread sleeps; fewer turns than in a quiet run = time taken by the rest. */
static struct k_thread busy_thread;
K_STACK_DEFINE(busy_stack, 512u);
static volatile uint32_t busy_count;
static volatile int busy_run;

static void *busy_main(void *arg)
{
    (void)arg;
    while (busy_run)
        busy_count++;
    return NULL;
}

static void cpu_load(int32_t ms)
{
    int r;
    busy_count = 0;
    busy_run = 1;
    r = k_thread_create(&busy_thread, "busy", busy_main, NULL, busy_stack, sizeof busy_stack,
                        K_PRIO_APP_MIN);
    if (r != K_OK) {
        reply(DRV_ERR_STATE);
        return;
    }
    (void)k_sleep_ticks(k_ms_to_ticks((uint32_t)ms));
    busy_run = 0;
    r = k_thread_join(&busy_thread, NULL, K_TICK_HZ);
    if (r != K_OK)
        reply(DRV_ERR_TIMEOUT);
    else
        k_printf("ok %lu\n", (unsigned long)busy_count);
}

static void count_irq(unsigned ch, void *arg)
{
    (void)arg;
    irq_counts[ch]++;
}

/* One line from the console, polled once a tick; drops what does not fit. */
static void read_line(char *buf, unsigned size)
{
    unsigned n = 0;
    for (;;) {
        while (DUART_REG(DUART_SRB) & DUART_SR_RXRDY) {
            char c = (char)DUART_REG(DUART_RBB);
            if (c == '\n' || c == '\r') {
                if (n > 0u) {
                    buf[n < size ? n : size - 1u] = '\0';
                    return;
                }
                continue;
            }
            if (n < size - 1u)
                buf[n] = c;
            n++;
        }
        (void)k_sleep_ticks(1);
    }
}

static void step_response(unsigned m, int32_t v, int32_t ms)
{
    struct motor_service_stats st;
    uint32_t last_periods, t0, n = 0, start_us;
    static int32_t speeds[512];
    static int16_t powers[512];
    static uint32_t times[512];
    int r;
    if (ms <= 0) {
        reply(DRV_ERR_RANGE);
        return;
    }
    start_us = (uint32_t)(((uint64_t)k_ticks() * 1000000u) / K_TICK_HZ);
    r = motor_set_speed(m, v);
    if (r < 0) {
        reply(r);
        return;
    }
    (void)motor_service_stats(&st);
    last_periods = st.periods;
    t0 = k_uptime_ms();
    while (k_uptime_ms() - t0 < (uint32_t)ms && n < 512u) {
        (void)k_sleep_ticks(1);
        (void)motor_service_stats(&st);
        if (st.periods != last_periods) {
            int power;
            last_periods = st.periods;
            (void)motor_speed(m, &speeds[n]);
            (void)motor_power(m, &power);
            powers[n] = (int16_t)power;
            times[n] = (uint32_t)(((uint64_t)k_ticks() * 1000000u) / K_TICK_HZ);
            n++;
        }
    }
    k_printf("ok %lu %lu\n", (unsigned long)n, (unsigned long)start_us);
    for (uint32_t i = 0; i < n; i++)
        k_printf("%lu %ld %d\n", (unsigned long)times[i], (long)speeds[i], (int)powers[i]);
}

/* The numbers of the line being run, for the commands below. */
static int32_t a[ARGS_MAX];
/* The commands' parameters (struct cmd's run): they take numbers only, from
 * a[] (run_command parses them), so the words and the line go unused. */
#define NUMBERS_ONLY int argc __attribute__((unused)), char **argv __attribute__((unused)), \
    const char *line __attribute__((unused))

static void m_pwm(NUMBERS_ONLY)
{
    unsigned ch = (unsigned)a[0];
    reply(tpu_pwm(ch, (uint32_t)a[1], (int)a[2]));
}

static void m_ticks(NUMBERS_ONLY)
{
    unsigned ch = (unsigned)a[0];
    reply(tpu_pwm_ticks(ch, (uint16_t)a[1], (uint16_t)a[2]));
}

static void m_pwmget(NUMBERS_ONLY)
{
    unsigned ch = (unsigned)a[0];
    int r;
    uint32_t hz;
    int pm;
    r = tpu_pwm_get(ch, &hz, &pm);
    if (r < 0)
        reply(r);
    else
        k_printf("ok %lu %d\n", (unsigned long)hz, pm);
}

static void m_dout(NUMBERS_ONLY)
{
    unsigned ch = (unsigned)a[0];
    reply(tpu_dio_write(ch, (int)a[1]));
}

static void m_din(NUMBERS_ONLY)
{
    unsigned ch = (unsigned)a[0];
    int r;
    r = tpu_dio_read(ch);
    if (r < 0)
        reply(r);
    else
        k_printf("ok %d\n", r);
}

static void m_itc(NUMBERS_ONLY)
{
    unsigned ch = (unsigned)a[0];
    reply(tpu_itc_start(ch, (unsigned)a[1]));
}

static void m_itcget(NUMBERS_ONLY)
{
    unsigned ch = (unsigned)a[0];
    int r;
    uint32_t c;
    r = tpu_itc_count(ch, &c);
    if (r < 0)
        reply(r);
    else
        k_printf("ok %lu\n", (unsigned long)c);
}

static void m_itcclr(NUMBERS_ONLY)
{
    unsigned ch = (unsigned)a[0];
    reply(tpu_itc_clear(ch));
}

static void m_qdec(NUMBERS_ONLY)
{
    unsigned ch = (unsigned)a[0];
    reply(tpu_qdec_start(ch, (unsigned)a[1]));
}

static void m_qpos(NUMBERS_ONLY)
{
    unsigned ch = (unsigned)a[0];
    int r;
    int32_t pos;
    r = tpu_qdec_position(ch, &pos);
    if (r < 0)
        reply(r);
    else
        k_printf("ok %ld\n", (long)pos);
}

static void m_qset(NUMBERS_ONLY)
{
    unsigned ch = (unsigned)a[0];
    reply(tpu_qdec_set(ch, a[1]));
}

static void m_irq(NUMBERS_ONLY)
{
    unsigned ch = (unsigned)a[0];
    if (ch < TPU_CHANNELS)
        irq_counts[ch] = 0;
    reply(tpu_attach_irq(ch, count_irq, NULL));
}

static void m_irqget(NUMBERS_ONLY)
{
    unsigned ch = (unsigned)a[0];
    if (ch >= TPU_CHANNELS)
        reply(DRV_ERR_CHANNEL);
    else
        k_printf("ok %lu %lu\n", (unsigned long)irq_counts[ch], (unsigned long)tpu_irq_count(ch));
}

static void m_irqwait(NUMBERS_ONLY)
{
    unsigned ch = (unsigned)a[0];
    if (!(ch < TPU_CHANNELS && a[1] >= 0)) {
        reply(DRV_ERR_PARAM);
        return;
    }
    /* Interrupts of ch during MS ms, counted inside the firmware: the
     * host's own pauses between commands do not enter the count. */
    uint32_t before = irq_counts[ch];
    (void)k_sleep_ticks(k_ms_to_ticks((uint32_t)a[1]));
    k_printf("ok %lu\n", (unsigned long)(irq_counts[ch] - before));
}

static void m_release(NUMBERS_ONLY)
{
    unsigned ch = (unsigned)a[0];
    reply(tpu_release(ch));
}

static void m_motor(NUMBERS_ONLY)
{
    unsigned ch = (unsigned)a[0];
    reply(motor_set(ch, (int)a[1]));
}

static void m_speed(NUMBERS_ONLY)
{
    unsigned ch = (unsigned)a[0];
    reply(motor_set_speed(ch, a[1]));
}

static void m_off(NUMBERS_ONLY)
{
    unsigned ch = (unsigned)a[0];
    reply(motor_control_off(ch));
}

static void m_gains(NUMBERS_ONLY)
{
    unsigned ch = (unsigned)a[0];
    reply(motor_set_gains(ch, a[1], a[2]));
}

static void m_period(NUMBERS_ONLY)
{
    reply(motor_control_start((unsigned)a[0]));
}

static void m_enc(NUMBERS_ONLY)
{
    unsigned ch = (unsigned)a[0];
    int r;
    int32_t pos, spd;
    int pw;
    r = motor_position(ch, &pos);
    if (r >= 0)
        r = motor_speed(ch, &spd);
    if (r >= 0)
        r = motor_power(ch, &pw);
    if (r < 0)
        reply(r);
    else
        k_printf("ok %ld %ld %d\n", (long)pos, (long)spd, pw);
}

static void m_stats(NUMBERS_ONLY)
{
    int r;
    struct motor_service_stats st;
    r = motor_service_stats(&st);
    if (r < 0)
        reply(r);
    else
        k_printf("ok %lu %lu %lu\n", (unsigned long)st.periods, (unsigned long)st.period_ms,
                 (unsigned long)st.late);
}

static void m_wait(NUMBERS_ONLY)
{
    if (!(a[0] >= 0)) {
        reply(DRV_ERR_PARAM);
        return;
    }
    (void)k_sleep_ticks(k_ms_to_ticks((uint32_t)a[0]));
    reply(DRV_OK);
}

static void m_step(NUMBERS_ONLY)
{
    unsigned ch = (unsigned)a[0];
    step_response(ch, a[1], a[2]);
}

static void m_odo(NUMBERS_ONLY)
{
    int r;
    int32_t l = 0, rt = 0;
    r = motor_position(ODO_LEFT, &l);
    if (r >= 0)
        r = motor_position(ODO_RIGHT, &rt);
    if (r >= 0)
        r = odometry_init(&odo, a[0], a[1], l, rt);
    reply(r);
}

static void m_odoget(NUMBERS_ONLY)
{
    int r;
    int32_t l = 0, rt = 0;
    r = motor_position(ODO_LEFT, &l);
    if (r >= 0)
        r = motor_position(ODO_RIGHT, &rt);
    if (r < 0) {
        reply(r);
    } else {
        odometry_update(&odo, l, rt);
        k_printf("ok %ld %ld %lu\n", (long)odo.x, (long)odo.y, (unsigned long)odo.heading);
    }
}

static void m_cpuload(NUMBERS_ONLY)
{
    if (!(a[0] > 0)) {
        reply(DRV_ERR_PARAM);
        return;
    }
    cpu_load(a[0]);
}

static void m_time(NUMBERS_ONLY)
{
    k_printf("ok %lu\n", (unsigned long)k_uptime_ms());
}

static void m_stamp(NUMBERS_ONLY)
{
    int r = k_timestamp_start();
    if (r < 0)
        k_printf("err %d\n", r);
    else
        k_printf("ok %lu\n", (unsigned long)k_timestamp_hz());
}

/* Every command takes exactly min_args numbers; anything else is err DRV_ERR_PARAM. */
static const struct cmd commands[] = {
    {"pwm", "", "", 3, 3, m_pwm},
    {"ticks", "", "", 3, 3, m_ticks},
    {"pwmget", "", "", 1, 1, m_pwmget},
    {"dout", "", "", 2, 2, m_dout},
    {"din", "", "", 1, 1, m_din},
    {"itc", "", "", 2, 2, m_itc},
    {"itcget", "", "", 1, 1, m_itcget},
    {"itcclr", "", "", 1, 1, m_itcclr},
    {"qdec", "", "", 2, 2, m_qdec},
    {"qpos", "", "", 1, 1, m_qpos},
    {"qset", "", "", 2, 2, m_qset},
    {"irq", "", "", 1, 1, m_irq},
    {"irqget", "", "", 1, 1, m_irqget},
    {"irqwait", "", "", 2, 2, m_irqwait},
    {"release", "", "", 1, 1, m_release},
    {"motor", "", "", 2, 2, m_motor},
    {"speed", "", "", 2, 2, m_speed},
    {"off", "", "", 1, 1, m_off},
    {"gains", "", "", 3, 3, m_gains},
    {"period", "", "", 1, 1, m_period},
    {"enc", "", "", 1, 1, m_enc},
    {"stats", "", "", 0, 0, m_stats},
    {"wait", "", "", 1, 1, m_wait},
    {"step", "", "", 3, 3, m_step},
    {"odo", "", "", 2, 2, m_odo},
    {"odoget", "", "", 0, 0, m_odoget},
    {"cpuload", "", "", 1, 1, m_cpuload},
    {"time", "", "", 0, 0, m_time},
    {"stamp", "", "", 0, 0, m_stamp},
};

static void run_command(char *line)
{
    char *argv[ARGS_MAX + 1u];
    const struct cmd *c;
    int argc = cmd_split(line, argv, (int)ARGS_MAX + 1);
    if (argc <= 0) {
        reply(DRV_ERR_PARAM);
        return;
    }
    for (int i = 1; i < argc; i++) {
        if (!cmd_parse_int(argv[i], &a[i - 1])) {
            reply(DRV_ERR_PARAM);
            return;
        }
    }
    if (cmd_find(commands, sizeof commands / sizeof commands[0], argc, argv, &c) != CMD_FOUND)
        reply(DRV_ERR_PARAM);
    else
        c->run(argc, argv, line);
}

static void *test_main(void *arg)
{
    static char line[LINE_MAX];
    (void)arg;
    k_printf("motiontest: tpu %d motor %d\n", tpu_init(), motor_init());
    k_printf("motiontest ready\n");
    for (;;) {
        read_line(line, sizeof line);
        run_command(line);
    }
    return NULL;
}

int main(void)
{
    board_start("motiontest");
    (void)board_spawn(&test_thread, "motiontest", test_main, NULL, test_stack, sizeof test_stack,
                      K_PRIO_APP_MIN + 1u);
    k_start();
    return 0;
}
