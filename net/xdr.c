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

int nxdr_error(const struct nxdr *x)
{
    return x->failed;
}

const char *nxdr_strerror(int err)
{
    switch (err) {
    case NXDR_OK: return "no error";
    case NXDR_ESHORT: return "item longer than the input left (or the room, encoding)";
    case NXDR_ETOOLONG: return "length or count above its maximum";
    case NXDR_EVALUE: return "value the type forbids";
    case NXDR_EELEMENT: return "an element's routine failed";
    default: return "unknown XDR error";
    }
}

/* Fails the stream; the first reason stays. */
static int nxdr_fail_why(struct nxdr *x, enum nxdr_err why)
{
    if (!x->failed)
        x->failed = (uint8_t)why;
    return 0;
}

static int nxdr_fail(struct nxdr *x)
{
    return nxdr_fail_why(x, NXDR_ESHORT);
}

/* Room for len bytes and then pad more? Lengths come from the input as
 * uint32_t, and size_t may be narrower (16 bits), as wide (the CPU32) or
 * wider: len and pad are compared with what is left one at a time, never
 * added to each other nor to pos first, so nothing wraps and no length is
 * truncated to size_t before it is checked. */
static int nxdr_room2(const struct nxdr *x, uint32_t len, uint32_t pad)
{
    size_t left;
    if (x->failed || x->pos > x->size)
        return 0;
    left = x->size - x->pos;
    return len <= left && pad <= left - len;
}

static int nxdr_room(const struct nxdr *x, uint32_t n)
{
    return nxdr_room2(x, n, 0);
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
        return nxdr_fail_why(x, NXDR_EVALUE);
    if (!nxdr_int(x, v))
        return 0;
    if (*v != 0 && *v != 1)
        return nxdr_fail_why(x, NXDR_EVALUE);
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
    /* not (size_t)len + pad: with a 32-bit size_t that is 0 for len
     * 0xFFFFFFFD..0xFFFFFFFF, and the copy below would run past both buffers */
    if (!nxdr_room2(x, len, pad))
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
    x->pos += (size_t)len + (size_t)pad;     /* at most what was left */
    return 1;
}

/* The length (or count) word before variable-length data: *n, at most max,
 * is written; a decoded one above max is refused. */
static int nxdr_length(struct nxdr *x, uint32_t *n, uint32_t max)
{
    if (x->op == NXDR_ENCODE && *n > max)
        return nxdr_fail_why(x, NXDR_ETOOLONG);
    if (!nxdr_u_int(x, n))
        return 0;
    if (*n > max)
        return nxdr_fail_why(x, NXDR_ETOOLONG);
    return 1;
}

int nxdr_bytes(struct nxdr *x, uint8_t *data, uint32_t *len, uint32_t max)
{
    uint32_t n = *len;
    if (!nxdr_length(x, &n, max))
        return 0;
    if (!nxdr_opaque(x, data, n))
        return 0;
    *len = n;
    return 1;
}

int nxdr_string(struct nxdr *x, char *str, uint32_t max)
{
    uint32_t n = 0;
    if (x->op == NXDR_ENCODE) {
        /* n < max, not n <= max: with max = UINT32_MAX, n++ would wrap */
        while (n < max && str[n] != '\0')
            n++;
        if (str[n] != '\0')        /* longer than max */
            return nxdr_fail_why(x, NXDR_ETOOLONG);
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
    /* every element's offset i * elsize must fit size_t (and i itself,
     * when size_t is narrower than 32 bits); no array is larger */
    if (count != 0u && elsize != 0u && count - 1u > SIZE_MAX / elsize)
        return nxdr_fail_why(x, NXDR_ETOOLONG);
    for (i = 0; i < count; i++) {
        if (!proc(x, p + (size_t)i * elsize))
            return nxdr_fail_why(x, NXDR_EELEMENT);
    }
    return 1;
}

int nxdr_array(struct nxdr *x, void *array, uint32_t *count, uint32_t max, size_t elsize,
              nxdr_proc proc)
{
    uint32_t n = *count;
    if (!nxdr_length(x, &n, max))
        return 0;
    /* Each element takes at least 4 bytes: refuse counts the input cannot hold
     * before calling proc (a decoder must not spin on a huge claimed count).
     * n is not cast to size_t: a 16-bit size_t would truncate it. pos <= size
     * here (nxdr_length just read the count). */
    if (x->op == NXDR_DECODE && n > (x->size - x->pos) / 4u)
        return nxdr_fail(x);
    if (!nxdr_vector(x, array, n, elsize, proc))
        return 0;
    *count = n;
    return 1;
}
