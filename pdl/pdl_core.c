/*
 * The PDL runtime core, the same on the board and on the host: the tables
 * of processes and quantities, the cycle (begin, due processes through the
 * unchanged bsched.c, commit) and dt. It drives the binding table
 * (pdl_bind.c) each cycle; both count and report misuse through
 * pdl_state.c, below them, so neither calls the other back.
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
#if PDL_MAX_PROCESSES > 255
#error "PDL_MAX_PROCESSES must fit the plan's uint8_t indices"
#endif
#if PDL_PLAN_RUNS > 65535
#error "PDL_PLAN_RUNS must fit a uint16_t"
#endif
#if PDL_MAX_QUANTITIES > 65535
#error "PDL_MAX_QUANTITIES must fit a uint16_t id"
#endif

static struct bsched pdl_sched;
static pdl_process_fn pdl_procs[PDL_MAX_PROCESSES];
static uint8_t pdl_pv[PDL_MAX_PROCESSES];
static uint32_t pdl_last_run_us[PDL_MAX_PROCESSES]; /* cycle start of the last run */
static uint16_t pdl_nprocs;

static struct pdl_head *pdl_quantities[PDL_MAX_QUANTITIES];
static uint16_t pdl_nquantities;
/* Quantities with contributions this cycle, each once, by kind (so the
 * commit loops need no dispatch). */
static struct pdl_quantity *pdl_pending_int[PDL_MAX_QUANTITIES];
static struct pdl_fquantity *pdl_pending_float[PDL_MAX_QUANTITIES];
static struct pdl_head *pdl_pending_narrow[PDL_MAX_QUANTITIES];
static uint32_t pdl_npending_int, pdl_npending_float, pdl_npending_narrow;

/* The plan of one major cycle, recorded from bsched_step at run_pdl(): for
 * minor cycle t, the processes pdl_plan_runs[pdl_plan_start[t] ..
 * pdl_plan_start[t+1]-1] in execution order. bsched's schedule is periodic
 * over the major cycle (proven, README "Proofs"), so replaying the record
 * runs exactly what bsched_run_cycle would, in O(processes run) instead of
 * O(processes). Sets whose major cycle does not fit are stepped live. */
static uint8_t pdl_plan_runs[PDL_PLAN_RUNS];
static uint16_t pdl_plan_start[PDL_PLAN_CYCLES + 1];
static uint32_t pdl_plan_mask;      /* 2^maxpv - 1 */
static uint32_t pdl_plan_t;         /* next minor cycle to replay */
static int pdl_plan_cached;
int pdl_plan_cache_enabled = 1;

static int pdl_current = -1;        /* process running now, or -1 */
static uint32_t pdl_cycle_start_us;
static uint32_t pdl_dt_us;
static uint32_t pdl_cycle_count_begun;

/* Set by the platform (pdl_set_frequency). */
uint32_t pdl_core_period_us = 1000000u / PDL_DEFAULT_HZ;

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

/* add_quantity_int8 & co.: the bounds are checked as int32 (every narrow
 * type fits). */
