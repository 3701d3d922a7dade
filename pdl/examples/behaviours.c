/* Example behaviours (see behaviours.h): integer quantities throughout, so
 * the board needs no soft-float in the cycle. */
#include "pdl/examples/behaviours.h"

struct pdl_sensor light_left, light_right, ir_left, ir_right, battery;
struct pdl_sensor bumper_left, bumper_right;
struct pdl_quantity motor_left, motor_right, seeking_led, hunger, wander_turn;

/* The wiring: one line per quantity. */
static const struct pdl_binding behaviours_bindings[] = {
    {&light_left.head,   PDL_ANALOG_IN, 0},
    {&light_right.head,  PDL_ANALOG_IN, 1},
    {&ir_left.head,      PDL_ANALOG_IN, 2},
    {&ir_right.head,     PDL_ANALOG_IN, 3},
    {&battery.head,      PDL_ANALOG_IN, 4},
    {&bumper_left.head,  PDL_BINARY_IN, 1},
    {&bumper_right.head, PDL_BINARY_IN, 2},
    {&motor_left.head,   PDL_MOTOR, 0},
    {&motor_right.head,  PDL_MOTOR, 1},
    {&seeking_led.head,  PDL_LED, 0},
};

/* Forward drive: a leak toward the cruising speed (1/8 of the gap per cycle). */
static void cruise(void)
{
    add_value(motor_left, (CRUISE_SPEED - value(motor_left)) / 8);
    add_value(motor_right, (CRUISE_SPEED - value(motor_right)) / 8);
}

/* Turn toward the light: the brighter side's wheel slows, the other speeds
 * up. Gain 1/8 when sated up to 1/2 when starving (hunger 1000). */
static void phototaxis(void)
{
    int32_t diff = value(light_left) - value(light_right);   /* > 0: light on the left */
    int32_t turn = diff * (125 + 3 * value(hunger) / 8) / 1000;
    add_value(motor_left, -turn);
    add_value(motor_right, turn);
}

/* Turn away from the nearer obstacle; brake in proportion to the nearer
 * one; back up while a bumper is pressed. */
static void avoid(void)
{
    int32_t l = value(ir_left), r = value(ir_right);
    int32_t near = l > r ? l : r;
    int32_t turn = (l - r) / 2;                             /* > 0: obstacle on the left */
    int32_t brake = near > 64 ? (near - 64) / 2 : 0;
    int32_t back = (value(bumper_left) & value(bumper_right)) ? 0 : 150;   /* 0 = pressed */
    add_value(motor_left, turn - brake - back);
    add_value(motor_right, -turn - brake - back);
}

/* A new pseudo-random turn bias every 8 cycles (pv 3), kept in a quantity so
 * it is part of the program's state like everything else. */
static uint32_t wander_seed = 12345u;
static void wander(void)
{
    int32_t target;
    wander_seed = wander_seed * 1103515245u + 12345u;
    target = (int32_t)((wander_seed >> 16) % 401u) - 200;   /* -200..200 */
    add_value(wander_turn, (target - value(wander_turn)) / 2);
    add_value(motor_left, value(wander_turn) / 4);
    add_value(motor_right, -value(wander_turn) / 4);
}

/* The slow motivation: hunger rises while the battery is low and falls
 * while it is not; the LED shows when the robot is seeking the charger. */
static void battery_monitor(void)
{
    add_value(hunger, value(battery) < BATTERY_LOW ? HUNGER_STEP : -HUNGER_STEP);
    add_value(seeking_led, (value(hunger) > HUNGRY) - value(seeking_led));
}

#define TRY(call)                   \
    do {                            \
        int r_ = (call);            \
        if (r_ < 0)                 \
            return r_;              \
    } while (0)

int behaviours_setup(unsigned which, int bind)
{
    TRY(add_sensor(&light_left, 0, 255));
    TRY(add_sensor(&light_right, 0, 255));
    TRY(add_sensor(&ir_left, 0, 255));
    TRY(add_sensor(&ir_right, 0, 255));
    TRY(add_sensor(&battery, 0, 255));
    TRY(add_sensor(&bumper_left, 0, 1));
    TRY(add_sensor(&bumper_right, 0, 1));
    TRY(add_quantity(&motor_left, -1000, 1000, 0));
    TRY(add_quantity(&motor_right, -1000, 1000, 0));
    TRY(add_quantity(&seeking_led, 0, 1, 0));
    TRY(add_quantity(&hunger, 0, 1000, 0));
    TRY(add_quantity(&wander_turn, -200, 200, 0));
    if (bind)
        TRY(pdl_bind_table(behaviours_bindings,
                           sizeof behaviours_bindings / sizeof behaviours_bindings[0]));
    if (which & BEH_CRUISE)
        TRY(add_process(cruise));
    if (which & BEH_PHOTOTAXIS)
        TRY(add_process(phototaxis));
    if (which & BEH_AVOID)
        TRY(add_process(avoid));
    if (which & BEH_WANDER)
        TRY(add_process_pv(wander, 3));
    if (which & BEH_BATTERY)
        TRY(add_process_pv(battery_monitor, 8));
    return PDL_OK;
}
