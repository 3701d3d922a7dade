/*
 * MC68332 on-chip registers used by the RoboCube firmware: SIM (system
 * integration module), TPURAM control and the QSM. Addresses assume
 * SIMCR.MM = 1 (modules at 0xFFF000-0xFFFFFF), which is the reset state and
 * what the startup code keeps.
 *
 * Each register is given as a volatile lvalue of its real width, so
 *     SIM_PICR = (uint16_t)((4u << 8) | 64u);
 * emits exactly one 16-bit bus cycle.
 */
#ifndef CPU32_MC68332_H
#define CPU32_MC68332_H

#include <stdint.h>

#define MC68332_REG8(addr)  (*(volatile uint8_t *)(uintptr_t)(addr))
#define MC68332_REG16(addr) (*(volatile uint16_t *)(uintptr_t)(addr))

/* ---- SIM: base 0xFFFA00 ---- */
#define SIM_BASE     0xFFFA00u
#define SIM_MCR      MC68332_REG16(SIM_BASE + 0x00) /* SIMCR */
#define SIM_SYNCR    MC68332_REG16(SIM_BASE + 0x04) /* clock synthesiser */
#define SIM_RSR      MC68332_REG8(SIM_BASE + 0x07)  /* reset status */
#define SIM_PORTE    MC68332_REG8(SIM_BASE + 0x11)
#define SIM_DDRE     MC68332_REG8(SIM_BASE + 0x15)
#define SIM_PEPAR    MC68332_REG8(SIM_BASE + 0x17)
#define SIM_PORTF    MC68332_REG8(SIM_BASE + 0x19)
#define SIM_DDRF     MC68332_REG8(SIM_BASE + 0x1D)
#define SIM_PFPAR    MC68332_REG8(SIM_BASE + 0x1F)
#define SIM_SYPCR    MC68332_REG8(SIM_BASE + 0x21)  /* write-once after reset */
#define SIM_PICR     MC68332_REG16(SIM_BASE + 0x22) /* PIT interrupt control */
#define SIM_PITR     MC68332_REG16(SIM_BASE + 0x24) /* PIT timing */
#define SIM_SWSR     MC68332_REG8(SIM_BASE + 0x27)  /* watchdog service */
#define SIM_CSPAR0   MC68332_REG16(SIM_BASE + 0x44)
#define SIM_CSPAR1   MC68332_REG16(SIM_BASE + 0x46)
#define SIM_CSBARBT  MC68332_REG16(SIM_BASE + 0x48)
#define SIM_CSORBT   MC68332_REG16(SIM_BASE + 0x4A)
#define SIM_CSBAR(n) MC68332_REG16(SIM_BASE + 0x4C + 4u * (n)) /* n = 0..10 */
#define SIM_CSOR(n)  MC68332_REG16(SIM_BASE + 0x4E + 4u * (n))

/* SYNCR fields: fsys = fref * 4 * (Y + 1) * 2^(2W + X), fref = 32.768 kHz. */
#define SYNCR_W      0x8000u
#define SYNCR_X      0x4000u
#define SYNCR_Y(y)   ((uint16_t)((y) << 8))
#define SYNCR_SLOCK  0x0008u /* synthesiser locked (read-only) */
/* 32768 * 4 * 64 * 2 = 16.777216 MHz, the RoboCube's clock. */
#define SYNCR_16_78MHZ (SYNCR_X | SYNCR_Y(63))
#define CPU_CLOCK_HZ 16777216u

/* PIT: period = PITM * 4 / 32768 s (PTP = 0) or PITM * 4 * 512 / 32768 s (PTP = 1). */
#define PIT_INPUT_HZ 8192u     /* 32.768 kHz reference / 4 */
#define PITR_PTP     0x0100u   /* extra /512 prescaler */
#define PITR_PITM_MAX 255u
#define PICR_LEVEL(l)  ((uint16_t)(((l) & 7u) << 8))
#define PICR_VECTOR(v) ((uint16_t)((v) & 0xFFu))

/* Chip-select base register: address bits 23..11 in bits 15..3, block size in 2..0. */
#define CSBAR_BLOCK_2K   0u
#define CSBAR_BLOCK_8K   1u
#define CSBAR_BLOCK_16K  2u
#define CSBAR_BLOCK_64K  3u
#define CSBAR_BLOCK_128K 4u
#define CSBAR_BLOCK_256K 5u
#define CSBAR_BLOCK_512K 6u
#define CSBAR_BLOCK_1M   7u
#define CSBAR(base, block) ((uint16_t)((((base) >> 8) & 0xFFF8u) | (block)))

/* ---- TPURAM control: base 0xFFFB00 ---- */
#define TRAM_MCR     MC68332_REG16(0xFFFB00u)
#define TRAM_TST     MC68332_REG16(0xFFFB02u)
#define TRAM_BAR     MC68332_REG16(0xFFFB04u)

/* ---- QSM: base 0xFFFC00 (only what the firmware touches) ---- */
#define QSM_MCR      MC68332_REG16(0xFFFC00u)
#define QSM_QILR     MC68332_REG8(0xFFFC04u)
#define QSM_QIVR     MC68332_REG8(0xFFFC05u)

/* ---- TPU: base 0xFFFE00, parameter RAM 0xFFFF00 (only what the board
 * support touches; drivers/tpu_regs.h has the rest for the TPU driver) ---- */
#define MC68332_TPUMCR   MC68332_REG16(0xFFFE00u)
#define MC68332_TPU_CFSR0 MC68332_REG16(0xFFFE0Cu) /* channels 12-15, ch 15 in bits 15-12 */
#define MC68332_TPU_HSQR0 MC68332_REG16(0xFFFE14u) /* channels 8-15, 2 bits each */
#define MC68332_TPU_HSRR0 MC68332_REG16(0xFFFE18u)
#define MC68332_TPU_CPR0  MC68332_REG16(0xFFFE1Cu)
/* Channel ch (8..15), its field in the two-bit registers above. */
#define MC68332_TPU_FIELD2(ch, v) ((uint16_t)((unsigned)(v) << (2u * ((ch) - 8u))))
/* Channel ch, parameter word k. */
#define MC68332_TPU_PARAM(ch, k) MC68332_REG16(0xFFFF00u + 16u * (ch) + 2u * (k))
/* TPUMCR as CubeOS set it (the TPU driver writes the same): TCR1 = fsys/16. */
#define MC68332_TPUMCR_CUBEOS 0x4ACDu
#define MC68332_TPU_FN_QDEC 0x6u

/* ---- Values the RoboCube v2.0 firmware programs (see start.S) ---- */
#define ROBOCUBE_FLASH_BASE  0xE00000u
#define ROBOCUBE_FLASH_SIZE  0x100000u
#define ROBOCUBE_SRAM_BASE   0x000000u
#define ROBOCUBE_SRAM_SIZE   0x100000u
#define ROBOCUBE_TPURAM_BASE 0xF20000u
#define ROBOCUBE_TPURAM_SIZE 0x800u

/* Interrupt vectors the firmware assigns (the CPU32 user vectors start at 64). */
#define VECTOR_PIT 64u
#define IRQ_LEVEL_PIT 4u

#endif /* CPU32_MC68332_H */
