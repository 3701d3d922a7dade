/*
 * <assert.h> for the CPU32 build of Mbed TLS: library/common.h includes it;
 * in this configuration no source calls assert() (MBEDTLS_CHECK_PARAMS is
 * off). Empty, so that a use would fail to compile.
 */
#ifndef NET_AUTH_LIBC_ASSERT_H
#define NET_AUTH_LIBC_ASSERT_H
#endif
