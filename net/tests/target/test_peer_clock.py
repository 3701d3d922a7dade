"""A host peer's timers run in the boards' virtual time (robocube_emu.radio_medium,
"Clock"; net/README.md, "Fixed bugs"): the medium's 05 k messages, the
PeerClock that counts them, and a peer that waits for a slow board without
retransmitting."""
import threading
import time

import pytest

from medium_station import MSG_CLOCK, MSG_DATA, Station, sealed
from netpeer.auth import DEV_KEY, Auth
from netpeer import MediumTransport, Peer                      # tools/ (conftest.py)
from netpeer.protocol import (ACK, Frame, FrameDecoder, encode_frame, frame_session,
                              frame_type)
from netpeer.transport import PeerClock


def test_medium_tells_paced_stations_the_boards_time(medium_factory):
    medium = medium_factory()
    board, peer, plain = (Station(medium.sock, n) for n in (1, 9, 2))
    peer.pace(19200)
    peer.settle()
    for _ in range(7):                               # 7 rounds of 500 us = 350 x 10 us
        board.sync_round()
    told = [v for k, v in peer.delivered() if k == MSG_CLOCK]
    assert told == [50] * 7
    board.close()                                    # the last board leaves the lock step
    assert (MSG_CLOCK, 0) in peer.delivered()
    # a station that did not ask to be paced keeps no clock
    assert all(k != MSG_CLOCK for k, _ in plain.delivered())


def test_clock_counts_virtual_time_only_while_told():
    c = PeerClock()
    t0 = c.now()
    time.sleep(0.05)
    assert c.now() >= t0 + 0.05                      # wall time before any 05 k
    c.advance(0.001)
    v = c.now()
    time.sleep(0.1)
    assert c.now() == v                              # boards slow: no time passes
    c.advance(0.002)
    assert c.now() == pytest.approx(v + 0.002)
    c.to_wall()
    w = c.now()
    assert w == pytest.approx(v + 0.002, abs=1e-3)   # continuous at the switch
    time.sleep(0.05)
    assert c.now() >= w + 0.05


def test_clock_falls_back_to_wall_time_when_the_boards_stall():
    c = PeerClock()
    c.STALL = 0.1
    c.advance(0.001)
    start = time.monotonic()
    assert not c.wait_until(c.now() + 0.2)           # returns although no tick comes
    assert 0.25 <= time.monotonic() - start < 10.0
    stalled = c.now()
    c.advance(0.001)                                 # a late tick does not go back
    assert c.now() >= stalled


def test_wait_until_returns_when_the_predicate_holds():
    c = PeerClock()
    c.advance(0.001)
    flag = []
    threading.Timer(0.1, lambda: (flag.append(1), c.notify())).start()
    assert c.wait_until(c.now() + 1.0, lambda: bool(flag))


class SlowBoard:
    """A station in lock step that runs ROUNDS_PER_S rounds a second (a board
    on a loaded host: far slower than real time) and acknowledges each DATA
    frame ACK_ROUNDS rounds after it heard it."""

    def __init__(self, path, station, rounds_per_s, ack_rounds):
        self.radio = Station(path, station)
        self.radio.selects(1)                            # RX
        self.station, self.rate, self.ack_rounds = station, rounds_per_s, ack_rounds
        self.decoder, self.heard, self.running = FrameDecoder(), [], True
        self.auth = Auth(DEV_KEY, 0)                     # seals its ACKs as a board would
        self.thread = threading.Thread(target=self.run, daemon=True)
        self.thread.start()

    def run(self):
        due, rnd = [], 0
        while self.running:
            try:
                round_msgs = self.radio.sync_round()
            except (OSError, AssertionError):            # stopped, or the medium left
                return
            rnd += 1
            data = bytes(v for k, v in round_msgs if k == MSG_DATA)
            for f in self.decoder.feed(data):
                if f.dst == self.station:
                    self.heard.append(rnd)
                    due.append((rnd + self.ack_rounds, f))
            for when, f in [d for d in due if d[0] <= rnd]:
                due.remove((when, f))
                self.radio.selects(2)                    # TX
                ack = Frame(self.station, f.src, frame_type(ACK, frame_session(f.type)), f.seq)
                self.radio.send(encode_frame(sealed(self.auth, ack)) + b"\x55")
                self.radio.selects(1)
            time.sleep(1 / self.rate)

    def stop(self):
        self.running = False
        self.thread.join(timeout=5)
        self.radio.s.close()


def test_peer_waits_for_a_slow_board_in_the_boards_time(medium_factory):
    """The board answers 20 rounds (10 ms of its time) after the frame, but
    at 40 rounds a second that is half a second of wall time, longer than the
    peer's first retransmission timeout (0.25-0.31 s). Timed in wall time the
    peer retransmitted; timed in the boards' time it must not."""
    medium = medium_factory()
    board = SlowBoard(medium.sock, 1, rounds_per_s=40, ack_rounds=20)
    try:
        with Peer(MediumTransport(medium.sock), 9) as peer:
            start = time.monotonic()
            peer.send(1, 1, b"slow but prompt")
            took = time.monotonic() - start
            assert peer.stats["retransmissions"] == 0, (peer.stats, took)
            assert took > 0.4                        # it really was slow in wall time
            assert len(board.heard) == 1
    finally:
        board.stop()
