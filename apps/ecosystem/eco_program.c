/*
 * The ecosystem robot's behaviours (see eco_program.h). Integer arithmetic
 * only (the CPU32 has no FPU). Conventions: speed and turn in permille of
 * full motor duty; turn > 0 is counter-clockwise (the right wheel faster).
 * Every process reads only values of the previous cycle and adds to
 * quantities, so the order in which the B-scheduler runs them is irrelevant.
 */
#include "eco_program.h"

/* Priority values (the process runs every 2^pv cycles). */
const uint8_t eco_pv[ECO_PROCS] = {
    [ECO_BUMP] = 0, [ECO_AVOID] = 0, [ECO_CRUISE] = 1, [ECO_PHOTO] = 1,
    [ECO_DOCK] = 1, [ECO_WANDER] = 2, [ECO_COMPETE] = 2, [ECO_BATTERY] = 4,
};

const char *const eco_names[ECO_PROCS] = {
    "bump", "avoid", "cruise", "photo", "dock", "wander", "compete", "battery",
};

/* Tuning (codes are the world's 8-bit sensor codes). */
#define CRUISE_SPEED      550   /* permille */
#define CREEP_SPEED       280   /* near the light when hungry */
#define IR_THRESHOLD       38   /* ~0.4 m from the sensor */
#define IR_TURN_GAIN        3
#define IR_SPEED_GAIN       1
#define LIGHT_TURN_GAIN     3
#define LIGHT_BRIGHT      150   /* sum of both light codes: the station is near */
#define LIGHT_DARK         40   /* sum below this: the light is behind us */
#define ESCAPE_CYCLES      40
#define ESCAPE_SPEED     (-250)
#define ESCAPE_TURN       450
#define LEAVE_CYCLES       70   /* turning round after a full charge */
#define LEAVE_TURN        500
#define WANDER_KICK       120
#define COMPETE_GAIN        2
#define COMPETE_NEAR      150   /* competitor light sum: close to a lamp */
#define BAT_HUNGRY        184   /* ~7.2 V: about 50 % charge */
#define BAT_FED_CHARGING  216   /* ~8.45 V with the charge boost: ~95 % */
#define BAT_FED           212

static void add(struct eco_program *p, enum eco_process who, struct eco_quantity *q, int32_t v)
{
    q->next += v;
    if (q == &p->speed) {
        p->contrib[who][0] += v;
    } else if (q == &p->turn) {
        p->contrib[who][1] += v;
    }
}

