/* Reed-Solomon framing; see fec.h. */
#include "fec.h"
#include "crc16.h"
#include "rs.h"

static struct rs_code fec_code;

#if defined(__GNUC__)
#define FEC_NO_MERGE() __asm__ volatile("" ::: "memory")
#else
#define FEC_NO_MERGE() ((void)0)
#endif

int fec_init(void)
{
    return rs_init(&fec_code, FEC_NSYM);
}

size_t fec_frame_encode(const struct frame *f, uint8_t *out, size_t size)
{
    uint8_t plain[FEC_CW_MAX * FEC_K];
    size_t body, ncw, i, n = 0;
    uint16_t crc = CRC16_INIT;
    if (f->len > FRAME_AIR_PAYLOAD_MAX || fec_code.nsym != FEC_NSYM)
        return 0;
    body = FRAME_HEADER_LEN + f->len + FRAME_CRC_LEN;
    ncw = (1u + body + FEC_K - 1u) / FEC_K;
    if (size < FRAME_PREAMBLE_LEN + 1u + FEC_COPIES + ncw * FEC_N)
        return 0;
    for (i = 0; i < sizeof plain; i++)
        plain[i] = 0;
    plain[0] = (uint8_t)body;
    plain[1] = f->src;             /* byte by byte: see fec_frame_decode */
    FEC_NO_MERGE();
    plain[2] = f->dst;
    FEC_NO_MERGE();
    plain[3] = f->type;
    FEC_NO_MERGE();
    plain[4] = f->seq;
    for (i = 0; i < f->len; i++)
        plain[1u + FRAME_HEADER_LEN + i] = f->payload[i];
    crc = crc16_update(crc, &plain[1], FRAME_HEADER_LEN + f->len);
    plain[1u + FRAME_HEADER_LEN + f->len] = (uint8_t)(crc >> 8);
    plain[2u + FRAME_HEADER_LEN + f->len] = (uint8_t)(crc & 0xFFu);
    for (i = 0; i < FRAME_PREAMBLE_LEN; i++)
        out[n++] = FRAME_PREAMBLE_BYTE;
    out[n++] = FRAME_FLAG;
    for (i = 0; i < FEC_COPIES; i++)
        out[n++] = (uint8_t)ncw;
    for (i = 0; i < ncw; i++) {
        size_t j;
        for (j = 0; j < FEC_K; j++)
            out[n + j] = plain[i * FEC_K + j];
        if (rs_encode(&fec_code, &plain[i * FEC_K], FEC_K, &out[n + FEC_K]) != 0)
            return 0;
        n += FEC_N;
    }
    return n;
}

void fec_rx_init(struct fec_rx *rx)
{
    rx->state = FEC_RX_HUNT;
    rx->ncopies = 0;
    rx->need = rx->n = 0;
    rx->raw.ncw = 0;
    rx->stats.bytes = rx->stats.frames = rx->stats.bad_count = 0;
}

/* A codeword count in range that at least two copies agree on, or 0. */
static uint8_t fec_vote(const uint8_t *copies)
{
    unsigned i, j;
    for (i = 0; i < FEC_COPIES; i++) {
        unsigned same = 0;
        if (copies[i] == 0u || copies[i] > FEC_CW_MAX)
            continue;
        for (j = 0; j < FEC_COPIES; j++)
            if (copies[j] == copies[i])
                same++;
        if (same >= 2u)
            return copies[i];
    }
    return 0;
}

int fec_rx_byte(struct fec_rx *rx, uint8_t byte, struct fec_raw *out)
{
    rx->stats.bytes++;
    if (rx->state == FEC_RX_COUNT) {
        uint8_t ncw;
        if (rx->ncopies >= FEC_COPIES) {           /* outside the invariant: resync */
            rx->state = FEC_RX_HUNT;
            return 0;
        }
        rx->copies[rx->ncopies++] = byte;
        if (rx->ncopies < FEC_COPIES)
            return 0;
        ncw = fec_vote(rx->copies);
        if (ncw == 0u) {
            rx->stats.bad_count++;
            rx->state = FEC_RX_HUNT;
            return 0;
        }
        rx->raw.ncw = ncw;
        rx->need = (uint16_t)(ncw * FEC_N);
        rx->n = 0;
        rx->state = FEC_RX_DATA;
        return 0;
    }
    if (rx->state == FEC_RX_DATA) {
        uint16_t i;
        if (rx->need > FEC_RAW_MAX || rx->n >= rx->need) {   /* outside the invariant */
            rx->state = FEC_RX_HUNT;
            return 0;
        }
        rx->raw.bytes[rx->n++] = byte;
        if (rx->n < rx->need)
            return 0;
        rx->state = FEC_RX_HUNT;
        out->ncw = rx->raw.ncw;
        for (i = 0; i < rx->need; i++)
            out->bytes[i] = rx->raw.bytes[i];
        rx->stats.frames++;
        return 1;
    }
    if (byte == FRAME_FLAG) {
        rx->state = FEC_RX_COUNT;
        rx->ncopies = 0;
    } else {
        rx->state = FEC_RX_HUNT;
    }
    return 0;
}

int fec_frame_decode(const struct fec_raw *raw, struct frame *out, struct fec_stats *st)
{
    uint8_t cw[FEC_N], plain[FEC_CW_MAX * FEC_K];
    size_t i, j, body;
    unsigned corrected = 0;
    uint16_t crc;
    if (raw->ncw == 0u || raw->ncw > FEC_CW_MAX || fec_code.nsym != FEC_NSYM) {
        st->bad_frames++;
        return 0;
    }
    for (i = 0; i < raw->ncw; i++) {
        int r;
        for (j = 0; j < FEC_N; j++)
            cw[j] = raw->bytes[i * FEC_N + j];
        r = rs_decode(&fec_code, cw, FEC_N);
        if (r < 0) {
            st->uncorrectable++;
            return 0;
        }
        corrected += (unsigned)r;
        for (j = 0; j < FEC_K; j++)
            plain[i * FEC_K + j] = cw[j];
    }
    body = plain[0];
    if (body < FRAME_HEADER_LEN + FRAME_CRC_LEN || body > FRAME_BODY_MAX ||
        (1u + body + FEC_K - 1u) / FEC_K != raw->ncw) {
        st->bad_frames++;
        return 0;
    }
    crc = crc16_update(CRC16_INIT, &plain[1], body);
    if (crc != 0u) {
        st->bad_frames++;
        return 0;
    }
    /* One byte at a time: GCC would merge these four into one long move
     * from the odd address plain + 1, an address error on the CPU32. */
    out->src = plain[1];
    FEC_NO_MERGE();
    out->dst = plain[2];
    FEC_NO_MERGE();
    out->type = plain[3];
    FEC_NO_MERGE();
    out->seq = plain[4];
    out->len = (uint16_t)(body - FRAME_HEADER_LEN - FRAME_CRC_LEN);
    for (i = 0; i < out->len; i++)
        out->payload[i] = plain[1u + FRAME_HEADER_LEN + i];
    st->frames++;
    st->corrected += corrected;
    return 1;
}
