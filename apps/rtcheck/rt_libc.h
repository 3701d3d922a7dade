/*
 * The C library's part of the runtime check: printf's conversions, snprintf,
 * string.h, stdlib.h and float libm, printed on stdout as "RTP ..." (exact:
 * the host's C library must print the same) and "RTM NAME INDEX BITS" (libm
 * results as float bits: the test allows a few units in the last place, since
 * neither C library promises correctly rounded sinf or atan2f).
 */
#ifndef APPS_RTCHECK_RT_LIBC_H
#define APPS_RTCHECK_RT_LIBC_H

/* Prints every line; returns how many. */
int rt_libc_run(void);

#endif
