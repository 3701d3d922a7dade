/* Host tool for net/tests/target/test_wire_constants.py: prints the wire
 * constants of net/ as "NAME value" lines, so the host peer's copies
 * (tools/netpeer) are checked against the C headers, where they are defined. */
#include <stdio.h>
#include "net/fec.h"
#include "net/frame.h"
#include "net/link.h"
#include "net/mac.h"
#include "net/packet.h"

#define SHOW(name) printf("%s %lu\n", #name, (unsigned long)(name))

int main(void)
{
    SHOW(FRAME_PREAMBLE_BYTE);
    SHOW(FRAME_PREAMBLE_LEN);
    SHOW(FRAME_FLAG);
    SHOW(FRAME_ESC);
    SHOW(FRAME_ESC_XOR);
    SHOW(FRAME_HEADER_LEN);
    SHOW(FRAME_CRC_LEN);
    SHOW(FRAME_PAYLOAD_MAX);
    SHOW(FRAME_TRAILER_MAX);
    SHOW(FRAME_AIR_PAYLOAD_MAX);
    SHOW(FRAME_BODY_MAX);
    SHOW(FRAME_BROADCAST);
    SHOW(LINK_DATA);
    SHOW(LINK_ACK);
    SHOW(LINK_DGRAM);
    SHOW(LINK_KIND_MASK);
    SHOW(LINK_SESSION_SHIFT);
    SHOW(LINK_SESSIONS);
    SHOW(LINK_MAX_STATIONS);
    SHOW(LINK_RTO_MS);
    SHOW(LINK_RTO_MAX_MS);
    SHOW(LINK_MAX_RETRIES);
    SHOW(NET_PORTS);
    SHOW(NET_MSG_MAX);
    SHOW(PACKET_HDR_LEN);
    SHOW(PACKET_DATA_MAX);
    SHOW(PACKET_LAST);
    SHOW(MAC_SLOT_MS);
    SHOW(MAC_CW_MIN);
    SHOW(MAC_CW_MAX);
    SHOW(MAC_MAX_ATTEMPTS);
    SHOW(FEC_K);
    SHOW(FEC_NSYM);
    SHOW(FEC_COPIES);
    SHOW(FEC_CW_MAX);
    return 0;
}
