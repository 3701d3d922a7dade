#!/usr/bin/env python3
"""The air between the emulated RoboCubes: a shared half-duplex radio channel.

Every board (qemu -M robocube with -global mc68681-duart.radio-medium=on, its
DUART channel A chardev connected to SOCKET) and every host peer
(tools/netpeer) joins by connecting to the Unix socket. Messages are two
bytes, both ways (emu/README.md, "Radio medium"):

    station -> medium   00 b  a character sent on air
                        01 c  selects: bit 0 RX select (OP0), bit 1 TX select (OP1)
                        02 n  hello: station number n (for out-of-range pairs, logs)
                        03 0  sync: my quantum of virtual time is over (lock step)
                        04 r  pace me: my characters take 10 bits at r x 300 baud
                              (host peers; see "Pacing")
    medium -> station   00 b  a character heard
                        01 c  carrier: 1 while any other station transmits
                        03 0  go on: every synchronised station finished the quantum
                        04 p  (to paced stations) your transmission is over:
                              p = 1 paced in the boards' virtual time, 0 not paced
                        05 k  (to paced stations) the boards' clock: k > 0, k x 10 us
                              of virtual time have passed; k = 0, nobody keeps
                              virtual time now (see "Clock")

Lock step: a board started with radio-sync-ns > 0 sends sync at the end of
each quantum of its virtual time and waits for go on; the medium answers once
every station that has ever sent sync (and is still here) has done so for
the round. So the boards' clocks advance together; host peers do not sync.

Pacing: a host peer has no virtual clock. While boards run in lock step,
the medium plays a paced station's messages (selects and characters, in the
order sent) in the boards' virtual time: one character per character time,
counted in sync rounds of --sync-ns each, so its transmission occupies the
air (carrier, collisions) exactly as long as a board's of the same length
would. Before this a peer keyed its transmitter for the frame's duration in
*wall* time; boards in lock step run several times faster than the wall
clock when the host is idle, so they saw the peer's carrier for three times
the frame's length after they had received it, and their ACK lost the
arbitration 12 times and was dropped (net/README.md, "Fixed bugs"). When no
board is in lock step, a paced station's messages apply at once (it then
paces itself in wall time).

Clock: a host peer's timers (retransmission, listen-before-talk) must run
in the boards' time too. In wall time they expire early whenever the boards
run slower than the wall clock (on a loaded host, boards niced beside proofs
made 50 rounds, 25 ms of virtual time, per second), so the peer gave up on
boards that were answering promptly in their own time (net/README.md, "Fixed
bugs"). So every round, the medium tells each paced station how much virtual
time passed (05 k, in 10 us units, the remainder carried to the next round),
and 05 0 when the last board leaves the lock step.

A station is *on air* while only TX select is on (both = the module's
loop-back test mode, which the board model keeps to itself), and *hears*
while only RX select is on. A transmission is one on-air span. Characters
are not delayed here: the board models give them their duration in their own
virtual time (see emu/README.md for why). Characters sent while another
station is on air collide: every listener gets garbage for them.

Faults, deterministic for --seed: the decisions for one transmission at one
receiver come from a generator seeded with (seed, sender, transmission
number, receiver), so they do not depend on how the processes interleave.
    --loss P       a receiver misses a whole transmission with probability P
    --corrupt Q    a receiver gets a transmission with 1-3 corrupted characters
                   with probability Q (a frame error rate: see net/README.md
                   for why not a per-character rate)
    --byte-errors Q  each character heard is corrupted with probability Q
    --noise R      with probability R a transmission gets a noise burst
                   (4-16 garbage characters) at a receiver, and a burst of
                   garbage follows it while the channel is idle
    --out-of-range A:B   stations A and B do not hear each other (repeatable;
                   also at run time on the control socket)

Control socket SOCKET.ctl, one line per command:
    range A B off|on      take the pair out of range / back in range
    stats                 one line of counters (key=value)
    station N             "received=R delivered=D" for the station that said
                          hello N (messages taken from it, messages written to
                          it), "none" if it is not here: what a test waits for
                          instead of sleeping (net/tests/target/medium_station.py)
A station that leaves, stalls or sends garbage never blocks the others: writes
never wait (a station whose backlog passes 1 MiB is dropped).
"""

import argparse
import asyncio
import os
import random
import signal
import sys
from collections import deque

