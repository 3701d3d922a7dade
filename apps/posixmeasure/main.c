/*
 * The cost of the POSIX layer against the kernel calls it stands on, counted
 * in instructions from an exec trace (apps/posixmeasure/tests/): each path
 * runs between two global labels, ten or twenty times.
 *   uncontended lock + unlock: k_mutex_lock/unlock, pthread_mutex_lock/unlock
 *   semaphore hand-off: from the post in one thread to the return from the
 *   wait in a more urgent one that was blocked on it: k_sem, sem_t
 */
#include <pthread.h>
#include <semaphore.h>
#include <stdio.h>
#include "kernel.h"

#define LABEL(name) __asm__ __volatile__(".globl " #name "\n" #name ":" ::: "memory")

static struct k_mutex kmutex;
static pthread_mutex_t pmutex = PTHREAD_MUTEX_INITIALIZER;

static void __attribute__((noinline)) measure_mutexes(void)
{
    int i;
    for (i = 0; i < 10; i++) {
        LABEL(pm_k_mutex_begin);
        k_mutex_lock(&kmutex);
        k_mutex_unlock(&kmutex);
        LABEL(pm_k_mutex_end);
    }
    for (i = 0; i < 10; i++) {
        LABEL(pm_pthread_mutex_begin);
        pthread_mutex_lock(&pmutex);
        pthread_mutex_unlock(&pmutex);
        LABEL(pm_pthread_mutex_end);
    }
}

static struct k_sem ksem;
static sem_t psem;

static void *k_taker(void *arg)
{
    int i;
    (void)arg;
    for (i = 0; i < 20; i++) {
        k_sem_wait(&ksem);
        LABEL(pm_k_sem_after_wait);
    }
    return NULL;
}

static void *k_giver(void *arg)
{
    int i;
    (void)arg;
    for (i = 0; i < 20; i++) {
        LABEL(pm_k_sem_before_post);
        k_sem_post(&ksem);
    }
    return NULL;
}

static void *p_taker(void *arg)
{
    int i;
    (void)arg;
    for (i = 0; i < 20; i++) {
        sem_wait(&psem);
        LABEL(pm_sem_after_wait);
    }
    return NULL;
}

static void *p_giver(void *arg)
{
    int i;
    (void)arg;
    for (i = 0; i < 20; i++) {
        LABEL(pm_sem_before_post);
        sem_post(&psem);
    }
    return NULL;
}

static void pair(void *(*taker)(void *), void *(*giver)(void *))
{
    pthread_attr_t a;
    struct sched_param sp;
    pthread_t t, g;
    pthread_attr_init(&a);
    pthread_attr_setinheritsched(&a, PTHREAD_EXPLICIT_SCHED);
    sp.sched_priority = 10;
    pthread_attr_setschedparam(&a, &sp);
    pthread_create(&t, &a, taker, NULL);    /* runs at once and waits */
    sp.sched_priority = 5;
    pthread_attr_setschedparam(&a, &sp);
    pthread_create(&g, &a, giver, NULL);
    pthread_join(g, NULL);
    pthread_join(t, NULL);
}

int main(void)
{
    k_mutex_init(&kmutex);
    measure_mutexes();
    k_sem_init(&ksem, 0, 100);
    sem_init(&psem, 0, 0);
    pair(k_taker, k_giver);
    pair(p_taker, p_giver);
    printf("POSIX MEASURE DONE\n");
    return 0;
}
