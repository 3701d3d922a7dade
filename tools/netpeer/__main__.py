"""python -m netpeer: send to or listen on the RoboCube radio network."""
import argparse
import sys

from . import MediumTransport, Peer, SerialTransport, Unreachable
from .auth import EPOCH_MAX, KEY_LEN
from .peer import MAX_STATIONS
from .protocol import BROADCAST, MSG_MAX, PACKET_DATA_MAX, PORTS

USAGE = ("netpeer (--socket PATH | --serial DEVICE) --station 0-15 [--baud N] [--fec] "
         "[--key HEX] [--epoch N] "
         "{send DST PORT TEXT [--datagram] [--wait-reply SECONDS] | "
         "listen PORT [--count N] [--timeout SECONDS]}")


class Parser(argparse.ArgumentParser):
    """Every bad argument: one line (what is wrong, then the usage) and exit 2."""

    def error(self, message):
        self.exit(2, f"netpeer: {message}; usage: {USAGE}\n")


def ranged(name, lo, hi, extra=()):
    """An argparse type: an integer lo..hi (or one of extra)."""
    def parse(text):
        try:
            v = int(text, 10)
        except ValueError:
            raise argparse.ArgumentTypeError(f"'{text}' is not a number") from None
        if not (lo <= v <= hi or v in extra):
            also = "".join(f" or {e}" for e in extra)
            raise argparse.ArgumentTypeError(f"{v} is not a {name} ({lo}..{hi}{also})")
        return v
    return parse


def hex_key():
    """An argparse type: the network key, KEY_LEN bytes in hexadecimal."""
    def parse(text):
        try:
            key = bytes.fromhex(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"key '{text}' is not hexadecimal") from None
        if len(key) != KEY_LEN:
            raise argparse.ArgumentTypeError(f"a key is {KEY_LEN} bytes ({2 * KEY_LEN} hex "
                                             f"digits), not {len(key)}")
        return key
    return parse


def positive_seconds():
    """An argparse type: a finite number of seconds > 0."""
    def parse(text):
        try:
            v = float(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"'{text}' is not a number") from None
        if not 0 < v < float("inf"):
            raise argparse.ArgumentTypeError(f"{text} is not a positive number of seconds")
        return v
    return parse


def parse_args(argv):
    ap = Parser(prog="netpeer", description=__doc__, usage=USAGE)
    where = ap.add_mutually_exclusive_group(required=True)
    where.add_argument("--socket", help="the radio medium's Unix socket (robocube_emu.radio_medium)")
    where.add_argument("--serial", help="a serial port with a real radio module")
    ap.add_argument("--station", type=ranged("station", 0, MAX_STATIONS - 1), required=True)
    ap.add_argument("--baud", type=ranged("baud", 300, 255 * 300), default=19200)
    ap.add_argument("--fec", action="store_true", help="Reed-Solomon frames (boards with NET_FEC)")
    ap.add_argument("--key", type=hex_key(), default=None,
                    help="the network key in hex (default: the public development key)")
    ap.add_argument("--epoch", type=ranged("epoch", 0, EPOCH_MAX), default=None,
                    help="this start's authentication epoch: above the last start's "
                         "(default: random, see net/README.md)")
    sub = ap.add_subparsers(dest="cmd", required=True, parser_class=Parser)
    s = sub.add_parser("send", usage=USAGE)
    s.add_argument("dst", type=ranged("destination", 0, MAX_STATIONS - 1, (BROADCAST,)))
    s.add_argument("port", type=ranged("port", 0, PORTS - 1))
    s.add_argument("text")
    s.add_argument("--datagram", action="store_true")
    s.add_argument("--wait-reply", type=positive_seconds(), metavar="SECONDS",
                   help="then print one message from the same port")
    lp = sub.add_parser("listen", usage=USAGE)
    lp.add_argument("port", type=ranged("port", 0, PORTS - 1))
    lp.add_argument("--count", type=ranged("count", 0, 1_000_000), default=0,
                    help="stop after this many (0: forever)")
    lp.add_argument("--timeout", type=positive_seconds(), default=None)
    a = ap.parse_args(argv)
    if a.socket is not None and a.baud % 300:
        ap.error(f"baud {a.baud} is not a multiple of 300 (the medium's unit)")
    if a.cmd == "send":
        size = len(a.text.encode())
        single = a.datagram or a.dst == BROADCAST
        if a.dst == a.station:
            ap.error(f"destination {a.dst} is this station")
        if size > (PACKET_DATA_MAX if single else MSG_MAX):
            ap.error(f"text of {size} bytes is longer than a "
                     f"{'datagram' if single else 'message'} "
                     f"({PACKET_DATA_MAX if single else MSG_MAX} bytes)")
    return a


def main(argv=None):
    a = parse_args(argv)
    try:
        t = MediumTransport(a.socket, a.baud) if a.socket else SerialTransport(a.serial, a.baud)
    except (OSError, ValueError) as e:            # pyserial's SerialException is an OSError
        print(f"netpeer: cannot reach the air at {a.socket or a.serial}: {e}", file=sys.stderr)
        return 2
    with Peer(t, a.station, fec=a.fec, key=a.key, epoch=a.epoch) as p:
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
