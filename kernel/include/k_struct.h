/*
 * The kernel's pure data structures, free of threads and interrupts so the
 * host tests can drive them directly:
 *   - k_prioq:   ready queues, one FIFO per priority plus a bitmap of the
 *                non-empty ones (highest priority found in 5 steps);
 *   - k_tlist:   the timer list, sorted by absolute deadline tick with
 *                wrap-safe comparisons (valid while deadlines are within
 *                2^31 ticks of each other);
 *   - k_ring:    a byte ring buffer for one producer and one consumer;
 *   - k_msgbuf:  a ring of fixed-size message slots in caller memory.
 * None of them locks: the callers (kernel, drivers) do.
 */
#ifndef K_STRUCT_H
#define K_STRUCT_H

#include <stddef.h>
#include <stdint.h>
#include "k_list.h"

/* ---- ready queues ---- */
#define K_PRIO_LEVELS 32u

struct k_prioq {
    uint32_t bitmap; /* bit p set <=> level p non-empty */
    struct k_list_node level[K_PRIO_LEVELS];
};

void k_prioq_init(struct k_prioq *q);
/* Appends node at priority prio (0 <= prio < K_PRIO_LEVELS). */
void k_prioq_append(struct k_prioq *q, struct k_list_node *node, unsigned prio);
/* Puts node at the head of priority prio (a pre-empted thread keeps its turn). */
void k_prioq_prepend(struct k_prioq *q, struct k_list_node *node, unsigned prio);
/* Removes node, which is queued at priority prio. */
void k_prioq_remove(struct k_prioq *q, struct k_list_node *node, unsigned prio);
/* The head of the highest non-empty level, or NULL. */
struct k_list_node *k_prioq_highest(const struct k_prioq *q);
/* Highest non-empty level, or -1 when empty. */
int k_prioq_top_prio(const struct k_prioq *q);
/* Moves the head of level prio to its tail (round robin); returns whether
 * the level has another node to run (i.e. held more than one). */
int k_prioq_rotate(struct k_prioq *q, unsigned prio);
/* Index of the highest set bit of a non-zero word. */
unsigned k_highest_bit(uint32_t word);

/* ---- timer list ---- */
/* a before b, modulo 2^32 */
static inline int k_tick_before(uint32_t a, uint32_t b)
{
    return (int32_t)(a - b) < 0;
}

struct k_timer_node {
    struct k_list_node node;
    uint32_t deadline; /* absolute tick */
};

struct k_tlist {
    struct k_list_node head; /* sorted by deadline, equal deadlines FIFO */
};

void k_tlist_init(struct k_tlist *l);
void k_tlist_insert(struct k_tlist *l, struct k_timer_node *t, uint32_t deadline);
void k_tlist_remove(struct k_timer_node *t);
static inline int k_tlist_active(const struct k_timer_node *t)
{
    return k_list_linked(&t->node);
}
/* Removes and returns the earliest timer whose deadline is at or before now,
 * or NULL. Call repeatedly from the tick to expire everything due. */
struct k_timer_node *k_tlist_pop_expired(struct k_tlist *l, uint32_t now);
/* The earliest timer, or NULL. */
struct k_timer_node *k_tlist_first(const struct k_tlist *l);

/* ---- byte ring ---- */
/* Capacity must be a power of two; head/tail run freely and wrap. Safe for one
 * producer and one consumer on one CPU without locking (each index is written
 * by one side only, and 16-bit stores are atomic on the 68k). */
struct k_ring {
    uint8_t *buf;
    uint16_t mask;          /* capacity - 1 */
    volatile uint16_t head; /* next write, producer only */
    volatile uint16_t tail; /* next read, consumer only */
};

/* Returns 0, or -1 when capacity is not a power of two in 2..32768. */
int k_ring_init(struct k_ring *r, uint8_t *buf, size_t capacity);
size_t k_ring_used(const struct k_ring *r);
size_t k_ring_free(const struct k_ring *r);
/* Returns 1 if the byte was stored, 0 if the ring is full. */
int k_ring_put(struct k_ring *r, uint8_t byte);
/* Returns 1 and the byte, or 0 when the ring is empty. */
int k_ring_get(struct k_ring *r, uint8_t *byte);
/* Stores as many bytes as fit; returns how many. */
size_t k_ring_write(struct k_ring *r, const uint8_t *data, size_t len);
size_t k_ring_read(struct k_ring *r, uint8_t *data, size_t len);

/* ---- fixed-size message slots ---- */
struct k_msgbuf {
    uint8_t *slots;     /* capacity * msg_size bytes */
    uint16_t msg_size;  /* bytes per message */
    uint16_t capacity;  /* slots */
    uint16_t first;     /* slot of the oldest message */
    uint16_t count;     /* messages stored */
};

/* Returns 0, or -1 on a NULL buffer or zero size/capacity. */
int k_msgbuf_init(struct k_msgbuf *b, void *storage, size_t msg_size, size_t capacity);
static inline int k_msgbuf_full(const struct k_msgbuf *b) { return b->count == b->capacity; }
static inline int k_msgbuf_empty(const struct k_msgbuf *b) { return b->count == 0; }
/* Copies msg_size bytes in at the tail; returns 0, or -1 when full. */
int k_msgbuf_put(struct k_msgbuf *b, const void *msg);
/* Copies the oldest message out; returns 0, or -1 when empty. */
int k_msgbuf_get(struct k_msgbuf *b, void *msg);

/* Freestanding byte copy and fill (no libc on the target). */
void k_memcpy(void *dst, const void *src, size_t n);
void k_memset(void *dst, int value, size_t n);
size_t k_strlen(const char *s);

#endif /* K_STRUCT_H */
