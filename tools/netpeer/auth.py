"""Frame authentication of the host peer: net/auth.c's MIC and replay counters
on the `cryptography` package's AES-CMAC, the same bytes as the C module
(compared byte for byte in net/tests/auth/test_auth_python.py).

A sealed payload ends in FCNT (4 bytes, big-endian) and the MIC (4 bytes):
    MIC = AES-CMAC(key, src dst type seq | FCNT | payload)[:4]
FCNT = epoch << COUNT_BITS | count; a receiver takes a frame from a source
only if its FCNT is above the last it took from that source (net/auth.h).
"""
import hmac

from cryptography.hazmat.primitives.ciphers import algorithms
from cryptography.hazmat.primitives.cmac import CMAC

KEY_LEN = 16
HEADER_LEN = 4          # src, dst, type, seq
FCNT_LEN = 4
MIC_LEN = 4
TRAILER_LEN = FCNT_LEN + MIC_LEN
PAYLOAD_MAX = 128       # before sealing
STATIONS = 16
CMAC_LEN = 16
COUNT_BITS = 20
EPOCH_MAX = (1 << (32 - COUNT_BITS)) - 1

# The public development key of net/net.h (net_auth_dev_key): the default of
# the shell, netnode and the host peer; it protects nothing (net/README.md).
DEV_KEY = b"bsched-dev-key!!"

# net/auth.h's return codes, for the errors below and the comparison tests.
OK, EFORGED, EREPLAY, EMALFORMED, EINVAL, EEXHAUSTED, ECRYPTO = 0, -1, -2, -3, -4, -5, -6


class AuthError(Exception):
    code = ECRYPTO


class Forged(AuthError):
    """The MIC is wrong: not sealed with the key, or changed on the way."""
    code = EFORGED


class Replayed(AuthError):
    """The MIC is right but the counter is not above the last taken from the source."""
    code = EREPLAY


class Malformed(AuthError):
    """Too short for a trailer, too long, or a source that is no station."""
    code = EMALFORMED


class Exhausted(AuthError):
    """This boot's counts are used up: restart with the next epoch."""
    code = EEXHAUSTED


def cmac(key, msg):
    """AES-CMAC (RFC 4493) of msg, all 16 bytes."""
    c = CMAC(algorithms.AES(bytes(key)))
    c.update(bytes(msg))
    return c.finalize()


def header_bytes(src, dst, type_, seq):
    return bytes((src, dst, type_, seq))


def mic(key, header, fcnt, payload):
    """The MIC of a frame: header is src, dst, type, seq as 4 bytes."""
    return cmac(key, bytes(header) + fcnt.to_bytes(FCNT_LEN, "big") + bytes(payload))[:MIC_LEN]


class Auth:
    """One station's counters under a network key (net/auth.h's struct auth)."""

    def __init__(self, key, epoch):
        if len(key) != KEY_LEN:
            raise ValueError(f"a key is {KEY_LEN} bytes, not {len(key)}")
        if not 0 <= epoch <= EPOCH_MAX:
            raise ValueError(f"epoch {epoch} not in 0..{EPOCH_MAX}")
        self.key = bytes(key)
        self.epoch = epoch
        self.count = 0
        self.rx_last = {}
        self.stats = {"sealed": 0, "opened": 0, "forged": 0, "replayed": 0, "malformed": 0}

    def seal(self, header, payload):
        """payload + FCNT + MIC; a fresh counter per call (seal every transmission)."""
        if len(payload) > PAYLOAD_MAX:
            raise ValueError(f"payload of {len(payload)} bytes > {PAYLOAD_MAX}")
        if self.count >= 1 << COUNT_BITS:
            raise Exhausted(f"epoch {self.epoch} used up")
        fcnt = self.epoch << COUNT_BITS | self.count
        self.count += 1
        self.stats["sealed"] += 1
        return bytes(payload) + fcnt.to_bytes(FCNT_LEN, "big") + mic(self.key, header, fcnt,
                                                                       payload)

    def open(self, header, data):
        """The payload of a sealed frame; raises Forged, Replayed or Malformed."""
        src = header[0]
        if not TRAILER_LEN <= len(data) <= PAYLOAD_MAX + TRAILER_LEN or src >= STATIONS:
            self.stats["malformed"] += 1
            raise Malformed(f"{len(data)} bytes from {src}")
        n = len(data) - TRAILER_LEN
        payload, fcnt = bytes(data[:n]), int.from_bytes(data[n:n + FCNT_LEN], "big")
        # cryptography's CMAC.verify takes the full 16 bytes only; the
        # truncated MIC is compared in constant time by the standard library.
        if not hmac.compare_digest(mic(self.key, header, fcnt, payload), bytes(data[n + FCNT_LEN:])):
            self.stats["forged"] += 1
            raise Forged(f"frame from {src}, FCNT {fcnt:#x}")
        if src in self.rx_last and fcnt <= self.rx_last[src]:
            self.stats["replayed"] += 1
            raise Replayed(f"FCNT {fcnt:#x} from {src}, last taken {self.rx_last[src]:#x}")
        self.rx_last[src] = fcnt
        self.stats["opened"] += 1
        return payload
