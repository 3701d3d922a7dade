/*
 * Named message queues on the kernel's queues of fixed-size messages: each
 * slot holds a message's length and up to mq_msgsize bytes. Queues and open
 * descriptors come from small fixed tables (MQ_OPEN_MAX each); a queue's
 * slots come from the heap when it is created and go back once it is
 * unlinked and its last descriptor closed.
 */
#include <fcntl.h>
#include <mqueue.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include "posix_internal.h"

/* The longest message a queue may take: a send and a receive copy one slot
 * through a buffer on the caller's stack. */
#define POSIX_MQ_MSGSIZE_MAX 256
#define POSIX_MQ_MAXMSG_MAX  1024
/* What mq_open gives a queue created without attributes. */
#define POSIX_MQ_DEFAULT_MAXMSG  8
#define POSIX_MQ_DEFAULT_MSGSIZE 64

struct posix_mq {
    struct k_mq q;
    void *slots;
    long maxmsg, msgsize;
    uint8_t in_use, unlinked, open_count;
    char name[MQ_NAME_MAX + 1];
};

struct posix_mqd {
    struct posix_mq *mq;
    int flags;        /* the access mode and O_NONBLOCK */
};

static struct posix_mq posix_mqs[MQ_OPEN_MAX];
static struct posix_mqd posix_mqds[MQ_OPEN_MAX];

struct posix_mq_slot {
    uint32_t len;
    char data[POSIX_MQ_MSGSIZE_MAX];
};

static int posix_mq_fail(int err)
{
    errno = err;
    return -1;
}

/* The descriptor's entry, or NULL (errno EBADF). */
static struct posix_mqd *posix_mqd_of(mqd_t d)
{
    if (d < 0 || d >= MQ_OPEN_MAX || posix_mqds[d].mq == NULL) {
        errno = EBADF;
        return NULL;
    }
    return &posix_mqds[d];
}

/* The descriptor's entry if it is open for sending (sending) or receiving,
 * or NULL (errno EBADF). */
static struct posix_mqd *posix_mqd_open_for(mqd_t d, int sending)
{
    struct posix_mqd *e = posix_mqd_of(d);
    if (e != NULL && (e->flags & O_ACCMODE) == (sending ? O_RDONLY : O_WRONLY)) {
        errno = EBADF;
        return NULL;
    }
    return e;
}

/* "/name": 1..MQ_NAME_MAX characters after the slash, no other slash. */
static int posix_mq_name(const char *name, const char **bare)
{
    size_t n;
    if (name == NULL || name[0] != '/' || name[1] == '\0' || strchr(name + 1, '/') != NULL)
        return EINVAL;
    n = strlen(name + 1);
    if (n > MQ_NAME_MAX)
        return ENAMETOOLONG;
    *bare = name + 1;
    return 0;
}

static struct posix_mq *posix_mq_find(const char *bare)
{
    unsigned i;
    for (i = 0; i < MQ_OPEN_MAX; i++)
        if (posix_mqs[i].in_use && !posix_mqs[i].unlinked && strcmp(posix_mqs[i].name, bare) == 0)
            return &posix_mqs[i];
    return NULL;
}

/* Frees a queue that is unlinked and no longer open (called with interrupts
 * masked; returns the slots to free once they are unmasked). */
static void *posix_mq_retire(struct posix_mq *mq)
{
    void *slots = NULL;
    if (mq->unlinked && mq->open_count == 0u) {
        slots = mq->slots;
        mq->slots = NULL;
        mq->q.magic = 0;
        mq->in_use = 0;
    }
    return slots;
}

