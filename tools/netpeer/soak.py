"""make net-soak: N boards and H host peers on a faulty medium; every board
sends M numbered reliable messages to every other station, every host peer to
every board (host peers do not talk to each other). With one board and eight
host peers, eight stations send to one board at once (make net-soak-fan-in).

Last line: net-soak: sent X, delivered Y, in order, D duplicates, L lost
(exit 0 only when Y == X, D == 0, L == 0). X counts every message a station
set out to send; Y the messages that arrived in order at their destination;
D those that arrived again; L = X - Y.
"""
import argparse
import os
import re
import sys
import tempfile
import threading
import time

import xdrlib3

from netpeer import MediumTransport, Peer, Unreachable
from netpeer.netnode import Board, MediumProcess, ROOT
from netpeer.__main__ import ranged

PORT_SOAK = 2
HOST_STATIONS = (9, 10, 11, 12, 13, 14, 15, 8)   # the first is the single host peer's


def soak_message(sender, number):
    """The XDR soak message of apps/netnode (u_int sender, u_int number, opaque fill[8])."""
    p = xdrlib3.Packer()
    p.pack_uint(sender)
    p.pack_uint(number)
    p.pack_fopaque(8, bytes((number + i) & 0xFF for i in range(8)))
    return p.get_buffer()


def soak_unpack(msg):
    u = xdrlib3.Unpacker(msg)
    sender, number = u.unpack_uint(), u.unpack_uint()
    u.unpack_fopaque(8)
    u.done()
    return sender, number


def show_live(boards, stop, period=0.2):
    """Prints each board's console lines as they come, "station N: LINE"
    (--live: make run APP=netnode), until `stop` is set; then one last pass, so
    that what a board wrote just before the end is shown too."""
    shown = [0] * len(boards)
    while True:
        last = stop.is_set()
        for i, b in enumerate(boards):
            text = b.text()
            end = text.rfind("\n") + 1
            for line in text[shown[i]:end].splitlines():
                # (not QEMU's own word that the soak stopped it)
                if line.strip() and "terminating on signal" not in line:
                    print(f"station {b.station}: {line}", flush=True)
            shown[i] = max(shown[i], end)
        if last:
            return
        stop.wait(period)


def run(args):
    workdir = tempfile.mkdtemp(prefix="net-soak-")
    sock = os.path.join(workdir, "air.sock")
    medium = MediumProcess(sock, seed=args.seed, loss=args.loss, corrupt=args.corrupt,
                           noise=args.noise, byte_errors=args.byte_errors)
    host_stations = list(HOST_STATIONS[:args.hosts])
    stations = list(range(args.boards)) + host_stations
    elf = args.elf
    boards = []
    hosts = []
    t0 = time.monotonic()
    try:
        for s in range(args.boards):
            boards.append(Board(elf, s, sock, workdir, mode="soak", peers=stations,
                                messages=args.messages, seed=args.seed + s,
                                linger_ms=args.linger * 1000, fec=args.fec))
        for n, station in enumerate(host_stations):
            hosts.append(HostSoak(Peer(MediumTransport(sock), station, seed=args.seed + n,
                                       fec=args.fec), args.boards, args.messages))
        live_stop = threading.Event()
        live = threading.Thread(target=show_live, args=(boards, live_stop), daemon=True)
        if args.live:
            live.start()
        senders = [threading.Thread(target=h.send_all, daemon=True) for h in hosts]
        for t in senders:
            t.start()
        deadline = time.monotonic() + args.timeout
        for t in senders:
            t.join(max(1.0, deadline - time.monotonic()))
        for b in boards:
            if not b.wait_for("netnode: done", max(1.0, deadline - time.monotonic())):
                print(f"net-soak: station {b.station} did not finish; console:\n{b.text()}")
        for h in hosts:                # 10 s of the boards' time for the last ACKs
            h.peer.t.clock.wait_until(h.peer.t.clock.now() + 10, h.all_in, poll=0.1)
        if live.is_alive():           # the boards' last lines, before they stop
            live_stop.set()
            live.join(10)
    finally:
        for b in boards:
            b.stop()
        for h in hosts:
            h.peer.close()
        stats = medium.stats() if medium.proc.poll() is None else {}
        medium.stop()
    wall = time.monotonic() - t0
    # Every board hears from every other station, every host peer from every board.
    expected = (args.boards * (len(stations) - 1) + len(hosts) * args.boards) * args.messages
    delivered = dups = 0
    for b in boards:
        text = b.text()
        if args.verbose:
            print(text)
        for m in re.finditer(r"netnode: from (\d+): (\d+) in order, (\d+) duplicates", text):
            delivered += int(m.group(2))
            dups += int(m.group(3))
    for h in hosts:
        delivered += sum(h.inorder.values())
        dups += sum(h.dup.values())
    lost = expected - delivered
    print(f"net-soak: {args.boards} boards + {len(hosts)} host peers, "
          f"{args.messages} messages per pair, loss {args.loss}, corrupt {args.corrupt}, "
          f"byte errors {args.byte_errors}, fec {'on' if args.fec else 'off'}, "
          f"seed {args.seed}, {wall:.1f} s wall; medium: " +
          " ".join(f"{k}={v}" for k, v in stats.items()))
    print(f"net-soak: sent {expected}, delivered {delivered}, in order, {dups} duplicates, "
          f"{lost} lost")
    return 0 if delivered == expected and dups == 0 and lost == 0 else 1


