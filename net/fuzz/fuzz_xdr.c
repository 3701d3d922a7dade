/* libFuzzer target: the XDR decoder on any input (make fuzz). ASan catches any
 * read past the input (the input buffer is exactly `size` bytes); a successful
 * decode must re-encode (to no more bytes than it consumed). */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "net/xdr.h"
#include "net/tests/xdr_sample.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    struct xdr_sample s;
    struct nxdr x;
    uint8_t *copy = malloc(size ? size : 1), out[256];
    if (copy == NULL)
        return 0;
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
    } else if (nxdr_getpos(&x) > size) {
        abort();
    }
    free(copy);
    return 0;
}
