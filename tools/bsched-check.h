/*
 * bsched-check: checks a B-schedule from the trace of one major cycle alone,
 * for bsched-plan --certify's run+check method.
 *
 * Written apart from the library on purpose: it includes neither bsched.h nor
 * Fig. 7's reference engine and calls none of their functions. It takes the
 * priority set from the caller and everything else from the trace, computes
 * Fig. 6's initial waits and runs Fig. 7 itself from the paper's definitions,
 * and compares (bsched-check.c says what is checked).
 */
#ifndef BSCHED_CHECK_H
#define BSCHED_CHECK_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

/* The largest set the checker takes: 65535 processes, priority values 0..16. */
#define CHECK_MAX_PROCS 65535u
#define CHECK_MAX_PV    16u

/* The trace, as the trace driver writes it (native byte order, one host):
 *   "BSTRACE1", int32 status of bsched_init, uint32 count, maxpv, perfect,
 *   count x uint8 pv, count x uint32 initial wait (bsched's offset[]);
 *   then per minor cycle t = 0 .. 2^maxpv - 1: int32 returned by bsched_run_cycle,
 *   uint32 number of processes it called, that many uint16 input indices in the
 *   order they were called;
 *   then uint32 cycle and uint32 reversed of the state after the major cycle, "BSTREND1". */
#define CHECK_TRACE_MAGIC "BSTRACE1"
#define CHECK_TRACE_END   "BSTREND1"

/* The properties checked, each counted on its own. */
enum check_property {
    CHECK_PLAN,    /* the library's plan: maxpv, perfect = ceil(U), initial waits = Fig. 6's */
    CHECK_PERIOD,  /* every process runs exactly every 2^pv cycles, with a constant phase */
    CHECK_BALANCE, /* every cycle's load is the balance theorem's count */
    CHECK_FIG7,    /* every cycle runs Fig. 7's processes, in Fig. 7's order */
    CHECK_REPEAT,  /* the library and Fig. 7 end the major cycle in the state they began */
    CHECK_COUNT
};

struct check_result {
    unsigned long cycles;                  /* 2^maxpv */
    unsigned long long executions;         /* process runs in the trace */
    unsigned long long failed[CHECK_COUNT];/* violations found, per property */
    unsigned long lowest_load, highest_load;
    unsigned long cycles_at_highest;
    int malformed;                         /* the trace ended early or is not a trace */
    char first_failure[256];               /* the first violation, "none" if none */
};

/* The names of the properties, as the certificate lists them. */
extern const char *const check_property_name[CHECK_COUNT];

/* Reads one trace from `trace` for the set pv[0 .. count-1] (count 1..65535, every
 * pv 0..16) and checks it. Memory: O(count + 2^maxpv), nothing kept per cycle.
 * Returns 0 when every property holds, 1 when one fails or the trace is
 * malformed (r says which and where), -1 when out of memory or the set is out
 * of range. */
int check_trace(FILE *trace, const uint8_t *pv, size_t count, struct check_result *r);

#endif /* BSCHED_CHECK_H */
