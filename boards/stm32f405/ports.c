/*
 * The STM32F405's ports (boards/include/board_ports.h): its port table and
 * the port access PDL reaches them through (pdl/ports/board.c). What QEMU's
 * netduinoplus2 models is used; the rest is a simulated I/O set in RAM
 * (struct stm32f405_sim_io), said so here:
 *
 *   analog in   n = 0..15  ADC1 channel n, one conversion per read (QEMU: a
 *                          synthetic sequence, +7 per conversion), 12 bits -> 8
 *   pwm         n = 0..3   TIM3 CCR1..4, 0..1000 per mille of ARR = 999
 *                          (QEMU models the registers, not the pins)
 *   led         0          the status LED (PA10; GPIO not modelled)
 *   simulated:  binary io n (0..15) -> bio bit n, read back as an input;
 *               motor n (0..3), analog out n (0..7), fast out n (0..7)
 *               -> stm32f405_sim_io; binary in n (0..7) reads
 *               stm32f405_sim_io.binin bit n (0 unless the image sets it).
 *   no encoders.
 */
#include <stddef.h>

#include "boards/include/board_led.h"
#include "boards/include/board_ports.h"
#include "boards/stm32f405/stm32f405.h"
#include "boards/stm32f405/board_stm32f405.h"

#define ADC_CHANNELS 16u
#define PWM_CHANNELS 4u
#define SIM_MOTORS 4u
#define SIM_ANALOG_OUTS 8u
#define SIM_FAST_OUTS 8u
#define ADC_POLLS 16u

const struct board_port_range board_ports[BOARD_PORT_KINDS] = {
    [BOARD_PORT_ANALOG_IN]  = {"analog in",  "ad",    0, ADC_CHANNELS - 1u, 1, 0, 0, 255, ""},
    [BOARD_PORT_ANALOG_OUT] = {"analog out", "da",    0, SIM_ANALOG_OUTS - 1u, 0, 1, 0, 255, ""},
    [BOARD_PORT_BINARY_IO]  = {"binary io",  "bio",   0, 15, 1, 1, 0, 1, ""},
    [BOARD_PORT_BINARY_IN]  = {"binary in",  "bin",   0, 7,  1, 0, 0, 1, ""},
    [BOARD_PORT_FAST_OUT]   = {"fast out",   "fast",  0, SIM_FAST_OUTS - 1u, 1, 1, 0, 1, ""},
    [BOARD_PORT_PWM]        = {"pwm",        "pwm",   0, PWM_CHANNELS - 1u, 1, 1, 0, 1000, "per-mille"},
    [BOARD_PORT_MOTOR]      = {"motor",      "motor", 0, SIM_MOTORS - 1u, 1, 1, -1000, 1000, "per-mille"},
    [BOARD_PORT_ENCODER]    = {"encoder",    "enc",   1, 0,  0, 0, 0, 0, "counts"},
    [BOARD_PORT_LED]        = {"led",        "led",   0, 0,  1, 1, 0, 1, ""},
};

struct stm32f405_sim_io stm32f405_sim_io;

#define TIM3_BASE   0x40000400u
#define TIM_CR1(b)  STM32_REG32((b) + 0x00u)
#define TIM_CCMR1(b) STM32_REG32((b) + 0x18u)
#define TIM_CCMR2(b) STM32_REG32((b) + 0x1Cu)
#define TIM_CCER(b) STM32_REG32((b) + 0x20u)
#define TIM_PSC(b)  STM32_REG32((b) + 0x28u)
#define TIM_ARR(b)  STM32_REG32((b) + 0x2Cu)
#define TIM_CCR(b, n) STM32_REG32((b) + 0x34u + 4u * (n))
#define RCC_APB1ENR_TIM3EN (1u << 1)

/* One conversion of ADC1 channel ch. A real chip sets EOC within about 15
 * ADC clocks, well inside the polls; QEMU 7.2's model never sets EOC and
 * converts when DR is read, so DR is read after the polls either way, and
 * the conversions that ended without EOC are counted (adc_no_eoc). */
static int adc_convert(unsigned ch)
{
    unsigned polls;
    ADC_SQR3(ADC1_BASE) = ch;
    ADC_CR2(ADC1_BASE) = ADC_CR2_ADON | ADC_CR2_SWSTART;
    for (polls = 0; polls < ADC_POLLS; polls++)
        if ((ADC_SR(ADC1_BASE) & ADC_SR_EOC) != 0u)
            break;
    if (polls == ADC_POLLS)
        stm32f405_sim_io.adc_no_eoc++;
    return (int)(ADC_DR(ADC1_BASE) & 0xFFFu);
}

int board_port_read(enum board_port_kind kind, unsigned index, int32_t *value)
{
    switch (kind) {
    case BOARD_PORT_ANALOG_IN:
        *value = (int32_t)((unsigned)adc_convert(index) >> 4);
        return 0;
    case BOARD_PORT_BINARY_IO:
        *value = (int32_t)((stm32f405_sim_io.bio >> index) & 1u);
        return 0;
    case BOARD_PORT_BINARY_IN:
        *value = (int32_t)((stm32f405_sim_io.binin >> index) & 1u);
        return 0;
    default:
        return -1;
    }
}

int board_port_write(enum board_port_kind kind, unsigned index, int32_t v)
{
    switch (kind) {
    case BOARD_PORT_PWM:
        TIM_CCR(TIM3_BASE, index) = (uint32_t)v;
        return 0;
    case BOARD_PORT_LED:
        led_set(v != 0);
        return 0;
    case BOARD_PORT_BINARY_IO:
        if (v != 0)
            stm32f405_sim_io.bio = (uint16_t)(stm32f405_sim_io.bio | (1u << index));
        else
            stm32f405_sim_io.bio = (uint16_t)(stm32f405_sim_io.bio & ~(1u << index));
        return 0;
    case BOARD_PORT_MOTOR:
        stm32f405_sim_io.motor[index] = v;
        return 0;
    case BOARD_PORT_ANALOG_OUT:
        stm32f405_sim_io.analog_out[index] = v;
        return 0;
    case BOARD_PORT_FAST_OUT:
        stm32f405_sim_io.fast_out[index] = v;
        return 0;
    default:
        return -1;
    }
}

int board_port_start(enum board_port_kind kind)
{
    static int adc_up, pwm_up;
    if (!adc_up && kind == BOARD_PORT_ANALOG_IN) {
        RCC_APB2ENR |= RCC_APB2ENR_ADC1EN;
        ADC_CR2(ADC1_BASE) = ADC_CR2_ADON;
        adc_up = 1;
    }
    if (!pwm_up && kind == BOARD_PORT_PWM) {
        RCC_APB1ENR |= RCC_APB1ENR_TIM3EN;
        TIM_PSC(TIM3_BASE) = 0;
        TIM_ARR(TIM3_BASE) = 999u;             /* 1000 steps: 48 kHz in QEMU's 48 MHz timer */
        TIM_CCMR1(TIM3_BASE) = 0x6868u;        /* PWM mode 1, preload, channels 1 and 2 */
        TIM_CCMR2(TIM3_BASE) = 0x6868u;        /* channels 3 and 4 */
        TIM_CCER(TIM3_BASE) = 0x1111u;         /* outputs on */
        TIM_CR1(TIM3_BASE) = 1u;               /* counter on */
        pwm_up = 1;
    }
    return 0;
}
