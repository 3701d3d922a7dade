/*
 * The ecosystem robot's behaviours, a PDL program (see eco_program.h).
 * Integer quantities only (the CPU32 has no FPU). Conventions: speed and
 * turn in permille of full motor duty; turn > 0 is counter-clockwise (the
 * right wheel faster). Every process reads only values of the previous
 * cycle and adds to quantities, so the order in which the B-scheduler runs
 * them is irrelevant. Process-private state lives in statics.
 */
#include "eco_program.h"
#include "pdl/robot.h"

struct pdl_sensor light_l, light_r, ir_l, ir_r, battery, comp_l, comp_r;
struct pdl_sensor bump_l, bump_r, charger;
struct pdl_quantity speed, turn, hunger, motor_l, motor_r;
int32_t eco_contrib[ECO_PROCS][2];
uint32_t eco_last_cycle[ECO_PROCS];

/* Priority values (the process runs every 2^pv cycles). */
const uint8_t eco_pv[ECO_PROCS] = {
    [ECO_BUMP] = 0, [ECO_AVOID] = 0, [ECO_CRUISE] = 1, [ECO_PHOTO] = 1,
    [ECO_DOCK] = 1, [ECO_WANDER] = 2, [ECO_COMPETE] = 2, [ECO_BATTERY] = 4,
    [ECO_MOTORS] = 0,
};

