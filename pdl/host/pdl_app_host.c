/*
 * Any PDL program (the C files of apps/NAME, an ordinary int main(void)) on the PDL host
 * runtime, driven by the arena (emu/world/hostmode.py, ctypes): make run
 * APP=NAME HOST=1. The program's sources are compiled with -Dmain=pdl_app_main
 * and linked with this file and $(PDL_HOST_SRCS) into one shared library.
 *
 * main runs on a thread of its own, as on the board, but never at the same
 * time as a cycle: the two hand one turn back and forth, as the board's
 * priorities do (the cycle thread above main). pdl_app_host_start runs main
 * until it waits (pdl_sleep_ms) or returns; each pdl_app_host_cycle runs one
 * PDL cycle, then main's turn if its wait is over. So a run depends only on
 * the program and the world's inputs, never on the host's thread scheduling.
 *
 * What the program prints (stdout and stderr, and the runtime's refusal
 * reports) is kept in a buffer the runner takes with pdl_app_host_console,
 * so it can show it as the robot's console, live.
 */
#define _GNU_SOURCE
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pdl/host/pdl_host.h"

int pdl_app_main(void);

static pthread_t main_thread;
static pthread_mutex_t turn_lock = PTHREAD_MUTEX_INITIALIZER;
static pthread_cond_t turn_changed = PTHREAD_COND_INITIALIZER;
static int main_turn;           /* 1: main runs, 0: the cycles (the runner) */
static int main_started, main_waiting, main_done, main_status;
static uint64_t main_wake_us;

static char *console_buf;
static size_t console_len, console_cap;

static ssize_t console_write(void *cookie, const char *data, size_t n)
{
    (void)cookie;
    if (console_len + n > console_cap) {
        size_t cap = (console_len + n) * 2u + 256u;
        char *p = realloc(console_buf, cap);
        if (p == NULL)
            return -1;
        console_buf = p;
        console_cap = cap;
    }
    memcpy(console_buf + console_len, data, n);
    console_len += n;
    return (ssize_t)n;
}

/* Called with turn_lock held: gives main the turn and waits for it back. */
static void run_main_turn(void)
{
    main_turn = 1;
    pthread_cond_broadcast(&turn_changed);
    while (main_turn)
        pthread_cond_wait(&turn_changed, &turn_lock);
}

/* main's pdl_sleep_ms: hands the turn back to the cycles until the
 * simulated clock reaches the end of the wait. */
static int app_sleep(uint32_t ms)
{
    pthread_mutex_lock(&turn_lock);
    main_wake_us = pdl_host_elapsed_us() + (uint64_t)ms * 1000u;
    main_waiting = 1;
    main_turn = 0;
    pthread_cond_broadcast(&turn_changed);
    while (!main_turn)
        pthread_cond_wait(&turn_changed, &turn_lock);
    main_waiting = 0;
    pthread_mutex_unlock(&turn_lock);
    return PDL_OK;
}

static void *main_entry(void *arg)
{
    (void)arg;
    pthread_mutex_lock(&turn_lock);
    while (!main_turn)
        pthread_cond_wait(&turn_changed, &turn_lock);
    pthread_mutex_unlock(&turn_lock);
    main_status = pdl_app_main();
    fflush(stdout);
    fflush(stderr);
    pthread_mutex_lock(&turn_lock);
    main_done = 1;
    main_turn = 0;
    pthread_cond_broadcast(&turn_changed);
    pthread_mutex_unlock(&turn_lock);
    return NULL;
}

/*
 * Starts the program: main runs until it first waits or returns. 0 when
 * run_pdl() was called; -1 when main returned or waits without it (nothing
 * would ever run); -2 when it was started already or the thread failed.
 */
int pdl_app_host_start(void)
{
    static cookie_io_functions_t console_io = {.write = console_write};
    FILE *console;
    if (main_started)
        return -2;
    console = fopencookie(NULL, "w", console_io);
    if (console == NULL)
        return -2;
    setvbuf(console, NULL, _IOLBF, 0);
    stdout = console;           /* glibc: the program's printf and puts */
    stderr = console;
    (void)pdl_reset();
    pdl_host_echo_reports(1);   /* refusals on the console, as on the board */
    pdl_host_set_sleep_hook(app_sleep);
    if (pthread_create(&main_thread, NULL, main_entry, NULL) != 0)
        return -2;
    main_started = 1;
    pthread_mutex_lock(&turn_lock);
    run_main_turn();
    pthread_mutex_unlock(&turn_lock);
    fflush(stdout);
    return pdl_host_started() ? 0 : -1;
}

/* main's return value once it has returned, else -1 (still running or waiting). */
int pdl_app_host_main_status(void) { return main_done ? main_status : -1; }

/*
 * One PDL cycle. analog: AIN0-23 (0..255); binin: the DUART input port's
 * levels (bit n = IPn, 1 = open); motors: what motors 0..2 were last given
 * (permille). Then main's turn if its wait is over. 0, or -1 if the runtime
 * refused to run the cycle.
 */
int pdl_app_host_cycle(const int32_t *analog, int32_t binin, int32_t *motors)
{
    unsigned i;
    for (i = 0; i < 24u; i++)
        (void)pdl_host_set_input(PDL_ANALOG_IN, i, analog[i]);
    for (i = 1; i <= 5u; i++)
        (void)pdl_host_set_input(PDL_BINARY_IN, i, (binin >> i) & 1);
    if (pdl_run_cycles(1) != 1)
        return -1;
    for (i = 0; i < 3u; i++)
        motors[i] = pdl_host_output(PDL_MOTOR, i);
    pthread_mutex_lock(&turn_lock);
    if (main_waiting && !main_done && pdl_host_elapsed_us() >= main_wake_us)
        run_main_turn();
    pthread_mutex_unlock(&turn_lock);
    fflush(stdout);
    return 0;
}

/* Moves up to size - 1 bytes of what the program printed into buf (NUL
 * terminated); returns how many. */
size_t pdl_app_host_console(char *buf, size_t size)
{
    size_t n;
    fflush(stdout);
    if (size == 0u)
        return 0;
    n = console_len < size - 1u ? console_len : size - 1u;
    memcpy(buf, console_buf, n);
    buf[n] = '\0';
    memmove(console_buf, console_buf + n, console_len - n);
    console_len -= n;
    return n;
}
