"""The host peer on its own: its ACK matching (on a loop-back transport whose
clock runs fast) and its command line (on a medium without boards)."""
import os
import queue
import subprocess
import sys
import threading
import time

import pytest

from medium_station import sealed
from netpeer import Peer, Unreachable
from netpeer.auth import DEV_KEY, Auth
from netpeer.protocol import ACK, DATA, Frame, FrameDecoder, encode_frame, frame_type
from netpeer.transport import PeerClock

TOOLS = os.path.join(os.path.dirname(__file__), "..", "..", "..", "tools")


class LoopTransport:
    """Air for one peer: the test puts the bytes it hears; what it transmits
    is kept. Its clock is virtual and runs 10 times faster than the wall
    clock, so a send that gives up after ~9 s takes ~1 s."""

    carrier = False

    def __init__(self):
        self.clock = PeerClock()
        self.inbox = queue.Queue()
        self.sent = []
        self.closed = False
        threading.Thread(target=self._tick, daemon=True).start()

    def _tick(self):
        while not self.closed:
            self.clock.advance(0.01)
            time.sleep(0.001)

    def hello(self, station):
        pass

    def transmit(self, data):
        self.sent.append(data)

    def read(self, timeout):
        if self.closed:
            return None
        try:
            return self.inbox.get(timeout=timeout)
        except queue.Empty:
            return b""

    def close(self):
        self.closed = True


def air(f, auth):
    """The on-air bytes of f sealed by auth (the station that sends it)."""
    return encode_frame(sealed(auth, f))


def wait(predicate, seconds=5):
    end = time.monotonic() + seconds
    while not predicate():
        assert time.monotonic() < end, "timed out"
        time.sleep(0.01)


def test_an_ack_nobody_waited_for_does_not_complete_a_later_send():
    """An ACK that arrives while no send waits for it (here: from station 4,
    for the very seq and session the next send to 4 will use) is stale: it
    is dropped, and a send to station 4, which is not there, is Unreachable.
    The peer used to keep every ACK in a queue and take this one as the
    answer to that send."""
    t = LoopTransport()
    with Peer(t, 9) as peer:
        t.inbox.put(air(Frame(4, 9, frame_type(ACK, peer.session), 0), Auth(DEV_KEY, 0)))
        wait(lambda: peer.stats["frames_received"] == 1)
        assert peer.stats["stale_acks"] == 1
        with pytest.raises(Unreachable):
            peer.send(4, 1, b"anyone?")
        sent = FrameDecoder().feed(b"".join(t.sent))
        assert len(sent) == 9 and all(f.type == frame_type(DATA, peer.session) for f in sent)


def test_only_the_ack_for_the_outstanding_frame_counts():
    """Right station, seq and session: an ACK with any one of them wrong is
    stale; the right one completes the send at once."""
    t = LoopTransport()
    with Peer(t, 9, session=5) as peer:
        done = []
        threading.Thread(target=lambda: done.append(peer.send(1, 1, b"hi")), daemon=True).start()
        wait(lambda: len(t.sent) >= 1)
        one, two = Auth(DEV_KEY, 0), Auth(DEV_KEY, 0)
        for f, a in ((Frame(2, 9, frame_type(ACK, 5), 0), two),      # another station
                     (Frame(1, 9, frame_type(ACK, 5), 1), one),      # another seq
                     (Frame(1, 9, frame_type(ACK, 6), 0), one)):     # another session
            t.inbox.put(air(f, a))
        wait(lambda: peer.stats["stale_acks"] == 3)
        assert not done
        t.inbox.put(air(Frame(1, 9, frame_type(ACK, 5), 0), one))
        wait(lambda: done == [None])
        assert peer.stats["unreachable"] == 0


def test_a_restarted_sender_is_heard_again():
    """Station 1 sends seq 0, restarts (another session) and sends seq 0
    again: the second message is delivered, not dropped as a repeat."""
    t = LoopTransport()
    with Peer(t, 9) as peer:
        for session, text in ((3, b"first boot"), (4, b"second boot")):
            t.inbox.put(air(Frame(1, 9, frame_type(DATA, session), 0, bytes((1, 0x80)) + text),
                            Auth(DEV_KEY, session)))
            assert peer.recv(1, timeout=5) == (1, text)
        assert peer.stats["duplicates"] == 0 and peer.stats["new_sessions"] == 1
        acks = [f for f in FrameDecoder().feed(b"".join(t.sent))]
        assert [(f.dst, f.type, f.seq) for f in acks] == [
            (1, frame_type(ACK, 3), 0), (1, frame_type(ACK, 4), 0)]


