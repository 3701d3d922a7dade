/* CBMC: the GF(256) operations of rs.c stay inside their tables for every
 * operand (gf_log of a nonzero byte is 0..254, so gf_exp is indexed at most
 * 509 < 510), once rs_init built the tables. Includes rs.c for its static
 * functions. */
#include <stdint.h>
#include "net/rs.c"

unsigned nondet_unsigned(void);
uint8_t nondet_u8(void);

void harness(void)
{
    struct rs_code c;
    uint8_t a = nondet_u8(), b = nondet_u8();
    __CPROVER_assert(rs_init(&c, 12) == 0, "tables built");
    (void)gf_mul(a, b);
    if (b != 0u)
        (void)gf_div(a, b);
    (void)gf_pow_alpha(nondet_unsigned());
    __CPROVER_assert(a == 0u || b == 0u || gf_mul(a, b) != 0u, "no zero divisors");
    __CPROVER_assert(b == 0u || gf_mul(gf_div(a, b), b) == a, "division inverts multiplication");
}
