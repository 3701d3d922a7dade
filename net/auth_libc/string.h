/*
 * <string.h> for the CPU32 build of Mbed TLS (ci/setup.d/mbedtls.sh): the
 * board has no C library, kernel/lib/kstring.c defines these, and every
 * firmware image links it.
 */
#ifndef NET_AUTH_LIBC_STRING_H
#define NET_AUTH_LIBC_STRING_H

#include <stddef.h>

void *memcpy(void *dst, const void *src, size_t n);
void *memmove(void *dst, const void *src, size_t n);
void *memset(void *dst, int c, size_t n);
int memcmp(const void *a, const void *b, size_t n);
size_t strlen(const char *s);
/* Not defined on the board: declared for cipher.c's
 * mbedtls_cipher_info_from_string, which net/auth.c never calls, so that it
 * compiles; the link's --gc-sections drops it, and an image that called it
 * would fail to link. */
int strcmp(const char *a, const char *b);

#endif /* NET_AUTH_LIBC_STRING_H */
