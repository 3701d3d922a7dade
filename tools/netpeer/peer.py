"""The link protocol of net/link.h on the host: reliable channel, datagrams, broadcast."""
import os
import queue
import random
import threading

from . import auth as netauth
from .protocol import (ACK, BROADCAST, DATA, DGRAM, PACKET_DATA_MAX, PAYLOAD_MAX, PORTS, SESSIONS, FecDecoder,
                       Frame, FrameDecoder, Reassembly, encode_frame, encode_frame_fec,
                       frame_kind, frame_session, frame_type, fragments)

RTO, RTO_MAX, MAX_RETRIES = 0.25, 1.0, 8
MAX_STATIONS = 16
# Listen before talk (net/mac.h): slot, contention window, attempts.
SLOT, CW_MIN, CW_MAX, MAC_ATTEMPTS = 0.003, 4, 64, 12

# The last authentication epoch each station number used in this process: a
# Peer started again for the same station takes the next one, so its frames
# are taken at once by receivers that heard the previous Peer (net/auth.h,
# "Restarts"), and its session, epoch % SESSIONS, differs from the previous
# one's (net/link.h, "Sessions"). The first is random in the lower half of
# the epochs, as a new host process is a new boot, and leaves room to grow;
# a host process started again may draw a lower epoch than its previous one
# and then is refused by boards that heard that one until they restart
# (pass epoch= from a counter of your own to avoid it).
_last_epoch = {}
_session_lock = threading.Lock()


