/*
 * MC68332 TPU registers and parameter RAM (where the board puts them:
 * board_tpu_regs and board_tpu_param, boards/include/board_io.h), as the
 * chip packs them (emu/IO.md section 1.1, facts section 3.3): CFSR 4 bits per
 * channel with channel 0 in the low nibble of CFSR3; HSQR, HSRR, CPR 2 bits
 * per channel with channels 0-7 in the second register.
 */
#ifndef DRIVERS_TPU_REGS_H
#define DRIVERS_TPU_REGS_H

#include <stdint.h>

#include "boards/include/board_io.h"

/* The register at byte offset off (even) from TPUMCR. */
#define TPU_REG16(off)  (board_tpu_regs[(off) / 2u])

#define TPU_MCR         TPU_REG16(0x00)
#define TPU_TICR        TPU_REG16(0x08)
#define TPU_CIER        TPU_REG16(0x0A)
#define TPU_CISR        TPU_REG16(0x20)
/* Register holding channel ch's field: CFSR0..3 at 0x0C..0x12, two-bit
 * registers at base (channels 8-15) and base + 2 (channels 0-7). */
#define TPU_CFSR(ch)    TPU_REG16(0x0Cu + 2u * (3u - (ch) / 4u))
#define TPU_CFSR_SHIFT(ch) (4u * ((ch) % 4u))
#define TPU_HSQR(ch)    TPU_REG16(0x14u + 2u * (1u - (ch) / 8u))
#define TPU_HSRR(ch)    TPU_REG16(0x18u + 2u * (1u - (ch) / 8u))
#define TPU_CPR(ch)     TPU_REG16(0x1Cu + 2u * (1u - (ch) / 8u))
#define TPU_FIELD2_SHIFT(ch) (2u * ((ch) % 8u))

/* Channel ch, parameter word k. */
#define TPU_PARAM(ch, k) (board_tpu_param[8u * (ch) + (k)])
/* Byte address of parameter word k of channel ch, as QDEC's pointers hold it. */
#define TPU_PARAM_ADDR(ch, k) ((uint16_t)(16u * (ch) + 2u * (k)))

/* TPUMCR as CubeOS: TCR1P = 2 (/4), PSCK = 1 (fsys/4): TCR1 = fsys/16;
 * SUPV = 1, IARB = 0xD. */
#define TPU_MCR_CUBEOS  0x4ACDu
/* TICR: CIRL (bits 10-8) = level, CIBV (bits 7-4) = vector base / 16. */
#define TPU_TICR_VALUE(level, base) ((uint16_t)(((level) << 8) | ((base) & 0xF0u)))

/* Function codes (mask-A ROM). */
#define TPU_FN_QDEC 0x6u
#define TPU_FN_DIO  0x8u
#define TPU_FN_PWM  0x9u
#define TPU_FN_ITC  0xAu

/* Channel priorities (CPR): 0 disabled, 1 low, 2 middle, 3 high. */
#define TPU_PRIO_OFF 0u
#define TPU_PRIO_MID 2u

#endif /* DRIVERS_TPU_REGS_H */
