/*
 * Framing of the radio link: how a frame looks on air, the encoder, and the
 * receiver's byte-by-byte state machine (run from the DUART receive
 * interrupt, one call per character).
 *
 * On air:  55 55 55  7E  body (byte-stuffed)  7E
 *   preamble  three 0x55 (alternating bits: the receiver's data slicer settles)
 *   flag      0x7E opens and closes the frame
 *   body      src, dst, type, seq, payload (0..FRAME_AIR_PAYLOAD_MAX bytes:
 *             up to FRAME_PAYLOAD_MAX of the layers above and the
 *             authentication trailer, net/auth.h), CRC-16/CCITT of
 *             src..payload, high byte first
 *   stuffing  0x7E and 0x7D inside the body go out as 0x7D, byte ^ 0x20
 *             (HDLC), so a flag never occurs inside a frame and a receiver
 *             that lost track resynchronises at the next flag.
 * Byte stuffing instead of the CubeOS 4-ones-per-byte code (facts 4.3)
 * because that code doubles every byte and would cap the goodput at 50 % of
 * the baud rate; the emulated medium needs no DC balance (see net/README.md).
 */
#ifndef NET_FRAME_H
#define NET_FRAME_H

#include <stddef.h>
#include <stdint.h>

#define FRAME_PREAMBLE_BYTE 0x55u
#define FRAME_PREAMBLE_LEN  3u
#define FRAME_FLAG          0x7Eu
#define FRAME_ESC           0x7Du
#define FRAME_ESC_XOR       0x20u
#define FRAME_HEADER_LEN    4u      /* src, dst, type, seq */
#define FRAME_CRC_LEN       2u
#define FRAME_PAYLOAD_MAX   128u    /* what the layers above may put in a frame */
#define FRAME_TRAILER_MAX   8u      /* the authentication trailer (AUTH_TRAILER_LEN) */
#define FRAME_AIR_PAYLOAD_MAX (FRAME_PAYLOAD_MAX + FRAME_TRAILER_MAX)
#define FRAME_BODY_MAX      (FRAME_HEADER_LEN + FRAME_AIR_PAYLOAD_MAX + FRAME_CRC_LEN)
/* Longest encoding: every body byte stuffed. */
#define FRAME_ENCODED_MAX   (FRAME_PREAMBLE_LEN + 2u + 2u * FRAME_BODY_MAX)

#define FRAME_BROADCAST     0xFFu   /* dst: every station */

/* len is 16 bits so that the structure is word-aligned with an even size:
 * the CPU32 faults on word accesses at odd addresses, which GCC emits when
 * it copies structures of bytes. */
struct frame {
    uint16_t len;                   /* payload bytes, 0..FRAME_AIR_PAYLOAD_MAX */
    uint8_t src, dst, type, seq;
    uint8_t payload[FRAME_AIR_PAYLOAD_MAX];   /* room for the sealed payload */
};

/* Writes the on-air bytes of f to out; returns their number, or 0 when
 * f->len > FRAME_AIR_PAYLOAD_MAX or out is too small. */
size_t frame_encode(const struct frame *f, uint8_t *out, size_t size);

enum frame_rx_state { FRAME_RX_HUNT = 0, FRAME_RX_BODY, FRAME_RX_ESCAPED };

struct frame_rx_stats {
    uint32_t bytes;        /* characters seen */
    uint32_t frames;       /* good frames */
    uint32_t crc_errors;   /* complete frames with a wrong CRC */
    uint32_t malformed;    /* too short, too long, or a bad escape */
};

struct frame_rx {
    uint8_t state;                  /* enum frame_rx_state */
    uint16_t n;                     /* body bytes collected */
    uint16_t crc;                   /* CRC of body[0..n) */
    uint8_t body[FRAME_BODY_MAX];
    struct frame_rx_stats stats;
};

void frame_rx_init(struct frame_rx *rx);
/* Feeds one received character. Returns 1 and fills *out when it completes a
 * frame with a good CRC, else 0. Any byte sequence keeps rx within its buffer
 * (checked by CBMC, net/proofs, and libFuzzer, net/fuzz). */
int frame_rx_byte(struct frame_rx *rx, uint8_t byte, struct frame *out);

#endif /* NET_FRAME_H */
