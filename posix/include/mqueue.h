/*
 * <mqueue.h> of the CubeOS POSIX layer: named message queues on the
 * nanokernel's (posix/README.md). A queue's storage comes from the heap when
 * it is created and goes back when it is unlinked and closed. The calls
 * return what POSIX says, or -1 with errno set.
 */
#ifndef _MQUEUE_H
#define _MQUEUE_H

#include <sys/types.h>
#include <fcntl.h>
#include <time.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Queues open at once, and the longest name (without the leading '/'). */
#define MQ_OPEN_MAX 8
#define MQ_NAME_MAX 15
/* Messages are kept in the order sent: priorities are not supported, so the
 * only one is 0 (posix/README.md). */
#define MQ_PRIO_MAX 1

typedef int mqd_t;

struct mq_attr {
    long mq_flags;     /* O_NONBLOCK or 0 */
    long mq_maxmsg;
    long mq_msgsize;
    long mq_curmsgs;
};

mqd_t mq_open(const char *name, int oflag, ...);
int mq_close(mqd_t mqdes);
int mq_unlink(const char *name);
int mq_send(mqd_t mqdes, const char *msg_ptr, size_t msg_len, unsigned msg_prio);
int mq_timedsend(mqd_t mqdes, const char *msg_ptr, size_t msg_len, unsigned msg_prio,
                 const struct timespec *abstime);
ssize_t mq_receive(mqd_t mqdes, char *msg_ptr, size_t msg_len, unsigned *msg_prio);
ssize_t mq_timedreceive(mqd_t mqdes, char *msg_ptr, size_t msg_len, unsigned *msg_prio,
                        const struct timespec *abstime);
int mq_getattr(mqd_t mqdes, struct mq_attr *mqstat);
int mq_setattr(mqd_t mqdes, const struct mq_attr *mqstat, struct mq_attr *omqstat);

#ifdef __cplusplus
}
#endif

#endif /* _MQUEUE_H */