#define PDL_ADD_NARROW_(fn, qtype, type, kind)                              \
    int fn(struct qtype *q, type min, type max, type initial)               \
    {                                                                       \
        int r = pdl_declare(q == NULL ? NULL : &q->head, #fn);              \
        if (r != PDL_OK)                                                    \
            return r;                                                       \
        if (min > max || initial < min || initial > max)                    \
            return pdl_refuse(PDL_ERR_BOUNDS, #fn);                         \
        q->min = min;                                                       \
        q->max = max;                                                       \
        q->cur = initial;                                                   \
        q->sum = 0;                                                         \
        pdl_register(&q->head, kind);                                       \
        return PDL_OK;                                                      \
    }
PDL_ADD_NARROW_(add_quantity_int8, pdl_quantity_int8, int8_t, PDL_KIND_INT8)
PDL_ADD_NARROW_(add_quantity_int16, pdl_quantity_int16, int16_t, PDL_KIND_INT16)
PDL_ADD_NARROW_(add_quantity_uint8, pdl_quantity_uint8, uint8_t, PDL_KIND_UINT8)
PDL_ADD_NARROW_(add_quantity_uint16, pdl_quantity_uint16, uint16_t, PDL_KIND_UINT16)

static int pdl_kind_narrow(uint8_t kind)
{
    return kind >= PDL_KIND_INT8 && kind <= PDL_KIND_UINT16;
}

/* The sum of a narrow quantity (its offset differs with the type). */
static int64_t *pdl_narrow_sum(struct pdl_head *h)
{
    switch (h->kind) {
    case PDL_KIND_INT8: return &((struct pdl_quantity_int8 *)(void *)h)->sum;
    case PDL_KIND_INT16: return &((struct pdl_quantity_int16 *)(void *)h)->sum;
    case PDL_KIND_UINT8: return &((struct pdl_quantity_uint8 *)(void *)h)->sum;
    default: return &((struct pdl_quantity_uint16 *)(void *)h)->sum;
    }
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

struct pdl_process_table pdl_process_table;

int pdl_add_process_named(pdl_process_fn f, int pv, const char *name, const char *fn)
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
    pdl_process_table.names[pdl_nprocs] = name != NULL ? name : "";
    pdl_process_table.runs[pdl_nprocs] = 0;
    pdl_process_table.count = (uint32_t)pdl_nprocs + 1u;
    return pdl_nprocs++;
}

/* The functions behind the macros (a program that takes their address). */
int (add_process)(pdl_process_fn f) { return pdl_add_process_named(f, 0, "", "add_process"); }
int (add_process_pv)(pdl_process_fn f, int pv)
{
    return pdl_add_process_named(f, pv, "", "add_process_pv");
}

int pdl_process_count(void) { return (int)pdl_process_table.count; }

const char *pdl_process_name(int id)
{
    return id >= 0 && (uint32_t)id < pdl_process_table.count ? pdl_process_table.names[id] : "";
}

uint32_t pdl_process_runs(int id)
{
    return id >= 0 && (uint32_t)id < pdl_process_table.count ? pdl_process_table.runs[id] : 0u;
}

/* Records one major cycle of the planned set (see pdl_plan_runs). Steps
 * pdl_sched through exactly 2^maxpv minor cycles, after which its state is
 * the initial one again; that is checked, and anything unexpected falls
 * back to live stepping from a fresh bsched_init. */
static void pdl_plan_record(void)
{
    uint32_t t, cycles, n = 0;
    uint16_t i;
    pdl_plan_cached = 0;
    pdl_plan_t = 0;
    if (!pdl_plan_cache_enabled || pdl_sched.maxpv > 30u)
        return;
    cycles = 1ul << pdl_sched.maxpv;
    if (cycles > PDL_PLAN_CYCLES)
        return;
    for (t = 0; t < cycles; t++) {
        int32_t ran = bsched_step(&pdl_sched);
        pdl_plan_start[t] = (uint16_t)n;
        if (ran < 0 || n + (uint32_t)ran > PDL_PLAN_RUNS)
            break;
        for (i = 0; i < (uint16_t)ran; i++)
            pdl_plan_runs[n++] = (uint8_t)pdl_sched.ran[i];
    }
    pdl_plan_start[cycles] = (uint16_t)n;
    if (t == cycles && pdl_sched.cycle == 0u) {
        for (i = 0; i < pdl_sched.count && bsched_wait(&pdl_sched, i) == (int32_t)pdl_sched.offset[i]; i++)
            ;
        if (i == pdl_sched.count) {
            pdl_plan_mask = cycles - 1u;
            pdl_plan_cached = 1;
            return;
        }
    }
    (void)bsched_init(&pdl_sched, pdl_pv, pdl_nprocs);   /* live stepping */
}

int pdl_core_plan_recorded(void) { return pdl_plan_cached; }

int pdl_core_plan(void)
{
    int32_t r;
    if (pdl_started)
        return pdl_refuse(PDL_ERR_RUNNING, "run_pdl");
    if (pdl_nprocs == 0u)
        return pdl_refuse(PDL_ERR_NO_PROCESSES, "run_pdl");
    r = bsched_init(&pdl_sched, pdl_pv, pdl_nprocs);
    if (r != BSCHED_OK)     /* cannot happen: count and pv were checked */
        return pdl_refuse(PDL_ERR_PV_RANGE, "run_pdl (bsched_init)");
    pdl_plan_record();
    pdl_cycle_count_begun = 0;
    pdl_dt_us = pdl_core_period_us;
    return PDL_OK;
}

int pdl_core_start(void)
{
    int r = pdl_core_plan();
    if (r != PDL_OK)
        return r;
    r = pdl_platform_start_ports();
    if (r != PDL_OK)
        return r;
    pdl_started = 1;
    pdl_bind_write_actuators(1);    /* the initial values */
    return PDL_OK;
}

/* The cycle's path (add_value's first use, running a process, the commit)
 * is compiled for speed, the rest of the runtime for size. */
#pragma GCC push_options
#pragma GCC optimize("O2")

/* Everything but a declared integer quantity in a process (pdl_pend). */
static void __attribute__((noinline)) pdl_pend_other(struct pdl_head *h)
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
        else if (pdl_kind_narrow(h->kind))
            *pdl_narrow_sum(h) = 0;
        else if (h->kind == PDL_KIND_FLOAT)
            ((struct pdl_fquantity *)(void *)h)->sum = 0.0f;
        (void)pdl_refuse(PDL_ERR_OUTSIDE_PROCESS, "add_value");
        return;
    }
    if (h->kind == PDL_KIND_FLOAT) {
        pdl_pending_float[pdl_npending_float++] = (struct pdl_fquantity *)(void *)h;
        h->pending = 1;
    } else if (pdl_kind_narrow(h->kind)) {
        pdl_pending_narrow[pdl_npending_narrow++] = h;
        h->pending = 1;
    } else {    /* a sensor cast to a quantity: never committed */
        (void)pdl_refuse(PDL_ERR_UNDECLARED, "add_value (not a writable quantity)");
    }
}