def _next_epoch(station):
    with _session_lock:
        last = _last_epoch.get(station)
        e = int.from_bytes(os.urandom(2), "big") % ((netauth.EPOCH_MAX + 1) // 2) \
            if last is None else (last + 1) % (netauth.EPOCH_MAX + 1)
        _last_epoch[station] = e
        return e


class Unreachable(Exception):
    """A reliable send got no acknowledgement after every retry."""


class Peer:
    def __init__(self, transport, station, seed=None, fec=False, session=None, key=None,
                 epoch=None, auth=True):
        """fec: Reed-Solomon frames (net/fec.h), as boards started with NET_FEC.
        key: the network key (16 bytes; default the public development key
        netpeer.auth.DEV_KEY, as the boards'); epoch: this peer's
        authentication epoch (0..auth.EPOCH_MAX), by default one above the
        last Peer of this station in this process; session: the link's
        session (0..SESSIONS-1), by default epoch % SESSIONS. auth=False: no
        authentication, as boards started without it (only to measure it)."""
        if not 0 <= station < MAX_STATIONS:
            raise ValueError(f"station {station}: 0..{MAX_STATIONS - 1}")
        if session is not None and not 0 <= session < SESSIONS:
            raise ValueError(f"session {session}: 0..{SESSIONS - 1}")
        if epoch is not None and not 0 <= epoch <= netauth.EPOCH_MAX:
            raise ValueError(f"epoch {epoch}: 0..{netauth.EPOCH_MAX}")
        self.t = transport
        self.station = station
        self.epoch = _next_epoch(station) if epoch is None else epoch
        with _session_lock:
            _last_epoch[station] = self.epoch
        self.session = self.epoch % SESSIONS if session is None else session
        # Raises ValueError for a key of another length.
        self.auth = netauth.Auth(netauth.DEV_KEY if key is None else key, self.epoch) \
            if auth else None
        self.rng = random.Random(seed if seed is not None else station)
        self.decoder = FecDecoder() if fec else FrameDecoder()
        self.encode = encode_frame_fec if fec else encode_frame
        self.tx_seq = [0] * MAX_STATIONS
        self.rx_last = [None] * MAX_STATIONS
        self.rx_session = [None] * MAX_STATIONS
        self.reasm = [Reassembly() for _ in range(MAX_STATIONS)]
        self.ports = [queue.Queue() for _ in range(PORTS)]
        # The one ACK a reliable send waits for: (station, seq), our session;
        # any other ACK is stale and dropped when it arrives (net/link.c).
        self.ack_lock = threading.Lock()
        self.awaiting = None
        self.acked = False
        self.tx_lock = threading.Lock()     # one transmission at a time
        self.send_lock = threading.Lock()   # one reliable send at a time
        self.stats = dict(frames_sent=0, frames_received=0, retransmissions=0,
                          duplicates=0, delivered=0, unreachable=0, stale_acks=0,
                          new_sessions=0, forged=0, replayed=0, malformed=0,
                          seal_failed=0)
        self.running = True
        self.t.hello(station)
        self.reader = threading.Thread(target=self._read_loop, daemon=True)
        self.reader.start()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def close(self):
        self.running = False
        self.reader.join(timeout=2)   # its reads time out in 0.2 s; a closed port raises
        self.t.close()

    # -- air ------------------------------------------------------------------
    def _transmit(self, frame, is_ack=False, burst=False):
        with self.tx_lock:
            # Listen before talk, as net/mac.c (initial wait for data frames,
            # except a fragment right after its predecessor's ACK: link_is_burst).
            if not is_ack and not burst:
                self.t.clock.sleep(self.rng.randrange(0, CW_MIN + 1) * SLOT)
            for attempt in range(MAC_ATTEMPTS):
                if not self.t.carrier:
                    break
                self.t.clock.sleep((1 + self.rng.randrange(min(CW_MIN << attempt, CW_MAX))) * SLOT)
            # Sealed last, under tx_lock: the frames reach the air in the
            # order of their counters, and each transmission (a
            # retransmission too) has a fresh one (net/auth.h).
            if self.auth is not None:
                try:
                    frame = Frame(frame.src, frame.dst, frame.type, frame.seq,
                                  self.auth.seal(bytes((frame.src, frame.dst, frame.type,
                                                        frame.seq)), frame.payload))
                except netauth.AuthError:
                    self.stats["seal_failed"] += 1
                    return
            self.t.transmit(self.encode(frame) + b"\x55")
            self.stats["frames_sent"] += 1

    def _read_loop(self):
        while self.running:
            data = self.t.read(0.2)
            if data is None:
                break
            for f in self.decoder.feed(data):
                self._receive(f)

    def _receive(self, f):
        if f.dst not in (self.station, BROADCAST) or f.src >= MAX_STATIONS or f.src == self.station:
            return
        self.stats["frames_received"] += 1
        if self.auth is not None:
            # Before the link: only frames sealed with the key and a counter
            # above the source's last are seen by it (net/net.c, net_open).
            try:
                f = Frame(f.src, f.dst, f.type, f.seq,
                          self.auth.open(bytes((f.src, f.dst, f.type, f.seq)), f.payload))
            except netauth.Forged:
                self.stats["forged"] += 1
                return
            except netauth.Replayed:
                self.stats["replayed"] += 1
                return
            except netauth.Malformed:
                self.stats["malformed"] += 1
                return
        elif len(f.payload) > PAYLOAD_MAX:
            return                          # a sealed frame: not for a peer without auth
        kind, session = frame_kind(f.type), frame_session(f.type)
        if kind == ACK and f.dst == self.station:
            with self.ack_lock:
                if self.awaiting == (f.src, f.seq) and session == self.session:
                    self.acked = True
                else:
                    self.stats["stale_acks"] += 1
            self.t.clock.notify()
        elif kind == DATA and f.dst == self.station:
            if self.rx_last[f.src] is not None and self.rx_session[f.src] != session:
                # The sender restarted: its numbers begin again (net/link.h, "Sessions").
                self.rx_last[f.src] = None
                self.reasm[f.src] = Reassembly()
                self.stats["new_sessions"] += 1
            threading.Thread(target=self._transmit,
                             args=(Frame(self.station, f.src, frame_type(ACK, session), f.seq),
                                   True),
                             daemon=True).start()
            if self.rx_last[f.src] == f.seq:
                self.stats["duplicates"] += 1
                return
            self.rx_last[f.src] = f.seq
            self.rx_session[f.src] = session
            self._deliver(f.src, f.payload, self.reasm[f.src])
        elif kind == DGRAM:
            self._deliver(f.src, f.payload, Reassembly())

    def _deliver(self, src, payload, reasm):
        try:
            done = reasm.add(payload)
        except ValueError:
            return
        if done:
            self.stats["delivered"] += 1
            self.ports[done[0]].put((src, done[1]))

    # -- API ------------------------------------------------------------------
    def send(self, dst, port, data, reliable=True):
        """Reliable (unicast): returns when dst acknowledged every fragment,
        raises Unreachable otherwise. Datagram/broadcast: at most
        PACKET_DATA_MAX bytes, sent once."""
        data = bytes(data)
        if not reliable or dst == BROADCAST:
            if len(data) > PACKET_DATA_MAX:
                raise ValueError(f"datagram of {len(data)} bytes > {PACKET_DATA_MAX}")
            self._transmit(Frame(self.station, dst, frame_type(DGRAM, self.session), 0,
                                 fragments(data, port)[0]))
            return
        if not 0 <= dst < MAX_STATIONS or dst == self.station:
            raise ValueError(f"destination {dst}")
        with self.send_lock:
            for i, payload in enumerate(fragments(data, port)):
                self._send_fragment(dst, payload, burst=i > 0)

    def _send_fragment(self, dst, payload, burst=False):
        seq = self.tx_seq[dst]
        rto = RTO
        with self.ack_lock:
            self.awaiting, self.acked = (dst, seq), False
        try:
            for attempt in range(MAX_RETRIES + 1):
                if attempt:
                    self.stats["retransmissions"] += 1
                self._transmit(Frame(self.station, dst, frame_type(DATA, self.session), seq,
                                     payload), burst=burst and attempt == 0)
                # The timeout counts in the boards' time when they keep one
                # (transport.PeerClock): a slow host must not make us give up.
                deadline = self.t.clock.now() + rto * (1 + self.rng.random() / 4)
                if self.t.clock.wait_until(deadline, lambda: self.acked):
                    self.tx_seq[dst] = (seq + 1) & 0xFF
                    return
                rto = min(rto * 2, RTO_MAX)
        finally:
            with self.ack_lock:
                self.awaiting = None
        self.tx_seq[dst] = (seq + 1) & 0xFF
        self.stats["unreachable"] += 1
        raise Unreachable(f"station {dst} did not acknowledge after {MAX_RETRIES} retries")

    def recv(self, port, timeout=None):
        """(src, message) from port, or None after timeout seconds."""
        if not 0 <= port < PORTS:
            raise ValueError(f"port {port}: 0..{PORTS - 1}")
        try:
            return self.ports[port].get(timeout=timeout)
        except queue.Empty:
            return None
