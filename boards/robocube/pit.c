/* SIM periodic interrupt timer as the system tick; see pit.h. */
#include "pit.h"

#include <stddef.h>

#include "kernel/arch/cpu32/cpu.h"
#include "boards/robocube/mc68332.h"

static volatile uint32_t tick_count;
static pit_tick_hook_fn tick_hook;
static uint32_t tick_rate_hz;

void pit_interrupt(void)
{
    uint32_t now = tick_count + 1u;
    tick_count = now;
    if (tick_hook != NULL) {
        tick_hook(now);
    }
}

/* The PIT interrupt: vector VECTOR_PIT (64), claimed by name from start.S's table. */
void cpu32_vector_64(void) __attribute__((interrupt_handler));
void cpu32_vector_64(void)
{
    pit_interrupt();
}

/* PITR value for rate_hz, or 0 if the PIT cannot make that rate exactly. */
static uint16_t pitr_for_rate(uint32_t rate_hz)
{
    if (rate_hz == 0u) {
        return 0;
    }
    if (PIT_INPUT_HZ % rate_hz == 0u && PIT_INPUT_HZ / rate_hz <= PITR_PITM_MAX) {
        return (uint16_t)(PIT_INPUT_HZ / rate_hz);
    }
    /* With the /512 prescaler the PIT counts at 16 Hz. */
    if (16u % rate_hz == 0u) {
        return (uint16_t)(PITR_PTP | (16u / rate_hz));
    }
    return 0;
}

int pit_start(uint32_t rate_hz, pit_tick_hook_fn hook)
{
    uint16_t pitr = pitr_for_rate(rate_hz);
    uint16_t sr;

    SIM_PITR = 0;
    if (pitr == 0u) {
        return -1;
    }
    sr = cpu32_irq_save();
    tick_count = 0;
    tick_hook = hook;
    tick_rate_hz = rate_hz;
    SIM_PICR = (uint16_t)(PICR_LEVEL(IRQ_LEVEL_PIT) | PICR_VECTOR(VECTOR_PIT));
    SIM_PITR = pitr;
    cpu32_irq_restore(sr);
    return 0;
}

void pit_set_hook(pit_tick_hook_fn hook)
{
    uint16_t sr = cpu32_irq_save();
    tick_hook = hook;
    cpu32_irq_restore(sr);
}

void pit_stop(void)
{
    SIM_PITR = 0;
}

uint32_t pit_ticks(void)
{
    /* A 32-bit aligned load is a single CPU32 bus access sequence the PIT
     * interrupt cannot split: interrupts are taken between instructions. */
    return tick_count;
}

uint32_t pit_rate_hz(void)
{
    return tick_rate_hz;
}

uint32_t pit_wait_tick_after(uint32_t seen)
{
    for (;;) {
        uint32_t now;
        (void)cpu32_irq_save();
        now = tick_count;
        if (now != seen) {
            cpu32_irq_enable();
            return now;
        }
        /* Masked check, then STOP lowers the mask: the tick cannot slip in between. */
        cpu32_wait_for_interrupt();
    }
}
