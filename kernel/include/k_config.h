/*
 * Configuration of the nanokernel: the one place for tick rate, priorities,
 * slice length and stack guards. The board side (clock rate, PIT divider,
 * which services start) lives in the firmware's board configuration; the
 * tick rate here must match what the PIT is programmed to.
 */
#ifndef K_CONFIG_H
#define K_CONFIG_H

/* Tick rate: the 68332 PIT from the 32.768 kHz reference with PITM=8 gives
 * 1024 Hz (976.5625 us), the closest it gets to a millisecond. Must divide
 * 2 000 000 000 so that clock_gettime needs no 64-bit division. */
#ifndef K_TICK_HZ
#define K_TICK_HZ 1024u
#endif

/* Round-robin slice within a priority, in ticks. */
#ifndef K_TIMESLICE_TICKS
#define K_TIMESLICE_TICKS 10u
#endif

#define K_PRIO_IDLE         0u
#define K_PRIO_APP_MIN      1u
#define K_PRIO_APP_MAX     27u  /* the B-scheduler thread */
#define K_PRIO_SERVICE_MIN 28u  /* communication and other kernel services */
#define K_PRIO_MAX         31u

/* Words at the low end of every stack filled with K_STACK_GUARD and checked
 * on every switch away from the thread. */
#ifndef K_STACK_GUARD_WORDS
#define K_STACK_GUARD_WORDS 4u
#endif
#define K_STACK_GUARD 0xDEADC0DEu

/* The last word of every struct k_thread holds this, XORed with the
 * struct's address (a copied or refilled struct does not pass). A stack
 * that lies right above a control block overflows into that word first,
 * just past its guard words; the kernel checks it at every switch (the
 * thread switched from and the one switched to) and in k_thread_list. */
#define K_THREAD_CANARY 0x7C0B1E55u

/* The smallest stack k_thread_create accepts, in bytes. */
#ifndef K_STACK_MIN_BYTES
#define K_STACK_MIN_BYTES 256u
#endif

/* The overrun reporter thread of a B-scheduler thread (struct k_bsched).
 * make stack: its own deepest path (k_printf down to a switch) is 648 bytes
 * on the CPU32 at -Os, and the interrupts add up to 352 on its stack (the
 * I2C images); 1280 leaves 264 (ASSURANCE.md). The host tests give it more:
 * x86-64 frames at -O0 or under the sanitizers are far larger. */
#ifndef K_BSCHED_REPORTER_STACK_BYTES
#define K_BSCHED_REPORTER_STACK_BYTES 1280u
#endif

/* The reporter prints at most one burst of lines (a "still running"
 * announcement and an overrun summary) per this many ticks; what happens in
 * between is summed into the next burst. Bounds its share of the CPU under
 * continuous overrun, whatever the console's speed. */
#ifndef K_BSCHED_REPORT_INTERVAL_TICKS
#define K_BSCHED_REPORT_INTERVAL_TICKS K_TICK_HZ
#endif

/* The interrupt stack of ports that have one (CPU32: every interrupt the
 * kernel routes runs on it, nested ones included; threads carry only the
 * entry frame). make stack checks its size against the nested worst case. */
#ifndef K_IRQ_STACK_BYTES
#define K_IRQ_STACK_BYTES 1024u
#endif

#ifndef K_IDLE_STACK_BYTES
#define K_IDLE_STACK_BYTES 512u
#endif

#endif /* K_CONFIG_H */