# Codes 00-03 and the select bits are the board's too (RADIO_MSG_*, RADIO_OP_*
# in emu/hw/mc68681_duart.c; emu/tests/test_core_radio_constants.py checks
# them against the C); 04 and 05 are spoken with host peers only.
MSG_DATA, MSG_CONTROL, MSG_HELLO, MSG_SYNC, MSG_PACE, MSG_CLOCK = 0, 1, 2, 3, 4, 5
CLOCK_UNIT_NS = 10_000          # the unit of 05 k
SEL_RX, SEL_TX = 1, 2
MAX_BACKLOG = 1 << 20


class Station:
    def __init__(self, medium, writer, serial):
        self.medium = medium
        self.writer = writer
        self.serial = serial          # connection number (unique)
        self.number = None            # from HELLO
        self.selects = 0
        self.carrier_sent = None
        self.tx_count = 0             # transmissions started
        self.tx_rngs = {}             # receiver serial -> fault generator
        self.tx_lost = set()          # receivers missing this transmission
        self.tx_burst = {}            # receiver serial -> (start, length)
        self.tx_corrupt = {}          # receiver serial -> character positions to corrupt
        self.tx_chars = 0             # characters in this transmission
        self.tx_collided = False
        self.char_ns = 0              # paced station: duration of one character
        self.backlog = deque()        # paced station: (kind, value) not yet played
        self.credit_ns = 0            # paced station: virtual time owed to its backlog
        self.clock_ns = 0             # paced station: virtual time not yet told (05 k)
        self.received = 0             # messages taken from it (the control's "station N")
        self.delivered = 0            # messages written to it

    @property
    def name(self):
        return f"station {self.number}" if self.number is not None else f"peer #{self.serial}"

    @property
    def key(self):
        return self.number if self.number is not None else 1000 + self.serial

    def on_air(self):
        return self.selects == SEL_TX

    def hears(self):
        return self.selects == SEL_RX

    def send(self, msg):
        if self.writer.is_closing():
            return
        if self.writer.transport.get_write_buffer_size() > MAX_BACKLOG:
            self.medium.log(f"{self.name} stalled (backlog > 1 MiB): dropped")
            self.writer.close()
            return
        self.writer.write(msg)
        self.delivered += len(msg) // 2


