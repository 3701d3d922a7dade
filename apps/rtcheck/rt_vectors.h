/*
 * Test vectors for the compiler runtime: int <-> float and int <-> double
 * conversions (signed and unsigned, 32 and 64 bits, edge values), float and
 * double arithmetic and comparisons, and 64-bit multiplication, division,
 * modulo and shifts (small divisors and divisors of 2^32 and more).
 *
 * The same file runs on the board (apps/rtcheck, through the CPU32 compiler
 * runtime) and on the host (its native instructions); each result is emitted
 * as its bit pattern, so the two outputs must agree character for character.
 * Only conversions C defines are used (no float to int out of range).
 */
#ifndef APPS_RTCHECK_RT_VECTORS_H
#define APPS_RTCHECK_RT_VECTORS_H

#include <stdint.h>

/* Receives one result: the operation's name, the vector's index, its bits. */
typedef void (*rt_emit_fn)(const char *name, unsigned index, uint64_t bits);

/* Computes every vector in a fixed order; returns how many were emitted. */
unsigned rt_vectors_run(rt_emit_fn emit);

#endif
