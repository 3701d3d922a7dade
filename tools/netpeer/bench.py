"""make net-bench: goodput of one sender and the latency of a 32-byte reliable
message between two boards in lock step (virtual time), as in net/README.md."""
import argparse
import os
import re
import sys
import tempfile

from netpeer.netnode import Board, MediumProcess, ROOT

BENCH = re.compile(r"netnode: bench (\d+) of (\d+) messages of (\d+) bytes to \d+ in (\d+) ms")
BAUD = re.compile(r"  radio (\d+) baud")


def bench(elf, size, messages, fec=False, auth=True):
    d = tempfile.mkdtemp(prefix="net-bench-")
    sock = os.path.join(d, "air.sock")
    medium = MediumProcess(sock)
    rx = tx = None
    try:
        rx = Board(elf, 1, sock, d, mode="echo", linger_ms=120000, fec=fec, auth=auth)
        if not rx.wait_for("station 1 up", 30):
            raise RuntimeError("receiver did not start:\n" + rx.text())
        tx = Board(elf, 0, sock, d, mode="bench", peers=(1,), messages=messages, size=size,
                   fec=fec, auth=auth)
        if not tx.wait_for("netnode: done", 300):
            raise RuntimeError("bench did not finish:\n" + tx.text())
        m = BENCH.search(tx.text())
        return tuple(int(x) for x in m.groups()) + (int(BAUD.search(tx.text())[1]),)
    finally:
        for b in (tx, rx):
            if b:
                b.stop()
        medium.stop()


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--elf", default=os.path.join(ROOT, "build", "firmware", "netnode",
                                                  "netnode.elf"))
    ap.add_argument("--fec", action="store_true", help="Reed-Solomon frames on both boards")
    ap.add_argument("--no-auth", action="store_true",
                    help="both boards without frame authentication (its cost: compare)")
    a = ap.parse_args(argv)
    fec = (" with FEC" if a.fec else "") + (", auth off" if a.no_auth else "")
    ok, n, size, ms, baud = bench(a.elf, 504, 4, a.fec, not a.no_auth)
    bits = ok * size * 8 * 1000 / ms
    print(f"net-bench: goodput{fec} {ok}/{n} x {size} bytes in {ms} ms virtual = {bits:.0f} "
          f"bit/s = {100 * bits / baud:.1f} % of {baud} baud (the board's report)")
    ok2, n2, size2, ms2, _ = bench(a.elf, 32, 40, a.fec, not a.no_auth)
    print(f"net-bench: latency{fec} of a {size2}-byte reliable message: {ms2 / n2:.1f} ms "
          f"({ok2}/{n2} acknowledged in {ms2} ms virtual)")
    return 0 if ok == n and ok2 == n2 else 1


if __name__ == "__main__":
    sys.exit(main())
