/*
 * PDL: behaviour processes on the B-scheduler (Birk, Kenn, Steels 2002,
 * section 5). The one header a PDL program includes, on the board and on
 * the host.
 *
 * A program is a network of processes that communicate only through
 * quantities: bounded variables holding a current value (what value(q)
 * returns all cycle long) and the sum of the cycle's contributions
 * (add_value(q, e)), committed and clipped to [min, max] at the end of the
 * cycle. Every cycle the runtime reads the sensors, runs the due processes
 * (one bsched minor cycle: a process with priority value pv runs every
 * 2^pv cycles), commits the sums and writes the actuators.
 *
 *     struct pdl_quantity speed;             // integer (fixed point) quantity
 *     struct pdl_sensor light;               // read-only, refreshed every cycle
 *     static void seek(void) { add_value(speed, (value(light) - 128) / 4); }
 *     ...
 *     add_quantity(&speed, -1000, 1000, 0);
 *     add_sensor(&light, 0, 255);
 *     pdl_bind_sensor(&light, PDL_ANALOG_IN, 0);
 *     pdl_bind_actuator(&speed, PDL_MOTOR, 0);
 *     add_process(seek);
 *     run_pdl();
 *
 * Every function returns PDL_OK (or an id >= 0) or a negative PDL_ERR_*
 * code; misuse is refused, counted (pdl_get_stats) and reported (console
 * on the board, pdl_last_message() on the host), never undefined.
 */
#ifndef PDL_H
#define PDL_H

#include <stddef.h>
#include <stdint.h>

/* Capacities (compile time; PDL_MAX_PROCESSES <= BSCHED_MAX_PROCS). */
#ifndef PDL_MAX_PROCESSES
#define PDL_MAX_PROCESSES 32
#endif
#ifndef PDL_MAX_QUANTITIES
#define PDL_MAX_QUANTITIES 64
#endif
#ifndef PDL_MAX_BINDINGS
#define PDL_MAX_BINDINGS 32
#endif
/* The plan of one major cycle is recorded at run_pdl() when it has at most
 * PDL_PLAN_CYCLES minor cycles (maxpv <= 8) and PDL_PLAN_RUNS process runs;
 * larger sets are stepped live through bsched_run_cycle (same schedule). */
#ifndef PDL_PLAN_CYCLES
#define PDL_PLAN_CYCLES 256
#endif
#ifndef PDL_PLAN_RUNS
#define PDL_PLAN_RUNS 1024
#endif
/* Largest priority value: a process runs every 2^pv cycles (bsched's range). */
#define PDL_MAX_PV 31

/* Status codes. */
#define PDL_OK                       0
#define PDL_ERR_NULL               (-1)  /* a NULL quantity or process */
#define PDL_ERR_RUNNING            (-2)  /* not allowed after run_pdl() */
#define PDL_ERR_TOO_MANY_PROCESSES (-3)  /* more than PDL_MAX_PROCESSES */
#define PDL_ERR_TOO_MANY_QUANTITIES (-4) /* more than PDL_MAX_QUANTITIES */
#define PDL_ERR_PV_RANGE           (-5)  /* pv < 0 or pv > PDL_MAX_PV */
#define PDL_ERR_BOUNDS             (-6)  /* min > max, or the initial value outside */
#define PDL_ERR_TWICE              (-7)  /* quantity declared or bound twice */
#define PDL_ERR_UNDECLARED         (-8)  /* quantity used before add_quantity/add_sensor */
#define PDL_ERR_NO_PROCESSES       (-9)  /* run_pdl() with no process */
#define PDL_ERR_PORT              (-10)  /* no such port, or the wrong direction */
#define PDL_ERR_PORT_TAKEN        (-11)  /* two actuator quantities on one output */
#define PDL_ERR_FREQUENCY         (-12)  /* f0 out of range */
#define PDL_ERR_NOT_RUNNING       (-13)  /* cycles asked for before run_pdl() */
#define PDL_ERR_DRIVER            (-14)  /* a driver refused (code in the report) */
#define PDL_ERR_KERNEL            (-15)  /* the kernel refused the cycle thread */
#define PDL_ERR_OUTSIDE_PROCESS   (-16)  /* add_value outside a process body */
#define PDL_ERR_TOO_MANY_BINDINGS (-17)  /* more than PDL_MAX_BINDINGS */
#define PDL_ERR_NOT_FINITE        (-18)  /* NaN or infinity added to an integer quantity */

