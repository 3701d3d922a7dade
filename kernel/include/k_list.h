/*
 * Intrusive circular doubly linked lists: the one container of the kernel.
 * A list head is a node whose next/prev point at itself when empty; a node
 * that is in no list has next == NULL, so membership is testable in O(1).
 */
#ifndef K_LIST_H
#define K_LIST_H

#include <stddef.h>

struct k_list_node {
    struct k_list_node *next;
    struct k_list_node *prev;
};

/* The enclosing structure of a list node. */
#define K_CONTAINER_OF(ptr, type, member) \
    ((type *)(void *)((char *)(ptr) - offsetof(type, member)))

static inline void k_list_init(struct k_list_node *head)
{
    head->next = head;
    head->prev = head;
}

static inline int k_list_empty(const struct k_list_node *head)
{
    return head->next == head;
}

/* Whether a node (not a head) is linked into some list. */
static inline int k_list_linked(const struct k_list_node *node)
{
    return node->next != NULL;
}

/* Inserts node before pos (at the tail when pos is the head). */
static inline void k_list_insert_before(struct k_list_node *pos, struct k_list_node *node)
{
    node->next = pos;
    node->prev = pos->prev;
    pos->prev->next = node;
    pos->prev = node;
}

static inline void k_list_append(struct k_list_node *head, struct k_list_node *node)
{
    k_list_insert_before(head, node);
}

static inline void k_list_prepend(struct k_list_node *head, struct k_list_node *node)
{
    k_list_insert_before(head->next, node);
}

static inline void k_list_remove(struct k_list_node *node)
{
    node->prev->next = node->next;
    node->next->prev = node->prev;
    node->next = NULL;
    node->prev = NULL;
}

/* First node, or NULL when empty. */
static inline struct k_list_node *k_list_first(const struct k_list_node *head)
{
    return head->next == head ? NULL : head->next;
}

#endif /* K_LIST_H */
