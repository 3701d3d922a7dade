/*
 * Unnamed semaphores on the kernel's counting semaphores. Calls return 0, or
 * -1 with errno set, as POSIX says.
 */
#include <semaphore.h>
#include "posix_internal.h"

static int posix_sem_result(int k_status)
{
    if (k_status == K_OK)
        return 0;
    errno = posix_errno(k_status);
    return -1;
}

int sem_init(sem_t *sem, int pshared, unsigned value)
{
    if (sem == NULL || value > (unsigned)SEM_VALUE_MAX) {
        errno = EINVAL;
        return -1;
    }
    if (pshared != 0) {
        errno = ENOSYS;   /* one program, one address space */
        return -1;
    }
    return posix_sem_result(k_sem_init(&sem->__s, value, (uint32_t)SEM_VALUE_MAX));
}

int sem_destroy(sem_t *sem)
{
    uint32_t irq;
    int r = K_OK;
    int32_t v;
    if (sem == NULL || k_sem_getvalue(&sem->__s, &v) != K_OK)
        return posix_sem_result(K_EINVAL);
    irq = k_arch_irq_save();
    if (!k_list_empty(&sem->__s.wq.waiters))
        r = K_EBUSY;   /* threads wait on it */
    else
        sem->__s.magic = 0;
    k_arch_irq_restore(irq);
    return posix_sem_result(r);
}

int sem_wait(sem_t *sem)
{
    return posix_sem_result(sem == NULL ? K_EINVAL : k_sem_wait(&sem->__s));
}

int sem_trywait(sem_t *sem)
{
    return posix_sem_result(sem == NULL ? K_EINVAL : k_sem_trywait(&sem->__s));
}

int sem_timedwait(sem_t *sem, const struct timespec *abstime)
{
    struct k_timespec t;
    int r;
    if (sem == NULL)
        return posix_sem_result(K_EINVAL);
    /* POSIX: the time is checked only when the semaphore cannot be taken. */
    r = k_sem_trywait(&sem->__s);
    if (r != K_EAGAIN)
        return posix_sem_result(r);
    if (posix_timespec(abstime, &t) != K_OK)
        return posix_sem_result(K_EINVAL);
    return posix_sem_result(k_sem_timedwait(&sem->__s, &t));
}

int sem_post(sem_t *sem)
{
    return posix_sem_result(sem == NULL ? K_EINVAL : k_sem_post(&sem->__s));
}

int sem_getvalue(sem_t *sem, int *sval)
{
    int32_t v;
    int r;
    if (sem == NULL || sval == NULL)
        return posix_sem_result(K_EINVAL);
    r = k_sem_getvalue(&sem->__s, &v);
    if (r == K_OK)
        *sval = (int)v;
    return posix_sem_result(r);
}