const char *const eco_names[ECO_PROCS] = {
    "bump", "avoid", "cruise", "photo", "dock", "wander", "compete", "battery", "motors",
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

/* add_value plus the record of what the process contributed (live view). */
#define ADD(who, q, e)                                      \
    do {                                                    \
        int32_t add_v_ = (int32_t)(e);                      \
        add_value(q, add_v_);                               \
        if (&(q) == &speed) {                               \
            eco_contrib[who][0] += add_v_;                  \
        } else if (&(q) == &turn) {                         \
            eco_contrib[who][1] += add_v_;                  \
        }                                                   \
    } while (0)

/* Start of every process body: its contribution record and cycle. */
static void ran(enum eco_process who)
{
    struct pdl_stats st;
    pdl_get_stats(&st);
    eco_last_cycle[who] = st.cycles;
    eco_contrib[who][0] = 0;
    eco_contrib[who][1] = 0;
}

static int32_t pos(int32_t v)
{
    return v > 0 ? v : 0;
}

static uint32_t rng_state = 0x2545F491u;

static uint32_t rng_next(void)
{
    uint32_t x = rng_state;        /* xorshift32 */
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    return rng_state = x;
}

static int hungry(void)
{
    return value(hunger) > 500;
}

static int charging(void)
{
    return value(charger) == 0;
}

/* Shared by bump and dock (the escape or leave manoeuvre under way). */
static int32_t escape_cycles, escape_turn;
/* avoid: -1 right, +1 left, 0 nothing in view. */
static int32_t avoid_dir;
/* battery: running mean of the battery code, x16. */
static int32_t battery_avg;

static void bump(void)
{
    ran(ECO_BUMP);
    if (escape_cycles == 0 && ((value(bump_l) == 0) || (value(bump_r) == 0))) {
        escape_cycles = ESCAPE_CYCLES;
        escape_turn = (value(bump_l) == 0) ? -ESCAPE_TURN : ESCAPE_TURN;
    }
    if (escape_cycles > 0 && escape_turn != LEAVE_TURN) {
        escape_cycles--;
        ADD(ECO_BUMP, speed, ESCAPE_SPEED - value(speed));
        ADD(ECO_BUMP, turn, escape_turn - value(turn));
    }
}

static void avoid(void)
{
    ran(ECO_AVOID);
    int32_t threshold = IR_THRESHOLD, el, er;

    if (hungry() && charging()) {
        return;                     /* docked: walls near the station are fine */
    }
    if (!hungry() && value(comp_l) + value(comp_r) > COMPETE_NEAR) {
        threshold += 60;            /* let the robot reach the competitor */
    }
    el = pos(value(ir_l) - threshold);
    er = pos(value(ir_r) - threshold);
    if (el == 0 && er == 0) {
        avoid_dir = 0;
        return;
    }
    /* Keep turning the way we started while anything is in view, so that a
     * corner (both sides seeing a wall in turn) does not make us dither. */
    if (avoid_dir == 0) {
        avoid_dir = el >= er ? -1 : 1;
    }
    ADD(ECO_AVOID, turn, avoid_dir * IR_TURN_GAIN * (el > er ? el : er));
    ADD(ECO_AVOID, speed, -IR_SPEED_GAIN * (el > er ? el : er));
}

static void cruise(void)
{
    ran(ECO_CRUISE);
    int32_t target = CRUISE_SPEED;
    if (hungry() && charging()) {
        target = 0;                 /* docked */
    } else if (hungry() && value(light_l) + value(light_r) > LIGHT_BRIGHT) {
        target = CREEP_SPEED;
    }
    ADD(ECO_CRUISE, speed, (target - value(speed)) / 4);
    ADD(ECO_CRUISE, turn, -value(turn) / 4);
}

static void photo(void)
{
    ran(ECO_PHOTO);
    int32_t sum = value(light_l) + value(light_r);
    if (!hungry() || charging()) {
        return;
    }
    /* Light out of sight (behind us or shadowed): no pull at all, so that
     * cruise and wander carry the robot on until it sees the light again (a
     * search turn here made it circle on the spot behind an obstacle). */
    if (sum >= LIGHT_DARK) {
        ADD(ECO_PHOTO, turn, LIGHT_TURN_GAIN * (value(light_l) - value(light_r)));
    }
}

static void dock(void)
{
    ran(ECO_DOCK);
    if (hungry() && charging()) {
        ADD(ECO_DOCK, speed, -value(speed));
        ADD(ECO_DOCK, turn, -value(turn));
        escape_cycles = LEAVE_CYCLES;   /* turn round when fed */
        escape_turn = LEAVE_TURN;
    } else if (!hungry() && escape_turn == LEAVE_TURN && escape_cycles > 0) {
        escape_cycles -= 2;             /* pv 1: every other cycle */
        if (escape_cycles <= 0) {
            escape_cycles = 0;
            escape_turn = 0;
        }
        ADD(ECO_DOCK, speed, -value(speed));
        ADD(ECO_DOCK, turn, LEAVE_TURN - value(turn));
    }
}

static void wander(void)
{
    ran(ECO_WANDER);
    int32_t kick = (int32_t)(rng_next() % (2u * WANDER_KICK + 1u)) - WANDER_KICK;
    if (hungry() && charging()) {
        return;
    }
    ADD(ECO_WANDER, turn, kick / 2);
}

static void compete(void)
{
    ran(ECO_COMPETE);
    if (hungry()) {
        return;
    }
    ADD(ECO_COMPETE, turn, COMPETE_GAIN * (value(comp_l) - value(comp_r)));
}

static void battery_monitor(void)
{
    ran(ECO_BATTERY);
    int32_t level;
    battery_avg += (16 * value(battery) - battery_avg) / 4;
    level = battery_avg / 16;
    if (level < BAT_HUNGRY) {
        ADD(ECO_BATTERY, hunger, 1000 - value(hunger));
    } else if (level >= (charging() ? BAT_FED_CHARGING : BAT_FED)) {
        ADD(ECO_BATTERY, hunger, -value(hunger));
    }
}

static void motors(void)
{
    ran(ECO_MOTORS);
    add_value(motor_l, value(speed) - value(turn) - value(motor_l));
    add_value(motor_r, value(speed) + value(turn) - value(motor_r));
}

uint32_t eco_ran_mask(uint32_t cycle)
{
    uint32_t mask = 0;
    unsigned i;
    for (i = 0; i < ECO_PROCS; i++) {
        if (eco_last_cycle[i] == cycle) {
            mask |= 1ul << i;
        }
    }
    return mask;
}

int eco_setup(uint32_t seed, int bind)
{
    static void (*const body[ECO_PROCS])(void) = {
        [ECO_BUMP] = bump, [ECO_AVOID] = avoid, [ECO_CRUISE] = cruise,
        [ECO_PHOTO] = photo, [ECO_DOCK] = dock, [ECO_WANDER] = wander,
        [ECO_COMPETE] = compete, [ECO_BATTERY] = battery_monitor, [ECO_MOTORS] = motors,
    };
    /* The arena robot's wiring (pdl/robot.h). */
    const struct pdl_binding wiring[] = {
        {&light_l.head, ROBOT_LIGHT_LEFT}, {&light_r.head, ROBOT_LIGHT_RIGHT},
        {&ir_l.head, ROBOT_IR_LEFT},       {&ir_r.head, ROBOT_IR_RIGHT},
        {&battery.head, ROBOT_BATTERY},
        {&comp_l.head, ROBOT_COMP_LEFT},   {&comp_r.head, ROBOT_COMP_RIGHT},
        {&bump_l.head, ROBOT_BUMPER_LEFT}, {&bump_r.head, ROBOT_BUMPER_RIGHT},
        {&charger.head, ROBOT_CHARGING},
        {&motor_l.head, ROBOT_MOTOR_LEFT}, {&motor_r.head, ROBOT_MOTOR_RIGHT},
    };
    struct pdl_sensor *analog[] = {&light_l, &light_r, &ir_l, &ir_r, &battery, &comp_l, &comp_r};
    struct pdl_sensor *binary[] = {&bump_l, &bump_r, &charger};
    unsigned i;
    int r = PDL_OK;

    rng_state = seed ? seed : 0x2545F491u;
    escape_cycles = escape_turn = avoid_dir = 0;
    battery_avg = 16 * 255;         /* full until measured */
    for (i = 0; i < ECO_PROCS; i++) {
        eco_contrib[i][0] = eco_contrib[i][1] = 0;
        eco_last_cycle[i] = 0xFFFFFFFFu;
    }
    for (i = 0; r == PDL_OK && i < sizeof analog / sizeof analog[0]; i++) {
        r = add_sensor(analog[i], 0, 255);
    }
    for (i = 0; r == PDL_OK && i < sizeof binary / sizeof binary[0]; i++) {
        r = add_sensor(binary[i], 0, 1);
    }
    if (r == PDL_OK) {
        r = add_quantity(&speed, -1000, 1000, 0);
    }
    if (r == PDL_OK) {
        r = add_quantity(&turn, -1000, 1000, 0);
    }
    if (r == PDL_OK) {
        r = add_quantity(&hunger, 0, 1000, 0);
    }
    if (r == PDL_OK) {
        r = add_quantity(&motor_l, -1000, 1000, 0);
    }
    if (r == PDL_OK) {
        r = add_quantity(&motor_r, -1000, 1000, 0);
    }
    if (r == PDL_OK && bind) {
        r = pdl_bind_table(wiring, sizeof wiring / sizeof wiring[0]);
    }
    for (i = 0; r >= 0 && i < ECO_PROCS; i++) {
        r = pdl_add_process_named(body[i], eco_pv[i], eco_names[i], "add_process_pv");
    }
    return r < 0 ? r : PDL_OK;
}
