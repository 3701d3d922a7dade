/*
 * RoboCube board: interrupt arbitration between the MC68332 on-chip modules
 * and the external chips, in front of the CPU32's IPL inputs.
 */
#ifndef ROBOCUBE_INTC_H
#define ROBOCUBE_INTC_H

#include "qemu/osdep.h"

/* Interrupt arbitration of the robocube board: every source requests an interrupt
 * priority level (0 = none) and supplies the vector the CPU gets on acknowledge. */
typedef struct RoboCubeIntc RoboCubeIntc;
enum RoboCubeIrqSource {
    RC_IRQ_PIT, RC_IRQ_SCI, RC_IRQ_TPU, RC_IRQ_DUART, RC_IRQ_I2C_A, RC_IRQ_I2C_B,
    RC_IRQ_SOURCES
};
void robocube_intc_request(RoboCubeIntc *intc, enum RoboCubeIrqSource source,
                           unsigned level, uint8_t vector);

/* QOM type of the arbiter (a plain device; the machine adds it as /machine/intc). */
#define TYPE_ROBOCUBE_INTC "robocube-intc"

/* Creates the arbiter as /machine/intc, driving the IPL of @cpu (machine only). */
struct ArchCPU;
RoboCubeIntc *robocube_intc_create(struct ArchCPU *cpu);

/*
 * Sources whose request the interrupt-acknowledge cycle clears (the SIM's
 * periodic interrupt timer) register a handler; the arbiter calls it when
 * the CPU acknowledges an interrupt that this source supplied.
 */
typedef void RoboCubeIackHandler(void *opaque);
void robocube_intc_set_iack_handler(RoboCubeIntc *intc,
                                    enum RoboCubeIrqSource source,
                                    RoboCubeIackHandler *handler, void *opaque);

#endif
