/* Reed-Solomon over GF(256); see rs.h. Polynomials are stored lowest degree
 * first except the generator (highest first, as the encoder's LFSR uses it).
 * A codeword byte cw[i] of an n-byte codeword is the coefficient of
 * x^(n-1-i) (reedsolo's order). */
#include "rs.h"

#define RS_PRIM 0x11Du

static uint8_t gf_exp[510];
static uint8_t gf_log[256];
static uint8_t gf_ready;

static void gf_init(void)
{
    unsigned i, x = 1u;
    if (gf_ready)
        return;
    for (i = 0; i < 255u; i++) {
        gf_exp[i] = (uint8_t)x;
        gf_log[x] = (uint8_t)i;
        x <<= 1;
        if (x & 0x100u)
            x ^= RS_PRIM;
    }
    for (i = 255u; i < 510u; i++)
        gf_exp[i] = gf_exp[i - 255u];
    gf_log[0] = 0;                    /* never used: callers test for 0 */
    gf_ready = 1;
}

#ifndef RS_GF_ABSTRACT
static uint8_t gf_mul(uint8_t a, uint8_t b)
{
    if (a == 0u || b == 0u)
        return 0;
    return gf_exp[gf_log[a] + gf_log[b]];
}

/* a / b, b != 0 */
static uint8_t gf_div(uint8_t a, uint8_t b)
{
    if (a == 0u)
        return 0;
    return gf_exp[gf_log[a] + 255u - gf_log[b]];
}

/* alpha^e for any e >= 0 */
static uint8_t gf_pow_alpha(unsigned e)
{
    return gf_exp[e % 255u];
}
#else
/* CBMC only (net/proofs/rs_decode_harness.c): every field operation returns
 * any byte. Memory safety depends on the values only through the loop
 * bounds and positions they lead to, so proving rs_decode safe for ANY
 * results proves it for the real ones; rs_gf_harness.c proves the real
 * operations' table accesses in bounds. */
uint8_t nondet_u8(void);
static uint8_t gf_mul(uint8_t a, uint8_t b) { (void)a; (void)b; return nondet_u8(); }
static uint8_t gf_div(uint8_t a, uint8_t b) { (void)a; (void)b; return nondet_u8(); }
static uint8_t gf_pow_alpha(unsigned e) { (void)e; return nondet_u8(); }
#endif

int rs_init(struct rs_code *c, unsigned nsym)
{
    unsigned i, j;
    if (nsym < 2u || nsym > RS_NSYM_MAX || (nsym & 1u) != 0u)
        return -1;
    gf_init();
    c->nsym = nsym;
    /* g(x) = prod_{i < nsym} (x - alpha^i), highest degree first */
    for (i = 0; i <= RS_NSYM_MAX; i++)
        c->gen[i] = 0;
    c->gen[0] = 1;
    for (i = 0; i < nsym; i++) {
        uint8_t root = gf_pow_alpha(i);
        /* multiply the degree-i polynomial gen[0..i] by (x + root) */
        for (j = i + 1u; j > 0u; j--)
            c->gen[j] = (uint8_t)(c->gen[j] ^ gf_mul(c->gen[j - 1u], root));
    }
    return 0;
}

int rs_encode(const struct rs_code *c, const uint8_t *msg, size_t k, uint8_t *parity)
{
    size_t i;
    unsigned j, nsym = c->nsym;
    if (nsym < 2u || nsym > RS_NSYM_MAX || k + nsym > RS_N_MAX)
        return -1;
    for (j = 0; j < nsym; j++)
        parity[j] = 0;
    /* remainder of msg(x) x^nsym / g(x), a shift register */
    for (i = 0; i < k; i++) {
        uint8_t fb = (uint8_t)(msg[i] ^ parity[0]);
        for (j = 0; j + 1u < nsym; j++)
            parity[j] = (uint8_t)(parity[j + 1u] ^ gf_mul(fb, c->gen[j + 1u]));
        parity[nsym - 1u] = gf_mul(fb, c->gen[nsym]);
    }
    return 0;
}

/* S_j = cw(alpha^j), j < nsym; returns 1 if any is nonzero. */
static int rs_syndromes(const uint8_t *cw, size_t n, unsigned nsym, uint8_t *s)
{
    unsigned j;
    size_t i;
    int any = 0;
    for (j = 0; j < nsym; j++) {
        uint8_t v = 0, a = gf_pow_alpha(j);
        for (i = 0; i < n; i++)
            v = (uint8_t)(gf_mul(v, a) ^ cw[i]);   /* Horner, highest first */
        s[j] = v;
        if (v != 0u)
            any = 1;
    }
    return any;
}

