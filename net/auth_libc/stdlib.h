/*
 * <stdlib.h> for the CPU32 build of Mbed TLS: cipher.c includes it, but in
 * the configuration of net/auth_mbedtls_config.h (MBEDTLS_PLATFORM_MEMORY
 * with its own calloc and free) nothing of it is used. Empty, so that any
 * use would fail to compile instead of linking a C library that is not there.
 */
#ifndef NET_AUTH_LIBC_STDLIB_H
#define NET_AUTH_LIBC_STDLIB_H
#endif
