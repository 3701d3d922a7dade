"""Frames and packets of the radio link, as net/frame.h and net/packet.h define them."""
import binascii
from dataclasses import dataclass

PREAMBLE = b"\x55\x55\x55"
FLAG, ESC, ESC_XOR = 0x7E, 0x7D, 0x20
HEADER_LEN, CRC_LEN = 4, 2
PAYLOAD_MAX = 128                # what the layers above put in a frame
TRAILER_MAX = 8                  # the authentication trailer (auth.TRAILER_LEN)
AIR_PAYLOAD_MAX = PAYLOAD_MAX + TRAILER_MAX
BODY_MAX = HEADER_LEN + AIR_PAYLOAD_MAX + CRC_LEN
BROADCAST = 0xFF
DATA, ACK, DGRAM = 1, 2, 3
# frame.type = kind | session << SESSION_SHIFT (net/link.h, "Sessions")
KIND_MASK, SESSION_SHIFT, SESSIONS = 0x03, 2, 64
PORTS = 8
MSG_MAX = 512
PACKET_HDR_LEN = 2
PACKET_DATA_MAX = PAYLOAD_MAX - PACKET_HDR_LEN
PACKET_LAST = 0x80


def frame_type(kind, session):
    """The type byte of a frame of kind (DATA, ACK, DGRAM) from session (LINK_TYPE)."""
    return kind | (session % SESSIONS) << SESSION_SHIFT


def frame_kind(type_byte):
    return type_byte & KIND_MASK


def frame_session(type_byte):
    return type_byte >> SESSION_SHIFT


def crc16(data, crc=0xFFFF):
    """CRC-16/CCITT-FALSE (net/crc16.h)."""
    return binascii.crc_hqx(bytes(data), crc)


@dataclass
class Frame:
    src: int
    dst: int
    type: int
    seq: int
    payload: bytes = b""


def _stuff(data):
    out = bytearray()
    for b in data:
        if b in (FLAG, ESC):
            out += bytes((ESC, b ^ ESC_XOR))
        else:
            out.append(b)
    return bytes(out)


def encode_frame(f):
    if len(f.payload) > AIR_PAYLOAD_MAX:
        raise ValueError(f"payload of {len(f.payload)} bytes > {AIR_PAYLOAD_MAX}")
    body = bytes((f.src, f.dst, f.type, f.seq)) + bytes(f.payload)
    c = crc16(body)
    return PREAMBLE + bytes((FLAG,)) + _stuff(body + bytes((c >> 8, c & 0xFF))) + bytes((FLAG,))


class ByteReceiver:
    """A receiver fed one byte at a time: byte(b) returns a completed frame or None."""

    def feed(self, data):
        """Returns the good frames completed by data."""
        return [f for f in map(self.byte, data) if f is not None]


class FrameDecoder(ByteReceiver):
    """The receive state machine of net/frame.c, one byte at a time."""
    HUNT, BODY, ESCAPED = 0, 1, 2

    def __init__(self):
        self.state = self.HUNT
        self.body = bytearray()
        self.frames = self.crc_errors = self.malformed = 0

    def byte(self, b):
        if b == FLAG:
            if self.state == self.ESCAPED:
                self.malformed += 1
                self.body.clear()
                self.state = self.BODY
                return None
            if self.state == self.HUNT:
                self.state = self.BODY
                self.body.clear()
                return None
            body = bytes(self.body)
            self.body.clear()
            if len(body) < HEADER_LEN + CRC_LEN:
                return None
            if crc16(body) != 0:
                self.crc_errors += 1
                return None
            self.frames += 1
            return Frame(body[0], body[1], body[2], body[3], body[4:-2])
        if self.state == self.BODY:
            if b == ESC:
                self.state = self.ESCAPED
                return None
        elif self.state == self.ESCAPED:
            b ^= ESC_XOR
            if b not in (FLAG, ESC):
                self.malformed += 1
                self.state = self.HUNT
                self.body.clear()
                return None
            self.state = self.BODY
        else:
            return None
        if len(self.body) >= BODY_MAX:
            self.malformed += 1
            self.state = self.HUNT
            self.body.clear()
            return None
        self.body.append(b)
        return None


