/* The kernel's pure data structures (see k_struct.h). */
#include "k_struct.h"

void k_memcpy(void *dst, const void *src, size_t n)
{
    uint8_t *d = dst;
    const uint8_t *s = src;
    while (n-- > 0u)
        *d++ = *s++;
}

void k_memset(void *dst, int value, size_t n)
{
    uint8_t *d = dst;
    while (n-- > 0u)
        *d++ = (uint8_t)value;
}

size_t k_strlen(const char *s)
{
    size_t n = 0;
    while (s[n] != '\0')
        n++;
    return n;
}

/* ---- ready queues ---- */

void k_prioq_init(struct k_prioq *q)
{
    unsigned p;
    q->bitmap = 0;
    for (p = 0; p < K_PRIO_LEVELS; p++)
        k_list_init(&q->level[p]);
}

void k_prioq_append(struct k_prioq *q, struct k_list_node *node, unsigned prio)
{
    k_list_append(&q->level[prio], node);
    q->bitmap |= (uint32_t)1u << prio;
}

void k_prioq_prepend(struct k_prioq *q, struct k_list_node *node, unsigned prio)
{
    k_list_prepend(&q->level[prio], node);
    q->bitmap |= (uint32_t)1u << prio;
}

void k_prioq_remove(struct k_prioq *q, struct k_list_node *node, unsigned prio)
{
    k_list_remove(node);
    if (k_list_empty(&q->level[prio]))
        q->bitmap &= ~((uint32_t)1u << prio);
}

/* CPU32 has no BFFFO: the index of the highest bit of each byte value,
 * looked up for the highest non-zero byte. */
static const uint8_t k_msb_of_byte[256] = {
#define K_MSB_2(n) n, n
#define K_MSB_4(n) K_MSB_2(n), K_MSB_2(n)
#define K_MSB_8(n) K_MSB_4(n), K_MSB_4(n)
#define K_MSB_16(n) K_MSB_8(n), K_MSB_8(n)
#define K_MSB_32(n) K_MSB_16(n), K_MSB_16(n)
#define K_MSB_64(n) K_MSB_32(n), K_MSB_32(n)
#define K_MSB_128(n) K_MSB_64(n), K_MSB_64(n)
    0, 0, K_MSB_2(1), K_MSB_4(2), K_MSB_8(3), K_MSB_16(4), K_MSB_32(5), K_MSB_64(6), K_MSB_128(7)
};

unsigned k_highest_bit(uint32_t word)
{
    if (word >> 16 != 0u) {
        if (word >> 24 != 0u)
            return 24u + k_msb_of_byte[word >> 24];
        return 16u + k_msb_of_byte[word >> 16];
    }
    if (word >> 8 != 0u)
        return 8u + k_msb_of_byte[word >> 8];
    return k_msb_of_byte[word];
}

int k_prioq_top_prio(const struct k_prioq *q)
{
    return q->bitmap == 0 ? -1 : (int)k_highest_bit(q->bitmap);
}

struct k_list_node *k_prioq_highest(const struct k_prioq *q)
{
    if (q->bitmap == 0)
        return NULL;
    return q->level[k_highest_bit(q->bitmap)].next;
}

int k_prioq_rotate(struct k_prioq *q, unsigned prio)
{
    struct k_list_node *head = &q->level[prio];
    struct k_list_node *first = head->next;
    if (first == head || first->next == head)
        return 0;
    k_list_remove(first);
    k_list_append(head, first);
    return 1;
}

/* ---- timer list ---- */

void k_tlist_init(struct k_tlist *l)
{
    k_list_init(&l->head);
}

void k_tlist_insert(struct k_tlist *l, struct k_timer_node *t, uint32_t deadline)
{
    struct k_list_node *pos = l->head.next;
    t->deadline = deadline;
    /* After every timer that is due at or before this one: FIFO among equals. */
    while (pos != &l->head &&
           !k_tick_before(deadline, K_CONTAINER_OF(pos, struct k_timer_node, node)->deadline))
        pos = pos->next;
    k_list_insert_before(pos, &t->node);
}

void k_tlist_remove(struct k_timer_node *t)
{
    if (k_list_linked(&t->node))
        k_list_remove(&t->node);
}

struct k_timer_node *k_tlist_first(const struct k_tlist *l)
{
    struct k_list_node *n = k_list_first(&l->head);
    return n == NULL ? NULL : K_CONTAINER_OF(n, struct k_timer_node, node);
}

struct k_timer_node *k_tlist_pop_expired(struct k_tlist *l, uint32_t now)
{
    struct k_timer_node *t = k_tlist_first(l);
    if (t == NULL || k_tick_before(now, t->deadline))
        return NULL;
    k_list_remove(&t->node);
    return t;
}

/* ---- byte ring ---- */

int k_ring_init(struct k_ring *r, uint8_t *buf, size_t capacity)
{
    if (buf == NULL || capacity < 2u || capacity > 32768u || (capacity & (capacity - 1u)) != 0u)
        return -1;
    r->buf = buf;
    r->mask = (uint16_t)(capacity - 1u);
    r->head = 0;
    r->tail = 0;
    return 0;
}

size_t k_ring_used(const struct k_ring *r)
{
    return (uint16_t)(r->head - r->tail);
}

size_t k_ring_free(const struct k_ring *r)
{
    return (size_t)r->mask + 1u - k_ring_used(r);
}

int k_ring_put(struct k_ring *r, uint8_t byte)
{
    uint16_t head = r->head;
    if ((uint16_t)(head - r->tail) > r->mask)
        return 0;
    r->buf[head & r->mask] = byte;
    r->head = (uint16_t)(head + 1u); /* publish after the byte is stored */
    return 1;
}

int k_ring_get(struct k_ring *r, uint8_t *byte)
{
    uint16_t tail = r->tail;
    if (tail == r->head)
        return 0;
    *byte = r->buf[tail & r->mask];
    r->tail = (uint16_t)(tail + 1u);
    return 1;
}

size_t k_ring_write(struct k_ring *r, const uint8_t *data, size_t len)
{
    size_t n = 0;
    while (n < len && k_ring_put(r, data[n]))
        n++;
    return n;
}

size_t k_ring_read(struct k_ring *r, uint8_t *data, size_t len)
{
    size_t n = 0;
    while (n < len && k_ring_get(r, &data[n]))
        n++;
    return n;
}

/* ---- message slots ---- */

int k_msgbuf_init(struct k_msgbuf *b, void *storage, size_t msg_size, size_t capacity)
{
    if (storage == NULL || msg_size == 0u || capacity == 0u || msg_size > 0xFFFFu || capacity > 0xFFFFu)
        return -1;
    b->slots = storage;
    b->msg_size = (uint16_t)msg_size;
    b->capacity = (uint16_t)capacity;
    b->first = 0;
    b->count = 0;
    return 0;
}

int k_msgbuf_put(struct k_msgbuf *b, const void *msg)
{
    uint32_t slot;
    if (b->count == b->capacity)
        return -1;
    slot = (uint32_t)b->first + b->count;
    if (slot >= b->capacity)
        slot -= b->capacity;
    k_memcpy(b->slots + slot * b->msg_size, msg, b->msg_size);
    b->count++;
    return 0;
}

int k_msgbuf_get(struct k_msgbuf *b, void *msg)
{
    if (b->count == 0)
        return -1;
    k_memcpy(msg, b->slots + (uint32_t)b->first * b->msg_size, b->msg_size);
    b->first = (uint16_t)(b->first + 1u == b->capacity ? 0u : b->first + 1u);
    b->count--;
    return 0;
}
