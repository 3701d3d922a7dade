/*
 * Packetizing: a message of up to NET_MSG_MAX bytes travels as fragments of
 * at most PACKET_DATA_MAX bytes, each in one frame whose payload starts with
 * a 2-byte packet header:
 *   port   the service the message is for (0..NET_PORTS-1)
 *   frag   bit 7: last fragment; bits 6-0: fragment index (0, 1, ...)
 * The reliable channel delivers fragments in order, so reassembly only
 * appends; anything out of place (a gap, another port mid-message, too long)
 * drops the partial message and is counted by the caller.
 */
#ifndef NET_PACKET_H
#define NET_PACKET_H

#include <stddef.h>
#include <stdint.h>
#include "frame.h"

#define NET_MSG_MAX       512u
#define NET_PORTS         8u
#define PACKET_HDR_LEN    2u
#define PACKET_DATA_MAX   (FRAME_PAYLOAD_MAX - PACKET_HDR_LEN)
#define PACKET_LAST       0x80u
#define PACKET_INDEX_MASK 0x7Fu

struct packet_reasm {
    uint8_t active;          /* a message is being collected */
    uint8_t port;
    uint8_t next_index;
    uint16_t len;
    uint8_t data[NET_MSG_MAX];
};

/* Fragment number index of a len-byte message: fills the frame payload
 * (header + data) and returns 1, or 0 when index is past the end. */
int packet_fragment(const uint8_t *msg, size_t len, uint8_t port, unsigned index,
                    struct frame *f);
/* Number of fragments of a len-byte message (1 for len 0). */
unsigned packet_count(size_t len);

enum packet_result { PACKET_INCOMPLETE = 0, PACKET_COMPLETE = 1, PACKET_ERROR = -1 };
void packet_reasm_init(struct packet_reasm *r);
/* Adds the fragment in payload[0..len). PACKET_COMPLETE: r->data/r->len/r->port
 * hold the message until the next call. PACKET_ERROR: dropped (and reset). */
int packet_reasm_add(struct packet_reasm *r, const uint8_t *payload, size_t len);

#endif /* NET_PACKET_H */
