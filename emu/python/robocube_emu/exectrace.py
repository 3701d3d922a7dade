"""Instruction counts from QEMU's exec trace, and a run until the console shows
a marker.

trace_pcs runs an image under -icount with -singlestep -d exec,nochain, so
QEMU logs one line per executed instruction (one instruction per translation
block, no block chaining); spans counts the instructions between two PCs."""

import os
import re
import select
import subprocess
import tempfile
import time
from pathlib import Path

from . import launch

TRACE = re.compile(r"^Trace \d+: \S+ \[[0-9a-f]+/([0-9a-f]+)/")


def symbols(elf, cross="m68k-linux-gnu-"):
    out = subprocess.run([cross + "nm", str(elf)], check=True, capture_output=True,
                         text=True).stdout
    table = {}
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 3:
            table[parts[2]] = int(parts[0], 16)
    return table


def run_until_result(cmd, seconds, marker=rb"KTEST RESULT [^\r\n]*\r?\n"):
    """Runs QEMU (cmd) until the console shows a KTEST RESULT line (or the
    regex `marker`) or `seconds` pass; returns (console bytes, stderr bytes)."""
    proc = subprocess.Popen(cmd, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, preexec_fn=launch.die_with_parent)
    out = b""
    deadline = time.monotonic() + seconds
    try:
        while not re.search(marker, out):
            left = deadline - time.monotonic()
            if left <= 0 or proc.poll() is not None:
                break
            ready, _, _ = select.select([proc.stdout], [], [], min(left, 0.2))
            if ready:
                chunk = os.read(proc.stdout.fileno(), 65536)
                if not chunk:
                    break
                out += chunk
    finally:
        proc.kill()
        _, err = proc.communicate()
    return out, err


def trace_pcs(qemu, elf, seconds=60.0, marker=rb"KTEST RESULT [^\r\n]*\r?\n",
              machine="robocube", icount=launch.ICOUNT):
    """The PCs of every instruction `elf` runs on `machine` until the console
    shows `marker` (or `seconds` pass), and the console text."""
    with tempfile.TemporaryDirectory() as tmp:
        log = Path(tmp) / "exec.log"
        out, _ = run_until_result(
            launch.command(["-serial", "stdio", "-singlestep", "-d", "exec,nochain", "-D", log],
                           kernel=elf, qemu=qemu, icount=icount, machine=machine), seconds, marker)
        pcs = []
        with open(log, errors="replace") as f:
            for line in f:
                m = TRACE.match(line)
                if m:
                    pcs.append(int(m.group(1), 16))
        return pcs, out.decode("latin-1")


def spans(pcs, start, end, must_pass=None, stop_at=None, after_range=None):
    """Instruction counts from each `start` PC to the next `end` PC."""
    found = []
    i = 0
    n = len(pcs)
    while i < n:
        if pcs[i] == start and (after_range is None or
                                (i > 0 and after_range[0] <= pcs[i - 1] < after_range[1])):
            j = i + 1
            passed = must_pass is None
            while j < n and pcs[j] != end and (stop_at is None or pcs[j] != stop_at or j == i):
                if must_pass is not None and pcs[j] == must_pass:
                    passed = True
                j += 1
            if j < n and pcs[j] == end and passed:
                found.append(j - i)
            i = j
        else:
            i += 1
    return found
