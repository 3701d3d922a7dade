/*
 * XDR (RFC 4506): platform-independent encoding of the data the robots
 * exchange. One routine per type serves both directions, as in Sun RPC's
 * xdr(3): the stream says whether it encodes (value -> bytes) or decodes
 * (bytes -> value), so a structure is one routine calling its members'.
 *
 * Every routine returns 1 on success and 0 on failure (out of room or
 * input, a value the type forbids such as bool 2 or a string longer than its
 * bound); after a failure the stream stays failed and later calls fail too,
 * so a caller may check once at the end, and nxdr_error() says why (the
 * first failure's reason). A decoder never reads or writes past the buffers
 * it was given, whatever length or count the input claims (up to
 * 0xFFFFFFFF) and whether size_t has 16, 32 or 64 bits: no length
 * computation can wrap (checked by CBMC, net/proofs, with the host's and the
 * CPU32's 32-bit size_t, and libFuzzer, net/fuzz, in 64- and 32-bit builds),
 * and it is compared byte for byte with libtirpc's xdrmem and the Python
 * xdrlib3 package (net/tests).
 * Floating point: IEEE 754 single/double bit patterns are copied, not
 * computed, so soft-float targets (the CPU32) need no float arithmetic.
 */
#ifndef NET_NXDR_H
#define NET_NXDR_H

#include <stddef.h>
#include <stdint.h>

enum nxdr_op { NXDR_ENCODE = 0, NXDR_DECODE = 1 };

/* Why a stream failed (nxdr_error). */
enum nxdr_err {
    NXDR_OK = 0,
    NXDR_ESHORT = 1,    /* the item does not fit: input ends (decode) or out of room (encode) */
    NXDR_ETOOLONG = 2,  /* a length or count above the caller's maximum */
    NXDR_EVALUE = 3,    /* a value the type forbids (a bool other than 0 or 1) */
    NXDR_EELEMENT = 4   /* a vector or array element's routine failed without a reason */
};

struct nxdr {
    uint8_t *buf;       /* decode: the input (never written) */
    size_t size;
    size_t pos;         /* next byte */
    uint8_t op;         /* enum nxdr_op */
    uint8_t failed;     /* enum nxdr_err of the first failure; 0 while none */
};

void nxdr_init_encode(struct nxdr *x, uint8_t *buf, size_t size);
void nxdr_init_decode(struct nxdr *x, const uint8_t *buf, size_t size);
/* Bytes encoded or consumed so far. */
size_t nxdr_getpos(const struct nxdr *x);
/* NXDR_OK, or why the stream failed (the first failure). */
int nxdr_error(const struct nxdr *x);
/* A sentence for an enum nxdr_err code. */
const char *nxdr_strerror(int err);

int nxdr_int(struct nxdr *x, int32_t *v);
int nxdr_u_int(struct nxdr *x, uint32_t *v);
int nxdr_hyper(struct nxdr *x, int64_t *v);
int nxdr_u_hyper(struct nxdr *x, uint64_t *v);
int nxdr_bool(struct nxdr *x, int32_t *v);    /* 0 or 1 only */
int nxdr_enum(struct nxdr *x, int32_t *v);
int nxdr_float(struct nxdr *x, float *v);
int nxdr_double(struct nxdr *x, double *v);
/* Fixed-length opaque data: len bytes plus zero padding to a multiple of 4. */
int nxdr_opaque(struct nxdr *x, uint8_t *data, uint32_t len);
/* Variable-length opaque data: length, bytes, padding; at most max bytes. */
int nxdr_bytes(struct nxdr *x, uint8_t *data, uint32_t *len, uint32_t max);
/* String of at most max bytes; str has room for max + 1 (the NUL). */
int nxdr_string(struct nxdr *x, char *str, uint32_t max);

typedef int (*nxdr_proc)(struct nxdr *x, void *element);
/* Fixed-length array of count elements of elsize bytes each (count * elsize
 * must fit size_t: a larger product describes no array and is refused). */
int nxdr_vector(struct nxdr *x, void *array, uint32_t count, size_t elsize, nxdr_proc proc);
/* Variable-length array: count, then the elements; at most max elements. */
int nxdr_array(struct nxdr *x, void *array, uint32_t *count, uint32_t max, size_t elsize,
              nxdr_proc proc);

#endif /* NET_NXDR_H */
