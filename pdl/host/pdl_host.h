/*
 * The host side of the PDL runtime (no emulator): cycles run on demand with
 * a simulated clock; a test or a simulator sets the board's inputs (or a
 * sensor quantity directly) and reads what the actuators were last given.
 * A PDL program itself includes only pdl/pdl.h.
 */
#ifndef PDL_HOST_H
#define PDL_HOST_H

#include "pdl/pdl.h"

/* Runs n cycles (after run_pdl()); the simulated clock advances by the
 * cycle period (pdl_host_set_cycle_us, default 1/f0) before each cycle
 * but the first. Returns the number of cycles run or an error. */
int pdl_run_cycles(uint32_t n);
/* Simulated time between the starts of the following cycles (> 0). */
int pdl_host_set_cycle_us(uint32_t us);
/* Simulated time of the start of the last cycle, microseconds. */
uint32_t pdl_host_now_us(void);

/* Board inputs the bound sensors read (values clipped to the port range).
 * After pdl_reset: analog inputs 0, binary inputs and BIO lines 1 (pulled
 * up, as on the board with nothing connected). */
int pdl_host_set_input(enum pdl_port port, unsigned index, int32_t v);
/* Which inputs count as read (bit i analog i, bit 24 BIO0-7, 25 BIO8-15,
 * 26 the binary inputs; default all): an unread input leaves its sensors
 * unchanged, as a failed I2C read does on the board. */
void pdl_host_set_input_valid(uint32_t valid);
/* Sets a sensor quantity directly (an unbound one keeps it; a bound one is
 * overwritten from its port at the next cycle). Clipped to its bounds. */
int pdl_host_set_sensor(struct pdl_sensor *q, int32_t v);
/* Last value written to an output port (0 before any write). */
int32_t pdl_host_output(enum pdl_port port, unsigned index);
/* Number of writes an output port received. */
uint32_t pdl_host_writes(enum pdl_port port, unsigned index);
/* Makes writes to one output fail with this driver code (0 = succeed). */
void pdl_host_fail_output(enum pdl_port port, unsigned index, int code);
/* The last report line (refused call or runtime problem), "" if none. */
const char *pdl_last_message(void);
/* Reports go to stderr as well when non-zero (default 0: tests stay quiet). */
void pdl_host_echo_reports(int on);

/* Non-zero after run_pdl() (until pdl_stop or pdl_reset). */
int pdl_host_started(void);
/* Simulated time since pdl_reset (the start of the last cycle), 64 bits. */
uint64_t pdl_host_elapsed_us(void);
/* What pdl_sleep_ms does on the host: by default it runs the cycles that
 * start within the interval; a simulator that drives the cycles itself (the
 * arena, pdl/host/pdl_app_host.c) hands main's waits to this hook.
 * NULL restores the default. */
void pdl_host_set_sleep_hook(int (*hook)(uint32_t ms));

#endif /* PDL_HOST_H */
