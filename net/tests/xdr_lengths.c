/* The XDR decoder's length arithmetic with this build's size_t. `make
 * check-net-xdr-widths` runs it built three ways: for the 64-bit host, for
 * the 32-bit host (-m32) and for the m68k (32-bit size_t, big-endian, as on
 * the CPU32) under qemu-user. Every length and count near 2^32, in
 * particular 0xFFFFFFFD..0xFFFFFFFF (for which (size_t)len + pad wraps to 0
 * when size_t has 32 bits), must be refused with its reason, and nothing
 * may be written past a destination (guard bytes checked) or read past the
 * input (an exact-size heap block: ASan sees it where it is on).
 * Plain C, not cmocka: there is no 32-bit or m68k build of cmocka here. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "net/xdr.h"

#define GUARD 0xA5u
#define DST 32u             /* destination bytes, then guard bytes */

static unsigned passed, failed;

static void check(int ok, const char *what, uint32_t len)
{
    if (ok) {
        passed++;
    } else {
        failed++;
        printf("FAILED: %s (length or count 0x%08lX)\n", what, (unsigned long)len);
    }
}

static uint8_t *input(const uint8_t *bytes, size_t n)
{
    uint8_t *in = malloc(n ? n : 1u);
    if (in == NULL) {
        printf("out of memory\n");
        exit(2);
    }
    memcpy(in, bytes, n);
    return in;
}

static void put_be32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)(v >> 24);
    p[1] = (uint8_t)(v >> 16);
    p[2] = (uint8_t)(v >> 8);
    p[3] = (uint8_t)v;
}

static int guard_intact(const uint8_t *dst, size_t from)
{
    size_t i;
    for (i = from; i < DST + 16u; i++)
        if (dst[i] != GUARD)
            return 0;
    return 1;
}

static int elem(struct nxdr *x, void *p) { return nxdr_int(x, p); }

/* The claimed length `len` after `lead` bytes of an int, with 8 data
 * bytes behind it, through every variable-length routine. */
static void variable_length(uint32_t len, size_t lead, int report)
{
    uint8_t bytes[4 + 4 + 8], dst[DST + 16];
    int32_t arr[DST / 4 + 4], lead_int = 0;
    size_t n = lead + 4u + 8u;
    uint32_t got, count;
    unsigned kind;
    memset(bytes, 0x11, sizeof bytes);
    put_be32(bytes, 7u);
    put_be32(bytes + lead, len);
    for (kind = 0; kind < 4; kind++) {
        uint8_t *in = input(bytes, n);
        struct nxdr x;
        int r = 1;
        memset(dst, GUARD, sizeof dst);
        memset(arr, GUARD, sizeof arr);
        nxdr_init_decode(&x, in, n);
        if (lead != 0u)
            check(nxdr_int(&x, &lead_int) && lead_int == 7, "leading int decoded", len);
        got = 0x55u;
        count = 0x55u;
        switch (kind) {
        case 0: r = nxdr_bytes(&x, dst, &got, UINT32_MAX); break;
        case 1: r = nxdr_string(&x, (char *)dst, UINT32_MAX); break;
        case 2: r = nxdr_array(&x, arr, &count, UINT32_MAX, sizeof(int32_t), elem); break;
        default: r = nxdr_opaque(&x, dst, len); break;     /* fixed: len from the caller */
        }
        check(r == 0, "refused", len);
        check(nxdr_error(&x) == NXDR_ESHORT, "reason: longer than the input left", len);
        check(nxdr_getpos(&x) <= n, "consumed no more than the input", len);
        check(got == 0x55u && count == 0x55u, "length and count outputs untouched", len);
        check(guard_intact(dst, 0) && guard_intact((uint8_t *)arr, 0), "destination untouched", len);
        if (report && kind == 0)
            printf("refused: bytes of length 0x%08lX (%lu-bit size_t): %s\n", (unsigned long)len,
                   (unsigned long)(sizeof(size_t) * 8u), nxdr_strerror(nxdr_error(&x)));
        free(in);
    }
}

/* Encoding a fixed opaque of length len into 12 bytes of room. */
static void encode_length(uint32_t len)
{
    uint8_t src[DST + 16], out[DST + 16];
    struct nxdr y;
    memset(src, 0x22, sizeof src);
    memset(out, GUARD, sizeof out);
    nxdr_init_encode(&y, out, 12u);
    check(nxdr_opaque(&y, src, len) == 0, "encode refused", len);
    check(nxdr_error(&y) == NXDR_ESHORT, "encode reason: out of room", len);
    check(nxdr_getpos(&y) == 0u && guard_intact(out, 0), "encode wrote nothing", len);
}

