"""The link protocol of net/link.h on the host: reliable channel, datagrams, broadcast."""
import queue
import random
import threading

from .protocol import (ACK, BROADCAST, DATA, DGRAM, PACKET_DATA_MAX, PORTS, FecDecoder, Frame,
                       FrameDecoder, Reassembly, encode_frame, encode_frame_fec, fragments)

RTO, RTO_MAX, MAX_RETRIES = 0.25, 1.0, 8
MAX_STATIONS = 16


class Unreachable(Exception):
    """A reliable send got no acknowledgement after every retry."""


class Peer:
    def __init__(self, transport, station, seed=None, fec=False):
        """fec: Reed-Solomon frames (net/fec.h), as boards started with NET_FEC."""
        if not 0 <= station < MAX_STATIONS:
            raise ValueError(f"station {station}: 0..{MAX_STATIONS - 1}")
        self.t = transport
        self.station = station
        self.rng = random.Random(seed if seed is not None else station)
        self.decoder = FecDecoder() if fec else FrameDecoder()
        self.encode = encode_frame_fec if fec else encode_frame
        self.tx_seq = [0] * MAX_STATIONS
        self.rx_last = [None] * MAX_STATIONS
        self.reasm = [Reassembly() for _ in range(MAX_STATIONS)]
        self.ports = [queue.Queue() for _ in range(PORTS)]
        self.acks = queue.Queue()
        self.tx_lock = threading.Lock()     # one transmission at a time
        self.send_lock = threading.Lock()   # one reliable send at a time
        self.stats = dict(frames_sent=0, frames_received=0, retransmissions=0,
                          duplicates=0, delivered=0, unreachable=0)
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
        data = self.encode(frame) + b"\x55"
        with self.tx_lock:
            # Listen before talk, as net/mac.c (initial wait for data frames,
            # except a fragment right after its predecessor's ACK: link_is_burst).
            if not is_ack and not burst:
                self.t.clock.sleep(self.rng.randrange(0, 5) * 0.003)
            for attempt in range(12):
                if not self.t.carrier:
                    break
                self.t.clock.sleep((1 + self.rng.randrange(4 << min(attempt, 4))) * 0.003)
            self.t.transmit(data)
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
        if f.type == ACK and f.dst == self.station:
            self.acks.put((f.src, f.seq))
            self.t.clock.notify()
        elif f.type == DATA and f.dst == self.station:
            threading.Thread(target=self._transmit,
                             args=(Frame(self.station, f.src, ACK, f.seq), True),
                             daemon=True).start()
            if self.rx_last[f.src] == f.seq:
                self.stats["duplicates"] += 1
                return
            self.rx_last[f.src] = f.seq
            self._deliver(f.src, f.payload, self.reasm[f.src])
        elif f.type == DGRAM:
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
            self._transmit(Frame(self.station, dst, DGRAM, 0, fragments(data, port)[0]))
            return
        if not 0 <= dst < MAX_STATIONS or dst == self.station:
            raise ValueError(f"destination {dst}")
        with self.send_lock:
            for i, payload in enumerate(fragments(data, port)):
                self._send_fragment(dst, payload, burst=i > 0)

    def _send_fragment(self, dst, payload, burst=False):
        seq = self.tx_seq[dst]
        rto = RTO
        for attempt in range(MAX_RETRIES + 1):
            if attempt:
                self.stats["retransmissions"] += 1
            self._transmit(Frame(self.station, dst, DATA, seq, payload),
                           burst=burst and attempt == 0)
            # The timeout counts in the boards' time when they keep one
            # (transport.PeerClock): a slow host must not make us give up.
            deadline = self.t.clock.now() + rto * (1 + self.rng.random() / 4)
            while self.t.clock.wait_until(deadline, lambda: not self.acks.empty()):
                src, aseq = self.acks.get_nowait()
                if src == dst and aseq == seq:
                    self.tx_seq[dst] = (seq + 1) & 0xFF
                    return
            rto = min(rto * 2, RTO_MAX)
        self.tx_seq[dst] = (seq + 1) & 0xFF
        self.stats["unreachable"] += 1
        raise Unreachable(f"station {dst} did not acknowledge after {MAX_RETRIES} retries")

    def recv(self, port, timeout=None):
        """(src, message) from port, or None after timeout seconds."""
        try:
            return self.ports[port].get(timeout=timeout)
        except queue.Empty:
            return None
