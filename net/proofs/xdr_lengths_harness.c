/* CBMC: the XDR length arithmetic at the widest maxima, run with size_t of
 * 32 bits (--32, the CPU32's width; make check-net-cbmc, runs XDR32_*).
 *
 * Bounds: an input (decode) or a room (encode) of any size up to
 * XDR_LEN_BOUND bytes with any contents and any starting position in it;
 * every length and count the caller or the input can give, 0..UINT32_MAX
 * (fixed opaque's len is a free uint32, the variable-length routines' max
 * is UINT32_MAX). Destinations and sources are XDR_LEN_BOUND bytes: they
 * must be enough, as a routine may touch no more bytes than the stream
 * holds; only an encoded array's count is assumed to fit its source array
 * (nxdr_int reads an element before it knows there is room for it, so the
 * caller's array must hold the count it gives). Loops are unwound to the
 * most iterations that many bytes allow (net/net.mk: the opaque copy and the
 * string scan XDR_LEN_BOUND, the padding 3, the array XDR_LEN_BOUND / 4) with
 * --unwinding-assertions, so a length that escaped its check also shows as
 * a loop past its bound.
 *
 * Checked: no access outside any object (--bounds-check --pointer-check),
 * no arithmetic overflow (--signed-overflow-check --unsigned-overflow-check,
 * so no length computation wraps), the position never passes the size, a
 * success fits the stream, a failure leaves a reason, and the lengths
 * 0xFFFFFFFD..0xFFFFFFFF (where (size_t)len + pad wrapped to 0) fail.
 * Not vacuous: the old nxdr_opaque fails the opaque, bytes and string runs,
 * and a success is reachable in each run (checked once with an assertion
 * that none is, which CBMC refuted). */
#include <stdint.h>
#include <stdlib.h>
#include "net/xdr.h"

#ifndef XDR_LEN_BOUND
#define XDR_LEN_BOUND 16
#endif
/* Which routine: 0 opaque, 1 bytes, 2 string, 3 array. One per CBMC run:
 * a nondeterministic choice among the four in one run merged their states
 * (at a bound of 8, start 0: 44 s of CPU, against 4.6 s for the four runs). */
#ifndef XDR_LEN_CASE
#error "XDR_LEN_CASE: 0 opaque, 1 bytes, 2 string, 3 array"
#endif

/* The width this run is meant to check, stated by make (-DXDR_LEN_SIZE_MAX):
 * a run at another width (no --32) does not compile, rather than pass
 * having checked something else. */
#ifdef XDR_LEN_SIZE_MAX
typedef char xdr_len_size_t_width[SIZE_MAX == XDR_LEN_SIZE_MAX ? 1 : -1];
#endif

size_t nondet_size(void);
uint32_t nondet_u32(void);
int nondet_int(void);

static int elem(struct nxdr *x, void *p) { return nxdr_int(x, p); }

void harness(void)
{
    size_t size = nondet_size(), start = nondet_size(), before;
    uint8_t *buf;
    uint8_t data[XDR_LEN_BOUND + 1];        /* + 1: a string's NUL */
    int32_t arr[XDR_LEN_BOUND / 4];
    uint32_t len = nondet_u32(), count = nondet_u32(), n = nondet_u32();
    int encode = nondet_int() != 0, ok = 0;
    struct nxdr x;
    __CPROVER_assume(size <= XDR_LEN_BOUND && start <= size);
    buf = malloc(size);                     /* exactly size bytes, contents arbitrary */
    if (buf == NULL)
        return;
    if (encode) {
        nxdr_init_encode(&x, buf, size);
        data[XDR_LEN_BOUND] = '\0';         /* a string to encode ends within data */
        __CPROVER_assume(count <= XDR_LEN_BOUND / 4);   /* arr holds the caller's count */
    } else {
        nxdr_init_decode(&x, buf, size);
    }
    x.pos = start;
    before = start;
    switch (XDR_LEN_CASE) {
    case 0:
        ok = nxdr_opaque(&x, data, len);
        if (ok)
            __CPROVER_assert(len <= size - before, "opaque: success fits the stream");
        if (len >= 0xFFFFFFFDu)
            __CPROVER_assert(!ok, "opaque: lengths 0xFFFFFFFD..0xFFFFFFFF fail");
        break;
    case 1:
        ok = nxdr_bytes(&x, data, &n, UINT32_MAX);
        if (ok)
            __CPROVER_assert(n <= size - before, "bytes: success fits the stream");
        break;
    case 2:
        ok = nxdr_string(&x, (char *)data, UINT32_MAX);
        break;
    default:
        ok = nxdr_array(&x, arr, &count, UINT32_MAX, sizeof(int32_t), elem);
        if (ok)
            __CPROVER_assert(count <= (size - before) / 4u, "array: success fits the stream");
        break;
    }
    __CPROVER_assert(nxdr_getpos(&x) <= size, "never past the stream's size");
    __CPROVER_assert(ok == (nxdr_error(&x) == NXDR_OK), "a failure leaves a reason, a success none");
    free(buf);
}
