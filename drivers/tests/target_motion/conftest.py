"""The motiontest image (apps/motiontest) on qemu-system-m68k -M robocube:
commands go to its console on stdin, one a line, and it answers one line
("ok ..." or "err CODE"); the board model is read and driven over QMP.

Environment (set by `make check-motion-target`):
  BSCHED_QEMU  the qemu-system-m68k with the robocube machine
  MOTION_ELF   build/firmware/motiontest/motiontest.elf
  FW_ICOUNT    the -icount setting of `make run`
"""
import os
import re
import select
import subprocess
import time
from pathlib import Path

import pytest

import robocube_emu

QEMU = os.environ.get("BSCHED_QEMU", "")
ELF = Path(os.environ.get("MOTION_ELF", Path(__file__).resolve().parents[3] / "build" / "firmware"
                          / "motiontest" / "motiontest.elf"))
ICOUNT = os.environ.get("FW_ICOUNT", "shift=8,sleep=off")
IO = "/machine/robocube-io"
REPLY_TIMEOUT = 20.0


class MotionBoard:
    def __init__(self, qmp_path):
        assert QEMU and os.access(QEMU, os.X_OK), f"BSCHED_QEMU not executable: {QEMU!r}"
        assert ELF.is_file(), f"missing image {ELF} (make firmware APP=motiontest)"
        self.proc = robocube_emu.popen(
            ["-serial", "stdio", "-qmp", f"unix:{qmp_path},server=on,wait=off"], kernel=ELF,
            icount=ICOUNT, qemu=QEMU, stdin=subprocess.PIPE)
        self.buf = b""
        self.qmp = robocube_emu.connect(qmp_path, self.proc)
        self.line(timeout=REPLY_TIMEOUT, pattern=rb"motiontest ready")

    def _qmp(self, name, **args):
        return self.qmp.command(name, **args)

    def get(self, path, prop):
        return self._qmp("qom-get", path=IO + path, property=prop)

    def set(self, path, prop, value):
        return self._qmp("qom-set", path=IO + path, property=prop, value=value)

    def line(self, timeout=REPLY_TIMEOUT, pattern=None):
        """The next console line (or the first matching pattern)."""
        deadline = time.monotonic() + timeout
        while True:
            while b"\n" in self.buf:
                raw, self.buf = self.buf.split(b"\n", 1)
                text = raw.decode("latin-1").strip()
                if pattern is None or re.search(pattern, raw):
                    return text
            left = deadline - time.monotonic()
            assert left > 0 and self.proc.poll() is None, \
                f"no reply within {timeout} s (qemu {self.proc.poll()}); buffer {self.buf!r}"
            ready, _, _ = select.select([self.proc.stdout], [], [], min(left, 0.2))
            if ready:
                chunk = os.read(self.proc.stdout.fileno(), 65536)
                self.buf += chunk

    def cmd(self, text):
        """Sends one command, returns the reply's fields after ok; asserts ok."""
        reply = self.send(text)
        assert reply.split()[0] == "ok", f"{text!r} -> {reply!r}"
        return [int(v) for v in reply.split()[1:]]

    def sample_while(self, text, probe):
        """Sends a command and, until its first reply line arrives, calls
        probe() over and over (QMP reads while the firmware works); returns
        (reply, [probe results])."""
        self.proc.stdin.write(text.encode() + b"\n")
        self.proc.stdin.flush()
        results = []
        deadline = time.monotonic() + REPLY_TIMEOUT
        while b"\n" not in self.buf:
            assert time.monotonic() < deadline and self.proc.poll() is None, "no reply"
            results.append(probe())
            ready, _, _ = select.select([self.proc.stdout], [], [], 0)
            if ready:
                self.buf += os.read(self.proc.stdout.fileno(), 65536)
        return self.line(), results

    def send(self, text):
        self.proc.stdin.write(text.encode() + b"\n")
        self.proc.stdin.flush()
        return self.line()

    def close(self):
        self.qmp.close()
        if self.proc.poll() is None:
            self.proc.kill()
        self.proc.wait(timeout=10)


@pytest.fixture(scope="module")
def board(tmp_path_factory):
    b = MotionBoard(tmp_path_factory.mktemp("motion") / "qmp.sock")
    yield b
    b.close()
