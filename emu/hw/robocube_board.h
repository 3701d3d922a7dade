/*
 * RoboCube board core: constructors of the board-core devices (SIM with chip
 * selects and TPURAM, QSM, MC68681 DUART) used by the machine in robocube.c.
 */
#ifndef ROBOCUBE_BOARD_H
#define ROBOCUBE_BOARD_H

#include "qemu/osdep.h"
#include "qemu/units.h"
#include "exec/memory.h"
#include "chardev/char.h"
#include "robocube_intc.h"

/* Board constants (RoboCube v2.0, see emu/README.md). */
#define RC_FLASH_SIZE        (1 * MiB)
#define RC_SRAM_SIZE         (1 * MiB)
#define RC_TPURAM_SIZE       (2 * KiB)
#define RC_SIM_BASE          0xFFFA00
#define RC_TPURAM_CTRL_BASE  0xFFFB00
#define RC_QSM_BASE          0xFFFC00
#define RC_DUART_BASE        0xFFE400
#define RC_EXTAL_HZ          32768      /* SIM reference crystal */
#define RC_DUART_XTAL_HZ     3686400    /* MC68681 X1 crystal */

/* QOM type names. */
#define TYPE_MC68332_SIM   "mc68332-sim"
#define TYPE_MC68332_QSM   "mc68332-qsm"
#define TYPE_MC68681_DUART "mc68681-duart"
#define TYPE_ROBOCUBE_LOCKSTEP "robocube-lockstep"

/*
 * The SIM decodes the boot chip select (flash) and CS0/CS1 (SRAM) and places
 * TPURAM per TRAMBAR inside @bus (the 16 MiB CPU32 address space).
 */
DeviceState *mc68332_sim_create(MemoryRegion *bus, MemoryRegion *flash,
                                MemoryRegion *sram, RoboCubeIntc *intc);
DeviceState *mc68332_qsm_create(MemoryRegion *bus, RoboCubeIntc *intc,
                                Chardev *sci_chr);
DeviceState *mc68681_duart_create(MemoryRegion *bus, hwaddr base,
                                  RoboCubeIntc *intc, Chardev *chr_a,
                                  Chardev *chr_b);

/* /machine/lockstep: pauses the VM at every step boundary of virtual time
 * (robocube_lockstep.c). */
void robocube_lockstep_create(void);

#endif