/* ---- quantities ---- */
enum pdl_kind {
    PDL_KIND_NONE = 0, PDL_KIND_INT, PDL_KIND_FLOAT, PDL_KIND_SENSOR,
    PDL_KIND_INT8, PDL_KIND_INT16, PDL_KIND_UINT8, PDL_KIND_UINT16
};

/* Bookkeeping shared by every kind (first member of each quantity). */
struct pdl_head {
    uint16_t id;        /* 1 + index in the runtime's table; 0 = not declared */
    uint8_t kind;       /* enum pdl_kind */
    uint8_t pending;    /* has contributions this cycle (on the commit list) */
};

/* Integer quantity: the programmer picks the fixed-point scale (e.g.
 * permille, or 1/256 units). Contributions are summed exactly (64 bits),
 * so the committed value is independent of the order of the processes. */
struct pdl_quantity {
    struct pdl_head head;
    int32_t cur;        /* value of the previous cycle: value(q) */
    int32_t min, max;
    int64_t sum;        /* this cycle's contributions */
};

/* Narrow integer quantities (the paper's "all native numerical datatypes
 * of C"): value(q) has the quantity's own type, and the semantics are
 * those of struct pdl_quantity: contributions summed exactly (64 bits,
 * saturating), the result clipped to [min, max] (which lie within the
 * type) at the end of the cycle. Actuators bind only int32 quantities. */
#define PDL_NARROW_QUANTITY_(name, type) \
    struct name {                        \
        struct pdl_head head;            \
        type cur;                        \
        type min, max;                   \
        int64_t sum;                     \
    }
PDL_NARROW_QUANTITY_(pdl_quantity_int8, int8_t);
PDL_NARROW_QUANTITY_(pdl_quantity_int16, int16_t);
PDL_NARROW_QUANTITY_(pdl_quantity_uint8, uint8_t);
PDL_NARROW_QUANTITY_(pdl_quantity_uint16, uint16_t);

/* Float quantity (soft-float on the CPU32: about ten times the cost).
 * Float addition is not associative: the committed value may differ in
 * the last bits with the order of the contributions. */
struct pdl_fquantity {
    struct pdl_head head;
    float cur;
    float min, max;
    float sum;
};

/* Sensor quantity: read-only. It has no sum, so add_value(sensor, e) does
 * not compile ("struct pdl_sensor has no member named 'sum'"). Refreshed at
 * the start of every cycle from its port (pdl_bind_sensor), clipped. */
struct pdl_sensor {
    struct pdl_head head;
    int32_t cur;
    int32_t min, max;
};

/* Declares a quantity to the runtime (before run_pdl()). */
int add_quantity(struct pdl_quantity *q, int32_t min, int32_t max, int32_t initial);
int add_fquantity(struct pdl_fquantity *q, float min, float max, float initial);
int add_quantity_int8(struct pdl_quantity_int8 *q, int8_t min, int8_t max, int8_t initial);
int add_quantity_int16(struct pdl_quantity_int16 *q, int16_t min, int16_t max, int16_t initial);
int add_quantity_uint8(struct pdl_quantity_uint8 *q, uint8_t min, uint8_t max, uint8_t initial);
int add_quantity_uint16(struct pdl_quantity_uint16 *q, uint16_t min, uint16_t max,
                        uint16_t initial);
int add_sensor(struct pdl_sensor *q, int32_t min, int32_t max);

/* value(q): the value of q from the previous cycle (an rvalue). */
#define value(q) ((void)0, (q).cur)

/* add_value(q, e): adds e (converted to q's type) to q's next value. The
 * cycle's contributions are summed and take effect at the end of the cycle,
 * clipped to [min, max]. Only from a process body. q is evaluated more
 * than once (use a quantity's name, as in the paper); e once.
 *
 * On an integer quantity no value of e is undefined: the sum saturates at
 * the int64 limits instead of overflowing, a floating e is truncated toward
 * zero and one beyond the int64 range counts as the nearer limit (so 1e300
 * clips q to its max), and NaN or an infinity is refused (PDL_ERR_NOT_FINITE,
 * counted in misuse and reported) while the cycle's other contributions stay.
 * A float or double is classified from its IEEE 754 bits, so this costs the
 * soft-float CPU32 no float arithmetic beyond the conversion it always had. */
