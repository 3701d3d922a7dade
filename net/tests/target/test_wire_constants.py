"""The host peer's copies of the wire constants (tools/netpeer) against the C
headers of net/, where they are defined (printed by net/tests/wire_constants.c)."""
import os
import subprocess

from netpeer import peer, protocol

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
TOOL = os.path.join(ROOT, "build", "net", "tests", "wire_constants")

PYTHON = {
    "FRAME_PREAMBLE_BYTE": protocol.PREAMBLE[0],
    "FRAME_PREAMBLE_LEN": len(protocol.PREAMBLE),
    "FRAME_FLAG": protocol.FLAG,
    "FRAME_ESC": protocol.ESC,
    "FRAME_ESC_XOR": protocol.ESC_XOR,
    "FRAME_HEADER_LEN": protocol.HEADER_LEN,
    "FRAME_CRC_LEN": protocol.CRC_LEN,
    "FRAME_PAYLOAD_MAX": protocol.PAYLOAD_MAX,
    "FRAME_TRAILER_MAX": protocol.TRAILER_MAX,
    "FRAME_AIR_PAYLOAD_MAX": protocol.AIR_PAYLOAD_MAX,
    "FRAME_BODY_MAX": protocol.BODY_MAX,
    "FRAME_BROADCAST": protocol.BROADCAST,
    "LINK_DATA": protocol.DATA,
    "LINK_ACK": protocol.ACK,
    "LINK_DGRAM": protocol.DGRAM,
    "LINK_KIND_MASK": protocol.KIND_MASK,
    "LINK_SESSION_SHIFT": protocol.SESSION_SHIFT,
    "LINK_SESSIONS": protocol.SESSIONS,
    "LINK_MAX_STATIONS": peer.MAX_STATIONS,
    "LINK_RTO_MS": round(peer.RTO * 1000),
    "LINK_RTO_MAX_MS": round(peer.RTO_MAX * 1000),
    "LINK_MAX_RETRIES": peer.MAX_RETRIES,
    "NET_PORTS": protocol.PORTS,
    "NET_MSG_MAX": protocol.MSG_MAX,
    "PACKET_HDR_LEN": protocol.PACKET_HDR_LEN,
    "PACKET_DATA_MAX": protocol.PACKET_DATA_MAX,
    "PACKET_LAST": protocol.PACKET_LAST,
    "MAC_SLOT_MS": round(peer.SLOT * 1000),
    "MAC_CW_MIN": peer.CW_MIN,
    "MAC_CW_MAX": peer.CW_MAX,
    "MAC_MAX_ATTEMPTS": peer.MAC_ATTEMPTS,
    "FEC_K": protocol.FEC_K,
    "FEC_NSYM": protocol.FEC_NSYM,
    "FEC_COPIES": protocol.FEC_COPIES,
    "FEC_CW_MAX": protocol.FEC_CW_MAX,
}


def test_host_peer_constants_equal_the_c_headers():
    out = subprocess.run([TOOL], capture_output=True, text=True, check=True).stdout
    c = {name: int(value) for name, value in (line.split() for line in out.splitlines())}
    assert set(c) == set(PYTHON)                 # every constant the tool prints is checked
    assert {k: PYTHON[k] for k in c if PYTHON[k] != c[k]} == {}, c
