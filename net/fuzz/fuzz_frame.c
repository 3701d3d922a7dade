/* libFuzzer target: the frame receiver on any byte stream (make fuzz). Checks
 * the state machine's invariants after every byte and that every frame it
 * accepts re-encodes to bytes that decode to the same frame. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "net/frame.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static struct frame_rx rx;
    struct frame f, g;
    uint8_t enc[FRAME_ENCODED_MAX];
    size_t i, n, j;
    frame_rx_init(&rx);
    for (i = 0; i < size; i++) {
        if (frame_rx_byte(&rx, data[i], &f)) {
            struct frame_rx rx2;
            int got = 0;
            if (f.len > FRAME_AIR_PAYLOAD_MAX)
                abort();
            n = frame_encode(&f, enc, sizeof enc);
            if (n == 0)
                abort();
            frame_rx_init(&rx2);
            for (j = 0; j < n; j++)
                got += frame_rx_byte(&rx2, enc[j], &g);
            if (got != 1 || g.len != f.len || memcmp(g.payload, f.payload, f.len) != 0 ||
                g.src != f.src || g.dst != f.dst || g.type != f.type || g.seq != f.seq)
                abort();
        }
        if (rx.n > FRAME_BODY_MAX || rx.state > FRAME_RX_ESCAPED)
            abort();
    }
    return 0;
}