static int32_t clip(int32_t v, int32_t lo, int32_t hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

static int32_t pos(int32_t v)
{
    return v > 0 ? v : 0;
}

static uint32_t rng_next(struct eco_program *p)
{
    uint32_t x = p->rng;           /* xorshift32 */
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    return p->rng = x;
}

static int hungry(const struct eco_program *p)
{
    return p->hunger.value > 500;
}

static void bump(struct eco_program *p)
{
    if (p->escape_cycles == 0 && (p->in.bump_l || p->in.bump_r)) {
        p->escape_cycles = ESCAPE_CYCLES;
        p->escape_turn = p->in.bump_l ? -ESCAPE_TURN : ESCAPE_TURN;
    }
    if (p->escape_cycles > 0 && p->escape_turn != LEAVE_TURN) {
        p->escape_cycles--;
        add(p, ECO_BUMP, &p->speed, ESCAPE_SPEED - p->speed.value);
        add(p, ECO_BUMP, &p->turn, p->escape_turn - p->turn.value);
    }
}

static void avoid(struct eco_program *p)
{
    int32_t threshold = IR_THRESHOLD, el, er;

    if (hungry(p) && p->in.charging) {
        return;                     /* docked: walls near the station are fine */
    }
    if (!hungry(p) && p->in.comp_l + p->in.comp_r > COMPETE_NEAR) {
        threshold += 60;            /* let the robot reach the competitor */
    }
    el = pos(p->in.ir_l - threshold);
    er = pos(p->in.ir_r - threshold);
    if (el == 0 && er == 0) {
        p->avoid_dir = 0;
        return;
    }
    /* Keep turning the way we started while anything is in view, so that a
     * corner (both sides seeing a wall in turn) does not make us dither. */
    if (p->avoid_dir == 0) {
        p->avoid_dir = el >= er ? -1 : 1;
    }
    add(p, ECO_AVOID, &p->turn, p->avoid_dir * IR_TURN_GAIN * (el > er ? el : er));
    add(p, ECO_AVOID, &p->speed, -IR_SPEED_GAIN * (el > er ? el : er));
}

static void cruise(struct eco_program *p)
{
    int32_t target = CRUISE_SPEED;
    if (hungry(p) && p->in.charging) {
        target = 0;                 /* docked */
    } else if (hungry(p) && p->in.light_l + p->in.light_r > LIGHT_BRIGHT) {
        target = CREEP_SPEED;
    }
    add(p, ECO_CRUISE, &p->speed, (target - p->speed.value) / 4);
    add(p, ECO_CRUISE, &p->turn, -p->turn.value / 4);
}

static void photo(struct eco_program *p)
{
    int32_t sum = p->in.light_l + p->in.light_r;
    if (!hungry(p) || p->in.charging) {
        return;
    }
    /* Light out of sight (behind us or shadowed): no pull at all, so that
     * cruise and wander carry the robot on until it sees the light again (a
     * search turn here made it circle on the spot behind an obstacle). */
    if (sum >= LIGHT_DARK) {
        add(p, ECO_PHOTO, &p->turn, LIGHT_TURN_GAIN * (p->in.light_l - p->in.light_r));
    }
}

static void dock(struct eco_program *p)
{
    if (hungry(p) && p->in.charging) {
        add(p, ECO_DOCK, &p->speed, -p->speed.value);
        add(p, ECO_DOCK, &p->turn, -p->turn.value);
        p->escape_cycles = LEAVE_CYCLES;   /* turn round when fed */
        p->escape_turn = LEAVE_TURN;
    } else if (!hungry(p) && p->escape_turn == LEAVE_TURN && p->escape_cycles > 0) {
        p->escape_cycles -= 2;             /* pv 1: every other cycle */
        if (p->escape_cycles <= 0) {
            p->escape_cycles = 0;
            p->escape_turn = 0;
        }
        add(p, ECO_DOCK, &p->speed, -p->speed.value);
        add(p, ECO_DOCK, &p->turn, LEAVE_TURN - p->turn.value);
    }
}

static void wander(struct eco_program *p)
{
    int32_t kick = (int32_t)(rng_next(p) % (2u * WANDER_KICK + 1u)) - WANDER_KICK;
    if (hungry(p) && p->in.charging) {
        return;
    }
    add(p, ECO_WANDER, &p->turn, kick / 2);
}

static void compete(struct eco_program *p)
{
    if (hungry(p)) {
        return;
    }
    add(p, ECO_COMPETE, &p->turn, COMPETE_GAIN * (p->in.comp_l - p->in.comp_r));
}

static void battery(struct eco_program *p)
{
    int32_t level;
    p->battery_avg += (16 * p->in.battery - p->battery_avg) / 4;
    level = p->battery_avg / 16;
    if (level < BAT_HUNGRY) {
        add(p, ECO_BATTERY, &p->hunger, 1000 - p->hunger.value);
    } else if (level >= (p->in.charging ? BAT_FED_CHARGING : BAT_FED)) {
        add(p, ECO_BATTERY, &p->hunger, -p->hunger.value);
    }
}

void eco_init(struct eco_program *p, uint32_t seed)
{
    struct eco_program zero = {0};
    *p = zero;
    p->speed.min = -1000;
    p->speed.max = 1000;
    p->turn.min = -1000;
    p->turn.max = 1000;
    p->hunger.min = 0;
    p->hunger.max = 1000;
    p->rng = seed ? seed : 0x2545F491u;
    p->battery_avg = 16 * 255;    /* full until measured */
}

void eco_begin_cycle(struct eco_program *p, const struct eco_inputs *in)
{
    p->in = *in;
}

void eco_run(struct eco_program *p, unsigned index)
{
    static void (*const body[ECO_PROCS])(struct eco_program *) = {
        [ECO_BUMP] = bump, [ECO_AVOID] = avoid, [ECO_CRUISE] = cruise,
        [ECO_PHOTO] = photo, [ECO_DOCK] = dock, [ECO_WANDER] = wander,
        [ECO_COMPETE] = compete, [ECO_BATTERY] = battery,
    };
    if (index < ECO_PROCS) {
        p->contrib[index][0] = 0;
        p->contrib[index][1] = 0;
        p->runs[index]++;
        body[index](p);
    }
}

static void commit(struct eco_quantity *q)
{
    q->value = clip(q->value + q->next, q->min, q->max);
    q->next = 0;
}

void eco_end_cycle(struct eco_program *p)
{
    commit(&p->speed);
    commit(&p->turn);
    commit(&p->hunger);
    p->motor_l = clip(p->speed.value - p->turn.value, -1000, 1000);
    p->motor_r = clip(p->speed.value + p->turn.value, -1000, 1000);
}
