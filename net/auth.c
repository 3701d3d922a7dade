/*
 * Frame authentication: AES-CMAC MIC and replay counters (see auth.h). The
 * MAC is Mbed TLS's; this file only lays out the bytes it covers and keeps
 * the counters.
 */
#include "auth.h"

#include "mbedtls/aes.h"
#include "mbedtls/cipher.h"
#include "mbedtls/cmac.h"
#include "mbedtls/constant_time.h"
#include "mbedtls/platform_util.h"

/* ---- the static pool behind mbedtls_calloc/mbedtls_free ----
 * The cipher layer allocates twice per key (cipher_wrap.c: the AES context;
 * cmac.c: the CMAC state), in net_auth_init only, and frees both when the
 * key changes (mbedtls_cipher_free). The board has no heap: two slots, each
 * big enough for either. A third allocation fails (the library reports
 * MBEDTLS_ERR_CIPHER_ALLOC_FAILED, net_auth_init AUTH_ECRYPTO). */
union auth_slot {
    mbedtls_aes_context aes;
    mbedtls_cmac_context_t cmac;
    uint32_t align;
};
#define AUTH_POOL_SLOTS 2u
static union auth_slot auth_pool[AUTH_POOL_SLOTS];
static uint8_t auth_pool_used[AUTH_POOL_SLOTS];

void *auth_mbedtls_calloc(size_t n, size_t size)
{
    unsigned i;
    if (n == 0u || size == 0u || size > sizeof(union auth_slot) / n)
        return NULL;
    for (i = 0; i < AUTH_POOL_SLOTS; i++) {
        if (!auth_pool_used[i]) {
            auth_pool_used[i] = 1u;
            mbedtls_platform_zeroize(&auth_pool[i], sizeof auth_pool[i]);   /* calloc zeroes */
            return &auth_pool[i];
        }
    }
    return NULL;
}

void auth_mbedtls_free(void *p)
{
    unsigned i;
    for (i = 0; i < AUTH_POOL_SLOTS; i++) {
        if (p == (void *)&auth_pool[i]) {
            /* The AES slot held the key schedule. */
            mbedtls_platform_zeroize(&auth_pool[i], sizeof auth_pool[i]);
            auth_pool_used[i] = 0u;
        }
    }
}

/* ---- the key ---- */
static mbedtls_cipher_context_t auth_ctx;
static uint8_t auth_keyed;

int net_auth_init(const uint8_t key[AUTH_KEY_LEN])
{
    const mbedtls_cipher_info_t *info;
    if (auth_keyed) {
        mbedtls_cipher_free(&auth_ctx);
        auth_keyed = 0u;
    }
    mbedtls_cipher_init(&auth_ctx);
    if (key == NULL)
        return AUTH_ECRYPTO;
    info = mbedtls_cipher_info_from_type(MBEDTLS_CIPHER_AES_128_ECB);
    if (info == NULL || mbedtls_cipher_setup(&auth_ctx, info) != 0 ||
        mbedtls_cipher_cmac_starts(&auth_ctx, key, AUTH_KEY_LEN * 8u) != 0) {
        mbedtls_cipher_free(&auth_ctx);
        return AUTH_ECRYPTO;
    }
    auth_keyed = 1u;
    return AUTH_OK;
}

/* CMAC of the concatenation a | b | c (any may be empty) into out. */
static int auth_cmac3(const uint8_t *a, size_t alen, const uint8_t *b, size_t blen,
                      const uint8_t *c, size_t clen, uint8_t out[AUTH_CMAC_LEN])
{
    /* cmac_update refuses a NULL input even for zero bytes: skip empty parts. */
    if (!auth_keyed || mbedtls_cipher_cmac_reset(&auth_ctx) != 0 ||
        (alen > 0u && mbedtls_cipher_cmac_update(&auth_ctx, a, alen) != 0) ||
        (blen > 0u && mbedtls_cipher_cmac_update(&auth_ctx, b, blen) != 0) ||
        (clen > 0u && mbedtls_cipher_cmac_update(&auth_ctx, c, clen) != 0) ||
        mbedtls_cipher_cmac_finish(&auth_ctx, out) != 0)
        return AUTH_ECRYPTO;
    return AUTH_OK;
}

int auth_cmac(const uint8_t *msg, size_t len, uint8_t out[AUTH_CMAC_LEN])
{
    if ((msg == NULL && len > 0u) || out == NULL)
        return AUTH_ECRYPTO;
    return auth_cmac3(msg, len, NULL, 0u, NULL, 0u, out);
}

/* MIC input after the header: FCNT big-endian (as on air), then the payload.
 * The header and FCNT go in as one 8-byte block: one update call less. */
