"""apps/posixcheck: the POSIX layer (posix/) on the emulated board. One boot
runs every test of the image; each of its "POSIX TEST" lines is one test
here, so a failing call is named by its own test. The figures the image
measures go to build/posix/figures.txt.

Environment (make check-posix, make check-NAME-posix): BSCHED_QEMU, FW_DIR and
K_BOARD, the board (robocube_emu.launch.BOARDS: its machine and -icount; the
RoboCube by default).
"""
import os
import re
from pathlib import Path

import pytest
import robocube_emu

ROOT = Path(__file__).resolve().parents[3]
FW = Path(os.environ.get("FW_DIR", ROOT / "build" / "firmware"))
ELF = FW / "posixcheck" / "posixcheck.elf"
BOARD_NAME = os.environ.get("K_BOARD", "robocube")
BOARD = robocube_emu.launch.board(BOARD_NAME)
# The RoboCube's console is the first of its three serial ports; another
# board has one, the console.
MACHINE_ARGS = {} if BOARD_NAME == "robocube" else {
    "machine": BOARD["machine"], "serial_names": ("console",), "qemu": os.environ.get("BSCHED_QEMU")}

TESTS = [
    "threads_preempt_by_priority",
    "sched_fifo_and_sched_rr",
    "priority_inheritance_bounds_inversion",
    "condition_variables",
    "semaphores",
    "sleeps_and_clocks",
    "clock_nanosleep_absolute_drift_free",
    "message_queues",
    "error_paths",
    "console_file_descriptors",
]


@pytest.fixture(scope="module")
def console():
    with robocube_emu.Machine(kernel=str(ELF), extra_args=["-icount", BOARD["test_icount"]],
                              timeout=60, **MACHINE_ARGS) as m:
        text = m.console.read_until(b"POSIX READY FOR INPUT\r\n", timeout=120).decode("latin-1")
        m.console.write(b"posix line\r")
        text += m.console.read_until(b"failed\r\n", timeout=60).decode("latin-1")
    figures = dict(re.findall(r"POSIX FIGURE (\S+) (-?\d+)", text))
    out = ROOT / "build" / "posix" / ("figures.txt" if BOARD_NAME == "robocube" else f"figures-{BOARD_NAME}.txt")
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text("".join(f"{k} {v}\n" for k, v in sorted(figures.items())))
    return text


@pytest.mark.parametrize("name", TESTS)
def test_on_the_board(console, name):
    m = re.search(rf"POSIX TEST {name}: (PASS|FAIL[^\r\n]*)", console)
    assert m, f"{name} did not report:\n{console}"
    assert m.group(1) == "PASS", m.group(1)


def test_every_test_reported_and_nothing_else(console):
    names = re.findall(r"POSIX TEST (\S+):", console)
    assert names == TESTS, names
    assert f"POSIX RESULT {len(TESTS)} passed, 0 failed" in console, console
    assert "EXCEPTION" not in console, console
