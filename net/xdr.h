/*
 * XDR (RFC 4506): platform-independent encoding of the data the robots
 * exchange. One routine per type serves both directions, as in Sun RPC's
 * xdr(3): the stream says whether it encodes (value -> bytes) or decodes
 * (bytes -> value), so a structure is one routine calling its members'.
 *
 * Every routine returns 1 on success and 0 on failure (out of room or
 * input, a value the type forbids such as bool 2 or a string longer than its
 * bound); after a failure the stream stays failed and later calls fail too,
 * so a caller may check once at the end. A decoder never reads or writes past
 * the buffers it was given (checked by CBMC, net/proofs, and libFuzzer,
 * net/fuzz), and is compared byte for byte with libtirpc's xdrmem and the
 * Python xdrlib3 package (net/tests).
 * Floating point: IEEE 754 single/double bit patterns are copied, not
 * computed, so soft-float targets (the CPU32) need no float arithmetic.
 */
#ifndef NET_XDR_H
#define NET_XDR_H

#include <stddef.h>
#include <stdint.h>

enum xdr_op { XDR_ENCODE = 0, XDR_DECODE = 1 };

struct xdr {
    uint8_t *buf;       /* decode: the input (never written) */
    size_t size;
    size_t pos;         /* next byte */
    uint8_t op;         /* enum xdr_op */
    uint8_t failed;
};

void xdr_init_encode(struct xdr *x, uint8_t *buf, size_t size);
void xdr_init_decode(struct xdr *x, const uint8_t *buf, size_t size);
/* Bytes encoded or consumed so far. */
size_t xdr_getpos(const struct xdr *x);

int xdr_int(struct xdr *x, int32_t *v);
int xdr_u_int(struct xdr *x, uint32_t *v);
int xdr_hyper(struct xdr *x, int64_t *v);
int xdr_u_hyper(struct xdr *x, uint64_t *v);
int xdr_bool(struct xdr *x, int32_t *v);    /* 0 or 1 only */
int xdr_enum(struct xdr *x, int32_t *v);
int xdr_float(struct xdr *x, float *v);
int xdr_double(struct xdr *x, double *v);
/* Fixed-length opaque data: len bytes plus zero padding to a multiple of 4. */
int xdr_opaque(struct xdr *x, uint8_t *data, uint32_t len);
/* Variable-length opaque data: length, bytes, padding; at most max bytes. */
int xdr_bytes(struct xdr *x, uint8_t *data, uint32_t *len, uint32_t max);
/* String of at most max bytes; str has room for max + 1 (the NUL). */
int xdr_string(struct xdr *x, char *str, uint32_t max);

typedef int (*xdr_proc)(struct xdr *x, void *element);
/* Fixed-length array of count elements of elsize bytes each. */
int xdr_vector(struct xdr *x, void *array, uint32_t count, size_t elsize, xdr_proc proc);
/* Variable-length array: count, then the elements; at most max elements. */
int xdr_array(struct xdr *x, void *array, uint32_t *count, uint32_t max, size_t elsize,
              xdr_proc proc);

#endif /* NET_XDR_H */
