"""A raw station on the radio medium's socket (robocube_emu.radio_medium), for the tests that speak the
medium's 2-byte messages themselves (test_medium, test_peer_clock) instead of
running a board or a host peer. The messages are in the medium's docstring."""
import socket
import time

# The message codes from the medium itself.
from robocube_emu.radio_medium import (MSG_CLOCK, MSG_CONTROL, MSG_DATA, MSG_HELLO,  # noqa: F401
                                       MSG_PACE, MSG_SYNC)


def sealed(auth, f):
    """Frame f with its payload sealed by auth (a netpeer.auth.Auth): what a
    station with that key and epoch would send (net/auth.h)."""
    from netpeer.protocol import Frame
    return Frame(f.src, f.dst, f.type, f.seq,
                 auth.seal(bytes((f.src, f.dst, f.type, f.seq)), f.payload))


class Station:
    def __init__(self, sock, number):
        self.s = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        self.s.connect(sock)
        self.s.sendall(bytes((MSG_HELLO, number)))
        self.buf = b""

    def selects(self, v):
        """Port 7 of the board: 1 RX, 2 TX (carrier for the others), 3 loop-back."""
        self.s.sendall(bytes((MSG_CONTROL, v)))

    def send(self, data):
        self.s.sendall(b"".join(bytes((MSG_DATA, b)) for b in data))

    def pace(self, baud):
        """Ask the medium to pace this station's characters (a host peer)."""
        self.s.sendall(bytes((MSG_PACE, baud // 300)))

    def _pairs(self):
        """The whole messages received so far; a half message stays in buf."""
        usable = len(self.buf) & ~1
        pairs = [(self.buf[i], self.buf[i + 1]) for i in range(0, usable, 2)]
        self.buf = self.buf[usable:]
        return pairs

    def drain(self, wait=0.3):
        """(characters heard, last carrier) after wait seconds."""
        time.sleep(wait)
        self.s.setblocking(False)
        try:
            while True:
                chunk = self.s.recv(65536)
                if not chunk:
                    break
                self.buf += chunk
        except BlockingIOError:
            pass
        self.s.setblocking(True)
        heard, carrier = bytearray(), None
        for kind, value in self._pairs():
            if kind == MSG_DATA:
                heard.append(value)
            else:
                carrier = value
        return bytes(heard), carrier

    def read_msgs(self, until_kind, timeout=5.0):
        """The messages up to and including the first of kind until_kind."""
        self.s.settimeout(timeout)
        out = []
        while True:
            chunk = self.s.recv(2 - len(self.buf))
            assert chunk, "medium closed the connection"
            self.buf += chunk
            if len(self.buf) == 2:
                out += self._pairs()
                if out[-1][0] == until_kind:
                    return out

    def messages(self, wait, until=None):
        """The messages that arrive within wait seconds (or up to the message
        until, if it comes first)."""
        self.s.settimeout(0.05)
        out, end = [], time.monotonic() + wait
        while time.monotonic() < end and until not in out:
            try:
                chunk = self.s.recv(4096)
            except socket.timeout:
                continue
            if not chunk:
                break
            self.buf += chunk
            out += self._pairs()
        return out

    def sync_round(self):
        """One lock-step round (as a board's device model runs it): SYNC, then
        what the medium delivers up to its SYNC back."""
        self.s.sendall(bytes((MSG_SYNC, 0)))
        return self.read_msgs(MSG_SYNC)
