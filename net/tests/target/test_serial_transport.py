"""tools/netpeer's SerialTransport (pyserial) for real: a board whose DUART
channel A is a host pseudo-terminal (as a serial adapter to a radio module
would be), the host peer on that tty through pyserial, both directions."""
import re

import pytest

from netpeer import Peer, SerialTransport, Unreachable


def test_host_peer_over_pyserial_and_board_both_ways(air):
    board = air.board(1, mode="echo", linger_ms=6000, medium_sock=None)
    path = board.pty_path()
    assert board.wait_for("station 1 up", 20), board.text()
    t = SerialTransport(path, 19200)
    peer = Peer(t, 9)
    air.closers.append(peer.close)
    msg = bytes(range(256)) * 2                           # 512 bytes: 5 fragments
    peer.send(1, 1, msg)                                  # host -> board, reliable
    assert peer.recv(1, timeout=20) == (1, msg)           # board -> host, reliable
    assert peer.stats["unreachable"] == 0
    assert not t.modem_lines                              # a pty has none: tolerated
    assert board.wait_for("netnode: done", 60), board.text()
    assert re.search(r"messages delivered 1,", board.text()), board.text()


def test_serial_peer_reports_a_silent_line(air):
    board = air.board(2, mode="echo", linger_ms=60000, medium_sock=None)
    peer = Peer(SerialTransport(board.pty_path(), 19200), 9)
    air.closers.append(peer.close)
    with pytest.raises(Unreachable):
        peer.send(5, 1, b"nobody is station 5")
