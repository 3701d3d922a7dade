/*
 * The PDL runtime core, the same on the board and on the host: the tables
 * of processes and quantities, the cycle (begin, due processes through the
 * unchanged bsched.c, commit), dt, and the refusal of misuse.
 *
 * Commit: add_value puts a quantity on the commit list the first time it
 * gets a contribution in a cycle, so the end of a cycle costs one step per
 * quantity that changed, not per quantity declared.
 */
#include "pdl/pdl_internal.h"
#include "bsched.h"

#if PDL_MAX_PROCESSES > BSCHED_MAX_PROCS
#error "PDL_MAX_PROCESSES exceeds BSCHED_MAX_PROCS: raise -DBSCHED_MAX_PROCS"
#endif
#if PDL_MAX_QUANTITIES > 65535
#error "PDL_MAX_QUANTITIES must fit a uint16_t id"
#endif

struct pdl_stats pdl_stats;

static struct bsched pdl_sched;
static pdl_process_fn pdl_procs[PDL_MAX_PROCESSES];
static uint8_t pdl_pv[PDL_MAX_PROCESSES];
static uint32_t pdl_last_run_us[PDL_MAX_PROCESSES]; /* cycle start of the last run */
static uint8_t pdl_has_run[PDL_MAX_PROCESSES];
static uint16_t pdl_nprocs;

static struct pdl_head *pdl_quantities[PDL_MAX_QUANTITIES];
static uint16_t pdl_nquantities;
/* Quantities with contributions this cycle, each once. */
static struct pdl_head *pdl_pending_list[PDL_MAX_QUANTITIES];
static uint16_t pdl_npending;

static int pdl_started;
static int pdl_current = -1;        /* process running now, or -1 */
static uint32_t pdl_cycle_start_us;
static uint32_t pdl_dt_us;
static uint32_t pdl_cycle_count_begun;

/* Set by the platform (pdl_set_frequency). */
uint32_t pdl_core_period_us = 1000000u / PDL_DEFAULT_HZ;

int pdl_refuse(int code, const char *what)
{
    pdl_stats.misuse++;
    pdl_stats.last_error = code;
    pdl_platform_report(code, what);
    return code;
}

const char *pdl_strerror(int code)
{
    switch (code) {
    case PDL_OK: return "ok";
    case PDL_ERR_NULL: return "NULL quantity or process";
    case PDL_ERR_RUNNING: return "not allowed after run_pdl()";
    case PDL_ERR_TOO_MANY_PROCESSES: return "too many processes";
    case PDL_ERR_TOO_MANY_QUANTITIES: return "too many quantities";
    case PDL_ERR_PV_RANGE: return "priority value out of range";
    case PDL_ERR_BOUNDS: return "min > max, or initial value outside [min, max]";
    case PDL_ERR_TWICE: return "quantity declared or bound twice";
    case PDL_ERR_UNDECLARED: return "quantity not declared";
    case PDL_ERR_NO_PROCESSES: return "no process";
    case PDL_ERR_PORT: return "no such port for this direction";
    case PDL_ERR_PORT_TAKEN: return "output already bound";
    case PDL_ERR_FREQUENCY: return "cycle frequency out of range";
    case PDL_ERR_NOT_RUNNING: return "run_pdl() not called";
    case PDL_ERR_DRIVER: return "driver error";
    case PDL_ERR_KERNEL: return "kernel refused the cycle thread";
    case PDL_ERR_OUTSIDE_PROCESS: return "add_value outside a process";
    case PDL_ERR_TOO_MANY_BINDINGS: return "too many bindings";
    default: return "unknown error";
    }
}

void pdl_core_set_started(int started) { pdl_started = started; }
int pdl_core_started(void) { return pdl_started; }

/* Common checks of add_quantity & co.; returns PDL_OK or the refusal. */
static int pdl_declare(struct pdl_head *h, const char *fn)
{
    if (h == NULL)
        return pdl_refuse(PDL_ERR_NULL, fn);
    if (pdl_started)
        return pdl_refuse(PDL_ERR_RUNNING, fn);
    if (h->id != 0u && h->id <= pdl_nquantities && pdl_quantities[h->id - 1u] == h)
        return pdl_refuse(PDL_ERR_TWICE, fn);
    if (pdl_nquantities >= PDL_MAX_QUANTITIES)
        return pdl_refuse(PDL_ERR_TOO_MANY_QUANTITIES, fn);
    return PDL_OK;
}

