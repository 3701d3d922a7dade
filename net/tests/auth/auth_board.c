/*
 * net/auth.c and the CPU32 build of Mbed TLS on the emulated board, no
 * kernel (the firmware base objects only: startup, polled console, kstring.c).
 * Prints, for net/tests/auth/test_auth_target.py to compare with the host
 * peer's Python:
 *   AUTH-BOARD CMAC LEN HEX               RFC 4493's examples under its key
 *   AUTH-BOARD SEAL SRC DST TYPE SEQ HEX  frames sealed under the test key
 *   AUTH-BOARD OPEN WHAT RC               a good, a forged and a replayed frame
 * then runs AUTH_BOARD_ROUNDS rounds of: seal and open of a full 128-byte
 * payload, seal and open of an ACK-sized (empty) one, open of a forged full
 * one. A label after each call (auth_board_after_*) marks where the call has
 * returned, for the instruction counts from an exec trace (auth_measure.py),
 * and ends with AUTH-BOARD DONE.
 */
#include <stdint.h>

#include "boards/robocube/duart_console.h"
#include "kernel/lib/kprintf.h"
#include "net/auth.h"
#include "net/tests/rfc4493.h"

#define AUTH_BOARD_ROUNDS 4u

/* The test key; test_auth_target.py holds the same. */
static const uint8_t test_key[16] = {
    0x42, 0x53, 0x43, 0x48, 0x45, 0x44, 0x2d, 0x52, 0x41, 0x44, 0x49, 0x4f, 0x2d, 0x4b, 0x45, 0x59,
};

static struct auth tx, rx;
static uint8_t full[AUTH_PAYLOAD_MAX + AUTH_TRAILER_LEN], ack[AUTH_TRAILER_LEN],
               forged[AUTH_PAYLOAD_MAX + AUTH_TRAILER_LEN];

static void hex(const uint8_t *b, unsigned n)
{
    unsigned i;
    for (i = 0; i < n; i++)
        kprintf("%02x", (unsigned)b[i]);
    kprintf("\n");
}

static void print_seal(const uint8_t header[AUTH_HEADER_LEN], const uint8_t *b, int n)
{
    kprintf("AUTH-BOARD SEAL %u %u %u %u ", (unsigned)header[0], (unsigned)header[1],
            (unsigned)header[2], (unsigned)header[3]);
    if (n < 0) {
        kprintf("error %d\n", n);
        return;
    }
    hex(b, (unsigned)n);
}

/* The measured calls; each label is passed once per round. */
static void measured_rounds(void)
{
    static const uint8_t data_hdr[AUTH_HEADER_LEN] = { 1, 2, 0x29, 17 };   /* DATA, session 10 */
    static const uint8_t ack_hdr[AUTH_HEADER_LEN] = { 2, 1, 0x2a, 17 };    /* its ACK */
    unsigned r, i;
    for (r = 0; r < AUTH_BOARD_ROUNDS; r++) {
        int n_full, n_ack, rc_full, rc_ack, rc_forged;
        for (i = 0; i < AUTH_PAYLOAD_MAX; i++)
            full[i] = (uint8_t)(r * 31u + i);
        n_full = auth_seal(&tx, data_hdr, full, AUTH_PAYLOAD_MAX, sizeof full);
        __asm__ __volatile__(".globl auth_board_after_seal_full\nauth_board_after_seal_full:" ::: "memory");
        rc_full = auth_open(&rx, data_hdr, full, (size_t)n_full);
        __asm__ __volatile__(".globl auth_board_after_open_full\nauth_board_after_open_full:" ::: "memory");
        n_ack = auth_seal(&tx, ack_hdr, ack, 0, sizeof ack);
        __asm__ __volatile__(".globl auth_board_after_seal_ack\nauth_board_after_seal_ack:" ::: "memory");
        rc_ack = auth_open(&rx, ack_hdr, ack, (size_t)n_ack);
        __asm__ __volatile__(".globl auth_board_after_open_ack\nauth_board_after_open_ack:" ::: "memory");
        for (i = 0; i < sizeof full; i++)
            forged[i] = full[i];
        forged[r] ^= 0x01u;                         /* one bit of the payload */
        rc_forged = auth_open(&rx, data_hdr, forged, (size_t)n_full);
        __asm__ __volatile__(".globl auth_board_after_open_forged\nauth_board_after_open_forged:" ::: "memory");
        kprintf("AUTH-BOARD ROUND %u seal %d open %d seal-ack %d open-ack %d forged %d\n", r,
                n_full, rc_full, n_ack, rc_ack, rc_forged);
    }
}

int main(void)
{
    static const uint8_t lens[4] = { 0, 16, 40, 64 };
    static const uint8_t hdr[AUTH_HEADER_LEN] = { 3, 0xFF, 0x07, 0x7E };
    uint8_t mac[AUTH_CMAC_LEN], buf[40 + AUTH_TRAILER_LEN], copy[sizeof buf];
    unsigned i;
    int n;
    console_init();
    kprintf("\nauth board test\n");
    if (net_auth_init(rfc_key) != AUTH_OK) {
        kprintf("AUTH-BOARD DONE FAIL net_auth_init\n");
        return 1;
    }
    for (i = 0; i < 4u; i++) {
        if (auth_cmac(rfc_msg, lens[i], mac) != AUTH_OK) {
            kprintf("AUTH-BOARD DONE FAIL auth_cmac\n");
            return 1;
        }
        kprintf("AUTH-BOARD CMAC %u ", (unsigned)lens[i]);
        hex(mac, AUTH_CMAC_LEN);
    }
    if (net_auth_init(test_key) != AUTH_OK || auth_init(&tx, 10) != AUTH_OK ||
        auth_init(&rx, 0) != AUTH_OK) {
        kprintf("AUTH-BOARD DONE FAIL init\n");
        return 1;
    }
    /* Three frames from station 3 (epoch 10): 40 bytes, empty, 40 bytes. */
    for (i = 0; i < 40u; i++)
        buf[i] = (uint8_t)(0x7Bu + i);
    n = auth_seal(&tx, hdr, buf, 40, sizeof buf);
    print_seal(hdr, buf, n);
    for (i = 0; i < sizeof buf; i++)
        copy[i] = buf[i];
    kprintf("AUTH-BOARD OPEN good %d\n", auth_open(&rx, hdr, buf, (size_t)n));
    kprintf("AUTH-BOARD OPEN replayed %d\n", auth_open(&rx, hdr, copy, (size_t)n));
    copy[n - 1] ^= 0x80u;
    kprintf("AUTH-BOARD OPEN forged %d\n", auth_open(&rx, hdr, copy, (size_t)n));
    n = auth_seal(&tx, hdr, buf, 0, sizeof buf);
    print_seal(hdr, buf, n);
    for (i = 0; i < 40u; i++)
        buf[i] = (uint8_t)(0x7Bu + i);
    n = auth_seal(&tx, hdr, buf, 40, sizeof buf);
    print_seal(hdr, buf, n);
    /* Counters from here on: the measured rounds run from a fresh state. */
    if (auth_init(&tx, 11) != AUTH_OK || auth_init(&rx, 0) != AUTH_OK)
        return 1;
    measured_rounds();
    kprintf("AUTH-BOARD stats sealed %lu opened %lu forged %lu replayed %lu\n",
            (unsigned long)tx.stats.sealed, (unsigned long)rx.stats.opened,
            (unsigned long)rx.stats.forged, (unsigned long)rx.stats.replayed);
    kprintf("AUTH-BOARD DONE\n");
    return 0;
}
