/* CBMC: XDR decoding of an arbitrary input of up to XDR_BOUND bytes never
 * reads outside it nor writes outside the destination objects, for every
 * type of the module (--bounds-check --pointer-check). */
#include <stdint.h>
#include <stdlib.h>
#include "net/xdr.h"

#ifndef XDR_BOUND
#define XDR_BOUND 24
#endif

size_t nondet_size(void);
unsigned nondet_choice(void);

static int elem(struct nxdr *x, void *p) { return nxdr_int(x, p); }

void harness(void)
{
    size_t size = nondet_size();
    __CPROVER_assume(size <= XDR_BOUND);
    uint8_t *in = malloc(size);               /* exactly size bytes, contents arbitrary */
    struct nxdr x;
    int32_t i32, arr[3];
    uint32_t u32, len = 0, count = 0;
    int64_t i64;
    double d;
    float f;
    uint8_t fixed[5], var[6];
    char str[7];
    if (in == NULL)
        return;
    nxdr_init_decode(&x, in, size);
    switch (nondet_choice() % 8u) {
    case 0: (void)nxdr_int(&x, &i32); (void)nxdr_u_int(&x, &u32); break;
    case 1: (void)nxdr_hyper(&x, &i64); break;
    case 2: (void)nxdr_bool(&x, &i32); (void)nxdr_enum(&x, &i32); break;
    case 3: (void)nxdr_float(&x, &f); (void)nxdr_double(&x, &d); break;
    case 4: (void)nxdr_opaque(&x, fixed, 5); break;
    case 5: (void)nxdr_bytes(&x, var, &len, 6); break;
    case 6: (void)nxdr_string(&x, str, 6); break;
    default: (void)nxdr_array(&x, arr, &count, 3, sizeof(int32_t), elem); break;
    }
    __CPROVER_assert(nxdr_getpos(&x) <= size, "never consumes past the input");
    __CPROVER_assert(len <= 6 && count <= 3, "lengths within their bounds");
    free(in);
}