#define add_value(q, e)                                             \
    do {                                                            \
        __typeof__(+(e)) pdl_e_ = (e);                              \
        if (PDL_ADD_(&(q).sum, pdl_e_) && !(q).head.pending)        \
            pdl_pend(&(q).head);                                    \
    } while (0)

/* Puts a quantity on the commit list (add_value's first use in a cycle). */
void pdl_pend(struct pdl_head *q);
/* Refuses a NaN or infinite contribution to an integer quantity (counted,
 * reported); returns 0. */
int pdl_not_finite(void);

/* add_value's sum by the types of q and e (each branch type-checks for any
 * arithmetic e; only the chosen one is compiled into code). */
#define PDL_IS_(x, type) __builtin_types_compatible_p(__typeof__(x), type)
#define PDL_ADD_(sum, v)                                                         \
    __builtin_choose_expr(PDL_IS_(*(sum), float),                                \
        pdl_add_to_float_((float *)(void *)(sum), (float)(v)),                   \
    __builtin_choose_expr(PDL_IS_(v, float),                                     \
        pdl_add_float_((int64_t *)(void *)(sum), (float)(v)),                    \
    __builtin_choose_expr(PDL_IS_(v, double),                                    \
        pdl_add_double_((int64_t *)(void *)(sum), (double)(v)),                  \
    __builtin_choose_expr(PDL_IS_(v, long double),                               \
        pdl_add_ldouble_((int64_t *)(void *)(sum), (long double)(v)),            \
    __builtin_choose_expr(PDL_IS_(v, unsigned long long) ||                      \
                          (PDL_IS_(v, unsigned long) && sizeof(long) > 4),        \
        pdl_add_u64_((int64_t *)(void *)(sum), (uint64_t)(v)),                   \
    __builtin_choose_expr(sizeof(v) <= 4,                                        \
        pdl_add_small_((int64_t *)(void *)(sum), (int64_t)(v)),                  \
        pdl_add_int_((int64_t *)(void *)(sum), (int64_t)(v))))))))

static inline int pdl_add_to_float_(float *sum, float v)
{
    *sum += v;
    return 1;
}

/* Every integer type but the unsigned 64-bit ones fits int64 exactly. */
static inline __attribute__((always_inline)) int pdl_add_int_(int64_t *sum, int64_t v)
{
    int64_t s;
    if (__builtin_add_overflow(*sum, v, &s))
        s = v < 0 ? INT64_MIN : INT64_MAX;
    *sum = s;
    return 1;
}

/* The int64 value of a uint64 bit pattern (two's complement), without the
 * implementation-defined conversion; compiles to nothing. */
static inline __attribute__((always_inline)) int64_t pdl_i64_(uint64_t u)
{
    return u <= (uint64_t)INT64_MAX ? (int64_t)u : -(int64_t)~u - 1;
}

/* Redoes a small addition whose result reached 2^62 in magnitude, with
 * saturation (pdl_core.c); *sum holds the wrapped result. */
void pdl_sum_far(int64_t *sum, int64_t v);

/* add_value's usual case, an integer type of 32 bits or less (|v| < 2^32):
 * added modulo 2^64 (never undefined), then one test of the result's high
 * word, 2 instructions on the CPU32 (an add that sets the sign, a branch):
 * only a result of magnitude 2^62 or more goes to pdl_sum_far, and an
 * addition that wrapped always lands there (from within 2^32 of one int64
 * limit to within 2^32 of the other). */
static inline __attribute__((always_inline)) int pdl_add_small_(int64_t *sum, int64_t v)
{
    uint64_t n = (uint64_t)*sum + (uint64_t)v;
    *sum = pdl_i64_(n);
    if ((uint32_t)(n >> 32) + 0x40000000u >= 0x80000000u)
        pdl_sum_far(sum, v);
    return 1;
}

static inline int pdl_add_u64_(int64_t *sum, uint64_t v)
{
    return pdl_add_int_(sum, v > (uint64_t)INT64_MAX ? INT64_MAX : (int64_t)v);
}

/* IEEE 754 binary32: exponent all ones is NaN or infinity; a biased
 * exponent of 127 + 63 or more is a magnitude of at least 2^63. */
