"""A raw station on the radio medium's socket (robocube_emu.radio_medium), for the tests that speak the
medium's 2-byte messages themselves (test_medium, test_peer_clock) instead of
running a board or a host peer. The messages are in the medium's docstring.

No wait here is a guess of how long the medium takes: a station counts the
messages it sent and read, the medium's control socket ("station N") says how
many it took from the station and wrote to it, and settle() and drain() wait
until those agree (or fail after SETTLE_TIMEOUT seconds)."""
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


SETTLE_TIMEOUT = 30.0
# The stations open on each medium (by socket path): drain() settles them all.
_open = {}


def _control(path, command):
    c = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    c.settimeout(SETTLE_TIMEOUT)
    try:
        c.connect(path + ".ctl")
        c.sendall((command + "\n").encode())
        return c.makefile().readline().strip()
    finally:
        c.close()


class Station:
    def __init__(self, sock, number):
        self.path, self.number = sock, number
        self.s = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        self.s.connect(sock)
        self.sent = self.got = 0         # messages sent to the medium, read from it
        self.buf = b""
        self._send(bytes((MSG_HELLO, number)))
        _open.setdefault(sock, []).append(self)

    def _send(self, msgs):
        self.s.sendall(msgs)
        self.sent += len(msgs) // 2

    def selects(self, v):
        """Port 7 of the board: 1 RX, 2 TX (carrier for the others), 3 loop-back."""
        self._send(bytes((MSG_CONTROL, v)))

    def send(self, data):
        self._send(b"".join(bytes((MSG_DATA, b)) for b in data))

    def pace(self, baud):
        """Ask the medium to pace this station's characters (a host peer)."""
        self._send(bytes((MSG_PACE, baud // 300)))

    def _counts(self):
        """(received, delivered) as the medium counts them, None once it has let us go."""
        reply = _control(self.path, f"station {self.number}")
        if reply == "none":
            return None
        fields = dict(kv.split("=") for kv in reply.split())
        return int(fields["received"]), int(fields["delivered"])

    def _until(self, what, done):
        deadline = time.monotonic() + SETTLE_TIMEOUT
        while not done():
            assert time.monotonic() < deadline, f"station {self.number}: {what} after {SETTLE_TIMEOUT} s"
            time.sleep(0.002)

    def settle(self):
        """Returns once the medium has taken every message this station sent."""
        self._until("the medium did not take all it sent",
                    lambda: (self._counts() or (None,))[0] == self.sent)

    def close(self):
        """Leaves the medium; returns once the medium has let the station go."""
        self.s.close()
        _open[self.path].remove(self)
        self._until("the medium kept it after it left", lambda: self._counts() is None)

    def _pairs(self):
        """The whole messages received so far; a half message stays in buf."""
        usable = len(self.buf) & ~1
        pairs = [(self.buf[i], self.buf[i + 1]) for i in range(0, usable, 2)]
        self.buf = self.buf[usable:]
        self.got += len(pairs)
        return pairs

    def delivered(self):
        """Every message the medium has written to this station, once every
        station open on the medium has been taken in full."""
        for st in list(_open.get(self.path, ())):
            if st.s.fileno() != -1:          # (closed without close(): nothing to wait for)
                st.settle()
        owed = self._counts()[1]
        out = self._pairs()
        self.s.settimeout(SETTLE_TIMEOUT)
        while self.got < owed:
            chunk = self.s.recv(2 * (owed - self.got) - len(self.buf))
            assert chunk, "medium closed the connection"
            self.buf += chunk
            out += self._pairs()
        return out

    def drain(self):
        """(characters heard, last carrier) of what the medium has written to
        this station since the last read (carrier None: no change told)."""
        heard, carrier = bytearray(), None
        for kind, value in self.delivered():
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

    def sync_round(self):
        """One lock-step round (as a board's device model runs it): SYNC, then
        what the medium delivers up to its SYNC back."""
        self._send(bytes((MSG_SYNC, 0)))
        return self.read_msgs(MSG_SYNC)
