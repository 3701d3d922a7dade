"""The iotest firmware (apps/iotest) on the emulated RoboCube: console
commands in, one '='-line out; the board model set and read over QMP."""

import os
import time
from pathlib import Path

import robocube_emu

ROOT = Path(__file__).resolve().parents[3]
ELF = Path(os.environ.get("IOTEST_ELF", ROOT / "build" / "firmware" / "iotest" / "iotest.elf"))
ICOUNT = os.environ.get("FW_ICOUNT", "shift=8,sleep=off")
IO = "/machine/robocube-io"
DUART = "/machine/duart"


class IoTestBoard:
    def __init__(self, timeout=20.0):
        assert ELF.is_file(), f"missing {ELF} (make firmware APP=iotest)"
        self.m = robocube_emu.Machine(kernel=str(ELF), extra_args=["-icount", ICOUNT])
        self.boot = self.read_until(b"iotest ready\r\n", timeout).decode(errors="replace")

    def close(self):
        self.m.close()

    def read_until(self, marker, timeout=20.0):
        return self.m.console.read_until(marker, timeout=timeout)

    def cmd(self, line, timeout=20.0):
        """Sends one command; returns the words of its '=' reply after the name."""
        self.m.console.write(line.encode() + b"\r")
        out = self.read_until(b"\n", timeout).decode(errors="replace").strip()
        while not out.startswith("="):
            out = self.read_until(b"\n", timeout).decode(errors="replace").strip()
        return out[1:].split()

    def ints(self, line, timeout=20.0):
        words = self.cmd(line, timeout)
        name = line.split()[0]
        assert words[0] == name, (line, words)
        return [int(w) for w in words[1:]]

    def get(self, path, prop):
        return self.m.qom_get(path, prop)

    def set(self, path, prop, value):
        self.m.qom_set(path, prop, value)

    def snap_after(self, seq, timeout=10.0):
        """The first snapshot with seq > seq (waits for the sampler)."""
        end = time.monotonic() + timeout
        while True:
            s = self.ints("snap")
            if s[0] > seq:
                return {"seq": s[0], "time_us": s[1], "valid": s[2], "bio": s[3],
                        "binin": s[4], "err": s[5], "analog": s[6:30]}
            assert time.monotonic() < end, "sampler made no new snapshot"
            time.sleep(0.02)