static inline int pdl_add_float_(int64_t *sum, float v)
{
    union { float f; uint32_t u; } bits;
    uint32_t exponent;
    bits.f = v;
    exponent = (bits.u >> 23) & 0xFFu;
    if (exponent == 0xFFu)
        return pdl_not_finite();
    if (exponent >= 127u + 63u)
        return pdl_add_int_(sum, (bits.u >> 31) != 0u ? INT64_MIN : INT64_MAX);
    return pdl_add_int_(sum, (int64_t)v);
}

/* IEEE 754 binary64, as above with exponent bias 1023. */
static inline int pdl_add_double_(int64_t *sum, double v)
{
    union { double d; uint64_t u; } bits;
    uint32_t exponent;
    bits.d = v;
    exponent = (uint32_t)(bits.u >> 52) & 0x7FFu;
    if (exponent == 0x7FFu)
        return pdl_not_finite();
    if (exponent >= 1023u + 63u)
        return pdl_add_int_(sum, (bits.u >> 63) != 0u ? INT64_MIN : INT64_MAX);
    return pdl_add_int_(sum, (int64_t)v);
}

/* long double's format differs between targets: compared, not dissected
 * (v - v is NaN, so not 0, exactly when v is infinite or NaN). */
static inline int pdl_add_ldouble_(int64_t *sum, long double v)
{
    if (v != v || v - v != 0.0L)
        return pdl_not_finite();
    if (v >= 0x1p63L)
        return pdl_add_int_(sum, INT64_MAX);
    if (v < -0x1p63L)
        return pdl_add_int_(sum, INT64_MIN);
    return pdl_add_int_(sum, (int64_t)v);
}

/* ---- processes ---- */
typedef void (*pdl_process_fn)(void);

/* Registers a process: runs every cycle (pv 0), or every 2^pv cycles.
 * Returns the process id (0, 1, ...) or an error. The macros keep the
 * function's name as written (pdl_process_name: what a runner shows). */
int add_process(pdl_process_fn f);
int add_process_pv(pdl_process_fn f, int pv);
int pdl_add_process_named(pdl_process_fn f, int pv, const char *name, const char *call);
#define add_process(f) pdl_add_process_named((f), 0, #f, "add_process")
#define add_process_pv(f, pv) pdl_add_process_named((f), (pv), #f, "add_process_pv")

/* The processes as a runner outside the program sees them: how many, each
 * one's name and how often it ran since run_pdl(). One table, in memory, so
 * that the arena (emu/world) can read it from the emulated board too
 * (pdl_process_table: count, runs[], then names[] as pointers). */
struct pdl_process_table {
    uint32_t count;
    uint32_t runs[PDL_MAX_PROCESSES];
    const char *names[PDL_MAX_PROCESSES];
};
extern struct pdl_process_table pdl_process_table;
int pdl_process_count(void);
/* "" for an id that is not a process. */
const char *pdl_process_name(int id);
uint32_t pdl_process_runs(int id);

/* ---- time ---- */
/* Time from the start of the previous cycle to the start of this one (the
 * nominal cycle period in the first cycle). */
float dt(void);
uint32_t dt_us(void);
/* In a process body: the time from the start of the cycle in which this
 * process last ran to the start of this cycle (2^pv nominal periods on its
 * first run); for a pv 0 process the same as dt(). 0 outside a process. */
float dt_process(void);
uint32_t dt_process_us(void);

/* ---- running ---- */
/* Cycle rate f0 in Hz (before run_pdl). On the board it is rounded to a
 * whole number of kernel ticks (pdl_frequency() tells what it became);
 * default PDL_DEFAULT_HZ. */
#ifndef PDL_DEFAULT_HZ
#define PDL_DEFAULT_HZ 100u
#endif
int pdl_set_frequency(uint32_t hz);
/* The cycle rate in effect, in millihertz (1024 Hz = 1024000). */
uint32_t pdl_frequency_mhz(void);
/* Nominal cycle period in microseconds. */
uint32_t pdl_period_us(void);

/* Plans the processes (bsched_init) and starts the cycles: on the board the
 * cycle thread (highest application priority) starts; on the host nothing
 * runs until pdl_run_cycles(). After it, add_process/add_quantity/bind are
 * refused. */