static void pdl_register(struct pdl_head *h, enum pdl_kind kind)
{
    pdl_quantities[pdl_nquantities] = h;
    pdl_nquantities++;
    h->id = pdl_nquantities;
    h->kind = (uint8_t)kind;
    h->pending = 0;
}

int add_quantity(struct pdl_quantity *q, int32_t min, int32_t max, int32_t initial)
{
    int r = pdl_declare(q == NULL ? NULL : &q->head, "add_quantity");
    if (r != PDL_OK)
        return r;
    if (min > max || initial < min || initial > max)
        return pdl_refuse(PDL_ERR_BOUNDS, "add_quantity");
    q->min = min;
    q->max = max;
    q->cur = initial;
    q->sum = 0;
    pdl_register(&q->head, PDL_KIND_INT);
    return PDL_OK;
}

int add_fquantity(struct pdl_fquantity *q, float min, float max, float initial)
{
    int r = pdl_declare(q == NULL ? NULL : &q->head, "add_fquantity");
    if (r != PDL_OK)
        return r;
    /* written so that NaN bounds or a NaN initial value are refused too */
    if (!(min <= max) || !(initial >= min) || !(initial <= max))
        return pdl_refuse(PDL_ERR_BOUNDS, "add_fquantity");
    q->min = min;
    q->max = max;
    q->cur = initial;
    q->sum = 0.0f;
    pdl_register(&q->head, PDL_KIND_FLOAT);
    return PDL_OK;
}

int add_sensor(struct pdl_sensor *q, int32_t min, int32_t max)
{
    int r = pdl_declare(q == NULL ? NULL : &q->head, "add_sensor");
    if (r != PDL_OK)
        return r;
    if (min > max)
        return pdl_refuse(PDL_ERR_BOUNDS, "add_sensor");
    q->min = min;
    q->max = max;
    q->cur = min;
    pdl_register(&q->head, PDL_KIND_SENSOR);
    return PDL_OK;
}

static int pdl_add(pdl_process_fn f, int pv, const char *fn)
{
    if (f == NULL)
        return pdl_refuse(PDL_ERR_NULL, fn);
    if (pdl_started)
        return pdl_refuse(PDL_ERR_RUNNING, fn);
    if (pv < 0 || pv > PDL_MAX_PV)
        return pdl_refuse(PDL_ERR_PV_RANGE, fn);
    if (pdl_nprocs >= PDL_MAX_PROCESSES)
        return pdl_refuse(PDL_ERR_TOO_MANY_PROCESSES, fn);
    pdl_procs[pdl_nprocs] = f;
    pdl_pv[pdl_nprocs] = (uint8_t)pv;
    pdl_has_run[pdl_nprocs] = 0;
    return pdl_nprocs++;
}

int add_process(pdl_process_fn f) { return pdl_add(f, 0, "add_process"); }
int add_process_pv(pdl_process_fn f, int pv) { return pdl_add(f, pv, "add_process_pv"); }

int pdl_core_plan(void)
{
    int32_t r;
    uint16_t i;
    if (pdl_started)
        return pdl_refuse(PDL_ERR_RUNNING, "run_pdl");
    if (pdl_nprocs == 0u)
        return pdl_refuse(PDL_ERR_NO_PROCESSES, "run_pdl");
    r = bsched_init(&pdl_sched, pdl_pv, pdl_nprocs);
    if (r != BSCHED_OK)     /* cannot happen: count and pv were checked */
        return pdl_refuse(PDL_ERR_PV_RANGE, "run_pdl (bsched_init)");
    for (i = 0; i < pdl_nprocs; i++)
        pdl_has_run[i] = 0;
    pdl_cycle_count_begun = 0;
    pdl_dt_us = pdl_core_period_us;
    return PDL_OK;
}

/* The cycle's path (add_value's first use, running a process, the commit)
 * is compiled for speed, the rest of the runtime for size. */
#pragma GCC push_options
#pragma GCC optimize("O2")

void pdl_pend(struct pdl_head *h)
{
    /* declared quantities have an id (pdl_reset clears them) */
    if (h->id == 0u) {
        (void)pdl_refuse(PDL_ERR_UNDECLARED, "add_value");
        return;
    }
    if (pdl_current < 0) {
        /* the contribution already went into the sum: take it back out, so
         * that a refused call leaves the quantity as it was */
        if (h->kind == PDL_KIND_INT)
            ((struct pdl_quantity *)(void *)h)->sum = 0;
        else
            ((struct pdl_fquantity *)(void *)h)->sum = 0.0f;
        (void)pdl_refuse(PDL_ERR_OUTSIDE_PROCESS, "add_value");
        return;
    }
    h->pending = 1;
    pdl_pending_list[pdl_npending] = h;
    pdl_npending++;
}

