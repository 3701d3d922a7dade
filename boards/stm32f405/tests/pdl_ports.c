/*
 * PDL target test image of the stm32f405 board (test_stm32f405.py): a PDL
 * program whose ports are the board's (boards/stm32f405/ports.c). Each cycle
 * one process copies ADC1 channel 0 to TIM3's PWM channel 0, another toggles
 * simulated BIO line 3, and a third counts the cycles in which BIO_IN 3
 * reads back what was written the cycle before. After one second main
 * prints what it saw, including TIM3 CCR1 read back from the timer.
 */
#include <stdio.h>

#include "kernel.h"
#include "pdl/pdl.h"
#include "boards/stm32f405/board_stm32f405.h"

#define TIM3_CCR1 (*(volatile uint32_t *)0x40000434u)

static struct pdl_sensor adc0, bio_in3;
static struct pdl_quantity pwm0, bio_out3, led;
static volatile int32_t adc_min = 4096, adc_max = -1, last_pwm = -1;
static volatile uint32_t loop_ok, loop_bad;

static void copy_adc(void)
{
    int32_t a = value(adc0);
    if (a < adc_min)
        adc_min = a;
    if (a > adc_max)
        adc_max = a;
    add_value(pwm0, a * 2 - value(pwm0));
    last_pwm = a * 2;
}

static void toggle(void)
{
    /* what BIO_IN 3 reads this cycle was written at the end of the last one */
    if (value(bio_in3) == value(bio_out3))
        loop_ok++;
    else
        loop_bad++;
    add_value(bio_out3, value(bio_out3) != 0 ? -1 : 1);
    add_value(led, value(bio_out3) != 0 ? -1 : 1);
}

int main(void)
{
    struct pdl_stats st;
    int r = add_sensor(&adc0, 0, 255);
    if (r >= 0) r = add_sensor(&bio_in3, 0, 1);
    if (r >= 0) r = add_quantity(&pwm0, 0, 1000, 0);
    if (r >= 0) r = add_quantity(&bio_out3, 0, 1, 0);
    if (r >= 0) r = add_quantity(&led, 0, 1, 0);
    if (r >= 0) r = pdl_bind_sensor(&adc0, PDL_ANALOG_IN, 0);
    if (r >= 0) r = pdl_bind_sensor(&bio_in3, PDL_BIO_IN, 3);
    if (r >= 0) r = pdl_bind_actuator(&pwm0, PDL_PWM, 0);
    if (r >= 0) r = pdl_bind_actuator(&bio_out3, PDL_BIO_OUT, 3);
    if (r >= 0) r = pdl_bind_actuator(&led, PDL_LED, 0);
    if (r >= 0) r = add_process(copy_adc);
    if (r >= 0) r = add_process(toggle);
    if (r >= 0) r = run_pdl();
    if (r < 0) {
        printf("PDL-PORTS FAIL %s (%d)\n", pdl_strerror(r), r);
        return 1;
    }
    (void)k_sleep_ticks(K_TICK_HZ);
    pdl_get_stats(&st);
    printf("PDL-PORTS cycles=%lu overruns=%lu adc_min=%ld adc_max=%ld pwm=%ld ccr1=%lu "
           "loop_ok=%lu loop_bad=%lu bio=0x%04x adc_no_eoc=%lu\n",
           (unsigned long)st.cycles, (unsigned long)st.overruns, (long)adc_min, (long)adc_max,
           (long)last_pwm, (unsigned long)TIM3_CCR1, (unsigned long)loop_ok,
           (unsigned long)loop_bad, (unsigned)stm32f405_sim_io.bio,
           (unsigned long)stm32f405_sim_io.adc_no_eoc);
    return 0;
}
