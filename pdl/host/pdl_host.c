/*
 * Host platform of the PDL runtime: run_pdl() plans and returns, cycles run
 * on demand (pdl_run_cycles) with a simulated clock, the board's ports are
 * plain arrays a test or a simulator (the ecosystem arena) fills and reads.
 */
#include <stdio.h>
#include <string.h>

#include "pdl/host/pdl_host.h"
#include "pdl/pdl_internal.h"

#define PDL_HOST_OUTPUTS 24     /* largest index range of an output port + 1 */

/* As on the board with nothing connected: binary inputs and BIO lines are
 * pulled up (read 1), analog inputs read 0. */
#define HOST_INPUTS_IDLE {.binin = 0x3E, .bio = 0xFFFF, .valid = PDL_VALID_ALL}
static struct pdl_inputs host_inputs = HOST_INPUTS_IDLE;
static int32_t host_outputs[PDL_PORT_END][PDL_HOST_OUTPUTS];
static uint32_t host_writes[PDL_PORT_END][PDL_HOST_OUTPUTS];
static int host_fail[PDL_PORT_END][PDL_HOST_OUTPUTS];
static uint32_t host_now_us;
static uint64_t host_elapsed_us;        /* host_now_us without the wrap */
static int (*host_sleep_hook)(uint32_t ms);
static uint32_t host_cycle_us;          /* 0: the nominal period */
static uint32_t host_cycles_run;
static char host_message[160];
static int host_echo;

void pdl_platform_report(int code, const char *what)
{
    snprintf(host_message, sizeof host_message, "pdl: %s: %s (%d)", what, pdl_strerror(code),
             code);
    if (host_echo)
        fprintf(stderr, "%s\n", host_message);
}

const char *pdl_last_message(void) { return host_message; }
void pdl_host_echo_reports(int on) { host_echo = on; }

int pdl_running(void) { return pdl_core_started(); }
int pdl_host_started(void) { return pdl_core_started(); }

void pdl_platform_read_inputs(struct pdl_inputs *in) { *in = host_inputs; }

void pdl_host_set_input_valid(uint32_t valid) { host_inputs.valid = valid; }

int pdl_platform_write(enum pdl_port port, unsigned index, int32_t v)
{
    if (host_fail[port][index] != 0)
        return host_fail[port][index];
    host_outputs[port][index] = v;
    host_writes[port][index]++;
    return 0;
}

int pdl_platform_start_ports(void) { return PDL_OK; }

void pdl_platform_stats(struct pdl_stats *out) { (void)out; }   /* no overruns in simulated time */

int pdl_set_frequency(uint32_t hz)
{
    if (pdl_core_started())
        return pdl_refuse(PDL_ERR_RUNNING, "pdl_set_frequency");
    if (hz == 0u || hz > 1000000u)
        return pdl_refuse(PDL_ERR_FREQUENCY, "pdl_set_frequency");
    pdl_core_period_us = (1000000u + hz / 2u) / hz;
    return PDL_OK;
}

uint32_t pdl_frequency_mhz(void)
{
    return (uint32_t)((1000000000ull + pdl_core_period_us / 2u) / pdl_core_period_us);
}

int run_pdl(void)
{
    int r = pdl_core_start();
    if (r == PDL_OK)
        host_cycles_run = 0;
    return r;
}

int pdl_run_cycles(uint32_t n)
{
    uint32_t k;
    if (!pdl_core_started())
        return pdl_refuse(PDL_ERR_NOT_RUNNING, "pdl_run_cycles");
    for (k = 0; k < n; k++) {
        if (host_cycles_run > 0u) {
            uint32_t step = host_cycle_us != 0u ? host_cycle_us : pdl_core_period_us;
            host_now_us += step;
            host_elapsed_us += step;
        }
        pdl_cycle_begin(host_now_us);
        (void)pdl_cycle_run();
        pdl_cycle_end();
        host_cycles_run++;
    }
    return (int)n;
}

