/* What the parts of the POSIX layer share: the kernel's status codes as POSIX
 * error numbers, and POSIX time as the kernel's. */
#ifndef POSIX_INTERNAL_H
#define POSIX_INTERNAL_H

#include <errno.h>
#include <time.h>
#include "kernel.h"

/* The kernel's codes are negated errno values as Linux numbers them; newlib
 * numbers some differently (EDEADLK, ETIMEDOUT, EOVERFLOW, EOWNERDEAD). */
int posix_errno(int k_status);

/* A POSIX timespec as the kernel's: K_EINVAL unless 0 <= tv_nsec < 10^9 and
 * tv_sec >= 0; seconds past the kernel's range become its largest. */
int posix_timespec(const struct timespec *ts, struct k_timespec *out);

/* CLOCK_MONOTONIC, or CLOCK_REALTIME (the board has no real-time clock: it
 * reads the time since start-up too). */
static inline int posix_clock_valid(clockid_t clock_id)
{
    return clock_id == CLOCK_MONOTONIC || clock_id == CLOCK_REALTIME;
}

#endif /* POSIX_INTERNAL_H */
