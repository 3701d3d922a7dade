/* XDR (RFC 4506) encode/decode; see xdr.h. */
#include "xdr.h"

void nxdr_init_encode(struct nxdr *x, uint8_t *buf, size_t size)
{
    x->buf = buf;
    x->size = size;
    x->pos = 0;
    x->op = NXDR_ENCODE;
    x->failed = 0;
}

void nxdr_init_decode(struct nxdr *x, const uint8_t *buf, size_t size)
{
    /* The decoder only reads through buf; the cast keeps one stream type. */
    x->buf = (uint8_t *)(uintptr_t)buf;
    x->size = size;
    x->pos = 0;
    x->op = NXDR_DECODE;
    x->failed = 0;
}

size_t nxdr_getpos(const struct nxdr *x)
{
    return x->pos;
}

static int nxdr_fail(struct nxdr *x)
{
    x->failed = 1;
    return 0;
}

/* Room for n more bytes? (Written so that pos + n cannot overflow.) */
static int nxdr_room(const struct nxdr *x, size_t n)
{
    return !x->failed && x->pos <= x->size && n <= x->size - x->pos;
}

static int nxdr_word(struct nxdr *x, uint32_t *v)
{
    uint8_t *p;
    if (!nxdr_room(x, 4))
        return nxdr_fail(x);
    p = x->buf + x->pos;
    if (x->op == NXDR_ENCODE) {
        p[0] = (uint8_t)(*v >> 24);
        p[1] = (uint8_t)(*v >> 16);
        p[2] = (uint8_t)(*v >> 8);
        p[3] = (uint8_t)*v;
    } else {
        *v = ((uint32_t)p[0] << 24) | ((uint32_t)p[1] << 16) | ((uint32_t)p[2] << 8) | p[3];
    }
    x->pos += 4;
    return 1;
}

int nxdr_u_int(struct nxdr *x, uint32_t *v)
{
    return nxdr_word(x, v);
}

int nxdr_int(struct nxdr *x, int32_t *v)
{
    uint32_t u = (uint32_t)*v;
    if (!nxdr_word(x, &u))
        return 0;
    /* Two's complement on every target this runs on; the conversion of a
     * value above INT32_MAX is implementation-defined in C99, so go through
     * the arithmetic that is not. */
    if (x->op == NXDR_DECODE)
        *v = u <= 0x7FFFFFFFu ? (int32_t)u : -(int32_t)(~u) - 1;
    return 1;
}

int nxdr_u_hyper(struct nxdr *x, uint64_t *v)
{
    uint32_t hi = (uint32_t)(*v >> 32), lo = (uint32_t)*v;
    if (!nxdr_word(x, &hi) || !nxdr_word(x, &lo))
        return 0;
    if (x->op == NXDR_DECODE)
        *v = ((uint64_t)hi << 32) | lo;
    return 1;
}

int nxdr_hyper(struct nxdr *x, int64_t *v)
{
    uint64_t u = (uint64_t)*v;
    if (!nxdr_u_hyper(x, &u))
        return 0;
    if (x->op == NXDR_DECODE)
        *v = u <= 0x7FFFFFFFFFFFFFFFull ? (int64_t)u : -(int64_t)(~u) - 1;
    return 1;
}

int nxdr_bool(struct nxdr *x, int32_t *v)
{
    if (x->op == NXDR_ENCODE && *v != 0 && *v != 1)
        return nxdr_fail(x);
    if (!nxdr_int(x, v))
        return 0;
    if (*v != 0 && *v != 1)
        return nxdr_fail(x);
    return 1;
}

int nxdr_enum(struct nxdr *x, int32_t *v)
{
    return nxdr_int(x, v);
}

int nxdr_float(struct nxdr *x, float *v)
{
    union { float f; uint32_t u; } bits;
    bits.f = *v;
    if (!nxdr_word(x, &bits.u))
        return 0;
    if (x->op == NXDR_DECODE)
        *v = bits.f;
    return 1;
}

int nxdr_double(struct nxdr *x, double *v)
{
    union { double d; uint64_t u; } bits;
    bits.d = *v;
    if (!nxdr_u_hyper(x, &bits.u))
        return 0;
    if (x->op == NXDR_DECODE)
        *v = bits.d;
    return 1;
}

int nxdr_opaque(struct nxdr *x, uint8_t *data, uint32_t len)
{
    uint32_t pad = (4u - (len & 3u)) & 3u;
    uint32_t i;
    if (!nxdr_room(x, (size_t)len + pad))
        return nxdr_fail(x);
    for (i = 0; i < len; i++) {
        if (x->op == NXDR_ENCODE)
            x->buf[x->pos + i] = data[i];
        else
            data[i] = x->buf[x->pos + i];
    }
    /* Padding is written as zeros and, as libtirpc does, not checked on input. */
    for (i = 0; i < pad && x->op == NXDR_ENCODE; i++)
        x->buf[x->pos + len + i] = 0;
    x->pos += (size_t)len + pad;
    return 1;
}

int nxdr_bytes(struct nxdr *x, uint8_t *data, uint32_t *len, uint32_t max)
{
    uint32_t n = *len;
    if (x->op == NXDR_ENCODE && n > max)
        return nxdr_fail(x);
    if (!nxdr_u_int(x, &n))
        return 0;
    if (n > max)
        return nxdr_fail(x);
    if (!nxdr_opaque(x, data, n))
        return 0;
    *len = n;
    return 1;
}

int nxdr_string(struct nxdr *x, char *str, uint32_t max)
{
    uint32_t n = 0;
    if (x->op == NXDR_ENCODE) {
        while (n <= max && str[n] != '\0')
            n++;
    }
    if (!nxdr_bytes(x, (uint8_t *)str, &n, max))
        return 0;
    if (x->op == NXDR_DECODE)
        str[n] = '\0';
    return 1;
}

int nxdr_vector(struct nxdr *x, void *array, uint32_t count, size_t elsize, nxdr_proc proc)
{
    uint8_t *p = array;
    uint32_t i;
    for (i = 0; i < count; i++) {
        if (!proc(x, p + (size_t)i * elsize))
            return nxdr_fail(x);
    }
    return 1;
}

int nxdr_array(struct nxdr *x, void *array, uint32_t *count, uint32_t max, size_t elsize,
              nxdr_proc proc)
{
    uint32_t n = *count;
    if (x->op == NXDR_ENCODE && n > max)
        return nxdr_fail(x);
    if (!nxdr_u_int(x, &n))
        return 0;
    if (n > max)
        return nxdr_fail(x);
    /* Each element takes at least 4 bytes: refuse counts the input cannot hold
     * before calling proc (a decoder must not spin on a huge claimed count). */
    if (x->op == NXDR_DECODE && (size_t)n > (x->size - x->pos) / 4u)
        return nxdr_fail(x);
    if (!nxdr_vector(x, array, n, elsize, proc))
        return 0;
    *count = n;
    return 1;
}