def fragments(msg, port):
    """Frame payloads (packet header + data) of a message (net/packet.c)."""
    if len(msg) > MSG_MAX or not 0 <= port < PORTS:
        raise ValueError(f"message of {len(msg)} bytes (max {MSG_MAX}) or port {port}")
    count = max(1, -(-len(msg) // PACKET_DATA_MAX))
    out = []
    for i in range(count):
        chunk = msg[i * PACKET_DATA_MAX:(i + 1) * PACKET_DATA_MAX]
        out.append(bytes((port, i | (PACKET_LAST if i + 1 == count else 0))) + bytes(chunk))
    return out


class Reassembly:
    """In-order reassembly of one peer's fragments (net/packet.c)."""

    def __init__(self):
        self.active = False
        self.port = 0
        self.next = 0
        self.data = bytearray()

    def add(self, payload):
        """Returns (port, message) when complete, None otherwise; ValueError when out of place."""
        if len(payload) < PACKET_HDR_LEN or payload[0] >= PORTS:
            self.active = False
            raise ValueError("bad packet header")
        port, index = payload[0], payload[1] & 0x7F
        if index == 0:
            self.active, self.port, self.next, self.data = True, port, 0, bytearray()
        if (not self.active or index != self.next or port != self.port
                or len(self.data) + len(payload) - 2 > MSG_MAX):
            self.active = False
            raise ValueError("fragment out of place")
        self.data += payload[2:]
        self.next += 1
        if payload[1] & PACKET_LAST:
            self.active = False
            return port, bytes(self.data)
        return None


# ---- forward error correction on air (net/fec.h) ----------------------------
FEC_K, FEC_NSYM = 16, 12
FEC_N = FEC_K + FEC_NSYM
FEC_COPIES = 5
FEC_CW_MAX = -(-(1 + BODY_MAX) // FEC_K)
_rs = None


def _codec():
    """reedsolo's RSCodec(12): GF(256), 0x11D, generator 2, first root alpha^0,
    the code of net/rs.c (checked against each other in net/tests)."""
    global _rs
    if _rs is None:
        import reedsolo
        _rs = reedsolo.RSCodec(FEC_NSYM)
    return _rs


def encode_frame_fec(f):
    """On-air bytes of f with FEC (net/fec.h): preamble, flag, the codeword
    count five times, the Reed-Solomon codewords of L + body."""
    if len(f.payload) > AIR_PAYLOAD_MAX:
        raise ValueError(f"payload of {len(f.payload)} bytes > {AIR_PAYLOAD_MAX}")
    body = bytes((f.src, f.dst, f.type, f.seq)) + bytes(f.payload)
    c = crc16(body)
    body += bytes((c >> 8, c & 0xFF))
    ncw = -(-(1 + len(body)) // FEC_K)
    plain = (bytes((len(body),)) + body).ljust(ncw * FEC_K, b"\0")
    out = bytearray(PREAMBLE + bytes((FLAG,)) + bytes((ncw,)) * FEC_COPIES)
    for i in range(ncw):
        out += _codec().encode(plain[i * FEC_K:(i + 1) * FEC_K])
    return bytes(out)


class FecDecoder(ByteReceiver):
    """The receiver of net/fec.c: collects a frame's codewords after the flag
    and the voted codeword count, then corrects them with reedsolo."""

    def __init__(self):
        self.state, self.copies, self.raw, self.need = "hunt", [], bytearray(), 0
        self.frames = self.corrected = self.uncorrectable = self.bad_frames = 0
        self.bad_count = 0

    def byte(self, b):
        if self.state == "count":
            self.copies.append(b)
            if len(self.copies) < FEC_COPIES:
                return None
            votes = [c for c in self.copies if 1 <= c <= FEC_CW_MAX and self.copies.count(c) >= 2]
            if not votes:
                self.bad_count += 1
                self.state = "hunt"
                return None
            self.need, self.raw, self.state = votes[0] * FEC_N, bytearray(), "data"
            return None
        if self.state == "data":
            self.raw.append(b)
            if len(self.raw) < self.need:
                return None
            self.state = "hunt"
            return self.decode(bytes(self.raw))
        if b == FLAG:
            self.state, self.copies = "count", []
        return None

    def decode(self, raw):
        import reedsolo
        plain = bytearray()
        for i in range(len(raw) // FEC_N):
            try:
                msg, _, errata = _codec().decode(raw[i * FEC_N:(i + 1) * FEC_N])
            except reedsolo.ReedSolomonError:
                self.uncorrectable += 1
                return None
            plain += msg
            self.corrected += len(errata)
        n = plain[0]
        if (n < HEADER_LEN + CRC_LEN or n > BODY_MAX or -(-(1 + n) // FEC_K) * FEC_N != len(raw)
                or crc16(plain[1:1 + n]) != 0):
            self.bad_frames += 1
            return None
        body = plain[1:1 + n]
        self.frames += 1
        return Frame(body[0], body[1], body[2], body[3], bytes(body[4:-2]))
