/*
 * The pthread types of the CubeOS POSIX layer (posix/). newlib's
 * <sys/types.h> includes this file; it comes first on the firmware's include
 * path (boards/robocube/board.mk), in place of newlib's own, whose types are
 * handles for another system's thread library.
 *
 * Each object embeds the nanokernel object it stands for, so a call is the
 * kernel call plus a few checks (posix/README.md has the measured cost), and
 * an object needs no pool: it lives where the program puts it.
 */
#ifndef _SYS__PTHREADTYPES_H_
#define _SYS__PTHREADTYPES_H_

#include <sys/sched.h>
/* Relative to this file, so that every firmware source finds it, whatever
 * -I flags it was compiled with. */
#include "../../../kernel/include/kernel.h"

/* A thread is its kernel control block: pthread_self() of a thread started
 * with k_thread_create (main, say) is as good as one from pthread_create. */
typedef struct k_thread *pthread_t;

#define PTHREAD_SCOPE_PROCESS 0
#define PTHREAD_SCOPE_SYSTEM  1
#define PTHREAD_INHERIT_SCHED  1
#define PTHREAD_EXPLICIT_SCHED 2
#define PTHREAD_CREATE_DETACHED 0
#define PTHREAD_CREATE_JOINABLE 1
#define PTHREAD_PROCESS_PRIVATE 0
#define PTHREAD_PROCESS_SHARED  1
#define PTHREAD_PRIO_NONE    0
#define PTHREAD_PRIO_INHERIT 1
#define PTHREAD_PRIO_PROTECT 2
#define PTHREAD_MUTEX_NORMAL     0
#define PTHREAD_MUTEX_RECURSIVE  1
#define PTHREAD_MUTEX_ERRORCHECK 2
#define PTHREAD_MUTEX_DEFAULT    3

typedef struct {
    int is_initialized;
    void *stackaddr;
    size_t stacksize;
    int contentionscope;
    int inheritsched;
    int schedpolicy;
    struct sched_param schedparam;
    int detachstate;
} pthread_attr_t;

/* __kind: 0 never initialised or destroyed; POSIX_MUTEX_STATIC set by the
 * static initializer (the kernel mutex is made at first use);
 * POSIX_MUTEX_READY for a normal, error-checking or default mutex (they
 * behave alike: posix/README.md), POSIX_MUTEX_RECURSIVE for a recursive one.
 * One compare tells the common case. */
typedef struct {
    struct k_mutex __m;
    uint16_t __kind;
    uint16_t __depth;   /* recursive mutexes: locks held beyond the first */
} pthread_mutex_t;
#define POSIX_MUTEX_STATIC 0x0100u
#define POSIX_MUTEX_READY  0x0200u
#define POSIX_MUTEX_RECURSIVE 0x0201u
#define PTHREAD_MUTEX_INITIALIZER { { 0 }, POSIX_MUTEX_STATIC, 0 }

typedef struct {
    int is_initialized;
    int type;
    int protocol;
    int pshared;
} pthread_mutexattr_t;

typedef struct {
    struct k_cond __c;
    uint32_t __state;   /* 0, POSIX_COND_STATIC or POSIX_COND_READY */
} pthread_cond_t;
#define POSIX_COND_STATIC 0x0100u
#define POSIX_COND_READY  0x0200u
#define PTHREAD_COND_INITIALIZER { { { { 0, 0 } }, 0 }, POSIX_COND_STATIC }

typedef struct {
    int is_initialized;
    clockid_t clock;
    int pshared;
} pthread_condattr_t;

typedef struct {
    volatile int __state;   /* 0 not run, 1 running, 2 done */
} pthread_once_t;
#define PTHREAD_ONCE_INIT { 0 }

/* Thread-specific data is not supported (posix/README.md); the type exists
 * because newlib's headers name it. */
typedef uint32_t pthread_key_t;

#endif /* _SYS__PTHREADTYPES_H_ */
