/*
 * The vectors of rt_vectors.h. The inputs are read through volatile pointers
 * so the compiler cannot fold the operations at build time: every result comes
 * from the runtime routine (or host instruction) being tested.
 */
#include "rt_vectors.h"

#include <stddef.h>

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

static const int32_t i32_in[] = {
    0, 1, -1, 2, -2, 100, -100, 16777215, 16777216, 16777217, -16777217, 33554435,
    0x7FFFFF80, 0x7FFFFFC0, 0x7FFFFFFF, -0x7FFFFFFF - 1, 123456789, -987654321,
};
static const uint32_t u32_in[] = {
    0u, 1u, 2u, 16777217u, 0x7FFFFFFFu, 0x80000000u, 0x80000001u, 0xFFFFFF7Fu, 0xFFFFFF80u,
    0xFFFFFFFFu, 3000000000u, 4294967040u,
};
/* In range for int32 (after truncation toward zero). */
static const float f2i_in[] = {
    0.0f, -0.0f, 0.4999f, 0.5f, -0.5f, 1.0f, 1.9999f, -1.9999f, 1e-30f, -1e-30f, 16777217.0f,
    2147483520.0f, -2147483648.0f, 123456.789f, -0.999999f, 1000.5f,
};
/* In range for uint32. */
static const float f2u_in[] = {
    0.0f, 0.99f, 1.0f, 2147483648.0f, 3e9f, 4294967040.0f, 65535.75f,
};
static const double d2i_in[] = {
    0.0, -0.0, 0.5, -0.5, 2147483647.0, 2147483647.9, -2147483648.0, -2147483648.9,
    1e-300, 123456789.987654321,
};
static const int64_t i64_in[] = {
    0, 1, -1, 0x7FFFFFFFFFFFFFFFll, -0x7FFFFFFFFFFFFFFFll - 1, 0x123456789ABCDEF0ll,
    -1000000000000000000ll, 9007199254740993ll, 4294967296ll, -4294967297ll, 16777217ll,
};
static const uint64_t u64_in[] = {
    0u, 1u, 0xFFFFFFFFFFFFFFFFull, 0x8000000000000000ull, 0xFEDCBA9876543210ull,
    0x100000000ull, 0xFFFFFFFFull, 9007199254740993ull,
};
/* Dividend, divisor: small divisors, divisors of 2^32 and more, negative ones. */
static const int64_t div_in[][2] = {
    {0x7FFFFFFFFFFFFFFFll, 3}, {-0x7FFFFFFFFFFFFFFFll - 1, 7}, {-0x7FFFFFFFFFFFFFFFll - 1, -3},
    {1000000000000000000ll, 10}, {-1000000000000000000ll, 10000000000ll},
    {0x123456789ABCDEF0ll, 0x100000000ll}, {0x123456789ABCDEF0ll, -0x100000001ll},
    {0x7FFFFFFFFFFFFFFFll, 0x7FFFFFFFFFFFFFFFll}, {5, 0x7FFFFFFFFFFFFFFFll},
    {-5, 2}, {5, -2}, {-5, -2}, {4294967296ll, 4294967295ll}, {0, 12345},
};
static const uint64_t udiv_in[][2] = {
    {0xFFFFFFFFFFFFFFFFull, 3u}, {0xFFFFFFFFFFFFFFFFull, 0xFFFFFFFFull},
    {0xFFFFFFFFFFFFFFFFull, 0x100000000ull}, {0xFFFFFFFFFFFFFFFFull, 0x8000000000000000ull},
    {0x8000000000000000ull, 0xFFFFFFFFFFFFFFFFull}, {0xFEDCBA9876543210ull, 0x123456789ull},
    {1000000000000u, 1000000u}, {12345u, 1u}, {0u, 7u},
};
static const float fpair_in[][2] = {
    {1.0f, 3.0f}, {-2.5f, 0.1f}, {1e30f, 1e-30f}, {3.4e38f, 10.0f}, {1.17549435e-38f, 0.5f},
    {16777216.0f, 1.0f}, {0.0f, -0.0f}, {-7.25f, -7.25f}, {100.0f, 1e-6f},
};
static const double dpair_in[][2] = {
    {1.0, 3.0}, {-2.5, 0.1}, {1e300, 1e-300}, {9007199254740992.0, 1.0}, {0.1, 0.2},
};

/* Bit patterns through unions: the board has no C library (no memcpy). A NaN
 * is emitted as one canonical pattern: IEEE 754 leaves a NaN's sign and payload
 * to the implementation (x86 gives 0/0 the sign bit, compiler-rt does not). */
