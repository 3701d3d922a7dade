/*
 * Reed-Solomon codes over GF(256) (primitive polynomial 0x11D, generator
 * alpha = 2, first consecutive root alpha^0): the code of the Python package
 * reedsolo (RSCodec(nsym), its defaults), so the host peer encodes and
 * decodes with a well-kept library and the firmware with this module, and
 * the two are checked against each other byte for byte (net/tests).
 *
 * Systematic: a codeword is the message followed by nsym parity bytes; any
 * length n = k + nsym <= 255 (shortened codes). The decoder corrects up to
 * nsym / 2 byte errors (syndromes, Berlekamp-Massey, Chien search, Forney).
 *
 * Why hand-written: the freestanding firmware has no libc and no heap, and
 * the C libraries of this code (Phil Karn's libfec, the Linux kernel's
 * lib/reed_solomon) allocate their tables at run time or need the kernel's
 * environment; this module is ~200 lines with fixed-size state only.
 */
#ifndef NET_RS_H
#define NET_RS_H

#include <stddef.h>
#include <stdint.h>

#define RS_NSYM_MAX 32u
#define RS_N_MAX    255u

struct rs_code {
    unsigned nsym;
    uint8_t gen[RS_NSYM_MAX + 1u];   /* generator polynomial, highest degree first */
};

/* Builds the GF(256) tables (once) and the generator for nsym parity bytes
 * (2..RS_NSYM_MAX, even). 0, or -1 for a bad nsym. */
int rs_init(struct rs_code *c, unsigned nsym);

/* parity[0..nsym) of msg[0..k); k + nsym <= RS_N_MAX. 0, or -1 for bad sizes. */
int rs_encode(const struct rs_code *c, const uint8_t *msg, size_t k, uint8_t *parity);

/* Corrects cw[0..n) (message then parity) in place. Returns the number of
 * bytes corrected (0..nsym/2), or -1 when the errors are beyond the code (cw
 * is then left unchanged) or the sizes are bad. Reads and writes only
 * cw[0..n), whatever the bytes (checked by CBMC and libFuzzer). */
int rs_decode(const struct rs_code *c, uint8_t *cw, size_t n);

#endif /* NET_RS_H */
