/*
 * Mbed TLS configuration of net/auth.c: AES-128 and CMAC (NIST SP 800-38B,
 * RFC 4493) and nothing else. The same file configures the CPU32 library
 * (ci/setup.d/mbedtls.sh, MBEDTLS_CONFIG_FILE) and the host builds of the
 * tests, so both run the same code.
 */
#ifndef NET_AUTH_MBEDTLS_CONFIG_H
#define NET_AUTH_MBEDTLS_CONFIG_H

#include <stddef.h>

#define MBEDTLS_AES_C
/* The AES tables as constants in flash (8.5 KB) instead of 8.5 KB of .bss
 * that the first key would have to fill at run time: the flash has room
 * (1 MB; the images take about 25 KB), and the tables cannot be overwritten.
 * All four tables per direction: one table each (MBEDTLS_AES_FEWER_TABLES)
 * would save 6 KB at the price of a rotation in three of every four look-ups. */
#define MBEDTLS_AES_ROM_TABLES
/* CMAC is written on the generic cipher layer (cipher.c, cipher_wrap.c);
 * with no mode enabled that layer carries AES-ECB only. */
#define MBEDTLS_CIPHER_C
#define MBEDTLS_CMAC_C

/* No heap on the board: the cipher layer's two allocations (the AES key
 * schedule and the CMAC state, made once per key in net_auth_init) come from
 * net/auth.c's static pool. MBEDTLS_PLATFORM_C is what the library requires
 * for MBEDTLS_PLATFORM_MEMORY; no file of platform.c is built, the macros
 * below replace all it would provide. No standard functions either: the only
 * C library functions the sources call are memcpy, memset and memcmp. */
#define MBEDTLS_PLATFORM_C
#define MBEDTLS_PLATFORM_MEMORY
#define MBEDTLS_PLATFORM_NO_STD_FUNCTIONS
#define MBEDTLS_PLATFORM_CALLOC_MACRO auth_mbedtls_calloc
#define MBEDTLS_PLATFORM_FREE_MACRO   auth_mbedtls_free
void *auth_mbedtls_calloc(size_t n, size_t size);
void auth_mbedtls_free(void *p);

#include "mbedtls/check_config.h"

#endif /* NET_AUTH_MBEDTLS_CONFIG_H */
