"""netpeer: a host PC as a station of the RoboCube radio network.

The same protocol as net/ on the boards (frame.h, link.h, packet.h):
    from netpeer import Peer, MediumTransport
    with Peer(MediumTransport("/tmp/air.sock"), station=9) as p:
        p.send(1, 1, b"hello", reliable=True)     # raises Unreachable
        src, data = p.recv(1, timeout=5.0)
CLI: python -m netpeer --socket PATH --station N send DST PORT TEXT
     python -m netpeer --socket PATH --station N listen PORT
(--serial DEVICE instead of --socket uses a real radio module through pyserial.)
"""
from .protocol import (Frame, FrameDecoder, encode_frame, crc16, BROADCAST,
                       DATA, ACK, DGRAM, PACKET_DATA_MAX, MSG_MAX, PORTS)
from .peer import Peer, Unreachable
from .transport import MediumTransport, SerialTransport

__all__ = ["Frame", "FrameDecoder", "encode_frame", "crc16", "BROADCAST", "DATA", "ACK",
           "DGRAM", "PACKET_DATA_MAX", "MSG_MAX", "PORTS", "Peer", "Unreachable",
           "MediumTransport", "SerialTransport"]
