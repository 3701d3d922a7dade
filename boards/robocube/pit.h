/*
 * System tick from the MC68332 SIM periodic interrupt timer (PIT), clocked
 * by the 32.768 kHz reference: rate = 8192 Hz / PITM (PITM 1..255), or
 * 16 Hz / PITM with the /512 prescaler. Interrupt level 4, vector 64
 * (VECTOR_PIT); the driver claims vector 64 in the flash table
 * (cpu32_vector_64). The kernel's board support routes vector 64 through the
 * kernel's interrupt entry instead (its interrupt stack) and calls
 * pit_interrupt from there.
 */
#ifndef DRIVERS_PIT_H
#define DRIVERS_PIT_H

#include <stdint.h>

/* Called from the tick interrupt (IPL 4, interrupts of level <= 4 masked)
 * with the new tick count; keep it short. */
typedef void (*pit_tick_hook_fn)(uint32_t ticks);

/*
 * Starts the PIT at exactly rate_hz ticks per second and resets the tick
 * count to 0. rate_hz must be 8192 / n or 16 / n for an n in 1..255.
 * hook may be NULL. Returns 0, or -1 (PIT left stopped) for a rate the PIT
 * cannot produce exactly.
 * Interrupts must be enabled (SR mask < 4) by the caller for ticks to count.
 */
int pit_start(uint32_t rate_hz, pit_tick_hook_fn hook);

/* The tick interrupt's work: counts the tick and calls the hook. For an
 * interrupt entry other than the driver's own vector. */
void pit_interrupt(void);

/* Replaces the hook pit_start installed (the next tick calls the new one). */
void pit_set_hook(pit_tick_hook_fn hook);

/* Stops the PIT (PITR = 0); the tick count keeps its value. */
void pit_stop(void);

/* Ticks since pit_start; wraps after 2^32 ticks. */
uint32_t pit_ticks(void);

/* The rate pit_start set, in Hz (0 while never started). */
uint32_t pit_rate_hz(void);

/* Waits (in STOP, low power) until the tick count differs from `seen`, and
 * returns the new count. Leaves interrupts enabled. */
uint32_t pit_wait_tick_after(uint32_t seen);

#endif /* DRIVERS_PIT_H */
