"""make net-soak: N boards and the host peer on a faulty medium; every station
sends M numbered reliable messages to every other station.

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

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from netpeer import MediumTransport, Peer, Unreachable            # noqa: E402
from netpeer.netnode import Board, MediumProcess, ROOT            # noqa: E402

PORT_SOAK = 2
HOST_STATION = 9


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


def run(args):
    workdir = tempfile.mkdtemp(prefix="net-soak-")
    sock = os.path.join(workdir, "air.sock")
    medium = MediumProcess(sock, seed=args.seed, loss=args.loss, corrupt=args.corrupt,
                           noise=args.noise, byte_errors=args.byte_errors)
    stations = list(range(args.boards)) + ([HOST_STATION] if not args.no_host else [])
    elf = args.elf
    boards = []
    peer = None
    t0 = time.monotonic()
    host = dict(sent=0, failed=0, next={}, inorder={}, dup={})
    try:
        for s in range(args.boards):
            boards.append(Board(elf, s, sock, workdir, mode="soak", peers=stations,
                                messages=args.messages, seed=args.seed + s,
                                linger_ms=args.linger * 1000, fec=args.fec))
        if not args.no_host:
            peer = Peer(MediumTransport(sock), HOST_STATION, seed=args.seed, fec=args.fec)
            for s in range(args.boards):
                host["next"][s] = host["inorder"][s] = host["dup"][s] = 0

            def host_rx():
                while peer.running:
                    got = peer.recv(PORT_SOAK, timeout=0.5)
                    if got is None:
                        continue
                    src, msg = got
                    if src not in host["next"]:
                        continue
                    try:
                        sender, number = soak_unpack(msg)
                    except (xdrlib3.Error, EOFError):
                        continue
                    if number == host["next"][src]:
                        host["inorder"][src] += 1
                        host["next"][src] += 1
                    elif number < host["next"][src]:
                        host["dup"][src] += 1
                    else:
                        host["next"][src] = number + 1
            threading.Thread(target=host_rx, daemon=True).start()
            for i in range(args.messages):
                for s in range(args.boards):
                    try:
                        peer.send(s, PORT_SOAK, soak_message(HOST_STATION, i))
                        host["sent"] += 1
                    except Unreachable:
                        host["failed"] += 1
        deadline = time.monotonic() + args.timeout
        for b in boards:
            if not b.wait_for("netnode: done", max(1.0, deadline - time.monotonic())):
                print(f"net-soak: station {b.station} did not finish; console:\n{b.text()}")
        if peer is not None:           # 10 s of the boards' time for the last ACKs
            peer.t.clock.wait_until(peer.t.clock.now() + 10, lambda: all(
                host["next"][s] >= args.messages for s in host["next"]), poll=0.1)
    finally:
        for b in boards:
            b.stop()
        if peer is not None:
            peer.close()
        stats = medium.stats() if medium.proc.poll() is None else {}
        medium.stop()
    wall = time.monotonic() - t0
    expected = len(stations) * (len(stations) - 1) * args.messages
    delivered = dups = 0
    for b in boards:
        text = b.text()
        if args.verbose:
            print(text)
        for m in re.finditer(r"netnode: from (\d+): (\d+) in order, (\d+) duplicates", text):
            delivered += int(m.group(2))
            dups += int(m.group(3))
    for s in host["inorder"]:
        delivered += host["inorder"][s]
        dups += host["dup"][s]
    lost = expected - delivered
    print(f"net-soak: {args.boards} boards{' + host peer' if peer else ''}, "
          f"{args.messages} messages per pair, loss {args.loss}, corrupt {args.corrupt}, "
          f"byte errors {args.byte_errors}, fec {'on' if args.fec else 'off'}, "
          f"seed {args.seed}, {wall:.1f} s wall; medium: " +
          " ".join(f"{k}={v}" for k, v in stats.items()))
    print(f"net-soak: sent {expected}, delivered {delivered}, in order, {dups} duplicates, "
          f"{lost} lost")
    return 0 if delivered == expected and dups == 0 and lost == 0 else 1


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--boards", type=int, default=2)
    ap.add_argument("--messages", type=int, default=5)
    ap.add_argument("--loss", type=float, default=0.0)
    ap.add_argument("--corrupt", type=float, default=0.0)
    ap.add_argument("--noise", type=float, default=0.0)
    ap.add_argument("--byte-errors", type=float, default=0.0, help="per character (medium)")
    ap.add_argument("--fec", action="store_true", help="Reed-Solomon frames on every station")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--timeout", type=float, default=300.0)
    ap.add_argument("--linger", type=int, default=60, help="s a board waits for its peers")
    ap.add_argument("--no-host", action="store_true")
    ap.add_argument("--elf", default=os.path.join(ROOT, "build", "firmware", "netnode",
                                                  "netnode.elf"))
    ap.add_argument("-v", "--verbose", action="store_true")
    args = ap.parse_args(argv)
    if not 2 <= args.boards <= 4:
        ap.error("BOARDS is 2 to 4")
    if not all(0 <= p <= 1 for p in (args.loss, args.corrupt, args.byte_errors, args.noise)):
        ap.error("LOSS, CORRUPT, BYTE_ERRORS and NOISE are probabilities 0..1")
    return run(args)


if __name__ == "__main__":
    sys.exit(main())
