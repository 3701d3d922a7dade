/*
 * The few <string.h> functions freestanding target code needs. GCC emits
 * calls to memcpy/memset/memmove/memcmp for structure copies and
 * initialisations even with -ffreestanding, so every image links these.
 */
#ifndef KERNEL_LIB_KSTRING_H
#define KERNEL_LIB_KSTRING_H

#include <stddef.h>

void *memcpy(void *dst, const void *src, size_t n);
void *memmove(void *dst, const void *src, size_t n);
void *memset(void *dst, int c, size_t n);
int memcmp(const void *a, const void *b, size_t n);
size_t strlen(const char *s);

#endif /* KERNEL_LIB_KSTRING_H */
