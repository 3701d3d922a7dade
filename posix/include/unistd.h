/*
 * newlib's <unistd.h>, plus usleep: the CubeOS API offers it (the POSIX
 * layer's time calls, posix/README.md) while newlib declares it only for
 * BSD or old XSI sources, not for a strict -std=c99 program.
 */
#ifndef _BSCHED_POSIX_UNISTD_H
#define _BSCHED_POSIX_UNISTD_H
#include_next <unistd.h>
int usleep(useconds_t useconds);
#endif
