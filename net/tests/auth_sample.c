/* Host tool for net/tests/auth/test_auth_python.py: net/auth.c against the
 * host peer's tools/netpeer/auth.py. Reads commands from stdin, one per line,
 * and answers each with one line (numbers in decimal, bytes in hex, "-" for
 * no bytes):
 *   key HEX                      net_auth_init          -> rc
 *   init EPOCH                   auth_init              -> rc
 *   cmac HEX                     auth_cmac              -> HEX (16 bytes) or rc
 *   mic SRC DST TYPE SEQ FCNT HEX  auth_mic             -> HEX (4 bytes) or rc
 *   seal SRC DST TYPE SEQ HEX    auth_seal              -> HEX (payload + trailer) or rc
 *   open SRC DST TYPE SEQ HEX    auth_open              -> rc (payload length or error)
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "net/auth.h"
#include "net/tests/sample_hex.h"

/* "-" is an empty argument (the tests' empty payload). */
static size_t unhex_or_empty(const char *text, uint8_t *out, size_t size)
{
    return strcmp(text, "-") == 0 ? 0 : unhex(text, out, size);
}

static void puthex(const uint8_t *b, size_t n)
{
    size_t i;
    if (n == 0u)
        printf("-");
    for (i = 0; i < n; i++)
        printf("%02x", b[i]);
    printf("\n");
}

int main(void)
{
    static char line[1024];
    static struct auth st;
    if (auth_init(&st, 0) != AUTH_OK)
        return 1;
    while (fgets(line, sizeof line, stdin) != NULL) {
        char cmd[8], hex[600];
        unsigned h[4];
        unsigned long v;
        uint8_t header[AUTH_HEADER_LEN], buf[300], out[AUTH_CMAC_LEN];
        size_t n;
        int rc;
        if (sscanf(line, "%7s", cmd) != 1)
            continue;
        if (strcmp(cmd, "key") == 0 && sscanf(line, "%*s %599s", hex) == 1) {
            if (unhex_or_empty(hex, buf, sizeof buf) != AUTH_KEY_LEN)
                return 2;
            printf("%d\n", net_auth_init(buf));
        } else if (strcmp(cmd, "init") == 0 && sscanf(line, "%*s %lu", &v) == 1) {
            printf("%d\n", auth_init(&st, (uint32_t)v));
        } else if (strcmp(cmd, "cmac") == 0 && sscanf(line, "%*s %599s", hex) == 1) {
            n = unhex_or_empty(hex, buf, sizeof buf);
            rc = auth_cmac(buf, n, out);
            if (rc == AUTH_OK)
                puthex(out, AUTH_CMAC_LEN);
            else
                printf("%d\n", rc);
        } else if (strcmp(cmd, "mic") == 0 &&
                   sscanf(line, "%*s %u %u %u %u %lu %599s", &h[0], &h[1], &h[2], &h[3], &v,
                          hex) == 6) {
            unsigned i;
            for (i = 0; i < 4; i++)
                header[i] = (uint8_t)h[i];
            n = unhex_or_empty(hex, buf, sizeof buf);
            rc = auth_mic(header, (uint32_t)v, buf, n, out);
            if (rc == AUTH_OK)
                puthex(out, AUTH_MIC_LEN);
            else
                printf("%d\n", rc);
        } else if ((strcmp(cmd, "seal") == 0 || strcmp(cmd, "open") == 0) &&
                   sscanf(line, "%*s %u %u %u %u %599s", &h[0], &h[1], &h[2], &h[3], hex) == 5) {
            unsigned i;
            for (i = 0; i < 4; i++)
                header[i] = (uint8_t)h[i];
            n = unhex_or_empty(hex, buf, sizeof buf);
            if (cmd[0] == 's') {
                rc = auth_seal(&st, header, buf, n, sizeof buf);
                if (rc >= 0)
                    puthex(buf, (size_t)rc);
                else
                    printf("%d\n", rc);
            } else {
                printf("%d\n", auth_open(&st, header, buf, n));
            }
        } else {
            return 2;
        }
        fflush(stdout);
    }
    return 0;
}