def test_forged_and_replayed_frames_are_refused_and_counted():
    """A DATA frame sealed with another key is forged: no ACK, nothing
    delivered; a good frame is taken once and its copy, re-sent as captured,
    is refused as a replay (no second delivery, no ACK for it)."""
    t = LoopTransport()
    with Peer(t, 9) as peer:
        forged = air(Frame(1, 9, frame_type(DATA, 3), 0, bytes((1, 0x80)) + b"forged"),
                     Auth(b"not the network!", 3))
        t.inbox.put(forged)
        wait(lambda: peer.stats["forged"] == 1)
        assert peer.recv(1, timeout=0.2) is None and t.sent == []
        good = air(Frame(1, 9, frame_type(DATA, 3), 0, bytes((1, 0x80)) + b"real"),
                   Auth(DEV_KEY, 3))
        t.inbox.put(good)
        assert peer.recv(1, timeout=5) == (1, b"real")
        wait(lambda: len(t.sent) == 1)                   # its ACK
        t.inbox.put(good)                                # captured and played again
        wait(lambda: peer.stats["replayed"] == 1)
        assert peer.recv(1, timeout=0.2) is None
        assert len(t.sent) == 1 and peer.stats["duplicates"] == 0


def test_a_forged_ack_does_not_complete_a_send():
    """An ACK with the right station, seq and session but not sealed with
    the key does not make the send succeed: it ends Unreachable."""
    t = LoopTransport()
    with Peer(t, 9) as peer:
        errors = []

        def send():
            try:
                peer.send(1, 1, b"hi")
            except Unreachable as e:
                errors.append(e)
        th = threading.Thread(target=send, daemon=True)
        th.start()
        wait(lambda: len(t.sent) >= 1)
        t.inbox.put(air(Frame(1, 9, frame_type(ACK, peer.session), 0), Auth(b"x" * 16, 0)))
        wait(lambda: peer.stats["forged"] == 1)
        th.join(timeout=30)
        assert len(errors) == 1 and peer.stats["unreachable"] == 1


BAD_ARGUMENTS = [
    ["listen", "-1"],                          # listened on port 7 (Python's ports[-1])
    ["listen", "8"],
    ["listen", "x"],
    ["listen", "1", "--count", "-1"],
    ["listen", "1", "--timeout", "0"],
    ["listen", "1", "--timeout", "nan"],
    ["send", "1", "9", "hi"],                  # a traceback from fragments()
    ["send", "16", "1", "hi"],
    ["send", "9", "1", "hi"],                  # to itself: a traceback from Peer.send
    ["send", "1", "1", "x" * 513],
    ["send", "1", "1", "x" * 127, "--datagram"],
    ["send", "1", "1", "hi", "--wait-reply", "-1"],
    ["send", "1"],
    ["fly"],
    [],
    ["--key", "00" * 15, "listen", "1"],     # 15 bytes
    ["--key", "zz" * 16, "listen", "1"],
    ["--epoch", "4096", "listen", "1"],
    ["--epoch", "-1", "listen", "1"],
]


def test_cli_refuses_bad_arguments_with_one_usage_line(medium_factory):
    """Every bad argument: exit 2 and one line on stderr that names the
    problem and gives the usage; no traceback, no listening, no sending. On
    a live medium, so an argument that slipped through would start a peer
    (and this would time out or print a traceback)."""
    medium = medium_factory()
    cases = [["--socket", medium.sock, "--station", "9"] + a for a in BAD_ARGUMENTS]
    cases += [["--socket", medium.sock, "--station", "16", "listen", "1"],   # a traceback from Peer
              ["--socket", medium.sock, "--station", "9", "--baud", "1000", "listen", "1"],
              ["--station", "9", "listen", "1"]]
    for args in cases:
        try:
            r = subprocess.run([sys.executable, "-m", "netpeer"] + args, cwd=TOOLS,
                               capture_output=True, text=True, timeout=10)
        except subprocess.TimeoutExpired:
            raise AssertionError(f"{args}: accepted (it ran on)") from None
        lines = r.stderr.splitlines()
        assert r.returncode == 2 and len(lines) == 1, (args, r.returncode, r.stderr)
        assert lines[0].startswith("netpeer: ") and "usage: netpeer" in lines[0], (args, r.stderr)
        assert r.stdout == "", (args, r.stdout)
