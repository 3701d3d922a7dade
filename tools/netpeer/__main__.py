"""python -m netpeer: send to or listen on the RoboCube radio network."""
import argparse
import sys

from . import MediumTransport, Peer, SerialTransport, Unreachable


def main(argv=None):
    ap = argparse.ArgumentParser(prog="netpeer", description=__doc__)
    where = ap.add_mutually_exclusive_group(required=True)
    where.add_argument("--socket", help="the radio medium's Unix socket (emu/radio_medium.py)")
    where.add_argument("--serial", help="a serial port with a real radio module")
    ap.add_argument("--station", type=int, required=True)
    ap.add_argument("--baud", type=int, default=19200)
    ap.add_argument("--fec", action="store_true", help="Reed-Solomon frames (boards with NET_FEC)")
    sub = ap.add_subparsers(dest="cmd", required=True)
    s = sub.add_parser("send")
    s.add_argument("dst", type=int)
    s.add_argument("port", type=int)
    s.add_argument("text")
    s.add_argument("--datagram", action="store_true")
    s.add_argument("--wait-reply", type=float, metavar="SECONDS",
                   help="then print one message from the same port")
    l = sub.add_parser("listen")
    l.add_argument("port", type=int)
    l.add_argument("--count", type=int, default=0, help="stop after this many (0: forever)")
    l.add_argument("--timeout", type=float, default=None)
    a = ap.parse_args(argv)
    try:
        t = MediumTransport(a.socket, a.baud) if a.socket else SerialTransport(a.serial, a.baud)
    except (OSError, ValueError) as e:            # pyserial's SerialException is an OSError
        print(f"netpeer: cannot reach the air at {a.socket or a.serial}: {e}", file=sys.stderr)
        return 2
    with Peer(t, a.station, fec=a.fec) as p:
        if a.cmd == "send":
            try:
                p.send(a.dst, a.port, a.text.encode(), reliable=not a.datagram)
            except Unreachable as e:
                print(f"netpeer: {e}", file=sys.stderr)
                return 1
            if a.wait_reply:
                got = p.recv(a.port, timeout=a.wait_reply)
                if got is None:
                    print("netpeer: no reply", file=sys.stderr)
                    return 1
                print(f"{got[0]}: {got[1].decode(errors='replace')}")
            return 0
        n = 0
        while a.count == 0 or n < a.count:
            got = p.recv(a.port, timeout=a.timeout)
            if got is None:
                print("netpeer: timeout", file=sys.stderr)
                return 1
            print(f"{got[0]}: {got[1].decode(errors='replace')}", flush=True)
            n += 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
