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


def command(args=(), kernel=None, icount=ICOUNT, qemu=None, machine="robocube"):
    """The argument list of one run of `machine` (the RoboCube unless another
    board's, e.g. netduinoplus2 with qemu-system-arm): no display, no monitor,
    `kernel` (an ELF run from flash) and `-icount icount` when given, then args."""
    cmd = [qemu_binary(qemu), "-M", machine, "-display", "none", "-monitor", "none"]
    if icount:
        cmd += ["-icount", icount]
    if kernel is not None:
        cmd += ["-kernel", str(kernel)]
    return cmd + [str(a) for a in args]


def popen(args=(), kernel=None, icount=ICOUNT, qemu=None, stdin=subprocess.DEVNULL,
          stdout=subprocess.PIPE, stderr=subprocess.PIPE, machine="robocube", **kwargs):
    """Starts one QEMU (command()) that dies with this process."""
    return subprocess.Popen(command(args, kernel, icount, qemu, machine), stdin=stdin, stdout=stdout,
                            stderr=stderr, preexec_fn=die_with_parent, **kwargs)


# What differs between the boards the firmware runs on: the QEMU machine, the
# -icount setting (each board's `make run` value), the one the target suites
# and the traces use, the binutils prefix, and the first instruction of the
# tick interrupt (where a tick span starts), and whether the kernel's port
# guards stacks with an MPU (a thread stopped at its first write into its
# guard, not at its next switch). The mps2-an385's suites run at make run's
# setting (64 ns per instruction). The stm32f405's suites run its
# virtual CPU at 64 ns per instruction instead of make run's 8: what they check
# is counted in ticks and instructions, never in instructions per tick, and
# eight times fewer instructions per tick make the long tests eight times
# shorter to emulate.
BOARDS = {
    "robocube": {"machine": "robocube", "icount": "shift=8,sleep=off",
                 "test_icount": "shift=8,sleep=off",
                 "cross": "m68k-linux-gnu-", "tick_entry": "k_isr_entry"},
    "stm32f405": {"machine": "netduinoplus2", "icount": "shift=3,sleep=off",
                  "test_icount": "shift=6,sleep=off",
                  "cross": "arm-none-eabi-", "tick_entry": "armv7m_systick",
                  "mpu_stack_guard": True},
    "mps2-an385": {"machine": "mps2-an385", "icount": "shift=6,sleep=off",
                   "test_icount": "shift=6,sleep=off",
                   "cross": "arm-none-eabi-", "tick_entry": "armv7m_systick",
                   "mpu_stack_guard": True},
}


def board(name=None):
    """The entry of BOARDS for `name`, else $K_BOARD, else the RoboCube."""
    return BOARDS[name or os.environ.get("K_BOARD", "robocube")]