void pdl_cycle_begin(uint32_t now_us)
{
    pdl_dt_us = pdl_cycle_count_begun == 0u ? pdl_core_period_us : now_us - pdl_cycle_start_us;
    pdl_cycle_start_us = now_us;
    pdl_cycle_count_begun++;
    pdl_bind_refresh_sensors();
}

void pdl_core_run_process(void *context, uint16_t index)
{
    (void)context;
    pdl_current = index;
    pdl_procs[index]();
    pdl_current = -1;
    pdl_last_run_us[index] = pdl_cycle_start_us;
    pdl_has_run[index] = 1;
    pdl_stats.process_runs++;
}

struct bsched *pdl_core_sched(void) { return &pdl_sched; }

int32_t pdl_cycle_run(void)
{
    return bsched_run_cycle(&pdl_sched, pdl_core_run_process, NULL);
}

/* Clips the sum of one integer quantity into its value. The usual case
 * (the cycle's sum fits 32 bits, and so does cur + sum) takes 32-bit
 * arithmetic only: 64-bit compares cost the CPU32 twice as much. */
static void pdl_commit_int(struct pdl_quantity *q)
{
    int64_t sum = q->sum;
    int32_t low = (int32_t)sum;
    int32_t v;
    q->sum = 0;
    if ((int64_t)low == sum && !__builtin_add_overflow(q->cur, low, &v)) {
        if (v > q->max)
            v = q->max;
        else if (v < q->min)
            v = q->min;
    } else {
        int64_t w = (int64_t)q->cur + sum;
        v = w > q->max ? q->max : w < q->min ? q->min : (int32_t)w;
    }
    q->cur = v;
}

static void pdl_commit_float(struct pdl_fquantity *q)
{
    float v = q->cur + q->sum;
    q->sum = 0.0f;
    if (v > q->max)
        v = q->max;
    else if (v < q->min)
        v = q->min;
    else if (v != v)    /* NaN contribution: keep the old value */
        v = q->cur;
    q->cur = v;
}

static void pdl_commit(void)
{
    struct pdl_head **p = pdl_pending_list;
    struct pdl_head **end = p + pdl_npending;
    pdl_stats.commits += pdl_npending;
    pdl_npending = 0;
    for (; p != end; p++) {
        struct pdl_head *h = *p;
        h->pending = 0;
        if (h->kind == PDL_KIND_INT)
            pdl_commit_int((struct pdl_quantity *)(void *)h);
        else
            pdl_commit_float((struct pdl_fquantity *)(void *)h);
    }
}

void pdl_cycle_end(void)
{
    pdl_commit();
    pdl_bind_write_actuators(0);
    pdl_stats.cycles++;
}

#pragma GCC pop_options

uint32_t dt_us(void) { return pdl_dt_us; }
float dt(void) { return (float)pdl_dt_us * 1e-6f; }

uint32_t dt_process_us(void)
{
    int i = pdl_current;
    if (i < 0)
        return 0;
    if (!pdl_has_run[i])
        return pdl_core_period_us << pdl_pv[i];
    return pdl_cycle_start_us - pdl_last_run_us[i];
}

float dt_process(void) { return (float)dt_process_us() * 1e-6f; }

uint32_t pdl_period_us(void) { return pdl_core_period_us; }

void pdl_get_stats(struct pdl_stats *out)
{
    if (out != NULL) {
        *out = pdl_stats;
        pdl_platform_stats(out);
    }
}

void pdl_core_reset(void)
{
    uint16_t i;
    for (i = 0; i < pdl_nquantities; i++) {
        pdl_quantities[i]->id = 0;
        pdl_quantities[i]->pending = 0;
    }
    pdl_nquantities = 0;
    pdl_npending = 0;
    pdl_nprocs = 0;
    pdl_started = 0;
    pdl_current = -1;
    pdl_cycle_count_begun = 0;
    pdl_core_period_us = 1000000u / PDL_DEFAULT_HZ;
    pdl_stats = (struct pdl_stats){0};
    pdl_bind_reset();
}
