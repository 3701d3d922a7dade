"""The net/ stack on emulated boards through robocube_emu.radio_medium, and the host peer."""
import re
import struct
import time

import pytest

import threading

from netpeer import MediumTransport, Peer, Unreachable
from netpeer.auth import DEV_KEY, Auth
from netpeer.protocol import ACK, DATA, Frame, FrameDecoder, encode_frame, frame_type
from netpeer.soak import soak_message

from medium_station import MSG_PACE, Station, sealed


def soak_results(text):
    """{peer: (in order, duplicates, lost)} and (acknowledged, failed) from a SOAK console."""
    per = {int(m[0]): tuple(map(int, m[1:])) for m in re.findall(
        r"netnode: from (\d+): (\d+) in order, (\d+) duplicates, (\d+) lost", text)}
    sent = re.search(r"sent (\d+) acknowledged, (\d+) failed", text)
    return per, (int(sent[1]), int(sent[2])) if sent else None


def run_soak(air, stations, messages, timeout=90, **faults):
    air.start_medium(**faults)
    boards = [air.board(s, mode="soak", peers=stations, messages=messages, seed=s + 1,
                        linger_ms=20000) for s in stations]
    for b in boards:
        assert b.wait_for("netnode: done", timeout), b.text()
    return boards


def test_two_boards_deliver_everything(air):
    boards = run_soak(air, [0, 1], 6)
    for b, other in zip(boards, (1, 0)):
        per, sent = soak_results(b.text())
        assert sent == (6, 0), b.text()
        assert per[other] == (6, 0, 0), b.text()
        assert "crc errors 0" in b.text()
        assert "radio 19200 baud" in b.text()       # the counter/timer clocks channel A


def test_three_boards_share_the_channel(air):
    boards = run_soak(air, [0, 1, 2], 4)
    for b in boards:
        per, sent = soak_results(b.text())
        assert sent == (8, 0), b.text()
        assert all(v == (4, 0, 0) for v in per.values()) and len(per) == 2, b.text()
    stats = air.medium.stats()
    assert int(stats["transmissions"]) >= 3 * 8 * 2      # data + ACK per message


def test_faulty_medium_still_delivers_in_order(air):
    boards = run_soak(air, [0, 1], 6, timeout=120, seed=5, loss=0.2, corrupt=0.2, noise=0.2)
    for b, other in zip(boards, (1, 0)):
        per, sent = soak_results(b.text())
        assert sent == (6, 0), b.text()
        assert per[other] == (6, 0, 0), b.text()
    stats = air.medium.stats()
    assert int(stats["lost"]) > 0 and int(stats["corrupted"]) > 0
    text = "".join(b.text() for b in boards)
    retx = sum(int(x) for x in re.findall(r"retransmissions (\d+)", text))
    crc = sum(int(x) for x in re.findall(r"crc errors (\d+)", text))
    assert retx > 0 and crc > 0


# A host peer that speaks first to a fresh board: once failed 4 runs in 6
# (net/README.md, "Fixed bugs"); make net-interop repeats these two.
@pytest.mark.interop
def test_host_peer_and_board_both_ways(air):
    air.start_medium()
    board = air.board(1, mode="echo", linger_ms=60000)
    assert board.wait_for("station 1 up", 10), board.text()
    peer = Peer(MediumTransport(air.sock), 9)
    air.closers.append(peer.close)
    msg = bytes(range(200))                              # two fragments
    peer.send(1, 1, msg)                                 # host -> board, reliable
    got = peer.recv(1, timeout=10)                       # board -> host (its echo), reliable
    assert got == (1, msg)
    assert peer.stats["unreachable"] == 0


def test_host_peer_reports_unreachable_station(air):
    air.start_medium()
    peer = Peer(MediumTransport(air.sock), 9)
    air.closers.append(peer.close)
    t0 = time.monotonic()
    try:
        peer.send(4, 1, b"anyone?")
        raise AssertionError("no error for an absent station")
    except Unreachable:
        pass
    assert time.monotonic() - t0 < 40


