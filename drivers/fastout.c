/*
 * Fast binary outputs (see fastout.h): the register is write-only, so every
 * change goes through the shadow, updated and written with interrupts masked
 * (a thread and a handler may both set bits).
 */
#include "drivers/fastout.h"

#include "boards/include/board_io.h"
#include "drivers/drv_err.h"
#include "kernel.h"

#define FASTOUT_REG board_fast_out_reg

static uint16_t fastout_shadow;

int fastout_write_all(uint16_t v)
{
    uint32_t s = k_arch_irq_save();
    fastout_shadow = v;
    FASTOUT_REG = v;
    k_arch_irq_restore(s);
    return DRV_OK;
}

int fastout_write(unsigned bit, int v)
{
    uint32_t s;
    if (bit >= FASTOUT_BITS)
        return DRV_ERR_CHANNEL;
    if (v != 0 && v != 1)
        return DRV_ERR_RANGE;
    s = k_arch_irq_save();
    if (v)
        fastout_shadow = (uint16_t)(fastout_shadow | (1u << bit));
    else
        fastout_shadow = (uint16_t)(fastout_shadow & ~(1u << bit));
    FASTOUT_REG = fastout_shadow;
    k_arch_irq_restore(s);
    return DRV_OK;
}

uint16_t fastout_get(void)
{
    return fastout_shadow;
}
