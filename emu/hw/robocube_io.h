/*
 * RoboCube board: the hook between the board core (machine, SIM, QSM, DUART)
 * and the I/O side (TPU, PCF8584 I2C controllers with the I/O board, motors,
 * host-side I/O interface).
 */
#ifndef ROBOCUBE_IO_H
#define ROBOCUBE_IO_H

#include "qemu/osdep.h"
#include "exec/memory.h"
#include "robocube_intc.h"

/* Creates TPU, the two PCF8584 I2C controllers with the I/O board behind them,
 * the motor model and the host-side I/O interface. */
void robocube_io_init(MemoryRegion *sysmem, RoboCubeIntc *intc);

/*
 * Current MC68681 output-port register OPR (bit n = 1: OPn asserted, i.e. the
 * pin is driven LOW).  OP0 = radio RX select, OP1 = radio TX select,
 * OP2..OP7 = motor direction bits (motor m: OP(2+2m), OP(3+2m)).
 * Returns 0 before the DUART exists.  Implemented in mc68681_duart.c.
 */
uint8_t robocube_duart_opr(void);

/* System clock in Hz as programmed in the SIM's SYNCR (mc68332_sim.c). */
uint64_t robocube_sim_system_clock_hz(void);

#endif
