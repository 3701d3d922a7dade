/*
 * CBMC harness `errors`: every invalid input gets its error code and leaves the
 * state untouched. The state starts with arbitrary contents (so "untouched" is
 * checked against every possible value), and each call gets arbitrary pointers
 * (NULL or valid), counts and priority values.
 *
 *   bsched_init:  s or pv NULL -> ERR_NULL; else count 0 -> ERR_NO_PROCS;
 *                 else count > BSCHED_MAX_PROCS -> ERR_TOO_MANY; else some
 *                 pv[i] > BSCHED_MAX_PV (i < count) -> ERR_PV_RANGE.
 *   bsched_step, bsched_run_cycle, bsched_due: s NULL (or run / due NULL) ->
 *                 ERR_NULL; a state not from bsched_init (count 0 or above the
 *                 capacity, maxpv > BSCHED_MAX_PV, perfect 0) -> ERR_STATE;
 *                 run_cycle then calls nothing, due writes nothing.
 * The header lists the codes in this order; where several apply the first wins.
 *
 * No invalid call gets past the checks: the Makefile's NOT_REACHED turns the
 * first function of each valid path (plan_classes, period_of) into
 * assert(false); assume(false). With -DERRORS_MUTANT_VALID_CALLS (make
 * MUTANT=1) the harness makes valid calls too, and those assertions must fail.
 */
#include "proof_model.h"

static struct bsched state;
static struct bsched saved;
static uint32_t callback_calls;

static void count_call(void *context, uint16_t index)
{
    (void)context;
    (void)index;
    callback_calls++;
}

/* Byte-wise equality of the whole struct, padding included. */
static int state_unchanged(void)
{
    const unsigned char *a = (const unsigned char *)&state;
    const unsigned char *b = (const unsigned char *)&saved;
    size_t i;
    for (i = 0u; i < sizeof state; i++) {
        if (a[i] != b[i]) {
            return 0;
        }
    }
    return 1;
}

static void check_init(void)
{
    uint8_t pv[BSCHED_MAX_PROCS];
    size_t count = nondet_size();
    int s_null = nondet_int();
    int pv_null = nondet_int();
    int any_out_of_range = 0;
    int32_t expected;
    int32_t rc;
    uint32_t i;

    for (i = 0u; i < PROOF_N; i++) {
        pv[i] = nondet_uint8();
        if ((size_t)i < count && pv[i] > BSCHED_MAX_PV) {
            any_out_of_range = 1;
        }
    }
    if (s_null || pv_null) {
        expected = BSCHED_ERR_NULL;
    } else if (count == 0u) {
        expected = BSCHED_ERR_NO_PROCS;
    } else if (count > (size_t)BSCHED_MAX_PROCS) {
        expected = BSCHED_ERR_TOO_MANY;
    } else if (any_out_of_range) {
        expected = BSCHED_ERR_PV_RANGE;
    } else {
#if defined(ERRORS_MUTANT_VALID_CALLS)
        (void)bsched_init(&state, pv, count);
#endif
        return; /* a valid call: the `init` harness covers it */
    }
    rc = bsched_init(s_null ? NULL : &state, pv_null ? NULL : pv, count);
    __CPROVER_assert(rc == expected, "init: invalid input gets its error code");
    __CPROVER_assert(state_unchanged(), "init: invalid input leaves the state untouched");
}

/* The negation of "came from bsched_init" as the header describes it. */
static int implausible(const struct bsched *s)
{
    return s->count == 0u || s->count > BSCHED_MAX_PROCS || s->maxpv > BSCHED_MAX_PV || s->perfect == 0u;
}

static void check_runtime_calls(void)
{
    uint16_t due[BSCHED_MAX_PROCS];
    uint16_t due_saved[BSCHED_MAX_PROCS];
    int s_null = nondet_int();
    int fn_null = nondet_int();
    int due_null = nondet_int();
    uint32_t ahead = nondet_uint32();
    int32_t rc;
    uint32_t i;

    /* Valid states are the business of the other harnesses (a forged state that
     * passes the plausibility check is outside the API contract). */
#if !defined(ERRORS_MUTANT_VALID_CALLS)
    __CPROVER_assume(s_null || implausible(&state));
#endif
    for (i = 0u; i < PROOF_N; i++) {
        due[i] = nondet_uint16();
        due_saved[i] = due[i];
    }

    rc = bsched_step(s_null ? NULL : &state);
    __CPROVER_assert(rc == (s_null ? BSCHED_ERR_NULL : BSCHED_ERR_STATE), "step: error code");
    __CPROVER_assert(state_unchanged(), "step: state untouched");

    callback_calls = 0u;
    rc = bsched_run_cycle(s_null ? NULL : &state, fn_null ? NULL : count_call, NULL);
    __CPROVER_assert(rc == (s_null || fn_null ? BSCHED_ERR_NULL : BSCHED_ERR_STATE), "run_cycle: error code");
    __CPROVER_assert(state_unchanged(), "run_cycle: state untouched");
    __CPROVER_assert(callback_calls == 0u, "run_cycle: no process runs on error");

    rc = bsched_due(s_null ? NULL : &state, ahead, due_null ? NULL : due);
    __CPROVER_assert(rc == (s_null || due_null ? BSCHED_ERR_NULL : BSCHED_ERR_STATE), "due: error code");
    __CPROVER_assert(state_unchanged(), "due: state untouched");
    for (i = 0u; i < PROOF_N; i++) {
        __CPROVER_assert(due[i] == due_saved[i], "due: nothing written on error");
    }
}

void harness(void)
{
    /* state and saved start equal and otherwise arbitrary. */
    unsigned char *a = (unsigned char *)&state;
    unsigned char *b = (unsigned char *)&saved;
    size_t i;
    for (i = 0u; i < sizeof state; i++) {
        a[i] = nondet_uint8();
        b[i] = a[i];
    }
    if (nondet_int()) {
        check_init();
    } else {
        check_runtime_calls();
    }
}
