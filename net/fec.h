/*
 * Forward error correction on air (optional, per network: net_init_flags
 * with NET_FEC, netnode's FEC flag, the host peer's fec=True): for a
 * channel that corrupts single characters, where a 30-character frame
 * survives 10 % errors per character only 4 % of the time.
 *
 * On air:  55 55 55  7E  C C C C C  codeword 1 .. codeword C  (+ the pad)
 *   C         the number of codewords (1..FEC_CW_MAX), sent five times; the
 *             receiver takes a value that occurs at least twice (so up to
 *             three of the five copies may be hit)
 *   plain     L, body (src, dst, type, seq, payload, CRC-16 as frame.h),
 *             L = body length, zero-padded to C x FEC_K bytes
 *   codeword  FEC_K plain bytes + FEC_NSYM Reed-Solomon parity bytes (rs.h;
 *             corrects 6 wrong bytes in each 28)
 * No byte stuffing and no closing flag: the length comes from C, so a
 * corrupted byte cannot end or split a frame. The CRC still guards against
 * a codeword decoded to the wrong message.
 *
 * Receive in two halves: fec_rx_byte (the DUART interrupt, one call per
 * character) only collects the codewords of a frame; fec_frame_decode (the
 * service thread) corrects them, which takes far longer than a character.
 */
#ifndef NET_FEC_H
#define NET_FEC_H

#include <stddef.h>
#include <stdint.h>
#include "frame.h"

#define FEC_K        16u
#define FEC_NSYM     12u
#define FEC_N        (FEC_K + FEC_NSYM)
#define FEC_COPIES   5u
#define FEC_CW_MAX   ((1u + FRAME_BODY_MAX + FEC_K - 1u) / FEC_K)
#define FEC_RAW_MAX  (FEC_CW_MAX * FEC_N)
#define FEC_ENCODED_MAX (FRAME_PREAMBLE_LEN + 1u + FEC_COPIES + FEC_RAW_MAX)

/* The codewords of one received frame, undecoded. Even size, word-aligned
 * (see struct frame). */
struct fec_raw {
    uint16_t ncw;                   /* codewords, 1..FEC_CW_MAX */
    uint8_t bytes[FEC_RAW_MAX];
};

enum fec_rx_state { FEC_RX_HUNT = 0, FEC_RX_COUNT, FEC_RX_DATA };

struct fec_rx_stats {
    uint32_t bytes;        /* characters seen */
    uint32_t frames;       /* codeword sets collected */
    uint32_t bad_count;    /* no codeword count agreed by two copies */
};

struct fec_rx {
    uint8_t state;                  /* enum fec_rx_state */
    uint8_t ncopies;
    uint8_t copies[FEC_COPIES];
    uint16_t need, n;               /* codeword bytes expected, collected */
    struct fec_raw raw;
    struct fec_rx_stats stats;
};

struct fec_stats {
    uint32_t frames;       /* good frames decoded */
    uint32_t corrected;    /* bytes corrected in them */
    uint32_t uncorrectable;/* a codeword beyond the code */
    uint32_t bad_frames;   /* decoded, but a bad length or CRC */
};

/* Prepares the code (the GF(256) tables); call before the others. 0 or -1. */
int fec_init(void);

/* Writes the on-air bytes of f; returns their number, or 0 when
 * f->len > FRAME_AIR_PAYLOAD_MAX or out is too small. */
size_t fec_frame_encode(const struct frame *f, uint8_t *out, size_t size);

void fec_rx_init(struct fec_rx *rx);
/* Feeds one received character. Returns 1 and fills *out when it completes
 * the codewords of a frame, else 0. Any byte sequence keeps rx within its
 * buffer. */
int fec_rx_byte(struct fec_rx *rx, uint8_t byte, struct fec_raw *out);

/* Corrects and checks raw; returns 1 and fills *out for a good frame, else 0
 * (counted in *st). Reads only raw->bytes[0..ncw x FEC_N) for ncw within
 * 1..FEC_CW_MAX, whatever the bytes. */
int fec_frame_decode(const struct fec_raw *raw, struct frame *out, struct fec_stats *st);

#endif /* NET_FEC_H */
