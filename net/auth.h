/*
 * Frame authentication for the radio: a message authentication code (MIC)
 * and a replay counter per frame, as LoRaWAN 1.1 (AES-CMAC MIC truncated to
 * 4 bytes, 32-bit frame counters) and IEEE 802.15.4 security (a frame
 * counter per sender, checked by every receiver) do it.
 *
 * A sealed frame's payload ends in a trailer of 8 bytes:
 *     payload (len bytes) | FCNT (4, big-endian) | MIC (4)
 *     MIC = first 4 bytes of AES-CMAC(K, src dst type seq | FCNT | payload)
 * K is the network key (16 bytes, every station of a network holds it).
 * The header bytes are those of the frame on air (net/frame.h: src, dst,
 * type, seq), so a frame cannot be moved to another address, kind, session
 * or sequence number without the key. The primitive is Mbed TLS's CMAC
 * (ci/setup.d/mbedtls.sh, configuration net/auth_mbedtls_config.h); the host
 * peer computes the same bytes with Python's cryptography package
 * (tools/netpeer/auth.py).
 *
 * Replay: each station seals with a counter that only grows, and a receiver
 * takes a frame from source s only if its FCNT is above the highest it took
 * from s (strict: stop and wait and one shared channel put a station's
 * frames on air in the order they were sealed, so a lower counter is a
 * replay). The counter is (epoch, count): FCNT = epoch << AUTH_COUNT_BITS |
 * count, the epoch fixed per boot, the count growing per sealed frame. A
 * station that restarts with a higher epoch is taken at once by every
 * receiver; the epoch must therefore grow from boot to boot (net/README.md,
 * "Authentication": where it comes from). A boot that runs out of counts
 * refuses to seal (AUTH_EEXHAUSTED) rather than step into the next epoch.
 *
 * Not reentrant: one key context for the module; call everything from one
 * thread (the network service thread).
 */
#ifndef NET_AUTH_H
#define NET_AUTH_H

#include <stddef.h>
#include <stdint.h>

#define AUTH_KEY_LEN      16u
#define AUTH_HEADER_LEN   4u      /* src, dst, type, seq */
#define AUTH_FCNT_LEN     4u
#define AUTH_MIC_LEN      4u
#define AUTH_TRAILER_LEN  (AUTH_FCNT_LEN + AUTH_MIC_LEN)
#define AUTH_PAYLOAD_MAX  128u    /* payload before sealing: FRAME_PAYLOAD_MAX */
#define AUTH_STATIONS     16u     /* sources 0..15: LINK_MAX_STATIONS */
#define AUTH_CMAC_LEN     16u

/* FCNT = epoch << AUTH_COUNT_BITS | count: 4096 epochs (boots) of 2^20
 * frames each (at the 19 200 baud air's most, about 100 ACK-sized frames a
 * second, that is 2.9 hours of nothing but ACKs; 22 hours of back-to-back
 * full fragments). */
#define AUTH_COUNT_BITS   20u
#define AUTH_EPOCH_MAX    ((1ul << (32u - AUTH_COUNT_BITS)) - 1u)

#define AUTH_OK            0
#define AUTH_EFORGED     (-1)   /* MIC wrong: not sealed with the key, or changed */
#define AUTH_EREPLAY     (-2)   /* MIC right, counter not above the last taken */
#define AUTH_EMALFORMED  (-3)   /* too short for a trailer, too long, or no station's src */
#define AUTH_EINVAL      (-4)   /* bad arguments (seal: too long, no room; epoch too big) */
#define AUTH_EEXHAUSTED  (-5)   /* this boot's counts are used up: restart with epoch + 1 */
#define AUTH_ECRYPTO     (-6)   /* no key set, or the library refused */

struct auth_stats {
    uint32_t sealed;
    uint32_t opened;        /* frames taken */
    uint32_t forged;        /* auth_forged: AUTH_EFORGED */
    uint32_t replayed;      /* auth_replayed: AUTH_EREPLAY */
    uint32_t malformed;
};

/* One station's counters: what it seals with, what it took from each source. */
struct auth {
    uint32_t tx_epoch;                  /* this boot's */
    uint32_t tx_count;                  /* the next frame's count, up to 2^20 (used up) */
    uint16_t rx_valid;                  /* bit s: rx_last[s] holds a counter from s */
    uint32_t rx_last[AUTH_STATIONS];
    struct auth_stats stats;
};

/* Sets the network key (16 bytes) of the module: AUTH_OK, or AUTH_ECRYPTO.
 * May be called again to change the key. */
int net_auth_init(const uint8_t key[AUTH_KEY_LEN]);

/* A station's counters for this boot's epoch (0..AUTH_EPOCH_MAX): nothing
 * taken from anyone yet, the first frame sealed with FCNT epoch << 20.
 * AUTH_OK, or AUTH_EINVAL (a is untouched). */
int auth_init(struct auth *a, uint32_t epoch);

/* Seals a frame: appends FCNT and MIC to payload[0..len) (len <=
 * AUTH_PAYLOAD_MAX; size, the buffer's size, at least len + AUTH_TRAILER_LEN).
 * Returns the new length, len + AUTH_TRAILER_LEN, or AUTH_EINVAL,
 * AUTH_EEXHAUSTED, AUTH_ECRYPTO (payload untouched, no counter used).
 * Seal every transmission anew: a retransmission with the old counter would
 * be refused as a replay by a receiver that took the first copy. */
int auth_seal(struct auth *a, const uint8_t header[AUTH_HEADER_LEN], uint8_t *payload,
              size_t len, size_t size);

/* Opens a received frame whose payload (len bytes) ends in the trailer:
 * checks the MIC in constant time, then the counter of header[0]'s source.
 * Returns the payload length without the trailer (len - AUTH_TRAILER_LEN)
 * and remembers the counter, or AUTH_EFORGED, AUTH_EREPLAY, AUTH_EMALFORMED
 * (each counted in a->stats; the counters stay as they were), AUTH_ECRYPTO. */
int auth_open(struct auth *a, const uint8_t header[AUTH_HEADER_LEN], const uint8_t *payload,
              size_t len);

/* The MIC of a frame with counter fcnt (what auth_seal appends): AUTH_OK or
 * AUTH_ECRYPTO. */
int auth_mic(const uint8_t header[AUTH_HEADER_LEN], uint32_t fcnt, const uint8_t *payload,
             size_t len, uint8_t mic[AUTH_MIC_LEN]);

/* AES-CMAC of msg with the network key, all 16 bytes (RFC 4493; the tests
 * check the module against its examples): AUTH_OK or AUTH_ECRYPTO. */
int auth_cmac(const uint8_t *msg, size_t len, uint8_t out[AUTH_CMAC_LEN]);

#endif /* NET_AUTH_H */
