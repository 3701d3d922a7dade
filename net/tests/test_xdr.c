/* Host tests of xdr.c, byte for byte against libtirpc's xdrmem. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>
#include <rpc/types.h>
#include <rpc/xdr.h>
#include "net/xdr.h"

#define BUF 256

struct sample {
    int32_t i;
    uint32_t u;
    int64_t h;
    uint64_t uh;
    int32_t b;
    int32_t e;
    float f;
    double d;
    uint8_t fixed[5];
    uint8_t var[16];
    uint32_t var_len;
    char str[32];
    int32_t arr[6];
    uint32_t arr_len;
};

static int elem_int(struct nxdr *x, void *p) { return nxdr_int(x, p); }

static int ours(struct nxdr *x, struct sample *s)
{
    return nxdr_int(x, &s->i) && nxdr_u_int(x, &s->u) && nxdr_hyper(x, &s->h) &&
           nxdr_u_hyper(x, &s->uh) && nxdr_bool(x, &s->b) && nxdr_enum(x, &s->e) &&
           nxdr_float(x, &s->f) && nxdr_double(x, &s->d) && nxdr_opaque(x, s->fixed, 5) &&
           nxdr_bytes(x, s->var, &s->var_len, 16) && nxdr_string(x, s->str, 31) &&
           nxdr_array(x, s->arr, &s->arr_len, 6, sizeof(int32_t), elem_int);
}

/* The same structure through libtirpc. */
static size_t theirs(const struct sample *s, uint8_t *buf)
{
    XDR x;
    struct sample c = *s;
    char *str = c.str, *var = (char *)c.var, *arr = (char *)c.arr;
    u_int var_len = c.var_len, arr_len = c.arr_len;
    bool_t b = c.b;
    enum_t e = c.e;
    quad_t h = c.h;
    u_quad_t uh = c.uh;
    xdrmem_create(&x, (char *)buf, BUF, XDR_ENCODE);
    assert_true(xdr_int32_t(&x, &c.i) && xdr_uint32_t(&x, &c.u) && xdr_quad_t(&x, &h) &&
                xdr_u_quad_t(&x, &uh) && xdr_bool(&x, &b) && xdr_enum(&x, &e) &&
                xdr_float(&x, &c.f) && xdr_double(&x, &c.d) &&
                xdr_opaque(&x, (char *)c.fixed, 5) && xdr_bytes(&x, &var, &var_len, 16) &&
                xdr_string(&x, &str, 31) &&
                xdr_array(&x, &arr, &arr_len, 6, sizeof(int32_t), (xdrproc_t)xdr_int32_t));
    return (size_t)xdr_getpos(&x);
}

static struct sample sample_values(int k)
{
    struct sample s;
    memset(&s, 0, sizeof s);
    s.i = k ? INT32_MIN : -2;
    s.u = k ? 0xFFFFFFFFu : 7;
    s.h = k ? INT64_MIN : -1234567890123ll;
    s.uh = k ? UINT64_MAX : 0x0102030405060708ull;
    s.b = k & 1;
    s.e = k ? -7 : 3;
    s.f = k ? -1.5e-30f : 3.25f;
    s.d = k ? 2.5e300 : -0.1;
    memcpy(s.fixed, "abcde", 5);
    s.var_len = k ? 16u : 3u;
    memset(s.var, 0xA5, sizeof s.var);
    strcpy(s.str, k ? "" : "RoboCube radio");
    s.arr_len = k ? 6u : 0u;
    for (int i = 0; i < 6; i++)
        s.arr[i] = i * -1000;
    return s;
}

static void test_same_bytes_as_libtirpc(void **state)
{
    (void)state;
    for (int k = 0; k < 2; k++) {
        uint8_t a[BUF], b[BUF];
        struct sample s = sample_values(k), d;
        struct nxdr x;
        size_t n;
        memset(a, 0xEE, sizeof a);
        memset(b, 0xEE, sizeof b);
        nxdr_init_encode(&x, a, sizeof a);
        assert_true(ours(&x, &s));
        n = theirs(&s, b);
        assert_int_equal(nxdr_getpos(&x), n);
        assert_memory_equal(a, b, n);
        /* and decoding gives the values back */
        memset(&d, 0, sizeof d);
        nxdr_init_decode(&x, b, n);
        assert_true(ours(&x, &d));
        assert_int_equal(nxdr_getpos(&x), n);
        assert_int_equal(d.i, s.i);
        assert_true(d.h == s.h && d.uh == s.uh);
        assert_memory_equal(&d.f, &s.f, sizeof d.f);
        assert_memory_equal(&d.d, &s.d, sizeof d.d);
        assert_string_equal(d.str, s.str);
        assert_int_equal(d.var_len, s.var_len);
        assert_int_equal(d.arr_len, s.arr_len);
        assert_memory_equal(d.arr, s.arr, s.arr_len * sizeof(int32_t));
    }
}

static void test_truncated_input_fails(void **state)
{
    uint8_t a[BUF];
    struct sample s = sample_values(0), d;
    struct nxdr x;
    size_t n, cut;
    (void)state;
    nxdr_init_encode(&x, a, sizeof a);
    assert_true(ours(&x, &s));
    n = nxdr_getpos(&x);
    for (cut = 0; cut < n; cut++) {
        nxdr_init_decode(&x, a, cut);
        assert_false(ours(&x, &d));
        assert_true(nxdr_getpos(&x) <= cut);
    }
}

static void test_bounds_and_bool(void **state)
{
    uint8_t buf[16] = { 0, 0, 0, 2 };
    int32_t b;
    uint8_t data[4];
    uint32_t len;
    int32_t len_as_bool = 2;
    char str[4];
    struct nxdr x;
    (void)state;
    nxdr_init_decode(&x, buf, 4);
    assert_int_equal(nxdr_error(&x), NXDR_OK);
    assert_false(nxdr_bool(&x, &b));                   /* 2 is no bool */
    assert_int_equal(nxdr_error(&x), NXDR_EVALUE);
    buf[3] = 5;
    nxdr_init_decode(&x, buf, 16);
    assert_false(nxdr_bytes(&x, data, &len, 4));       /* 5 > max 4 */
    assert_int_equal(nxdr_error(&x), NXDR_ETOOLONG);
    nxdr_init_decode(&x, buf, 16);
    assert_false(nxdr_string(&x, str, 3));
    assert_int_equal(nxdr_error(&x), NXDR_ETOOLONG);
    nxdr_init_encode(&x, buf, 16);
    assert_false(nxdr_string(&x, "four", 3));          /* encoding: longer than max */
    assert_int_equal(nxdr_error(&x), NXDR_ETOOLONG);
    assert_int_equal(nxdr_getpos(&x), 0);
    buf[0] = 0xFF;                                    /* huge count */
    nxdr_init_decode(&x, buf, 16);
    assert_false(nxdr_bytes(&x, data, &len, 0xFFFFFFFFu));
    assert_int_equal(nxdr_error(&x), NXDR_ESHORT);
    assert_non_null(strstr(nxdr_strerror(nxdr_error(&x)), "longer than the input"));
    nxdr_init_encode(&x, buf, 3);
    b = 1;
    assert_false(nxdr_int(&x, &b));                    /* no room */
    assert_false(nxdr_bool(&x, &len_as_bool));         /* stays failed ... */
    assert_int_equal(nxdr_error(&x), NXDR_ESHORT);     /* ... with the first reason */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_same_bytes_as_libtirpc),
        cmocka_unit_test(test_truncated_input_fails),
        cmocka_unit_test(test_bounds_and_bool),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