/* Lengths that fit are decoded: the checks above are not refusing everything. */
static void controls(void)
{
    static const uint8_t ok_bytes[] = {0, 0, 0, 5, 'h', 'e', 'l', 'l', 'o', 0, 0, 0};
    static const uint8_t ok_array[] = {0, 0, 0, 2, 0, 0, 0, 3, 0xFF, 0xFF, 0xFF, 0xFE};
    uint8_t dst[DST + 16], *in;
    int32_t arr[4];
    uint32_t got = 0, count = 0;
    struct nxdr x;
    memset(dst, GUARD, sizeof dst);
    in = input(ok_bytes, sizeof ok_bytes);
    nxdr_init_decode(&x, in, sizeof ok_bytes);
    check(nxdr_bytes(&x, dst, &got, UINT32_MAX) == 1 && got == 5u &&
          memcmp(dst, "hello", 5) == 0 && guard_intact(dst, 5) &&
          nxdr_getpos(&x) == sizeof ok_bytes && nxdr_error(&x) == NXDR_OK,
          "5 bytes with max UINT32_MAX decoded", 5u);
    free(in);
    in = input(ok_bytes, sizeof ok_bytes);
    nxdr_init_decode(&x, in, sizeof ok_bytes);
    check(nxdr_string(&x, (char *)dst, UINT32_MAX) == 1 && strcmp((char *)dst, "hello") == 0,
          "string with max UINT32_MAX decoded", 5u);
    free(in);
    in = input(ok_array, sizeof ok_array);
    nxdr_init_decode(&x, in, sizeof ok_array);
    check(nxdr_array(&x, arr, &count, UINT32_MAX, sizeof(int32_t), elem) == 1 && count == 2u &&
          arr[0] == 3 && arr[1] == -2, "array with max UINT32_MAX decoded", 2u);
    free(in);
    /* one more than the input holds, and over a smaller maximum */
    in = input(ok_bytes, sizeof ok_bytes);
    in[3] = 9;
    nxdr_init_decode(&x, in, sizeof ok_bytes);
    check(nxdr_bytes(&x, dst, &got, UINT32_MAX) == 0 && nxdr_error(&x) == NXDR_ESHORT,
          "9 bytes in 8 refused", 9u);
    free(in);
    in = input(ok_bytes, sizeof ok_bytes);
    nxdr_init_decode(&x, in, sizeof ok_bytes);
    check(nxdr_bytes(&x, dst, &got, 4u) == 0 && nxdr_error(&x) == NXDR_ETOOLONG,
          "5 bytes over a maximum of 4 refused as too long", 5u);
    free(in);
}

/* A fixed array whose byte size does not fit this size_t describes no
 * array: refused before any element (only a 32-bit or narrower size_t). */
static void vector_size(void)
{
    static const uint8_t bytes[8] = {0, 0, 0, 1, 0, 0, 0, 2};
    int32_t arr[DST / 4 + 4];
    struct nxdr x;
    uint8_t *in;
    uint32_t count = (uint32_t)(SIZE_MAX / 8u) + 2u;    /* (count - 1) * 8 > SIZE_MAX */
    if (SIZE_MAX > UINT32_MAX)
        return;
    memset(arr, GUARD, sizeof arr);
    in = input(bytes, sizeof bytes);
    nxdr_init_decode(&x, in, sizeof bytes);
    check(nxdr_vector(&x, arr, count, 8u, elem) == 0 && nxdr_error(&x) == NXDR_ETOOLONG &&
          nxdr_getpos(&x) == 0u && guard_intact((uint8_t *)arr, 0),
          "vector beyond the address space refused before any element", count);
    free(in);
}

int main(void)
{
    static const uint32_t lengths[] = {
        0xFFFFFFFFu, 0xFFFFFFFEu, 0xFFFFFFFDu, 0xFFFFFFFCu, 0xFFFFFFFBu,
        0xFFFFFFF8u, 0x80000000u, 0x7FFFFFFFu, 0x00010000u, 0x0000FFFFu, 13u,
    };
    unsigned i;
    for (i = 0; i < sizeof lengths / sizeof lengths[0]; i++) {
        variable_length(lengths[i], 0u, lengths[i] >= 0xFFFFFFFDu);
        variable_length(lengths[i], 4u, 0);
        encode_length(lengths[i]);
    }
    controls();
    vector_size();
    printf("xdr_lengths (%lu-bit size_t, %s-endian): %u passed, %u failed\n",
           (unsigned long)(sizeof(size_t) * 8u),
           *(const uint8_t *)&(const uint16_t){1} ? "little" : "big", passed, failed);
    return failed == 0u ? 0 : 1;
}