/* The usual case first and alone, as the CPU32 runs it once per quantity
 * and cycle: a declared integer quantity's first contribution in a process. */
void pdl_pend(struct pdl_head *h)
{
    if (h->kind == PDL_KIND_INT && h->id != 0u && pdl_current >= 0) {
        pdl_pending_int[pdl_npending_int++] = (struct pdl_quantity *)(void *)h;
        h->pending = 1;
        return;
    }
    pdl_pend_other(h);
}

void pdl_sum_far(int64_t *sum, int64_t v)
{
    /* the sum before the addition, exactly: the addition was modulo 2^64 */
    int64_t before = pdl_i64_((uint64_t)*sum - (uint64_t)v);
    (void)pdl_add_int_(&before, v);
    *sum = before;
}

int pdl_not_finite(void)
{
    (void)pdl_refuse(PDL_ERR_NOT_FINITE, "add_value");
    return 0;
}

void pdl_cycle_begin(uint32_t now_us)
{
    if (pdl_cycle_count_begun == 0u) {
        uint16_t i;
        /* as if each process had last run 2^pv nominal periods ago */
        for (i = 0; i < pdl_nprocs; i++)
            pdl_last_run_us[i] = now_us - (pdl_core_period_us << pdl_pv[i]);
        pdl_dt_us = pdl_core_period_us;
    } else {
        pdl_dt_us = now_us - pdl_cycle_start_us;
    }
    pdl_cycle_start_us = now_us;
    pdl_cycle_count_begun++;
    pdl_bind_refresh_sensors();
}

static void pdl_core_run_process(void *context, uint16_t index)
{
    (void)context;
    pdl_current = index;
    pdl_procs[index]();
    pdl_current = -1;
    pdl_last_run_us[index] = pdl_cycle_start_us;
    pdl_process_table.runs[index]++;
}

int32_t pdl_cycle_run(void)
{
    uint32_t k, end;
    int32_t ran;
    if (!pdl_plan_cached) {
        ran = bsched_run_cycle(&pdl_sched, pdl_core_run_process, NULL);
    } else {
        k = pdl_plan_start[pdl_plan_t];
        end = pdl_plan_start[pdl_plan_t + 1u];
        ran = (int32_t)(end - k);
        pdl_plan_t = (pdl_plan_t + 1u) & pdl_plan_mask;
        /* pdl_current is set for each process and cleared once after the
         * last: nothing but this loop runs between them (2 instructions a
         * run on the CPU32, which pay for add_value's overflow test) */
        for (; k < end; k++) {
            uint8_t index = pdl_plan_runs[k];
            pdl_current = index;
            pdl_procs[index]();
            pdl_last_run_us[index] = pdl_cycle_start_us;
            pdl_process_table.runs[index]++;
        }
        pdl_current = -1;
    }
    if (ran > 0)
        pdl_stats.process_runs += (uint32_t)ran;
    return ran;
}

