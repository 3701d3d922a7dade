/*
 * MC68332 Time Processor Unit: the standard mask-A time functions the board
 * model has, one channel at a time: PWM (frequency and duty), DIO (discrete
 * in/out), ITC (pulse accumulation, extended to 32 bits in software) and
 * QDEC (quadrature decoding on a channel pair, extended to 32 bits), plus
 * per-channel interrupts routed through the kernel (k_irq_register).
 *
 * Channels are the TPU channel numbers TP0..TP15. The RoboCube brings all
 * of them out: TP0-TP5 on the motor header H3 (the motor driver uses TP0-TP5
 * and the encoder B phases TP12-TP14, see drivers/motor.h), TP6-TP15 on the
 * timer header H11 (the "10 timer channels"). A channel the board support
 * holds (board_tpu_reserved: TP15 once the kernel's fine time stamp runs,
 * k_timestamp_start) is refused with DRV_ERR_CHANNEL. Setting a function on
 * a channel replaces whatever ran there before.
 *
 * Timebase: tpu_init sets TPUMCR = 0x4ACD as CubeOS did: TCR1 = fsys/16 =
 * 1.048576 MHz (TPU_TCR1_HZ). Interrupts: TICR = 0x0480, level 4, vectors
 * 0x80 + channel.
 *
 * Every function returns >= 0 on success, DRV_ERR_CHANNEL for a channel
 * above 15 or held by the board (or a QDEC pair that is not two distinct
 * channels),
 * DRV_ERR_RANGE for a value out of range, DRV_ERR_STATE before tpu_init or
 * when the channel does not run the function asked about. No call blocks.
 */
#ifndef DRIVERS_TPU_H
#define DRIVERS_TPU_H

#include <stdint.h>

#define TPU_CHANNELS      16u
#define TPU_TCR1_HZ       1048576u   /* fsys / 16 at 16.777216 MHz */
#define TPU_IRQ_LEVEL     4u
#define TPU_VECTOR_BASE   0x80u      /* channel n interrupts with vector 0x80 + n */

/* PWM frequency range: PWMPER is a 16-bit count of TCR1 ticks. */
#define TPU_PWM_HZ_MIN    17u        /* 1048576 / 17 = 61681 ticks */
#define TPU_PWM_HZ_MAX    20000u     /* 52 ticks: duty resolution about 2 % */
#define TPU_PWM_HZ_DEFAULT 1000u     /* when a channel starts PWM with hz = 0 */

/* ITC edge selections (the PAC field of CHANNEL_CONTROL). */
#define TPU_EDGE_RISING   1u
#define TPU_EDGE_FALLING  2u
#define TPU_EDGE_BOTH     3u

/* Sets up the TPU (TPUMCR, TICR, CIER = 0), registers the 16 channel
 * vectors with the kernel. Call after k_init, before k_start; again = no-op. */
int tpu_init(void);

/* PWM on ch: hz = TPU_PWM_HZ_MIN..TPU_PWM_HZ_MAX, or 0 to keep the channel's
 * current frequency (TPU_PWM_HZ_DEFAULT if it did not run PWM). permille
 * 0..1000 of the period high (0 = always low, 1000 = always high). A channel
 * already running PWM changes at once (HSR 01 immediate update), without a
 * glitch in the running period's start. */
int tpu_pwm(unsigned ch, uint32_t hz, int permille);
/* What the channel runs now: *hz (rounded) and *permille (rounded), either
 * pointer may be NULL. DRV_ERR_STATE if ch does not run PWM. */
int tpu_pwm_get(unsigned ch, uint32_t *hz, int *permille);
/* Raw form: high time and period in TCR1 ticks (period 1..65535, high <= period). */
int tpu_pwm_ticks(unsigned ch, uint16_t high, uint16_t period);

/* DIO: drive ch high (v != 0) or low; the channel becomes an output. */
int tpu_dio_write(unsigned ch, int v);
/* DIO: the pin level 0/1. A channel that is not a DIO input is made one
 * first (its pin is sampled at once); an output channel reads its level. */
int tpu_dio_read(unsigned ch);

/* ITC: counts edges (TPU_EDGE_*) on ch from 0, continuously, into a 32-bit
 * count (the TPU counts 16 bits and interrupts at every TPU_ITC_CHUNK
 * edges; the interrupt adds the chunk). */
#define TPU_ITC_CHUNK     0x4000u
int tpu_itc_start(unsigned ch, unsigned edges);
/* ITC: edges counted since tpu_itc_start (or the last tpu_itc_clear). */
int tpu_itc_count(unsigned ch, uint32_t *count);
int tpu_itc_clear(unsigned ch);

/* QDEC on a pair: primary_ch is the encoder's phase A, secondary_ch phase B
 * (the model counts up when A leads B); any two distinct channels. The
 * position starts at 0. */
int tpu_qdec_start(unsigned primary_ch, unsigned secondary_ch);
/* The 32-bit position (4 counts per encoder line). The TPU counts 16 bits:
 * call at least once per 32767 counts (the motor service does every period). */
int tpu_qdec_position(unsigned primary_ch, int32_t *pos);
/* The position and the TCR1 time of the edge that made it (16 bits), read
 * as one consistent pair: the motor driver's speed estimate uses both. */
int tpu_qdec_sample(unsigned primary_ch, int32_t *pos, uint16_t *edge_tcr1);
/* Moves the position to pos (the count restarts there). */
int tpu_qdec_set(unsigned primary_ch, int32_t pos);

/* Calls fn(ch, arg) from the TPU interrupt (level 4, interrupt context) at
 * each of the channel's interrupts: PWM every period start, DIO input every
 * record, ITC every TPU_ITC_CHUNK edges (QDEC has none). fn NULL detaches and
 * disables the channel's interrupt (unless ITC needs it). */
typedef void (*tpu_irq_fn)(unsigned ch, void *arg);
int tpu_attach_irq(unsigned ch, tpu_irq_fn fn, void *arg);
/* Interrupts of ch served since tpu_init. */
uint32_t tpu_irq_count(unsigned ch);

/* Stops whatever runs on ch (no function, CISR/CIER cleared, pin an input). */
int tpu_release(unsigned ch);

#endif /* DRIVERS_TPU_H */
