/* Host tool for net/tests/target/test_xdr_python.py: encodes the sample record
 * with net/xdr.c and prints it in hex ("encode"), or decodes hex given as
 * argv[2] and prints the values one per line ("decode"), so Python's xdrlib3
 * can be compared with it in both directions. */
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "net/xdr.h"
#include "xdr_sample.h"

int main(int argc, char **argv)
{
    uint8_t buf[512];
    struct xdr_sample s;
    struct nxdr x;
    size_t i, n;
    memset(&s, 0, sizeof s);
    if (argc == 2 && strcmp(argv[1], "encode") == 0) {
        s.i = -123456; s.u = 4000000000u; s.h = -9000000000000000000ll;
        s.uh = 18000000000000000000ull; s.b = 1; s.e = 7; s.f = -2.5f; s.d = 3.141592653589793;
        memcpy(s.fixed, "RoboC", 5);
        s.var_len = 3; s.var[0] = 1; s.var[1] = 2; s.var[2] = 3;
        strcpy(s.str, "radio");
        s.arr_len = 4; s.arr[0] = 1; s.arr[1] = -1; s.arr[2] = 65536; s.arr[3] = -65536;
        nxdr_init_encode(&x, buf, sizeof buf);
        if (!xdr_sample_codec(&x, &s))
            return 1;
        for (i = 0; i < nxdr_getpos(&x); i++)
            printf("%02x", buf[i]);
        printf("\n");
        return 0;
    }
    if (argc == 3 && strcmp(argv[1], "decode") == 0) {
        n = strlen(argv[2]) / 2;
        if (n > sizeof buf)
            return 2;
        for (i = 0; i < n; i++) {
            unsigned v;
            if (sscanf(argv[2] + 2 * i, "%2x", &v) != 1)
                return 2;
            buf[i] = (uint8_t)v;
        }
        nxdr_init_decode(&x, buf, n);
        if (!xdr_sample_codec(&x, &s) || nxdr_getpos(&x) != n)
            return 3;
        printf("%d\n%u\n%lld\n%llu\n%d\n%d\n%.9g\n%.17g\n%.5s\n", s.i, s.u, (long long)s.h,
               (unsigned long long)s.uh, s.b, s.e, (double)s.f, s.d, (char *)s.fixed);
        for (i = 0; i < s.var_len; i++)
            printf("%u ", s.var[i]);
        printf("\n%s\n", s.str);
        for (i = 0; i < s.arr_len; i++)
            printf("%d ", s.arr[i]);
        printf("\n");
        return 0;
    }
    fprintf(stderr, "usage: xdr_sample encode | decode HEX\n");
    return 2;
}