mqd_t mq_open(const char *name, int oflag, ...)
{
    const char *bare = NULL;
    struct mq_attr *attr = NULL;
    struct posix_mq *mq, *fresh = NULL;
    void *slots = NULL;
    long maxmsg = POSIX_MQ_DEFAULT_MAXMSG, msgsize = POSIX_MQ_DEFAULT_MSGSIZE;
    int r, d = -1, acc = oflag & O_ACCMODE;
    unsigned i;
    uint32_t irq;
    va_list ap;
    r = posix_mq_name(name, &bare);
    if (r != 0)
        return posix_mq_fail(r);
    if (acc != O_RDONLY && acc != O_WRONLY && acc != O_RDWR)
        return posix_mq_fail(EINVAL);
    if ((oflag & O_CREAT) != 0) {
        va_start(ap, oflag);
        (void)va_arg(ap, int);              /* mode: no permissions here */
        attr = va_arg(ap, struct mq_attr *);
        va_end(ap);
        if (attr != NULL) {
            if (attr->mq_maxmsg <= 0 || attr->mq_maxmsg > POSIX_MQ_MAXMSG_MAX ||
                attr->mq_msgsize <= 0 || attr->mq_msgsize > POSIX_MQ_MSGSIZE_MAX)
                return posix_mq_fail(EINVAL);
            maxmsg = attr->mq_maxmsg;
            msgsize = attr->mq_msgsize;
        }
        /* Allocated before the tables are looked at: the heap is not for
         * interrupts-masked code. Freed again if the queue exists already. */
        slots = malloc((size_t)maxmsg * ((size_t)msgsize + sizeof(uint32_t)));
        if (slots == NULL)
            return posix_mq_fail(ENOMEM);
    }
    irq = k_arch_irq_save();
    mq = posix_mq_find(bare);
    if (mq != NULL && (oflag & (O_CREAT | O_EXCL)) == (O_CREAT | O_EXCL)) {
        r = EEXIST;
    } else if (mq == NULL && (oflag & O_CREAT) == 0) {
        r = ENOENT;
    } else {
        for (i = 0; i < MQ_OPEN_MAX && d < 0; i++)
            if (posix_mqds[i].mq == NULL)
                d = (int)i;
        if (d < 0)
            r = EMFILE;
        else if (mq == NULL) {
            for (i = 0; i < MQ_OPEN_MAX && fresh == NULL; i++)
                if (!posix_mqs[i].in_use)
                    fresh = &posix_mqs[i];
            if (fresh == NULL) {
                r = ENFILE;
            } else {
                mq = fresh;
                (void)k_mq_init(&mq->q, slots, (size_t)msgsize + sizeof(uint32_t), (size_t)maxmsg);
                mq->slots = slots;
                slots = NULL;
                mq->maxmsg = maxmsg;
                mq->msgsize = msgsize;
                mq->in_use = 1;
                mq->unlinked = 0;
                mq->open_count = 0;
                strcpy(mq->name, bare);
            }
        }
        if (r == 0) {
            mq->open_count++;
            posix_mqds[d].mq = mq;
            posix_mqds[d].flags = oflag & (O_ACCMODE | O_NONBLOCK);
        }
    }
    k_arch_irq_restore(irq);
    free(slots);   /* not used: the queue existed, or the call failed */
    return r == 0 ? d : posix_mq_fail(r);
}

int mq_close(mqd_t mqdes)
{
    struct posix_mqd *d;
    void *slots;
    uint32_t irq = k_arch_irq_save();
    d = posix_mqd_of(mqdes);
    if (d == NULL) {
        k_arch_irq_restore(irq);
        return -1;
    }
    d->mq->open_count--;
    slots = posix_mq_retire(d->mq);
    d->mq = NULL;
    k_arch_irq_restore(irq);
    free(slots);
    return 0;
}

int mq_unlink(const char *name)
{
    const char *bare = NULL;
    struct posix_mq *mq;
    void *slots = NULL;
    uint32_t irq;
    int r = posix_mq_name(name, &bare);
    if (r != 0)
        return posix_mq_fail(r);
    irq = k_arch_irq_save();
    mq = posix_mq_find(bare);
    if (mq != NULL) {
        mq->unlinked = 1;   /* the name is free at once; the queue lives while open */
        slots = posix_mq_retire(mq);
    }
    k_arch_irq_restore(irq);
    free(slots);
    return mq != NULL ? 0 : posix_mq_fail(ENOENT);
}

/* How long a send or receive that found the queue full or empty waits:
 * 0 and *ticks set, or the error number (O_NONBLOCK: EAGAIN; a timed call
 * whose time has passed: ETIMEDOUT; a bad time: EINVAL). */
static int posix_mq_wait_for(const struct posix_mqd *d, const struct timespec *abstime,
                             int timed, k_ticks_t *ticks)
{
    struct k_timespec t;
    if ((d->flags & O_NONBLOCK) != 0)
        return EAGAIN;
    if (!timed) {
        *ticks = K_FOREVER;
        return 0;
    }
    if (posix_timespec(abstime, &t) != K_OK || k_abs_to_timeout(&t, ticks) != K_OK)
        return EINVAL;
    return *ticks == K_NO_WAIT ? ETIMEDOUT : 0;
}

/* Moves one slot into (sending) or out of d's queue: at once if it can,
 * else waiting as posix_mq_wait_for says. 0 or the error number. */
