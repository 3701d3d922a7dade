/* libFuzzer target: the FEC receiver (fec_rx_byte, interrupt half) and the
 * decoder (fec_frame_decode, rs_decode) on any bytes the radio delivers.
 * Every frame it accepts must re-encode and decode to itself. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "net/fec.h"
#include "net/rs.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static struct fec_rx rx;
    static struct fec_raw raw;
    static struct rs_code code;
    struct fec_stats st = { 0 };
    struct frame f, g;
    uint8_t enc[FEC_ENCODED_MAX], cw[FEC_N];
    size_t i;
    if (fec_init() != 0 || rs_init(&code, FEC_NSYM) != 0)
        abort();
    /* the Reed-Solomon decoder alone on the first codeword's worth */
    if (size >= FEC_N) {
        int r;
        memcpy(cw, data, FEC_N);
        r = rs_decode(&code, cw, FEC_N);
        if (r > (int)(FEC_NSYM / 2u) || (r >= 0 && rs_decode(&code, cw, FEC_N) != 0))
            abort();
    }
    fec_rx_init(&rx);
    for (i = 0; i < size; i++) {
        if (!fec_rx_byte(&rx, data[i], &raw))
            continue;
        if (raw.ncw == 0u || raw.ncw > FEC_CW_MAX)
            abort();
        if (fec_frame_decode(&raw, &f, &st)) {
            struct fec_rx rx2;
            size_t n, j;
            int got = 0;
            if (f.len > FRAME_AIR_PAYLOAD_MAX)
                abort();
            n = fec_frame_encode(&f, enc, sizeof enc);
            if (n == 0)
                abort();
            fec_rx_init(&rx2);
            for (j = 0; j < n; j++)
                if (fec_rx_byte(&rx2, enc[j], &raw))
                    got += fec_frame_decode(&raw, &g, &st);
            if (got != 1 || g.len != f.len || memcmp(g.payload, f.payload, f.len) != 0 ||
                g.src != f.src || g.seq != f.seq)
                abort();
        }
    }
    return 0;
}