/* Clips the sum of one integer quantity into its value. The usual case,
 * a cycle's sum that fits 32 bits, compares it with the distances to the
 * bounds (exact as unsigned: cur is within [min, max]), so it needs no
 * 64-bit arithmetic, which costs the CPU32 two instructions per step. */
static void pdl_commit_int(struct pdl_quantity *q)
{
    int64_t sum = q->sum;
    int32_t low = (int32_t)sum;
    int32_t high = (int32_t)(sum >> 32);
    int32_t cur = q->cur;
    q->sum = 0;
    if (low >= 0 && high == 0) {
        if ((uint32_t)low > (uint32_t)q->max - (uint32_t)cur)
            cur = q->max;
        else
            cur = (int32_t)((uint32_t)cur + (uint32_t)low);
    } else if (low < 0 && high == -1) {
        if (0u - (uint32_t)low > (uint32_t)cur - (uint32_t)q->min)
            cur = q->min;
        else
            cur = (int32_t)((uint32_t)cur + (uint32_t)low);
    } else if (sum > 0) {   /* |sum| >= 2^31: rare, 64-bit */
        /* compared with the distance to the bound, as cur + sum could pass
         * INT64_MAX (the sum saturates there, add_value) */
        cur = sum > (int64_t)q->max - cur ? q->max : (int32_t)(cur + sum);
    } else {
        cur = sum < (int64_t)q->min - cur ? q->min : (int32_t)(cur + sum);
    }
    q->cur = cur;
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

/* A narrow quantity: cur + sum clipped to [min, max], in 64 bits (the sum
 * saturates at the int64 limits, and |cur| < 2^16, so cur + sum cannot
 * overflow but at those limits, which are compared first). */
static int32_t pdl_clip64(int32_t cur, int64_t sum, int32_t min, int32_t max)
{
    if (sum > (int64_t)max - cur)
        return max;
    if (sum < (int64_t)min - cur)
        return min;
    return (int32_t)(cur + sum);
}

#define PDL_COMMIT_NARROW_(qtype, type, h)                                   \
    do {                                                                     \
        struct qtype *n_ = (struct qtype *)(void *)(h);                      \
        n_->cur = (type)pdl_clip64(n_->cur, n_->sum, n_->min, n_->max);      \
        n_->sum = 0;                                                         \
    } while (0)

static void pdl_commit_narrow(struct pdl_head *h)
{
    switch (h->kind) {
    case PDL_KIND_INT8: PDL_COMMIT_NARROW_(pdl_quantity_int8, int8_t, h); break;
    case PDL_KIND_INT16: PDL_COMMIT_NARROW_(pdl_quantity_int16, int16_t, h); break;
    case PDL_KIND_UINT8: PDL_COMMIT_NARROW_(pdl_quantity_uint8, uint8_t, h); break;
    default: PDL_COMMIT_NARROW_(pdl_quantity_uint16, uint16_t, h); break;
    }
}

/* Out of the usual path: a cycle without narrow quantities pays one test. */
static void __attribute__((noinline)) pdl_commit_narrow_all(void)
{
    uint32_t k;
    pdl_stats.commits += pdl_npending_narrow;
    for (k = 0; k < pdl_npending_narrow; k++) {
        pdl_pending_narrow[k]->pending = 0;
        pdl_commit_narrow(pdl_pending_narrow[k]);
    }
    pdl_npending_narrow = 0;
}

static void pdl_commit(void)
{
    struct pdl_quantity **p = pdl_pending_int, **end = p + pdl_npending_int;
    struct pdl_fquantity **f = pdl_pending_float, **fend = f + pdl_npending_float;
    if (pdl_npending_narrow != 0u)
        pdl_commit_narrow_all();
    pdl_stats.commits += pdl_npending_int + pdl_npending_float;
    pdl_npending_int = 0;
    pdl_npending_float = 0;
    for (; p != end; p++) {
        (*p)->head.pending = 0;
        pdl_commit_int(*p);
    }
    for (; f != fend; f++) {
        (*f)->head.pending = 0;
        pdl_commit_float(*f);
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
    pdl_npending_int = 0;
    pdl_npending_float = 0;
    pdl_npending_narrow = 0;
    pdl_nprocs = 0;
    pdl_process_table.count = 0;
    pdl_started = 0;
    pdl_current = -1;
    pdl_cycle_count_begun = 0;
    pdl_core_period_us = 1000000u / PDL_DEFAULT_HZ;
    pdl_stats = (struct pdl_stats){0};
    pdl_bind_reset();
}
