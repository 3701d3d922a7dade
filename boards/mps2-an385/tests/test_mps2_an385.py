"""The firmware on the mps2-an385 board (qemu-system-arm -M mps2-an385, a
Cortex-M3): table1 repeats exactly in virtual time, its LED thread blinks the
FPGA's LED0 (read back from QEMU's model of the register), an ordinary
program prints through newlib, and make refuses what the board lacks.
table1's Table 2 through `make run` is apps/table1/tests (K_BOARD=mps2-an385).

Environment (set by `make check-mps2-an385-firmware`):
  MPS2_BUILD     build/mps2-an385 (images)
  BSCHED_QEMU    qemu-system-arm
"""
import os
import re
import subprocess
import time
from pathlib import Path

import robocube_emu
from robocube_emu import launch

ROOT = Path(__file__).resolve().parents[3]
BUILD = Path(os.environ.get("MPS2_BUILD", ROOT / "build" / "mps2-an385"))
QEMU = os.environ.get("BSCHED_QEMU", "qemu-system-arm")
BOARD = launch.board("mps2-an385")
LED_REGISTER = 0x40028000     # FPGAIO_LED (boards/mps2-an385/mps2_an385.h)


def make(*args, timeout=300):
    env = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MAKELEVEL")}
    return subprocess.run(["make", "--no-print-directory", *args], cwd=ROOT, env=env,
                          capture_output=True, text=True, timeout=timeout)


def boot(elf):
    return robocube_emu.Machine(kernel=str(elf), qemu=QEMU, machine=BOARD["machine"],
                                serial_names=("console",), extra_args=["-icount", BOARD["icount"]])


def led(m):
    """LED0 as the board model holds it (QEMU's monitor reads the register)."""
    out = m.qmp_cmd("human-monitor-command", **{"command-line": f"xp /1wx {LED_REGISTER:#x}"})
    value = re.search(r":\s*(0x[0-9a-f]+)", str(out))
    assert value, out
    return int(value.group(1), 16) & 1


def test_table1_runs_in_virtual_time():
    """Under -icount the run repeats exactly: the same console text twice."""
    texts = []
    for _ in range(2):
        with boot(BUILD / "table1" / "table1.elf") as m:
            texts.append(m.console.read_until(b"table1 done at tick", 30.0))
    assert b"cycle 15:" in texts[0]
    assert texts[0] == texts[1]


def test_led_blinks_after_table1():
    """After the run table1's LED thread toggles LED0 every 0.5 s: the
    register is seen both on and off."""
    with boot(BUILD / "table1" / "table1.elf") as m:
        m.console.read_until(b"LED thread blinks at 1 Hz", 30.0)
        seen, deadline = set(), time.monotonic() + 30.0
        while seen != {0, 1} and time.monotonic() < deadline:
            seen.add(led(m))
            time.sleep(0.05)
    assert seen == {0, 1}, f"LED0 only ever read {seen}"


def test_ordinary_program_prints_through_newlib():
    """apps/hello unchanged: main as a thread, printf through newlib's stdio
    and the board's console."""
    with boot(BUILD / "hello" / "hello.elf") as m:
        text = m.console.read_until(b"42\r\n", 30.0).decode("latin-1")
    assert text.endswith("hello from the RoboCube\r\n42\r\n"), text


def test_make_refuses_what_the_board_lacks():
    r = make("firmware", "BOARD=mps2-an385", "APP=netnode")
    assert r.returncode == 2
    lines = [line for line in r.stderr.splitlines() if line.strip()]
    assert len(lines) == 1, r.stderr
    assert "APP=netnode needs radio: BOARD=mps2-an385 lacks it" in lines[0], lines[0]
    r = make("firmware", "BOARD=mps2-an385", "APP=shell")
    assert r.returncode == 2
    assert "APP=shell is for BOARD=robocube|stm32f405 only" in r.stderr, r.stderr
    assert not (BUILD / "netnode").exists() and not (BUILD / "shell").exists()
