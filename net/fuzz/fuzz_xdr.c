/* libFuzzer target: the XDR decoder on any input (make fuzz; built for the
 * 64-bit host as fuzz_xdr and with -m32 as fuzz_xdr32, where size_t has the
 * CPU32's 32 bits). ASan catches any read past the input (the input buffer
 * is exactly `size` bytes) and any write past a destination. Two passes:
 * (1) the sample record with its small maxima: a successful decode must
 * re-encode (to no more bytes than it consumed); (2) every variable-length
 * routine with the widest maximum, UINT32_MAX, into destinations of the
 * input's size (a decoder writes no more than the input held), and a fixed
 * opaque whose length, any uint32, is the input's first word. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "net/xdr.h"
#include "net/tests/xdr_sample.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int elem(struct nxdr *x, void *p) { return nxdr_int(x, p); }

static void sample(const uint8_t *data, size_t size)
{
    struct xdr_sample s;
    struct nxdr x;
    uint8_t *copy = malloc(size ? size : 1), out[256];
    if (copy == NULL)
        return;
    memcpy(copy, data, size);                  /* exact-size heap block: ASan bounds */
    memset(&s, 0, sizeof s);
    nxdr_init_decode(&x, copy, size);
    if (xdr_sample_codec(&x, &s)) {
        size_t used = nxdr_getpos(&x);
        struct nxdr y;
        if (used > size)
            abort();
        nxdr_init_encode(&y, out, sizeof out);
        /* A decoded string may hold a NUL byte, after which C sees it shorter:
         * the re-encoding is never longer, and the same when there is none. */
        if (!xdr_sample_codec(&y, &s) || nxdr_getpos(&y) > used ||
            (strlen(s.str) == XDR_SAMPLE_STR_MAX && nxdr_getpos(&y) != used))
            abort();
    } else if (nxdr_getpos(&x) > size || nxdr_error(&x) == NXDR_OK) {
        abort();
    }
    free(copy);
}

static void widest(const uint8_t *data, size_t size)
{
    unsigned kind;
    for (kind = 0; kind < 4u; kind++) {
        uint8_t *copy = malloc(size ? size : 1), *dst = malloc(size + 1u);
        int32_t *arr = malloc((size / 4u + 1u) * sizeof *arr);
        uint32_t len = 0, count = 0, fixed = 0;
        struct nxdr x;
        int ok = 0;
        if (copy == NULL || dst == NULL || arr == NULL)
            abort();
        memcpy(copy, data, size);
        nxdr_init_decode(&x, copy, size);
        switch (kind) {
        case 0:
            ok = nxdr_bytes(&x, dst, &len, UINT32_MAX);
            if (ok && (size < 4u || len > size - 4u))
                abort();
            break;
        case 1: ok = nxdr_string(&x, (char *)dst, UINT32_MAX); break;
        case 2:
            ok = nxdr_array(&x, arr, &count, UINT32_MAX, sizeof *arr, elem);
            if (ok && count > size / 4u)
                abort();
            break;
        default:
            ok = nxdr_u_int(&x, &fixed) && nxdr_opaque(&x, dst, fixed);
            if (ok && fixed > size - 4u)
                abort();
            break;
        }
        if (nxdr_getpos(&x) > size || (ok != 0) != (nxdr_error(&x) == NXDR_OK))
            abort();
        free(arr);
        free(dst);
        free(copy);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    sample(data, size);
    widest(data, size);
    return 0;
}
