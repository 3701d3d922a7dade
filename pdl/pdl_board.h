/*
 * Board-only additions to pdl/pdl.h (the nanokernel's cycle thread). The
 * cycle thread's stack is PDL_STACK_BYTES (default 2048); the kernel fills
 * it with its guard pattern, so its use can be measured.
 */
#ifndef PDL_BOARD_H
#define PDL_BOARD_H

#include "pdl/pdl.h"

struct k_thread;

/* Bytes of the cycle thread's stack ever used (high-water mark). */
uint32_t pdl_stack_used(void);
uint32_t pdl_stack_size(void);
/* The cycle thread (to join it, or for reports). */
struct k_thread *pdl_cycle_thread(void);

#endif /* PDL_BOARD_H */