int run_pdl(void);
/* Board: asks the cycle thread to stop after its current cycle and waits
 * for it (bounded: timeout_ms). Host: stops accepting cycles. */
int pdl_stop(uint32_t timeout_ms);
/* Forgets every process, quantity and binding (not while the cycle thread runs). */
int pdl_reset(void);

/* For main after run_pdl(): waits ms milliseconds of the program's time
 * while the cycles run (board: the kernel clock; host: the simulated clock,
 * the cycles in between run first), and the time since the start (board:
 * since boot; host: the start of the current cycle). A program that keeps to
 * pdl.h, these and the C library runs unchanged on the board and on the
 * host (make run APP=x HOST=1). */
int pdl_sleep_ms(uint32_t ms);
uint32_t pdl_uptime_ms(void);

struct pdl_stats {
    uint32_t cycles;            /* cycles completed */
    uint32_t process_runs;      /* process bodies run */
    uint32_t commits;           /* quantities committed (with contributions) */
    uint32_t overruns;          /* releases missed because a cycle ran late */
    uint32_t overrun_events;    /* cycles that overran */
    uint32_t max_cycle_ticks;   /* longest cycle in kernel ticks (board) */
    uint32_t misuse;            /* refused calls */
    uint32_t driver_errors;     /* actuator writes a driver refused */
    int last_driver_code;       /* the driver's code of the last refused write */
    int last_error;             /* the last refused call's code (0 = none) */
};
void pdl_get_stats(struct pdl_stats *out);
/* Human-readable name of a PDL_ERR_* code. */
const char *pdl_strerror(int code);

/* ---- binding quantities to the board's ports (pdl_bind.c) ----
 * The numbers and ranges are the board's port table (boards/NAME/ports.c);
 * on the RoboCube, and on the host (the arena's RoboCube), they are:
 * Sensor ports (read at the start of each cycle, from the drivers' sampler
 * snapshot on the RoboCube):
 *   PDL_ANALOG_IN  0..23  8-bit analog inputs AIN0-23 (0..255)
 *   PDL_BINARY_IN  1..5   DUART inputs IP1-IP5 (0/1)
 *   PDL_BIO_IN     0..15  binary I/O lines BIO0-15 read as inputs (0/1)
 * Actuator ports (written at the end of each cycle when the value changed):
 *   PDL_MOTOR      0..2   motor set-point, permille -1000..1000 (open loop)
 *   PDL_ANALOG_OUT 0..5   analog outputs AOUT0-5 (0..255)
 *   PDL_BIO_OUT    0..15  binary I/O lines (0/1)
 *   PDL_FAST_OUT   0..15  fast binary outputs (0/1)
 *   PDL_PWM        0..15  TPU channel PWM duty, permille 0..1000 at the channel's frequency (1 kHz unless set)
 *   PDL_LED        0      the board LED (0 off, else on)
 * A value outside a port's range is clipped to it when written. */
enum pdl_port {
    PDL_ANALOG_IN = 1, PDL_BINARY_IN, PDL_BIO_IN,
    PDL_MOTOR, PDL_ANALOG_OUT, PDL_BIO_OUT, PDL_FAST_OUT, PDL_PWM, PDL_LED,
    PDL_PORT_END
};
int pdl_bind_sensor(struct pdl_sensor *q, enum pdl_port port, unsigned index);
int pdl_bind_actuator(struct pdl_quantity *q, enum pdl_port port, unsigned index);
/* One line of a binding table (pdl_bind_table binds them all). */
struct pdl_binding {
    struct pdl_head *q;  /* &sensor.head or &quantity.head */
    enum pdl_port port;
    unsigned index;
};
int pdl_bind_table(const struct pdl_binding *table, size_t count);

/* ---- fixed-point help for integer quantities ---- */
/* a * b / 2^shift, rounded toward minus infinity (the arithmetic shift GCC and
 * Clang define), saturated to the int32 range; a shift of 63 or more gives 0 or
 * -1. Never undefined: the product is exact in 64 bits. */
static inline int32_t pdl_mul_shift(int32_t a, int32_t b, unsigned shift)
{
    int64_t p = (int64_t)a * b;
    p >>= shift < 63u ? shift : 63u;
    return p > INT32_MAX ? INT32_MAX : p < INT32_MIN ? INT32_MIN : (int32_t)p;
}

#endif /* PDL_H */
