/*
 * The PDL runtime's ports on the STM32F405 (pdl/pdl_board.c built with
 * PDL_PORTS_EXTERNAL). What QEMU's netduinoplus2 models is used; the rest is
 * a simulated I/O set in RAM (struct stm32f405_sim_io), said so here:
 *
 *   PDL_ANALOG_IN  n = 0..15  ADC1 channel n, one conversion per cycle
 *                             (QEMU: a synthetic sequence, +7 per
 *                             conversion), 12 bits -> 8
 *   PDL_PWM        n = 0..3   TIM3 CCR1..4, 0..1000 per mille of ARR = 999
 *                             (QEMU models the registers, not the pins)
 *   PDL_LED        0          the status LED (PA10; GPIO not modelled)
 *   simulated:     PDL_BIO_OUT n -> bio bit n, read back by PDL_BIO_IN n;
 *                  PDL_MOTOR n (0..3), PDL_ANALOG_OUT n (0..7),
 *                  PDL_FAST_OUT n (0..7) -> stm32f405_sim_io; PDL_BINARY_IN
 *                  reads stm32f405_sim_io.binin (0 unless the image sets it).
 */
#include "pdl/pdl_internal.h"
#include "boards/include/board_led.h"
#include "boards/stm32f405/stm32f405.h"
#include "boards/stm32f405/board_stm32f405.h"

struct stm32f405_sim_io stm32f405_sim_io;

#define ADC_CHANNELS 16u
#define PWM_CHANNELS 4u
#define ADC_POLLS 16u

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

void pdl_platform_read_inputs(struct pdl_inputs *in)
{
    unsigned i;
    uint32_t valid = PDL_VALID_BIO0 | PDL_VALID_BIO1 | PDL_VALID_BININ;
    for (i = 0; i < 24u; i++)
        in->analog[i] = 0;
    if (pdl_bind_uses(PDL_ANALOG_IN)) {
        for (i = 0; i < ADC_CHANNELS; i++) {
            in->analog[i] = (uint8_t)((unsigned)adc_convert(i) >> 4);
            valid |= 1ul << i;
        }
    }
    in->bio = stm32f405_sim_io.bio;
    in->binin = stm32f405_sim_io.binin;
    in->valid = valid;
}

int pdl_platform_write(enum pdl_port port, unsigned index, int32_t v)
{
    switch (port) {
    case PDL_PWM:
        if (index >= PWM_CHANNELS)
            return -1;
        TIM_CCR(TIM3_BASE, index) = (uint32_t)(v < 0 ? 0 : v > 1000 ? 1000 : v);
        return 0;
    case PDL_LED:
        led_set(v != 0);
        return 0;
    case PDL_BIO_OUT:
        if (index >= 16u)
            return -1;
        if (v != 0)
            stm32f405_sim_io.bio = (uint16_t)(stm32f405_sim_io.bio | (1u << index));
        else
            stm32f405_sim_io.bio = (uint16_t)(stm32f405_sim_io.bio & ~(1u << index));
        return 0;
    case PDL_MOTOR:
        if (index >= 4u)
            return -1;
        stm32f405_sim_io.motor[index] = v;
        return 0;
    case PDL_ANALOG_OUT:
        if (index >= 8u)
            return -1;
        stm32f405_sim_io.analog_out[index] = v;
        return 0;
    case PDL_FAST_OUT:
        if (index >= 8u)
            return -1;
        stm32f405_sim_io.fast_out[index] = v;
        return 0;
    default:
        return -1;
    }
}

int pdl_platform_start_ports(void)
{
    static int adc_up, pwm_up;
    if (!adc_up && pdl_bind_uses(PDL_ANALOG_IN)) {
        RCC_APB2ENR |= RCC_APB2ENR_ADC1EN;
        ADC_CR2(ADC1_BASE) = ADC_CR2_ADON;
        adc_up = 1;
    }
    if (!pwm_up && pdl_bind_uses(PDL_PWM)) {
        RCC_APB1ENR |= RCC_APB1ENR_TIM3EN;
        TIM_PSC(TIM3_BASE) = 0;
        TIM_ARR(TIM3_BASE) = 999u;             /* 1000 steps: 48 kHz in QEMU's 48 MHz timer */
        TIM_CCMR1(TIM3_BASE) = 0x6868u;        /* PWM mode 1, preload, channels 1 and 2 */
        TIM_CCMR2(TIM3_BASE) = 0x6868u;        /* channels 3 and 4 */
        TIM_CCER(TIM3_BASE) = 0x1111u;         /* outputs on */
        TIM_CR1(TIM3_BASE) = 1u;               /* counter on */
        pwm_up = 1;
    }
    return PDL_OK;
}
