/*
 * Time: clock_gettime, clock_getres, clock_nanosleep, nanosleep, usleep and
 * sleep on the kernel's monotonic clock (one tick's resolution), and the
 * conversions the other parts use.
 */
#include <stdint.h>
#include <unistd.h>
#include "posix_internal.h"

int posix_errno(int k_status)
{
    switch (k_status) {
    case K_OK:          return 0;
    case K_EPERM:       return EPERM;
    case K_ESRCH:       return ESRCH;
    case K_EAGAIN:      return EAGAIN;
    case K_EBUSY:       return EBUSY;
    case K_EDEADLK:     return EDEADLK;
    case K_EOVERFLOW:   return EOVERFLOW;
    case K_ETIMEDOUT:   return ETIMEDOUT;
    case K_EOWNERDEAD:  return EOWNERDEAD;
    case K_EISR:        return EPERM;    /* a blocking call from an interrupt handler */
    default:            return EINVAL;   /* K_EINVAL, K_ESTACK */
    }
}

int posix_timespec(const struct timespec *ts, struct k_timespec *out)
{
    if (ts == NULL || ts->tv_nsec < 0 || ts->tv_nsec >= 1000000000L || ts->tv_sec < 0)
        return K_EINVAL;
    out->tv_sec = ts->tv_sec > (time_t)INT32_MAX ? INT32_MAX : (int32_t)ts->tv_sec;
    out->tv_nsec = (int32_t)ts->tv_nsec;
    return K_OK;
}

int clock_gettime(clockid_t clock_id, struct timespec *tp)
{
    struct k_timespec now;
    if (!posix_clock_valid(clock_id) || tp == NULL) {
        errno = EINVAL;
        return -1;
    }
    (void)k_clock_gettime(K_CLOCK_MONOTONIC, &now);
    tp->tv_sec = now.tv_sec;
    tp->tv_nsec = now.tv_nsec;
    return 0;
}

int clock_getres(clockid_t clock_id, struct timespec *res)
{
    if (!posix_clock_valid(clock_id)) {
        errno = EINVAL;
        return -1;
    }
    if (res != NULL) {
        res->tv_sec = 0;
        res->tv_nsec = (long)((1000000000u + K_TICK_HZ - 1u) / K_TICK_HZ);
    }
    return 0;
}

int clock_settime(clockid_t clock_id, const struct timespec *tp)
{
    (void)tp;
    /* The clocks count from start-up and cannot be set. */
    errno = posix_clock_valid(clock_id) ? EPERM : EINVAL;
    return -1;
}

/* Returns an error number, as clock_nanosleep does. No signals exist, so a
 * sleep is never interrupted and *rem (relative sleeps) is always zero. */
int clock_nanosleep(clockid_t clock_id, int flags, const struct timespec *rqtp,
                    struct timespec *rmtp)
{
    struct k_timespec t;
    if (!posix_clock_valid(clock_id) || (flags & ~TIMER_ABSTIME) != 0 ||
        posix_timespec(rqtp, &t) != K_OK)
        return EINVAL;
    if (k_in_isr())
        return EPERM;
    if ((flags & TIMER_ABSTIME) != 0)
        return posix_errno(k_clock_nanosleep(K_CLOCK_MONOTONIC, K_TIMER_ABSTIME, &t));
    if (rmtp != NULL) {
        rmtp->tv_sec = 0;
        rmtp->tv_nsec = 0;
    }
    return posix_errno(k_nanosleep(&t));
}

int nanosleep(const struct timespec *rqtp, struct timespec *rmtp)
{
    int r = clock_nanosleep(CLOCK_MONOTONIC, 0, rqtp, rmtp);
    if (r != 0) {
        errno = r;
        return -1;
    }
    return 0;
}

int usleep(useconds_t useconds)
{
    struct timespec t;
    t.tv_sec = (time_t)(useconds / 1000000u);
    t.tv_nsec = (long)(useconds % 1000000u) * 1000L;
    return nanosleep(&t, NULL);
}

unsigned sleep(unsigned seconds)
{
    struct timespec t;
    t.tv_sec = (time_t)seconds;
    t.tv_nsec = 0;
    return nanosleep(&t, NULL) == 0 ? 0u : seconds;
}
