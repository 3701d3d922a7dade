/* CBMC: the Reed-Solomon decoder of the FEC frames (rs_decode with FEC_NSYM
 * parity bytes on FEC_N-byte codewords, as fec_frame_decode calls it) reads
 * and writes only the codeword and its own arrays, without overflow, for
 * EVERY content of the codeword, and returns -1 or at most FEC_NSYM / 2.
 * Built with RS_GF_ABSTRACT: each GF(256) operation returns any byte (see
 * rs.c), a sound over-approximation for memory safety that keeps the proof
 * small; rs_gf_harness.c proves the real operations in bounds. */
#include <stdint.h>
#include "net/fec.h"
#include "net/rs.h"

uint8_t nondet_u8(void);

void harness(void)
{
    struct rs_code c;
    uint8_t cw[FEC_N];
    unsigned i;
    int r;
    __CPROVER_assert(rs_init(&c, FEC_NSYM) == 0, "the code of the frames");
    for (i = 0; i < FEC_N; i++)
        cw[i] = nondet_u8();
    r = rs_decode(&c, cw, FEC_N);
    __CPROVER_assert(r >= -1 && r <= (int)(FEC_NSYM / 2u), "result in range");
}