static int posix_mq_transfer(const struct posix_mqd *d, struct posix_mq_slot *slot, int sending,
                             const struct timespec *abstime, int timed)
{
    k_ticks_t ticks = K_NO_WAIT;
    int r, tries;
    /* POSIX: the time is checked only when the queue is full (empty). */
    for (tries = 0; tries < 2; tries++) {
        r = sending ? k_mq_send_ticks(&d->mq->q, slot, ticks)
                    : k_mq_receive_ticks(&d->mq->q, slot, ticks);
        if (r != K_EAGAIN || tries > 0)
            break;
        r = posix_mq_wait_for(d, abstime, timed, &ticks);
        if (r != 0)
            return r;
    }
    return r == K_OK ? 0 : posix_errno(r);
}

static int posix_mq_send(mqd_t mqdes, const char *msg_ptr, size_t msg_len, unsigned msg_prio,
                         const struct timespec *abstime, int timed)
{
    struct posix_mqd *d = posix_mqd_open_for(mqdes, 1);
    struct posix_mq_slot slot;
    int r;
    if (d == NULL)
        return -1;
    if (msg_prio >= MQ_PRIO_MAX || (msg_ptr == NULL && msg_len > 0u))
        return posix_mq_fail(EINVAL);
    if (msg_len > (size_t)d->mq->msgsize)
        return posix_mq_fail(EMSGSIZE);
    slot.len = (uint32_t)msg_len;
    if (msg_len > 0u)
        memcpy(slot.data, msg_ptr, msg_len);
    r = posix_mq_transfer(d, &slot, 1, abstime, timed);
    return r == 0 ? 0 : posix_mq_fail(r);
}

int mq_send(mqd_t mqdes, const char *msg_ptr, size_t msg_len, unsigned msg_prio)
{
    return posix_mq_send(mqdes, msg_ptr, msg_len, msg_prio, NULL, 0);
}

int mq_timedsend(mqd_t mqdes, const char *msg_ptr, size_t msg_len, unsigned msg_prio,
                 const struct timespec *abstime)
{
    return posix_mq_send(mqdes, msg_ptr, msg_len, msg_prio, abstime, 1);
}

static ssize_t posix_mq_receive(mqd_t mqdes, char *msg_ptr, size_t msg_len, unsigned *msg_prio,
                                const struct timespec *abstime, int timed)
{
    struct posix_mqd *d = posix_mqd_open_for(mqdes, 0);
    struct posix_mq_slot slot;
    int r;
    if (d == NULL)
        return -1;
    if (msg_ptr == NULL)
        return posix_mq_fail(EINVAL);
    if (msg_len < (size_t)d->mq->msgsize)
        return posix_mq_fail(EMSGSIZE);
    r = posix_mq_transfer(d, &slot, 0, abstime, timed);
    if (r != 0)
        return posix_mq_fail(r);
    memcpy(msg_ptr, slot.data, slot.len);
    if (msg_prio != NULL)
        *msg_prio = 0;
    return (ssize_t)slot.len;
}

ssize_t mq_receive(mqd_t mqdes, char *msg_ptr, size_t msg_len, unsigned *msg_prio)
{
    return posix_mq_receive(mqdes, msg_ptr, msg_len, msg_prio, NULL, 0);
}

ssize_t mq_timedreceive(mqd_t mqdes, char *msg_ptr, size_t msg_len, unsigned *msg_prio,
                        const struct timespec *abstime)
{
    return posix_mq_receive(mqdes, msg_ptr, msg_len, msg_prio, abstime, 1);
}

int mq_getattr(mqd_t mqdes, struct mq_attr *mqstat)
{
    struct posix_mqd *d = posix_mqd_of(mqdes);
    if (d == NULL)
        return -1;
    if (mqstat == NULL)
        return posix_mq_fail(EINVAL);
    mqstat->mq_flags = d->flags & O_NONBLOCK;
    mqstat->mq_maxmsg = d->mq->maxmsg;
    mqstat->mq_msgsize = d->mq->msgsize;
    mqstat->mq_curmsgs = k_mq_count(&d->mq->q);
    return 0;
}

int mq_setattr(mqd_t mqdes, const struct mq_attr *mqstat, struct mq_attr *omqstat)
{
    struct posix_mqd *d = posix_mqd_of(mqdes);
    if (d == NULL)
        return -1;
    if (mqstat == NULL || (mqstat->mq_flags & ~(long)O_NONBLOCK) != 0)
        return posix_mq_fail(EINVAL);
    if (omqstat != NULL)
        (void)mq_getattr(mqdes, omqstat);
    d->flags = (d->flags & ~O_NONBLOCK) | (int)(mqstat->mq_flags & O_NONBLOCK);
    return 0;
}
