/* Host tool for net/tests/target/test_fec_python.py: net/fec.c against the
 * host peer's reedsolo, both directions.
 *   fec_sample encode SRC DST TYPE SEQ HEXPAYLOAD  -> the on-air bytes in hex
 *   fec_sample decode HEX  -> one line per good frame:
 *                             SRC DST TYPE SEQ HEXPAYLOAD CORRECTED */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "net/fec.h"
#include "net/tests/sample_hex.h"

int main(int argc, char **argv)
{
    static uint8_t buf[8192];
    struct frame f;
    size_t i, n;
    if (fec_init() != 0)
        return 1;
    if (argc == 7 && strcmp(argv[1], "encode") == 0) {
        memset(&f, 0, sizeof f);
        f.src = (uint8_t)atoi(argv[2]);
        f.dst = (uint8_t)atoi(argv[3]);
        f.type = (uint8_t)atoi(argv[4]);
        f.seq = (uint8_t)atoi(argv[5]);
        f.len = (uint16_t)unhex(argv[6], f.payload, sizeof f.payload);
        n = fec_frame_encode(&f, buf, sizeof buf);
        if (n == 0u)
            return 3;
        for (i = 0; i < n; i++)
            printf("%02x", buf[i]);
        printf("\n");
        return 0;
    }
    if (argc == 3 && strcmp(argv[1], "decode") == 0) {
        static struct fec_rx rx;
        static struct fec_raw raw;
        struct fec_stats st;
        n = unhex(argv[2], buf, sizeof buf);
        fec_rx_init(&rx);
        for (i = 0; i < n; i++) {
            memset(&st, 0, sizeof st);
            if (fec_rx_byte(&rx, buf[i], &raw) && fec_frame_decode(&raw, &f, &st)) {
                unsigned j;
                printf("%u %u %u %u ", f.src, f.dst, f.type, f.seq);
                for (j = 0; j < f.len; j++)
                    printf("%02x", f.payload[j]);
                printf(" %lu\n", (unsigned long)st.corrected);
            }
        }
        return 0;
    }
    fprintf(stderr, "usage: fec_sample encode SRC DST TYPE SEQ HEX | decode HEX\n");
    return 2;
}
