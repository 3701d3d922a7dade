"""Starting qemu-system-m68k with the robocube machine: the one place that knows
where the binary is and how every emulator process is started.

The binary: $BSCHED_QEMU, else this checkout's build/emu/qemu-system-m68k
(ci/setup qemu builds it)."""

import ctypes
import os
import signal
import subprocess
from pathlib import Path

# This checkout: emu/python/robocube_emu/launch.py is three folders below it.
ROOT = Path(__file__).resolve().parents[3]
# Virtual time follows the instruction count only: the same run on any host.
ICOUNT = "shift=8,sleep=off"


def die_with_parent():
    """preexec_fn: the kernel sends SIGKILL to the child when this process dies,
    so a killed or crashed test run never leaves an emulator spinning (under
    -icount sleep=off an idle guest keeps a host core busy)."""
    ctypes.CDLL(None, use_errno=True).prctl(1, signal.SIGKILL)   # PR_SET_PDEATHSIG


def qemu_binary(path=None):
    """path, else $BSCHED_QEMU, else build/emu/qemu-system-m68k; raises
    FileNotFoundError when it is not an executable."""
    path = str(path or os.environ.get("BSCHED_QEMU") or ROOT / "build" / "emu" / "qemu-system-m68k")
    if not os.access(path, os.X_OK):
        raise FileNotFoundError(
            f"{path}: qemu-system-m68k with the robocube machine is not built "
            "(run ci/setup qemu)")
    return path


def command(args=(), kernel=None, icount=ICOUNT, qemu=None):
    """The argument list of one robocube run: no display, no monitor, `kernel`
    (an ELF run from flash) and `-icount icount` when given, then args."""
    cmd = [qemu_binary(qemu), "-M", "robocube", "-display", "none", "-monitor", "none"]
    if icount:
        cmd += ["-icount", icount]
    if kernel is not None:
        cmd += ["-kernel", str(kernel)]
    return cmd + [str(a) for a in args]


def popen(args=(), kernel=None, icount=ICOUNT, qemu=None, stdin=subprocess.DEVNULL,
          stdout=subprocess.PIPE, stderr=subprocess.PIPE, **kwargs):
    """Starts one robocube QEMU (command()) that dies with this process."""
    return subprocess.Popen(command(args, kernel, icount, qemu), stdin=stdin, stdout=stdout,
                            stderr=stderr, preexec_fn=die_with_parent, **kwargs)
