/* The XDR sample record: every type of net/xdr.h once. Shared by the host
 * tool xdr_sample.c (compared with Python's xdrlib3) and the fuzzer
 * net/fuzz/fuzz_xdr.c (decoded from any bytes). */
#ifndef NET_TESTS_XDR_SAMPLE_H
#define NET_TESTS_XDR_SAMPLE_H

#include <stdint.h>
#include "net/xdr.h"

#define XDR_SAMPLE_VAR_MAX 16u
#define XDR_SAMPLE_STR_MAX 31u
#define XDR_SAMPLE_ARR_MAX 6u

struct xdr_sample {
    int32_t i, b, e;
    uint32_t u, var_len, arr_len;
    int64_t h;
    uint64_t uh;
    float f;
    double d;
    uint8_t fixed[5], var[XDR_SAMPLE_VAR_MAX];
    char str[XDR_SAMPLE_STR_MAX + 1u];
    int32_t arr[XDR_SAMPLE_ARR_MAX];
};

static inline int xdr_sample_elem(struct nxdr *x, void *p)
{
    return nxdr_int(x, p);
}

/* Encodes or decodes (as x was set up) the whole record; 1 or 0. */
static inline int xdr_sample_codec(struct nxdr *x, struct xdr_sample *s)
{
    return nxdr_int(x, &s->i) && nxdr_u_int(x, &s->u) && nxdr_hyper(x, &s->h) &&
           nxdr_u_hyper(x, &s->uh) && nxdr_bool(x, &s->b) && nxdr_enum(x, &s->e) &&
           nxdr_float(x, &s->f) && nxdr_double(x, &s->d) && nxdr_opaque(x, s->fixed, 5) &&
           nxdr_bytes(x, s->var, &s->var_len, XDR_SAMPLE_VAR_MAX) &&
           nxdr_string(x, s->str, XDR_SAMPLE_STR_MAX) &&
           nxdr_array(x, s->arr, &s->arr_len, XDR_SAMPLE_ARR_MAX, sizeof(int32_t),
                      xdr_sample_elem);
}

#endif /* NET_TESTS_XDR_SAMPLE_H */
