/*
 * RoboCube board: interrupt arbitration.
 *
 * Every interrupt source of the board (SIM PIT, QSM SCI, TPU, MC68681 DUART,
 * the two PCF8584s) requests one interrupt priority level together with the
 * vector it returns in the interrupt-acknowledge cycle.  The CPU32 sees the
 * highest requested level; among sources at the same level the one earlier
 * in enum RoboCubeIrqSource wins (on the real chip the SIM arbitrates the
 * on-chip modules by IARB and the external devices answer the IACK cycle in
 * GAL order; the RoboCube firmware never puts two sources on one level with
 * different expectations, see emu/README.md).
 *
 * For qtest the arbiter exports seven GPIO outputs: output n-1 is high while
 * the presented level is n.  QOM properties "level" and "vector" show the
 * request presented to the CPU.
 */
#include "qemu/osdep.h"
#include "qapi/error.h"
#include "qapi/visitor.h"
#include "hw/qdev-core.h"
#include "hw/irq.h"
#include "qom/object.h"
#include "cpu.h"
#include "robocube_intc.h"

OBJECT_DECLARE_SIMPLE_TYPE(RoboCubeIntc, ROBOCUBE_INTC)

struct RoboCubeIntc {
    DeviceState parent_obj;
    M68kCPU *cpu;
    uint8_t level[RC_IRQ_SOURCES];
    uint8_t vector[RC_IRQ_SOURCES];
    RoboCubeIackHandler *iack[RC_IRQ_SOURCES];
    void *iack_opaque[RC_IRQ_SOURCES];
    int cur_source;                 /* -1: none */
    uint8_t cur_level;
    uint8_t cur_vector;
    qemu_irq ipl_out[7];
};

static void robocube_intc_update(RoboCubeIntc *s)
{
    unsigned best_level = 0;
    uint8_t best_vector = 0;
    int best_source = -1;
    int i;

    for (i = 0; i < RC_IRQ_SOURCES; i++) {
        if (s->level[i] > best_level) {
            best_level = s->level[i];
            best_vector = s->vector[i];
            best_source = i;
        }
    }
    s->cur_source = best_source;
    if (best_level != s->cur_level) {
        if (s->cur_level) {
            qemu_set_irq(s->ipl_out[s->cur_level - 1], 0);
        }
        if (best_level) {
            qemu_set_irq(s->ipl_out[best_level - 1], 1);
        }
    }
    s->cur_level = best_level;
    s->cur_vector = best_vector;
    if (s->cpu) {
        m68k_set_irq_level(s->cpu, best_level, best_vector);
    }
}

void robocube_intc_request(RoboCubeIntc *s, enum RoboCubeIrqSource source,
                           unsigned level, uint8_t vector)
{
    assert(source < RC_IRQ_SOURCES);
    if (level > 7) {
        level = 7;
    }
    if (s->level[source] == level && s->vector[source] == vector) {
        return;
    }
    s->level[source] = level;
    s->vector[source] = vector;
    robocube_intc_update(s);
}

void robocube_intc_set_iack_handler(RoboCubeIntc *s,
                                    enum RoboCubeIrqSource source,
                                    RoboCubeIackHandler *handler, void *opaque)
{
    assert(source < RC_IRQ_SOURCES);
    s->iack[source] = handler;
    s->iack_opaque[source] = opaque;
}

/* Called by the CPU after it took an interrupt of @level (IACK cycle). */
static void robocube_intc_iack(void *opaque, int level)
{
    RoboCubeIntc *s = opaque;
    int source = s->cur_source;

    if (source >= 0 && s->level[source] == level && s->iack[source]) {
        s->iack[source](s->iack_opaque[source]);
    }
}

RoboCubeIntc *robocube_intc_create(struct ArchCPU *cpu)
{
    RoboCubeIntc *s = ROBOCUBE_INTC(object_new(TYPE_ROBOCUBE_INTC));

    object_property_add_child(qdev_get_machine(), "intc", OBJECT(s));
    qdev_realize(DEVICE(s), NULL, &error_fatal);
    object_unref(OBJECT(s));
    s->cpu = cpu;
    cpu->env.iack_hook = robocube_intc_iack;
    cpu->env.iack_opaque = s;
    robocube_intc_update(s);
    return s;
}

static void robocube_intc_get_u8(Object *obj, Visitor *v, const char *name,
                                 void *opaque, Error **errp)
{
    uint8_t value = *(uint8_t *)opaque;

    visit_type_uint8(v, name, &value, errp);
}

static void robocube_intc_init(Object *obj)
{
    RoboCubeIntc *s = ROBOCUBE_INTC(obj);

    s->cur_source = -1;
    qdev_init_gpio_out(DEVICE(obj), s->ipl_out, 7);
    object_property_add(obj, "level", "uint8", robocube_intc_get_u8,
                        NULL, NULL, &s->cur_level);
    object_property_add(obj, "vector", "uint8", robocube_intc_get_u8,
                        NULL, NULL, &s->cur_vector);
}

static const TypeInfo robocube_intc_info = {
    .name = TYPE_ROBOCUBE_INTC,
    .parent = TYPE_DEVICE,
    .instance_size = sizeof(RoboCubeIntc),
    .instance_init = robocube_intc_init,
};

static void robocube_intc_register_types(void)
{
    type_register_static(&robocube_intc_info);
}

type_init(robocube_intc_register_types)
