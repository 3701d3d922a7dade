"""robocube_emu.radio_medium alone, with raw stations: carrier, hearing rules,
collisions, deterministic faults, stations that leave."""
from medium_station import MSG_PACE, Station


def test_hearing_carrier_and_loopback(medium_factory):
    m = medium_factory()
    a, b, c = (Station(m.sock, n) for n in (1, 2, 3))
    b.selects(1)                                 # RX
    c.selects(3)                                 # loop-back test mode: hears nothing
    b.settle(), c.settle()                       # (sockets are served independently)
    a.selects(2)                                 # TX: carrier for the others
    a.send(b"hello")
    heard_b, carrier_b = b.drain()
    heard_c, _ = c.drain()
    assert heard_b == b"hello" and carrier_b == 1
    assert heard_c == b""
    a.selects(1)
    assert b.drain()[1] == 0


def test_collision_garbles_overlap(medium_factory):
    m = medium_factory()
    a, b, r = (Station(m.sock, n) for n in (1, 2, 3))
    r.selects(1)
    b.selects(2)                                 # both keyed: they collide
    r.settle(), b.settle()
    a.selects(2)
    a.send(b"A" * 50)
    heard, _ = r.drain()
    assert len(heard) == 50 and heard != b"A" * 50
    assert int(m.stats()["collisions"]) >= 1


def run_faulty(medium_factory, seed):
    m = medium_factory(seed=seed, loss=0.3, corrupt=0.3, noise=0.3)
    a, r = Station(m.sock, 1), Station(m.sock, 2)
    r.selects(1)
    r.settle()
    out = []
    for k in range(20):
        a.selects(2)
        a.send(bytes(range(k, k + 20)))
        a.selects(1)
        out.append(r.drain()[0])
    out.append(r.drain()[0])
    return b"|".join(out), m.stats()


def test_faults_are_deterministic_for_a_seed(medium_factory):
    one, s1 = run_faulty(medium_factory, 7)
    two, s2 = run_faulty(medium_factory, 7)
    other, _ = run_faulty(medium_factory, 8)
    assert one.replace(b"|", b"") == two.replace(b"|", b"")
    assert {k: s1[k] for k in ("lost", "corrupted", "noise_bursts")} == \
           {k: s2[k] for k in ("lost", "corrupted", "noise_bursts")}
    assert int(s1["lost"]) > 0 and int(s1["corrupted"]) > 0 and int(s1["noise_bursts"]) > 0
    assert one.replace(b"|", b"") != other.replace(b"|", b"")


def test_out_of_range_and_leaving_station(medium_factory):
    m = medium_factory()
    a, b = Station(m.sock, 1), Station(m.sock, 2)
    b.selects(1)
    b.settle()
    assert m.control("range 1 2 off") == "ok"
    a.selects(2)
    a.send(b"far")
    heard, carrier = b.drain()
    assert heard == b"" and not carrier
    assert m.control("range 1 2 on") == "ok"
    assert b.drain()[1] == 1                     # in range again: its carrier
    a.close()                                    # leaves while keyed
    assert b.drain()[1] == 0                     # carrier gone, medium alive
    c = Station(m.sock, 3)
    c.selects(2)
    c.send(b"ok")
    assert b.drain()[0] == b"ok"
    assert m.control("bogus") .startswith("error")


def test_host_peer_is_paced_in_the_boards_virtual_time(medium_factory):
    """A paced station's transmission lasts its air time in lock-step rounds
    (the fix of net/README.md "Fixed bugs"), not in wall time."""
    m = medium_factory()
    board, peer = Station(m.sock, 1), Station(m.sock, 9)
    board.selects(1)
    peer.pace(19200)                             # pace me at 19200 baud
    board.sync_round()                           # the board joins the lock step
    frame = bytes(range(20))                     # 20 x 0.52 ms = 10.4 ms = 21 rounds
    peer.selects(2)
    peer.send(frame)
    peer.selects(1)
    peer.settle()                                # all of it queued at the medium
    heard, heard_at, carrier_rounds = bytearray(), [], set()
    carrier = 0
    for rnd in range(1, 41):
        for kind, value in board.sync_round():
            if kind == 0:
                heard.append(value)
                heard_at.append(rnd)
            elif kind == 1:
                carrier = value
        if carrier:
            carrier_rounds.add(rnd)
    assert bytes(heard) == frame
    # character k reaches the air (k + 1) character times after the start
    assert heard_at == [-(-(k + 1) * 520833 // 500000) for k in range(20)], heard_at
    assert 20 <= len(carrier_rounds) <= 22, sorted(carrier_rounds)
    assert peer.read_msgs(MSG_PACE)[-1] == (MSG_PACE, 1)    # "over, paced"


def test_host_peer_alone_is_not_paced(medium_factory):
    m = medium_factory()
    listener, peer = Station(m.sock, 1), Station(m.sock, 9)
    listener.selects(1)
    peer.pace(19200)
    listener.settle(), peer.settle()
    peer.selects(2)
    peer.send(b"at once")
    peer.selects(1)
    assert listener.drain()[0] == b"at once"
    assert peer.read_msgs(MSG_PACE)[-1] == (MSG_PACE, 0)    # "over, not paced": pace yourself