int rs_decode(const struct rs_code *c, uint8_t *cw, size_t n)
{
    uint8_t s[RS_NSYM_MAX], lam[RS_NSYM_MAX + 1u], prev[RS_NSYM_MAX + 1u];
    uint8_t tmp[RS_NSYM_MAX + 1u], omega[RS_NSYM_MAX];
    uint8_t pos[RS_NSYM_MAX / 2u], mag[RS_NSYM_MAX / 2u];
    unsigned nsym = c->nsym, L = 0, m = 1, i, j, found = 0;
    uint8_t b = 1;
    size_t p;

    if (nsym < 2u || nsym > RS_NSYM_MAX || n <= nsym || n > RS_N_MAX || !gf_ready)
        return -1;
    if (!rs_syndromes(cw, n, nsym, s))
        return 0;
    /* Berlekamp-Massey: the error locator lam(x), lowest degree first */
    for (i = 0; i <= nsym; i++)
        lam[i] = prev[i] = 0;
    lam[0] = prev[0] = 1;
    for (i = 0; i < nsym; i++) {
        uint8_t d = s[i], coef;
        for (j = 1; j <= L; j++)
            d = (uint8_t)(d ^ gf_mul(lam[j], s[i - j]));
        if (d == 0u) {
            m++;
            continue;
        }
        coef = gf_div(d, b);
        for (j = 0; j <= nsym; j++)
            tmp[j] = lam[j];
        for (j = 0; j + m <= nsym; j++)
            lam[j + m] = (uint8_t)(lam[j + m] ^ gf_mul(coef, prev[j]));
        if (2u * L <= i) {
            L = i + 1u - L;
            for (j = 0; j <= nsym; j++)
                prev[j] = tmp[j];
            b = d;
            m = 1;
        } else {
            m++;
        }
    }
    if (L > nsym / 2u)
        return -1;
    for (j = L + 1u; j <= nsym; j++)
        if (lam[j] != 0u)
            return -1;
    /* omega(x) = s(x) lam(x) mod x^nsym */
    for (i = 0; i < nsym; i++) {
        uint8_t v = 0;
        for (j = 0; j <= i && j <= L; j++)
            v = (uint8_t)(v ^ gf_mul(lam[j], s[i - j]));
        omega[i] = v;
    }
    /* Chien search over the n positions; Forney for the magnitudes */
    for (p = 0; p < n; p++) {
        unsigned e = (unsigned)(n - 1u - p);          /* cw[p] is x^e */
        uint8_t xinv = gf_pow_alpha(255u - e), v = 0, xp = 1, num = 0, den = 0;
        for (j = 0; j <= L; j++) {                    /* lam(X^-1) */
            v = (uint8_t)(v ^ gf_mul(lam[j], xp));
            xp = gf_mul(xp, xinv);
        }
        if (v != 0u)
            continue;
        if (found == L)
            return -1;                                /* more roots than the degree */
        xp = 1;
        for (j = 0; j < nsym; j++) {                  /* omega(X^-1) */
            num = (uint8_t)(num ^ gf_mul(omega[j], xp));
            xp = gf_mul(xp, xinv);
        }
        xp = 1;
        for (j = 1; j <= L; j += 2u) {                /* lam'(X^-1): odd terms */
            den = (uint8_t)(den ^ gf_mul(lam[j], xp));
            xp = gf_mul(xp, gf_mul(xinv, xinv));
        }
        if (den == 0u)
            return -1;
        pos[found] = (uint8_t)p;
        mag[found] = gf_mul(gf_pow_alpha(e), gf_div(num, den));   /* X omega / lam' (fcr 0) */
        found++;
    }
    if (found != L)
        return -1;
    for (i = 0; i < found; i++)
        cw[pos[i]] = (uint8_t)(cw[pos[i]] ^ mag[i]);
    if (rs_syndromes(cw, n, nsym, s)) {               /* not a codeword: undo */
        for (i = 0; i < found; i++)
            cw[pos[i]] = (uint8_t)(cw[pos[i]] ^ mag[i]);
        return -1;
    }
    return (int)found;
}
