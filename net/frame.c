/* Frame encoder and receive state machine; the format is in frame.h. */
#include "frame.h"
#include "crc16.h"

static int frame_needs_escape(uint8_t b)
{
    return b == FRAME_FLAG || b == FRAME_ESC;
}

/* Appends b (stuffed) at out[*n]; returns 0 when it does not fit. */
static int frame_put_stuffed(uint8_t *out, size_t size, size_t *n, uint8_t b)
{
    if (frame_needs_escape(b)) {
        if (*n + 2u > size)
            return 0;
        out[(*n)++] = FRAME_ESC;
        out[(*n)++] = (uint8_t)(b ^ FRAME_ESC_XOR);
    } else {
        if (*n + 1u > size)
            return 0;
        out[(*n)++] = b;
    }
    return 1;
}

size_t frame_encode(const struct frame *f, uint8_t *out, size_t size)
{
    uint8_t head[FRAME_HEADER_LEN];
    uint16_t crc = CRC16_INIT;
    size_t n = 0;
    unsigned i;

    if (f->len > FRAME_AIR_PAYLOAD_MAX || size < FRAME_PREAMBLE_LEN + 1u)
        return 0;
    for (i = 0; i < FRAME_PREAMBLE_LEN; i++)
        out[n++] = FRAME_PREAMBLE_BYTE;
    out[n++] = FRAME_FLAG;
    head[0] = f->src;
    head[1] = f->dst;
    head[2] = f->type;
    head[3] = f->seq;
    for (i = 0; i < FRAME_HEADER_LEN; i++) {
        crc = crc16_byte(crc, head[i]);
        if (!frame_put_stuffed(out, size, &n, head[i]))
            return 0;
    }
    for (i = 0; i < f->len; i++) {
        crc = crc16_byte(crc, f->payload[i]);
        if (!frame_put_stuffed(out, size, &n, f->payload[i]))
            return 0;
    }
    if (!frame_put_stuffed(out, size, &n, (uint8_t)(crc >> 8)) ||
        !frame_put_stuffed(out, size, &n, (uint8_t)(crc & 0xFFu)) || n + 1u > size)
        return 0;
    out[n++] = FRAME_FLAG;
    return n;
}

void frame_rx_init(struct frame_rx *rx)
{
    rx->state = FRAME_RX_HUNT;
    rx->n = 0;
    rx->crc = CRC16_INIT;
    rx->stats.bytes = 0;
    rx->stats.frames = 0;
    rx->stats.crc_errors = 0;
    rx->stats.malformed = 0;
}

/* A closing flag: checks the collected body. The flag also opens the next
 * frame, so the state stays BODY with an empty body. */
static int frame_rx_close(struct frame_rx *rx, struct frame *out)
{
    uint16_t n = rx->n;
    uint16_t crc;
    unsigned i;

    crc = rx->crc;
    rx->n = 0;
    rx->crc = CRC16_INIT;
    rx->state = FRAME_RX_BODY;
    if (n == 0u)
        return 0;                   /* back-to-back flags */
    if (n < FRAME_HEADER_LEN + FRAME_CRC_LEN)
        return 0;                   /* a runt: the preamble or a pad before the next flag */
    /* The CRC runs over the body and its own two bytes, high first: a good
     * frame leaves the register at 0 (CRC-16/CCITT has no final XOR). */
    if (crc != 0u) {
        rx->stats.crc_errors++;
        return 0;
    }
    out->src = rx->body[0];
    out->dst = rx->body[1];
    out->type = rx->body[2];
    out->seq = rx->body[3];
    out->len = (uint8_t)(n - FRAME_HEADER_LEN - FRAME_CRC_LEN);
    for (i = 0; i < out->len; i++)
        out->payload[i] = rx->body[FRAME_HEADER_LEN + i];
    rx->stats.frames++;
    return 1;
}

int frame_rx_byte(struct frame_rx *rx, uint8_t byte, struct frame *out)
{
    rx->stats.bytes++;
    if (byte == FRAME_FLAG) {
        if (rx->state == FRAME_RX_ESCAPED) {
            rx->stats.malformed++;   /* ESC then flag: abort, the flag opens anew */
            rx->n = 0;
            rx->crc = CRC16_INIT;
            rx->state = FRAME_RX_BODY;
            return 0;
        }
        if (rx->state == FRAME_RX_HUNT) {
            rx->state = FRAME_RX_BODY;
            rx->n = 0;
            rx->crc = CRC16_INIT;
            return 0;
        }
        return frame_rx_close(rx, out);
    }
    switch (rx->state) {
    case FRAME_RX_BODY:
        if (byte == FRAME_ESC) {
            rx->state = FRAME_RX_ESCAPED;
            return 0;
        }
        break;
    case FRAME_RX_ESCAPED:
        byte = (uint8_t)(byte ^ FRAME_ESC_XOR);
        if (!frame_needs_escape(byte)) {
            rx->stats.malformed++;   /* only flag and ESC are ever escaped */
            rx->state = FRAME_RX_HUNT;
            rx->n = 0;
            return 0;
        }
        rx->state = FRAME_RX_BODY;
        break;
    default:                          /* HUNT (or a corrupted state): wait for a flag */
        rx->state = FRAME_RX_HUNT;
        return 0;
    }
    if (rx->n >= FRAME_BODY_MAX) {
        rx->stats.malformed++;       /* longer than any frame: garbage, hunt */
        rx->state = FRAME_RX_HUNT;
        rx->n = 0;
        return 0;
    }
    rx->body[rx->n++] = byte;
    /* Per character, so the closing flag costs no CRC pass in the interrupt. */
    rx->crc = crc16_byte(rx->crc, byte);
    return 0;
}