static uint64_t float_bits(float f)
{
    union { float f; uint32_t u; } v;
    v.f = f;
    return f != f ? 0x7FC00000u : v.u;
}

static uint64_t double_bits(double d)
{
    union { double d; uint64_t u; } v;
    v.d = d;
    return d != d ? 0x7FF8000000000000u : v.u;
}

static uint64_t compare_bits(int lt, int le, int eq, int ne, int ge, int gt)
{
    return (uint64_t)((lt << 5) | (le << 4) | (eq << 3) | (ne << 2) | (ge << 1) | gt);
}

unsigned rt_vectors_run(rt_emit_fn emit)
{
    unsigned n = 0, i;
    const volatile int32_t *i32 = i32_in;
    const volatile uint32_t *u32 = u32_in;
    const volatile float *f2i = f2i_in;
    const volatile float *f2u = f2u_in;
    const volatile double *d2i = d2i_in;
    const volatile int64_t *i64 = i64_in;
    const volatile uint64_t *u64 = u64_in;
    volatile float nan_f = 0.0f;
    nan_f = nan_f / nan_f;

    for (i = 0; i < COUNT(i32_in); i++, n++) {
        emit("i32_to_float", i, float_bits((float)i32[i]));
        emit("i32_to_double", i, double_bits((double)i32[i]));
    }
    for (i = 0; i < COUNT(u32_in); i++, n++) {
        emit("u32_to_float", i, float_bits((float)u32[i]));
        emit("u32_to_double", i, double_bits((double)u32[i]));
    }
    for (i = 0; i < COUNT(f2i_in); i++, n++) {
        emit("float_to_i32", i, (uint32_t)(int32_t)f2i[i]);
        emit("float_to_i64", i, (uint64_t)(int64_t)f2i[i]);
        emit("float_to_double", i, double_bits((double)f2i[i]));
    }
    for (i = 0; i < COUNT(f2u_in); i++, n++) {
        emit("float_to_u32", i, (uint32_t)f2u[i]);
        emit("float_to_u64", i, (uint64_t)f2u[i]);
    }
    for (i = 0; i < COUNT(d2i_in); i++, n++) {
        emit("double_to_i32", i, (uint32_t)(int32_t)d2i[i]);
        emit("double_to_float", i, float_bits((float)d2i[i]));
    }
    for (i = 0; i < COUNT(i64_in); i++, n++) {
        emit("i64_to_float", i, float_bits((float)i64[i]));
        emit("i64_to_double", i, double_bits((double)i64[i]));
        emit("i64_shl_13", i, (uint64_t)i64[i] << 13);
        emit("i64_sar_37", i, (uint64_t)(i64[i] >> 37));
        emit("i64_mul", i, (uint64_t)i64[i] * 0x9E3779B97F4A7C15ull);
    }
    for (i = 0; i < COUNT(u64_in); i++, n++) {
        emit("u64_to_float", i, float_bits((float)u64[i]));
        emit("u64_to_double", i, double_bits((double)u64[i]));
        emit("u64_shr_33", i, u64[i] >> 33);
    }
    for (i = 0; i < COUNT(div_in); i++, n++) {
        const volatile int64_t *p = div_in[i];
        emit("i64_div", i, (uint64_t)(p[0] / p[1]));
        emit("i64_mod", i, (uint64_t)(p[0] % p[1]));
    }
    for (i = 0; i < COUNT(udiv_in); i++, n++) {
        const volatile uint64_t *p = udiv_in[i];
        emit("u64_div", i, p[0] / p[1]);
        emit("u64_mod", i, p[0] % p[1]);
    }
    for (i = 0; i < COUNT(fpair_in); i++, n++) {
        const volatile float *p = fpair_in[i];
        float a = p[0], b = p[1];
        emit("float_add", i, float_bits(a + b));
        emit("float_sub", i, float_bits(a - b));
        emit("float_mul", i, float_bits(a * b));
        emit("float_div", i, float_bits(a / b));
        emit("float_cmp", i, compare_bits(a < b, a <= b, a == b, a != b, a >= b, a > b));
        emit("float_cmp_nan", i, compare_bits(a < nan_f, a <= nan_f, a == nan_f, a != nan_f,
                                              a >= nan_f, a > nan_f));
    }
    for (i = 0; i < COUNT(dpair_in); i++, n++) {
        const volatile double *p = dpair_in[i];
        double a = p[0], b = p[1];
        emit("double_add", i, double_bits(a + b));
        emit("double_sub", i, double_bits(a - b));
        emit("double_mul", i, double_bits(a * b));
        emit("double_div", i, double_bits(a / b));
        emit("double_cmp", i, compare_bits(a < b, a <= b, a == b, a != b, a >= b, a > b));
    }
    return n;
}