def test_station_that_leaves_is_reported_and_others_go_on(air):
    air.start_medium()
    stations = [0, 1, 2]
    boards = [air.board(s, mode="soak", peers=stations, messages=2, seed=s + 1,
                        linger_ms=5000) for s in stations]
    assert boards[2].wait_for("station 2 up", 10)
    boards[2].stop()                                     # gone mid-transfer
    for b, other in ((boards[0], 1), (boards[1], 0)):
        assert b.wait_for("netnode: done", 120), b.text()
        per, sent = soak_results(b.text())
        assert per[other] == (2, 0, 0), b.text()         # the survivors still talk
        assert sent[1] >= 1, b.text()                    # sends to station 2 failed ...
        assert re.search(r"send \d+ to 2 failed \(-113\)", b.text()), b.text()  # ... as unreachable


def test_boards_go_on_when_the_medium_dies(air):
    air.start_medium()
    boards = [air.board(s, mode="soak", peers=[0, 1], messages=3, seed=s + 1, linger_ms=2000)
              for s in (0, 1)]
    for b in boards:
        assert b.wait_for("up, mode 1", 10), b.text()
    air.medium.stop()                                    # the air is gone mid-transfer
    for b in boards:
        assert b.wait_for("netnode: done", 60), b.text() # no board hangs in the lock step
        per, sent = soak_results(b.text())
        assert sent[0] + sent[1] == 3                    # every send came back


