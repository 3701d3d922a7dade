/* Interrupt handler registry: one handler per exception vector. */
#include "k_internal.h"

struct k_irq_slot {
    k_irq_handler handler;
    void *arg;
    uint8_t level;
};

static struct k_irq_slot k_irq_table[256];

int k_irq_register(unsigned vector, unsigned level, k_irq_handler handler, void *arg)
{
    uint32_t s;
    int r;
    /* 24 = spurious, 25..31 autovectors, 64..255 user vectors; 32..63 are
     * TRAPs and reserved entries that no device raises. */
    if (vector < 24u || (vector > 31u && vector < 64u) || vector > 255u ||
        level < 1u || level > 7u || handler == NULL)
        return K_EINVAL;
    s = k_arch_irq_save();
    k_irq_table[vector].handler = handler;
    k_irq_table[vector].arg = arg;
    k_irq_table[vector].level = (uint8_t)level;
    r = k_arch_irq_route(vector);
    k_arch_irq_restore(s);
    return r;
}

unsigned k_irq_level(unsigned vector)
{
    return k_irq_table[vector & 0xFFu].level;
}

void k_irq_dispatch(unsigned vector)
{
    const struct k_irq_slot *slot = &k_irq_table[vector & 0xFFu];
    if (slot->handler != NULL)
        slot->handler(slot->arg);
    else
        k_stats.spurious_irqs++;
}

void k_isr_run(unsigned vector)
{
    k_isr_enter();
    k_irq_dispatch(vector);
    k_isr_exit();
}