int auth_mic(const uint8_t header[AUTH_HEADER_LEN], uint32_t fcnt, const uint8_t *payload,
             size_t len, uint8_t mic[AUTH_MIC_LEN])
{
    uint8_t head[AUTH_HEADER_LEN + AUTH_FCNT_LEN], full[AUTH_CMAC_LEN];
    unsigned i;
    int rc;
    if (header == NULL || mic == NULL || (payload == NULL && len > 0u))
        return AUTH_ECRYPTO;
    for (i = 0; i < AUTH_HEADER_LEN; i++)
        head[i] = header[i];
    head[4] = (uint8_t)(fcnt >> 24);
    head[5] = (uint8_t)(fcnt >> 16);
    head[6] = (uint8_t)(fcnt >> 8);
    head[7] = (uint8_t)fcnt;
    rc = auth_cmac3(head, sizeof head, payload, len, NULL, 0u, full);
    if (rc == AUTH_OK) {
        for (i = 0; i < AUTH_MIC_LEN; i++)
            mic[i] = full[i];
    }
    return rc;
}

/* ---- counters ---- */
int auth_init(struct auth *a, uint32_t epoch)
{
    unsigned i;
    if (a == NULL || epoch > AUTH_EPOCH_MAX)
        return AUTH_EINVAL;
    a->tx_epoch = epoch;
    a->tx_count = 0u;
    a->rx_valid = 0u;
    for (i = 0; i < AUTH_STATIONS; i++)
        a->rx_last[i] = 0u;
    a->stats.sealed = 0u;
    a->stats.opened = 0u;
    a->stats.forged = 0u;
    a->stats.replayed = 0u;
    a->stats.malformed = 0u;
    return AUTH_OK;
}

int auth_seal(struct auth *a, const uint8_t header[AUTH_HEADER_LEN], uint8_t *payload,
              size_t len, size_t size)
{
    uint32_t fcnt;
    uint8_t mic[AUTH_MIC_LEN];
    unsigned i;
    int rc;
    if (a == NULL || header == NULL || payload == NULL || len > AUTH_PAYLOAD_MAX ||
        size < len + AUTH_TRAILER_LEN)
        return AUTH_EINVAL;
    if (a->tx_count >= (1ul << AUTH_COUNT_BITS))
        return AUTH_EEXHAUSTED;
    fcnt = (a->tx_epoch << AUTH_COUNT_BITS) | a->tx_count;
    rc = auth_mic(header, fcnt, payload, len, mic);
    if (rc != AUTH_OK)
        return rc;
    a->tx_count++;
    payload[len] = (uint8_t)(fcnt >> 24);
    payload[len + 1u] = (uint8_t)(fcnt >> 16);
    payload[len + 2u] = (uint8_t)(fcnt >> 8);
    payload[len + 3u] = (uint8_t)fcnt;
    for (i = 0; i < AUTH_MIC_LEN; i++)
        payload[len + AUTH_FCNT_LEN + i] = mic[i];
    a->stats.sealed++;
    return (int)(len + AUTH_TRAILER_LEN);
}

int auth_open(struct auth *a, const uint8_t header[AUTH_HEADER_LEN], const uint8_t *payload,
              size_t len)
{
    uint8_t mic[AUTH_MIC_LEN];
    uint32_t fcnt;
    size_t n;
    uint8_t src;
    int rc;
    if (a == NULL || header == NULL || payload == NULL)
        return AUTH_EINVAL;
    src = header[0];
    if (len < AUTH_TRAILER_LEN || len > AUTH_PAYLOAD_MAX + AUTH_TRAILER_LEN ||
        src >= AUTH_STATIONS) {
        a->stats.malformed++;
        return AUTH_EMALFORMED;
    }
    n = len - AUTH_TRAILER_LEN;
    fcnt = (uint32_t)payload[n] << 24 | (uint32_t)payload[n + 1u] << 16 |
           (uint32_t)payload[n + 2u] << 8 | (uint32_t)payload[n + 3u];
    rc = auth_mic(header, fcnt, payload, n, mic);
    if (rc != AUTH_OK)
        return rc;
    /* The MIC first, in constant time (no early exit on the first wrong
     * byte to time); the counter only for frames sealed with the key, so a
     * forged frame can never move a source's counter. */
    if (mbedtls_ct_memcmp(mic, payload + n + AUTH_FCNT_LEN, AUTH_MIC_LEN) != 0) {
        a->stats.forged++;
        return AUTH_EFORGED;
    }
    if ((a->rx_valid & (1u << src)) != 0u && fcnt <= a->rx_last[src]) {
        a->stats.replayed++;
        return AUTH_EREPLAY;
    }
    a->rx_last[src] = fcnt;
    a->rx_valid = (uint16_t)(a->rx_valid | (1u << src));
    a->stats.opened++;
    return (int)n;
}