class Medium:
    def __init__(self, args):
        self.args = args
        self.stations = []
        self.serial = 0
        self.out_of_range = set()
        for pair in args.out_of_range:
            a, b = (int(x) for x in pair.split(":"))
            self.out_of_range.add(frozenset((a, b)))
        self.sync_members = set()       # stations that take part in the lock step
        self.sync_done = set()          # ... that finished the current round
        self.clock_running = False      # rounds are counted (paced stations told 05 k)
        self.stats = dict(sync_rounds=0, transmissions=0, characters=0, delivered=0, collisions=0,
                          collided_chars=0, lost=0, corrupted=0, noise_bursts=0,
                          stations=0)

    def log(self, text):
        if self.args.verbose:
            print(f"radio-medium: {text}", file=sys.stderr, flush=True)

    def in_range(self, a, b):
        return frozenset((a.key, b.key)) not in self.out_of_range

    def update_carrier(self):
        for st in self.stations:
            carrier = any(o is not st and o.on_air() and self.in_range(o, st)
                          for o in self.stations)
            if carrier != st.carrier_sent:
                st.carrier_sent = carrier
                st.send(bytes((MSG_CONTROL, int(carrier))))

    def fault_rng(self, sender, receiver):
        return random.Random(f"{self.args.seed}:{sender.key}:{sender.tx_count}:{receiver.key}")

    def start_transmission(self, st):
        st.tx_count += 1
        st.tx_chars = 0
        st.tx_collided = False
        st.tx_rngs = {}
        st.tx_lost = set()
        st.tx_burst = {}
        st.tx_corrupt = {}
        self.stats["transmissions"] += 1
        for r in self.stations:
            if r is st:
                continue
            rng = self.fault_rng(st, r)
            st.tx_rngs[r.serial] = rng
            if rng.random() < self.args.loss:
                st.tx_lost.add(r.serial)
            if rng.random() < self.args.noise:
                st.tx_burst[r.serial] = (rng.randrange(0, 64), rng.randrange(4, 17))
            if rng.random() < self.args.corrupt:
                # Positions 4..11 lie inside every frame (the shortest, an
                # ACK, is 12 characters with its pad).
                st.tx_corrupt[r.serial] = set(rng.sample(range(4, 12), rng.randrange(1, 4)))

    def end_transmission(self, st):
        # Idle noise after the transmission, at the receivers it was drawn for.
        for r in self.stations:
            rng = st.tx_rngs.get(r.serial)
            if r is st or rng is None or r.serial not in st.tx_burst:
                continue
            if r.hears():
                self.stats["noise_bursts"] += 1
                for _ in range(rng.randrange(4, 17)):
                    r.send(bytes((MSG_DATA, rng.randrange(256))))

    def character(self, st, byte):
        if not st.on_air():
            return                                 # not keyed: nothing radiates
        self.stats["characters"] += 1
        collided = any(o is not st and o.on_air() for o in self.stations)
        if collided:
            self.stats["collided_chars"] += 1
            if not st.tx_collided:
                st.tx_collided = True
                self.stats["collisions"] += 1
        index = st.tx_chars
        st.tx_chars += 1
        for r in self.stations:
            if r is st or not r.hears() or not self.in_range(st, r):
                continue
            rng = st.tx_rngs.get(r.serial)
            if rng is None:                        # joined mid-transmission
                continue
            if r.serial in st.tx_lost:
                if index == 0:
                    self.stats["lost"] += 1
                continue
            out = byte
            burst = st.tx_burst.get(r.serial)
            if collided:
                out = rng.randrange(256)
            elif burst and burst[0] <= index < burst[0] + burst[1]:
                if index == burst[0]:
                    self.stats["noise_bursts"] += 1
                out = rng.randrange(256)
            elif (index in st.tx_corrupt.get(r.serial, ())
                  or rng.random() < self.args.byte_errors):
                out = byte ^ rng.randrange(1, 256)
                self.stats["corrupted"] += 1
            self.stats["delivered"] += 1
            r.send(bytes((MSG_DATA, out)))

    def message(self, st, kind, value):
        if st.char_ns and kind in (MSG_DATA, MSG_CONTROL) and st not in self.sync_members:
            if self.sync_members or st.backlog:
                st.backlog.append((kind, value))
                if not self.sync_members:
                    self.play(st, unpaced=True)
                return
        self.apply(st, kind, value)

    def apply(self, st, kind, value):
        if kind == MSG_DATA:
            self.character(st, value)
        elif kind == MSG_CONTROL:
            self.set_selects(st, value)
        elif kind == MSG_SYNC:
            self.sync(st)
        elif kind == MSG_HELLO:
            st.number = value
            self.log(f"peer #{st.serial} is station {value}")
            self.update_carrier()
        elif kind == MSG_PACE and value:
            st.char_ns = 10 * 10**9 // (300 * value)
            self.log(f"{st.name} paced at {300 * value} baud")
        else:
            self.log(f"{st.name}: unknown message {kind}, ignored")

    def play(self, st, unpaced=False):
        """Applies a paced station's backlog: everything up to the next
        character at once, characters as the virtual time owed allows."""
        while st.backlog:
            kind, value = st.backlog[0]
            if kind == MSG_DATA and not unpaced:
                if st.credit_ns < st.char_ns:
                    break
                st.credit_ns -= st.char_ns
            st.backlog.popleft()
            self.apply(st, kind, value)
        if not st.backlog:
            st.credit_ns = 0                     # idle time is not owed

    def sync(self, st):
        self.sync_members.add(st)
        self.sync_done.add(st)
        self.sync_check()

    def sync_check(self):
        if not self.sync_members:
            for p in self.stations:              # nobody keeps virtual time now
                if p.backlog:
                    self.play(p, unpaced=True)
                if p.char_ns and self.clock_running:
                    p.send(bytes((MSG_CLOCK, 0)))
            self.clock_running = False
            return
        if self.sync_done >= self.sync_members:
            self.stats["sync_rounds"] += 1
            self.clock_running = True
            # The paced stations' share of the round, before the boards go on,
            # so what they send in this round reaches the boards in their next.
            for p in self.stations:
                if p.backlog:
                    p.credit_ns += self.args.sync_ns
                    self.play(p)
                if p.char_ns:
                    self.tell_clock(p, self.args.sync_ns)
            for m in self.sync_done:
                m.send(bytes((MSG_SYNC, 0)))
            self.sync_done = set()

    def tell_clock(self, st, ns):
        st.clock_ns += ns
        while st.clock_ns >= CLOCK_UNIT_NS:
            k = min(255, st.clock_ns // CLOCK_UNIT_NS)
            st.clock_ns -= k * CLOCK_UNIT_NS
            st.send(bytes((MSG_CLOCK, k)))

    def set_selects(self, st, selects):
        if self.args.trace:
            print(f"radio-medium: round {self.stats['sync_rounds']} {st.name} selects {selects} "
                  f"after {st.tx_chars} characters", file=sys.stderr, flush=True)
        was = st.on_air()
        st.selects = selects & (SEL_RX | SEL_TX)
        if st.on_air() and not was:
            self.start_transmission(st)
        elif was and not st.on_air():
            self.end_transmission(st)
            if st.char_ns:
                st.send(bytes((MSG_PACE, int(bool(self.sync_members)))))
        self.update_carrier()

    async def serve_station(self, reader, writer):
        self.serial += 1
        st = Station(self, writer, self.serial)
        self.stations.append(st)
        self.stats["stations"] += 1
        self.log(f"{st.name} joined")
        st.carrier_sent = None
        self.update_carrier()
        try:
            pending = b""
            while True:
                chunk = await reader.read(4096)
                if not chunk:
                    break
                pending += chunk
                usable = len(pending) & ~1
                for i in range(0, usable, 2):
                    self.message(st, pending[i], pending[i + 1])
                    st.received += 1
                pending = pending[usable:]
        except (ConnectionError, OSError):
            pass
        finally:
            self.stations.remove(st)
            self.sync_members.discard(st)
            self.sync_done.discard(st)
            self.sync_check()
            if st.on_air():
                self.end_transmission(st)
            self.update_carrier()
            writer.close()
            self.log(f"{st.name} left")

    def stats_line(self):
        return " ".join(f"{k}={v}" for k, v in self.stats.items())

    async def serve_control(self, reader, writer):
        try:
            while True:
                line = await reader.readline()
                if not line:
                    break
                words = line.decode(errors="replace").split()
                reply = "error: commands are 'range A B on|off', 'stats' and 'station N'"
                if words == ["stats"]:
                    reply = self.stats_line()
                elif len(words) == 2 and words[0] == "station" and words[1].isdigit():
                    here = [st for st in self.stations if st.number == int(words[1])]
                    reply = (f"received={here[-1].received} delivered={here[-1].delivered}"
                             if here else "none")
                elif len(words) == 4 and words[0] == "range" and words[3] in ("on", "off"):
                    try:
                        pair = frozenset((int(words[1]), int(words[2])))
                    except ValueError:
                        pair = None
                    if pair is not None:
                        if words[3] == "off":
                            self.out_of_range.add(pair)
                        else:
                            self.out_of_range.discard(pair)
                        self.update_carrier()
                        reply = "ok"
                writer.write((reply + "\n").encode())
                await writer.drain()
        except (ConnectionError, OSError):
            pass
        finally:
            writer.close()


async def run(args):
    medium = Medium(args)
    for path in (args.socket, args.socket + ".ctl"):
        if os.path.exists(path):
            os.unlink(path)
    server = await asyncio.start_unix_server(medium.serve_station, path=args.socket)
    control = await asyncio.start_unix_server(medium.serve_control, path=args.socket + ".ctl")
    stop = asyncio.Event()
    loop = asyncio.get_running_loop()
    for sig in (signal.SIGTERM, signal.SIGINT):
        loop.add_signal_handler(sig, stop.set)
    print(f"radio-medium: listening on {args.socket}", flush=True)
    async with server, control:
        await stop.wait()
    print(f"radio-medium: {medium.stats_line()}", flush=True)
    for path in (args.socket, args.socket + ".ctl"):
        if os.path.exists(path):
            os.unlink(path)


def probability(text):
    value = float(text)
    if not 0.0 <= value <= 1.0:
        raise argparse.ArgumentTypeError(f"{text}: a probability is 0..1")
    return value


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--socket", required=True, help="Unix socket the stations join")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--loss", type=probability, default=0.0)
    ap.add_argument("--corrupt", type=probability, default=0.0)
    ap.add_argument("--byte-errors", type=probability, default=0.0)
    ap.add_argument("--noise", type=probability, default=0.0)
    ap.add_argument("--sync-ns", type=int, default=500_000,
                    help="virtual time of one lock-step round: the boards' radio-sync-ns "
                         "(paces host peers)")
    ap.add_argument("--out-of-range", action="append", default=[], metavar="A:B")
    ap.add_argument("-v", "--verbose", action="store_true")
    ap.add_argument("--trace", action="store_true", help="log every select change with its time")
    args = ap.parse_args(argv)
    asyncio.run(run(args))


if __name__ == "__main__":
    main()
