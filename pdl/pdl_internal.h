/*
 * Inside the PDL runtime: what the core (pdl_core.c), the binding table
 * (pdl_bind.c) and the two platforms (pdl_board.c on the nanokernel, with
 * the board's ports through pdl/ports/; host/pdl_host.c on the host) say to
 * each other.
 */
#ifndef PDL_INTERNAL_H
#define PDL_INTERNAL_H

#include "pdl/pdl.h"

/* ---- core -> platform ---- */
/* Reports a refused call or a runtime problem (console / stored message). */
void pdl_platform_report(int code, const char *what);
/* Non-zero while the cycles run (the board's thread, or the host after run_pdl). */
int pdl_running(void);

/* ---- platform -> core: one cycle in three steps ---- */
/* Start of a cycle at time now_us (wraps): dt, then the sensors. */
void pdl_cycle_begin(uint32_t now_us);
/* The due processes (one bsched minor cycle); returns how many ran. */
int32_t pdl_cycle_run(void);
/* Commits the cycle's sums, then writes the actuators. */
void pdl_cycle_end(void);

/* Non-zero (default): record and replay the major cycle (tests compare both ways). */
extern int pdl_plan_cache_enabled;
/* Non-zero when run_pdl recorded the major cycle (else bsched steps live). */
int pdl_core_plan_recorded(void);
/* Plans the process set (bsched_init); PDL_OK or an error (reported). */
int pdl_core_plan(void);
/* run_pdl's common part: plan, bring up the ports, mark the set started
 * (declarations are refused from now on), write the initial actuator values. */
int pdl_core_start(void);
void pdl_core_reset(void);

/* ---- shared state below the core and the binding table (pdl_state.c) ---- */
/* Non-zero once run_pdl() started the set (declarations are refused). */
extern int pdl_started;
/* Marks the set as started (refuses further declarations). */
void pdl_core_set_started(int started);
int pdl_core_started(void);
/* Counts and reports a refused call (pdl_state.c). */
void pdl_count_refusal(int code, const char *what);
/* pdl_count_refusal, then code: inline, so that a caller's analysis sees the
 * refusal's result (a refused NULL is never dereferenced after it). */
static inline int pdl_refuse(int code, const char *what)
{
    pdl_count_refusal(code, what);
    return code;
}
/* Statistics the platform keeps (overruns, cycle ticks). */
extern struct pdl_stats pdl_stats;
/* Nominal cycle period (the platform sets it from f0). */
extern uint32_t pdl_core_period_us;

/* ---- binding table (pdl_bind.c) ---- */
/* Inputs of the whole board at the start of a cycle. */
struct pdl_inputs {
    uint8_t analog[24];
    uint8_t binin;      /* bit n = DUART IPn (n = 1..5) */
    uint16_t bio;       /* bit n = BIO line n */
    uint32_t valid;     /* read successfully: bit i analog i, PDL_VALID_* */
};
#define PDL_VALID_BIO0  (1ul << 24)     /* BIO0-7 (the sampler's layout) */
#define PDL_VALID_BIO1  (1ul << 25)     /* BIO8-15 */
#define PDL_VALID_BININ (1ul << 26)
#define PDL_VALID_ALL   0x07FFFFFFul
void pdl_bind_refresh_sensors(void);
/* Writes every actuator whose value changed (or all, with force). */
void pdl_bind_write_actuators(int force);
/* Valid port/index for a direction: PDL_OK or PDL_ERR_PORT. */
int pdl_port_check(enum pdl_port port, unsigned index, int output);
/* The port's kind in the board's port table (boards/include/board_ports.h), or -1. */
int pdl_port_kind(enum pdl_port port);
void pdl_bind_reset(void);

/* ---- platform ports ---- */
/* Fills *in from the drivers' latest snapshot (board) or the test's values (host). */
void pdl_platform_read_inputs(struct pdl_inputs *in);
/* Writes one actuator; >= 0 or a negative driver code. */
int pdl_platform_write(enum pdl_port port, unsigned index, int32_t v);
/* Adds what the platform counts (overruns, cycle ticks) to *out. */
void pdl_platform_stats(struct pdl_stats *out);
/* Non-zero if some quantity is bound to `port`. */
int pdl_bind_uses(enum pdl_port port);
/* Prepares the drivers the bindings use (at run_pdl); PDL_OK or an error. */
int pdl_platform_start_ports(void);

#endif /* PDL_INTERNAL_H */