@pytest.mark.interop
def test_host_peer_cli_send_and_reply(air):
    import os
    import subprocess
    import sys
    air.start_medium()
    board = air.board(2, mode="echo", linger_ms=60000)
    assert board.wait_for("station 2 up", 10), board.text()
    tools = os.path.join(os.path.dirname(__file__), "..", "..", "..", "tools")
    r = subprocess.run([sys.executable, "-m", "netpeer", "--socket", air.sock, "--station", "9",
                        "--key", DEV_KEY.hex(), "--epoch", "3",
                        "send", "2", "1", "hello cube", "--wait-reply", "10"],
                       cwd=tools, capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "2: hello cube"


@pytest.mark.interop
def test_host_peer_and_board_with_fec_through_byte_errors(air):
    """FEC on both ends (reedsolo on the host, net/rs.c on the board) through
    10 % corrupted characters: a 2-fragment message each way, and the board
    reports the bytes it corrected."""
    air.start_medium(seed=3, byte_errors=0.1)
    board = air.board(1, mode="echo", fec=True, linger_ms=15000)
    assert board.wait_for("station 1 up, mode 2, fec", 10), board.text()
    peer = Peer(MediumTransport(air.sock), 9, fec=True)
    air.closers.append(peer.close)
    msg = bytes(range(250))
    peer.send(1, 1, msg)
    assert peer.recv(1, timeout=30) == (1, msg)
    assert peer.decoder.corrected > 0
    assert int(air.medium.stats()["corrupted"]) > 0
    assert board.wait_for("netnode: done", 60), board.text()
    corrected = re.search(r"fec: bytes corrected (\d+)", board.text())
    assert corrected and int(corrected[1]) > 0, board.text()


def test_a_burst_from_one_station_does_not_stop_the_board(air):
    """A raw station keys its transmitter for 300 back-to-back DATA frames to
    the board, frame 40 an echo request: the board cannot get a single ACK
    out while it lasts. Its transmit queue used to fill with those ACKs and
    drop the echo's DATA frame, whose retransmission timer then never ran:
    the link stayed busy for ever and every later send timed out (-110).
    Now the board gives the echo up as unreachable (the raw station never
    acknowledges) and answers the host peer that asks next."""
    air.start_medium()
    board = air.board(1, mode="echo", linger_ms=25000)
    assert board.wait_for("station 1 up", 10), board.text()
    raw = Station(air.sock, 5)
    air.closers.append(raw.s.close)
    raw.pace(19200)
    raw.selects(1)
    auth = Auth(DEV_KEY, 0)                              # the network's key: heard by the board
    burst = b"".join(
        encode_frame(sealed(auth, Frame(5, 1, frame_type(DATA, 0), i & 0xFF,
                                        bytes((1 if i == 40 else 3, 0x80)) +
                                        (b"echo me" if i == 40 else b"x" * 8))))
        for i in range(300))
    raw.selects(2)
    raw.send(burst)
    raw.selects(1)
    raw.read_msgs(MSG_PACE, timeout=120)                 # the medium played it (Pacing)
    raw.s.close()
    peer = Peer(MediumTransport(air.sock), 9)
    air.closers.append(peer.close)
    peer.send(1, 1, b"still there?")
    assert peer.recv(1, timeout=60) == (1, b"still there?"), board.text()
    assert board.wait_for("netnode: done", 180), board.text()
    text = board.text()
    assert "echo to 5 failed (-113)" in text, text       # given up, not stuck (-110)
    assert "(-110)" not in text, text
    replaced = re.search(r"acks replaced (\d+)", text)
    assert replaced and int(replaced[1]) > 0, text       # one queued ACK for the burst


def test_restarted_stations_are_heard_again(air):
    """Sequence numbers restart at 0 with a station. The board restarts and
    sends its first message (seq 0) to the host peer, which had taken seq 0
    from the board's previous boot; then the host peer restarts and sends
    seq 0 to the board, which had taken seq 0 from the peer's previous
    session. Each used to be acknowledged and dropped as a repeat."""
    air.start_medium()
    a = Peer(MediumTransport(air.sock), 9)
    air.closers.append(a.close)
    first = air.board(1, mode="soak", peers=[1, 9], messages=1, linger_ms=500)
    assert a.recv(2, timeout=60) == (1, soak_message(1, 0)), first.text()
    assert first.wait_for("netnode: done", 60), first.text()
    first.stop()
    second = air.board(1, mode="soak", peers=[1, 9], messages=1, linger_ms=30000)
    assert a.recv(2, timeout=60) == (1, soak_message(1, 0)), second.text()   # the new boot's
    a.send(1, 2, soak_message(9, 0))                    # the peer's only message: seq 0
    assert second.wait_for("netnode: done", 60), second.text()
    per, sent = soak_results(second.text())
    assert per[9] == (1, 0, 0) and sent == (1, 0), second.text()
    a.close()
    b = Peer(MediumTransport(air.sock), 9)              # the host peer restarted
    air.closers.append(b.close)
    assert b.session != a.session
    b.send(1, 1, b"after the restart")                  # seq 0 again
    assert b.recv(1, timeout=60) == (1, b"after the restart"), second.text()


# ---- authentication (net/auth.h): what a station without the key cannot do ----

class RawRadio:
    """A station on the medium that speaks raw frames (no link, no key of the
    network): it hears every frame on the air, may answer some (react(f) ->
    on-air bytes or None) and may send what it captured."""

    def __init__(self, sock, station, react=None):
        self.t = MediumTransport(sock)
        self.t.hello(station)
        self.react, self.frames, self.running = react, [], True
        self.thread = threading.Thread(target=self._run, daemon=True)
        self.thread.start()

    def _run(self):
        decoder = FrameDecoder()
        while self.running:
            data = self.t.read(0.2)
            if data is None:
                return
            for f in decoder.feed(data):
                self.frames.append(f)
                answer = self.react(f) if self.react else None
                if answer:
                    # Not from this thread: transmit waits for the medium's
                    # end-of-transmission word, which this thread reads.
                    threading.Thread(target=self.t.transmit, args=(answer + b"\x55",),
                                     daemon=True).start()

    def send(self, f):
        self.t.transmit(encode_frame(f) + b"\x55")

    def close(self):
        self.running = False
        self.thread.join(timeout=2)
        self.t.close()


def auth_counts(text):
    m = re.search(r"auth: epoch \d+, forged (\d+), replayed (\d+), malformed (\d+)", text)
    assert m, text
    return tuple(map(int, m.groups()))


def test_a_forged_data_frame_is_refused_and_counted(air):
    """A station without the key sends an echo request under station 2's
    address, sealed with another key: the board counts it as forged and
    delivers nothing (it would echo to station 2, which is not there, and
    report that). The host peer, with the key, is answered as before."""
    air.start_medium()
    board = air.board(1, mode="echo", linger_ms=4000)
    assert board.wait_for("station 1 up", 10), board.text()
    raw = RawRadio(air.sock, 5)
    air.closers.append(raw.close)
    raw.send(sealed(Auth(b"not the network!", 7),
                    Frame(2, 1, frame_type(DATA, 7), 0, bytes((1, 0x80)) + b"forged echo")))
    peer = Peer(MediumTransport(air.sock), 9)
    air.closers.append(peer.close)
    peer.send(1, 1, b"genuine")
    assert peer.recv(1, timeout=60) == (1, b"genuine"), board.text()
    assert board.wait_for("netnode: done", 60), board.text()
    text = board.text()
    assert "echo to 2" not in text, text
    assert "messages delivered 1," in text, text                # the peer's only
    assert not any(f.src == 1 and f.dst == 2 for f in raw.frames), text   # no ACK to 2
    assert auth_counts(text)[0] == 1, text


def test_a_forged_ack_does_not_make_the_sender_report_success(air):
    """The board sends a soak message to station 2, which is not there; a
    station without the key answers each of its DATA frames at once with an
    ACK under station 2's address, right seq and session, sealed with
    another key. The board must count them as forged and report the send as
    failed (unreachable), not acknowledged."""
    air.start_medium()
    fake = Auth(b"not the network!", 0)
    answered = []

    def ack(f):
        if f.src == 1 and f.dst == 2 and f.type & 3 == DATA:
            answered.append(f.seq)
            return encode_frame(sealed(fake, Frame(2, 1, frame_type(ACK, f.type >> 2), f.seq)))
        return None
    raw = RawRadio(air.sock, 2, react=ack)
    air.closers.append(raw.close)
    board = air.board(1, mode="soak", peers=[1, 2], messages=1, linger_ms=500)
    assert board.wait_for("netnode: done", 120), board.text()
    text = board.text()
    per, sent = soak_results(text)
    assert sent == (0, 1), text
    # Every answer the board heard intact is counted; one may collide with a
    # retransmission (the raw station answers in wall time, without listening).
    assert len(answered) >= 2 and 1 <= auth_counts(text)[0] <= len(answered), (answered, text)


def test_a_replayed_data_frame_is_refused_and_counted(air):
    """A station without the key captures the host peer's first echo request
    (seq 0) and plays it again after the peer's second (seq 1) was taken.
    The link alone would take it as a new message (its seq differs from the
    last); the board must refuse it as a replay: counted, not echoed."""
    air.start_medium()
    board = air.board(1, mode="echo", linger_ms=6000)
    assert board.wait_for("station 1 up", 10), board.text()
    raw = RawRadio(air.sock, 5)
    air.closers.append(raw.close)
    peer = Peer(MediumTransport(air.sock), 9)
    air.closers.append(peer.close)
    peer.send(1, 1, b"first")
    assert peer.recv(1, timeout=60) == (1, b"first"), board.text()
    peer.send(1, 1, b"second")
    assert peer.recv(1, timeout=60) == (1, b"second"), board.text()
    captured = [f for f in raw.frames if f.src == 9 and f.dst == 1 and f.type & 3 == DATA]
    assert captured and captured[0].seq == 0, raw.frames
    # After the peer's ACK of the second echo, on a quiet channel: the raw
    # station does not listen before it talks, and a collision would only
    # make a CRC error of the replay.
    deadline = time.monotonic() + 30
    while sum(f.src == 9 and f.dst == 1 and f.type & 3 == ACK for f in raw.frames) < 2:
        assert time.monotonic() < deadline, raw.frames
        time.sleep(0.05)
    time.sleep(0.5)
    raw.send(captured[0])
    assert peer.recv(1, timeout=5) is None, board.text()        # not echoed again
    assert board.wait_for("netnode: done", 60), board.text()
    text = board.text()
    assert auth_counts(text)[1] == 1, text
    assert "messages delivered 2," in text, text
