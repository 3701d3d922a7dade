import os
import tempfile

import pytest
from netpeer.netnode import Board, MediumProcess

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))


class Air:
    """A medium plus the boards and peers a test starts; all stopped at the end."""

    def __init__(self):
        self.dir = tempfile.mkdtemp(prefix="net-target-")
        self.sock = os.path.join(self.dir, "air.sock")
        self.elf = os.environ.get("NETNODE_ELF") or os.path.join(
            ROOT, "build", "firmware", "netnode", "netnode.elf")
        self.medium = None
        self.boards = []
        self.closers = []

    def start_medium(self, **faults):
        self.medium = MediumProcess(self.sock, **faults)
        return self.medium

    def board(self, station, medium_sock="medium", **config):
        """A board on this test's medium, or (medium_sock=None) on a pty. A
        station started again in the same test is its next boot (a new session)."""
        config.setdefault("boot", sum(b.station == station for b in self.boards))
        b = Board(self.elf, station, self.sock if medium_sock == "medium" else medium_sock,
                  self.dir, **config)
        self.boards.append(b)
        return b

    def close(self):
        for c in self.closers:
            c()
        for b in self.boards:
            b.stop()
        if self.medium:
            self.medium.stop()


def pytest_configure(config):
    config.addinivalue_line("markers", "interop: a host peer speaks first to a fresh board "
                            "(make net-interop repeats these)")


@pytest.fixture
def air():
    a = Air()
    yield a
    a.close()


@pytest.fixture
def medium_factory():
    """make(**faults): a medium of its own (no boards), stopped at the end."""
    made = []

    def make(**faults):
        m = MediumProcess(os.path.join(tempfile.mkdtemp(), "air.sock"), **faults)
        made.append(m)
        return m
    yield make
    for m in made:
        m.stop()