class HostSoak:
    """One host peer of the soak: sends M numbered messages to every board,
    round robin, and checks what arrives from each (in order, duplicates)."""

    def __init__(self, peer, boards, messages):
        self.peer, self.boards, self.messages = peer, boards, messages
        self.sent = self.failed = 0
        self.next = {s: 0 for s in range(boards)}
        self.inorder = {s: 0 for s in range(boards)}
        self.dup = {s: 0 for s in range(boards)}
        threading.Thread(target=self.receive, daemon=True).start()

    def all_in(self):
        return all(n >= self.messages for n in self.next.values())

    def send_all(self):
        for i in range(self.messages):
            for s in range(self.boards):
                try:
                    self.peer.send(s, PORT_SOAK, soak_message(self.peer.station, i))
                    self.sent += 1
                except Unreachable:
                    self.failed += 1

    def receive(self):
        while self.peer.running:
            got = self.peer.recv(PORT_SOAK, timeout=0.5)
            if got is None:
                continue
            src, msg = got
            if src not in self.next:
                continue
            try:
                sender, number = soak_unpack(msg)
            except (xdrlib3.Error, EOFError):
                continue
            if number == self.next[src]:
                self.inorder[src] += 1
                self.next[src] += 1
            elif number < self.next[src]:
                self.dup[src] += 1
            else:
                self.next[src] = number + 1
            self.peer.t.clock.notify()         # all_in() may hold now


SOAK_USAGE = ("soak.py [--boards 1..4] [--hosts 0..8 | --no-host] [--messages 1..10000] "
              "[--loss P] [--corrupt P] [--noise P] [--byte-errors P] [--fec] [--seed 0..4294967295] "
              "[--timeout SECONDS] [--linger 1..3600] [--elf FILE] [-v] [--live]  (P: a probability 0..1)")


class SoakParser(argparse.ArgumentParser):
    """Every bad argument: one line (what is wrong, then the usage) and exit 2."""

    def error(self, message):
        self.exit(2, f"soak.py: {message}; usage: {SOAK_USAGE}\n")


def probability(text):
    """An argparse type: a probability, a finite number 0..1."""
    try:
        v = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}' is not a number") from None
    if not 0.0 <= v <= 1.0:            # NaN fails both comparisons
        raise argparse.ArgumentTypeError(f"{text} is not a probability (0..1)")
    return v


def seconds(text):
    try:
        v = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}' is not a number") from None
    if not 0.0 < v <= 86400.0:
        raise argparse.ArgumentTypeError(f"{text} is not a number of seconds (0..86400]")
    return v


def main(argv=None):
    ap = SoakParser(description=__doc__.split("\n")[0])
    ap.add_argument("--boards", type=ranged("number of boards", 1, 4), default=2)
    ap.add_argument("--messages", type=ranged("number of messages", 1, 10000), default=5)
    ap.add_argument("--loss", type=probability, default=0.0)
    ap.add_argument("--corrupt", type=probability, default=0.0)
    ap.add_argument("--noise", type=probability, default=0.0)
    ap.add_argument("--byte-errors", type=probability, default=0.0, help="per character (medium)")
    ap.add_argument("--fec", action="store_true", help="Reed-Solomon frames on every station")
    ap.add_argument("--seed", type=ranged("seed", 0, 2**32 - 1), default=1)
    ap.add_argument("--timeout", type=seconds, default=300.0)
    ap.add_argument("--linger", type=ranged("linger time", 1, 3600), default=60,
                    help="s a board waits for its peers")
    ap.add_argument("--hosts", type=ranged("number of host peers", 0, len(HOST_STATIONS)),
                    default=1, help=f"host peers (0..{len(HOST_STATIONS)}), stations {HOST_STATIONS}")
    ap.add_argument("--no-host", dest="hosts", action="store_const", const=0)
    ap.add_argument("--elf", default=os.path.join(ROOT, "build", "firmware", "netnode",
                                                  "netnode.elf"))
    ap.add_argument("-v", "--verbose", action="store_true", help="every board's console at the end")
    ap.add_argument("--live", action="store_true", help="every board's console lines as they come")
    args = ap.parse_args(argv)
    if args.boards + args.hosts < 2:
        ap.error("there must be at least 2 stations (boards + host peers)")
    if not os.path.isfile(args.elf):
        ap.error(f"--elf {args.elf}: no such file")
    return run(args)


if __name__ == "__main__":
    sys.exit(main())
