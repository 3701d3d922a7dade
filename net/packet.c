/* Message fragmentation and reassembly; see packet.h. */
#include "packet.h"

unsigned packet_count(size_t len)
{
    return len == 0u ? 1u : (unsigned)((len + PACKET_DATA_MAX - 1u) / PACKET_DATA_MAX);
}

int packet_fragment(const uint8_t *msg, size_t len, uint8_t port, unsigned index,
                    struct frame *f)
{
    unsigned count = packet_count(len);
    size_t off = (size_t)index * PACKET_DATA_MAX;
    size_t n, i;

    if (index >= count || len > NET_MSG_MAX || port >= NET_PORTS)
        return 0;
    n = len - off < PACKET_DATA_MAX ? len - off : PACKET_DATA_MAX;
    f->payload[0] = port;
    f->payload[1] = (uint8_t)((index & PACKET_INDEX_MASK) | (index + 1u == count ? PACKET_LAST : 0u));
    for (i = 0; i < n; i++)
        f->payload[PACKET_HDR_LEN + i] = msg[off + i];
    f->len = (uint8_t)(PACKET_HDR_LEN + n);
    return 1;
}

void packet_reasm_init(struct packet_reasm *r)
{
    r->active = 0;
    r->port = 0;
    r->next_index = 0;
    r->len = 0;
}

int packet_reasm_add(struct packet_reasm *r, const uint8_t *payload, size_t len)
{
    uint8_t port, index;
    size_t n, i;

    if (len < PACKET_HDR_LEN || len > FRAME_PAYLOAD_MAX || payload[0] >= NET_PORTS) {
        packet_reasm_init(r);
        return PACKET_ERROR;
    }
    port = payload[0];
    index = (uint8_t)(payload[1] & PACKET_INDEX_MASK);
    n = len - PACKET_HDR_LEN;
    if (index == 0u) {
        r->active = 1;      /* a new message (an unfinished one is abandoned) */
        r->port = port;
        r->next_index = 0;
        r->len = 0;
    }
    if (!r->active || index != r->next_index || port != r->port ||
        (size_t)r->len + n > NET_MSG_MAX) {
        packet_reasm_init(r);
        return PACKET_ERROR;
    }
    for (i = 0; i < n; i++)
        r->data[r->len + i] = payload[PACKET_HDR_LEN + i];
    r->len = (uint16_t)(r->len + n);
    r->next_index++;
    if ((payload[1] & PACKET_LAST) != 0u) {
        r->active = 0;
        return PACKET_COMPLETE;
    }
    return PACKET_INCOMPLETE;
}
