/* libFuzzer target: the XDR decoder on any input (make fuzz). ASan catches any
 * read past the input (the input buffer is exactly `size` bytes); a successful
 * decode must re-encode (to no more bytes than it consumed). */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "net/xdr.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

struct sample {
    int32_t i, b, e;
    uint32_t u, var_len, arr_len;
    int64_t h;
    uint64_t uh;
    float f;
    double d;
    uint8_t fixed[5], var[16];
    char str[17];
    int32_t arr[4];
};

static int elem(struct nxdr *x, void *p) { return nxdr_int(x, p); }

static int codec(struct nxdr *x, struct sample *s)
{
    return nxdr_int(x, &s->i) && nxdr_u_int(x, &s->u) && nxdr_hyper(x, &s->h) &&
           nxdr_u_hyper(x, &s->uh) && nxdr_bool(x, &s->b) && nxdr_enum(x, &s->e) &&
           nxdr_float(x, &s->f) && nxdr_double(x, &s->d) && nxdr_opaque(x, s->fixed, 5) &&
           nxdr_bytes(x, s->var, &s->var_len, 16) && nxdr_string(x, s->str, 16) &&
           nxdr_array(x, s->arr, &s->arr_len, 4, sizeof(int32_t), elem);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    struct sample s;
    struct nxdr x;
    uint8_t *copy = malloc(size ? size : 1), out[256];
    if (copy == NULL)
        return 0;
    memcpy(copy, data, size);                  /* exact-size heap block: ASan bounds */
    memset(&s, 0, sizeof s);
    nxdr_init_decode(&x, copy, size);
    if (codec(&x, &s)) {
        size_t used = nxdr_getpos(&x);
        struct nxdr y;
        if (used > size)
            abort();
        nxdr_init_encode(&y, out, sizeof out);
        /* A decoded string may hold a NUL byte, after which C sees it shorter:
         * the re-encoding is never longer, and the same when there is none. */
        if (!codec(&y, &s) || nxdr_getpos(&y) > used ||
            (strlen(s.str) == 16 && nxdr_getpos(&y) != used))
            abort();
    } else if (nxdr_getpos(&x) > size) {
        abort();
    }
    free(copy);
    return 0;
}