int pdl_host_set_cycle_us(uint32_t us)
{
    if (us == 0u)
        return pdl_refuse(PDL_ERR_FREQUENCY, "pdl_host_set_cycle_us");
    host_cycle_us = us;
    return PDL_OK;
}

uint32_t pdl_host_now_us(void) { return host_now_us; }

int pdl_stop(uint32_t timeout_ms)
{
    (void)timeout_ms;
    if (!pdl_core_started())
        return pdl_refuse(PDL_ERR_NOT_RUNNING, "pdl_stop");
    pdl_core_set_started(0);
    return PDL_OK;
}

int pdl_reset(void)
{
    pdl_core_reset();
    host_inputs = (struct pdl_inputs)HOST_INPUTS_IDLE;
    memset(host_outputs, 0, sizeof host_outputs);
    memset(host_writes, 0, sizeof host_writes);
    memset(host_fail, 0, sizeof host_fail);
    host_now_us = 0;
    host_elapsed_us = 0;
    host_cycle_us = 0;
    host_cycles_run = 0;
    host_message[0] = '\0';
    return PDL_OK;
}

int pdl_host_set_input(enum pdl_port port, unsigned index, int32_t v)
{
    if (pdl_port_check(port, index, 0) != PDL_OK)
        return pdl_refuse(PDL_ERR_PORT, "pdl_host_set_input");
    switch (port) {
    case PDL_ANALOG_IN:
        host_inputs.analog[index] = (uint8_t)(v < 0 ? 0 : v > 255 ? 255 : v);
        break;
    case PDL_BINARY_IN:
        host_inputs.binin = (uint8_t)(v ? host_inputs.binin | (1u << index)
                                        : host_inputs.binin & ~(1u << index));
        break;
    default:
        host_inputs.bio = (uint16_t)(v ? host_inputs.bio | (1u << index)
                                       : host_inputs.bio & ~(1u << index));
        break;
    }
    return PDL_OK;
}

int pdl_host_set_sensor(struct pdl_sensor *q, int32_t v)
{
    if (q == NULL)
        return pdl_refuse(PDL_ERR_NULL, "pdl_host_set_sensor");
    if (q->head.id == 0u || q->head.kind != PDL_KIND_SENSOR)
        return pdl_refuse(PDL_ERR_UNDECLARED, "pdl_host_set_sensor");
    q->cur = v < q->min ? q->min : v > q->max ? q->max : v;
    return PDL_OK;
}

int32_t pdl_host_output(enum pdl_port port, unsigned index)
{
    if (pdl_port_check(port, index, 1) != PDL_OK)
        return 0;
    return host_outputs[port][index];
}

uint32_t pdl_host_writes(enum pdl_port port, unsigned index)
{
    if (pdl_port_check(port, index, 1) != PDL_OK)
        return 0;
    return host_writes[port][index];
}

void pdl_host_fail_output(enum pdl_port port, unsigned index, int code)
{
    if (pdl_port_check(port, index, 1) == PDL_OK)
        host_fail[port][index] = code;
}

void pdl_host_set_sleep_hook(int (*hook)(uint32_t ms)) { host_sleep_hook = hook; }

uint64_t pdl_host_elapsed_us(void) { return host_elapsed_us; }

uint32_t pdl_uptime_ms(void) { return (uint32_t)(host_elapsed_us / 1000u); }

/* Without a hook: runs the cycles that start within the next ms. */
int pdl_sleep_ms(uint32_t ms)
{
    uint64_t until = host_elapsed_us + (uint64_t)ms * 1000u;
    uint32_t step;
    if (host_sleep_hook != NULL)
        return host_sleep_hook(ms);
    if (!pdl_core_started())
        return pdl_refuse(PDL_ERR_NOT_RUNNING, "pdl_sleep_ms");
    step = host_cycle_us != 0u ? host_cycle_us : pdl_core_period_us;
    if (host_cycles_run == 0u)
        (void)pdl_run_cycles(1);
    while (host_elapsed_us + step <= until)
        (void)pdl_run_cycles(1);
    return PDL_OK;
}
