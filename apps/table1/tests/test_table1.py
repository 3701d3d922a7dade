"""table1 on the board K_BOARD names (robocube, the default, stm32f405 or mps2-an385),
through `make run` as a user runs it: the unchanged bsched.c in the kernel's
B-scheduler thread prints the paper's Table 2 row by row, the periods it
measured and the kernel's own accounting of the thread, in the same format on
every board. On every board but the RoboCube table1 is make run's default
image, so it runs there without APP (that default is checked too).

Run by `make check-firmware-boot` (the RoboCube), `make check-stm32f405-firmware`
(K_BOARD=stm32f405) and `make check-mps2-an385-firmware` (K_BOARD=mps2-an385).
"""
import os
import re
import subprocess
from pathlib import Path

from robocube_emu import launch

ROOT = Path(__file__).resolve().parents[3]
BOARD = os.environ.get("K_BOARD", "robocube")
BOARD_NAMES = {"robocube": ("RoboCube", "MC68332"), "stm32f405": ("STM32F405", "Cortex-M4 (STM32F405)"),
               "mps2-an385": ("MPS2 AN385", "Cortex-M3 (MPS2 AN385)")}
RUN_SECONDS = 5

# The paper's Table 1 process set and Table 2 (one major cycle).
NAMES = ["p1.1", "p1.2", "p1.3", "p2.1", "p2.2", "p3.1", "p4.1", "p4.2", "p4.3"]
PV = [1, 1, 1, 2, 2, 3, 4, 4, 4]
TABLE2 = [
    "p1.1 p1.3 p3.1", "p1.2 p2.1", "p1.1 p1.3 p4.3", "p1.2 p2.2",
    "p1.1 p1.3 p4.1", "p1.2 p2.1", "p1.1 p1.3", "p1.2 p2.2",
    "p1.1 p1.3 p3.1", "p1.2 p2.1", "p1.1 p1.3", "p1.2 p2.2",
    "p1.1 p1.3 p4.2", "p1.2 p2.1", "p1.1 p1.3", "p1.2 p2.2",
]
MAJOR_CYCLES = 4          # TABLE1_MAJOR_CYCLES in apps/table1/table1.c
TICK_HZ = 128             # table1_TICK_HZ in apps/table1/app.mk (the image's K_TICK_HZ)
B_SCHED_PRIORITY = 27     # K_PRIO_APP_MAX in kernel/include/k_config.h


def check_table1_text(text):
    """What table1 prints on any board: Table 2 row by row, the measured
    periods, the kernel's accounting."""
    assert f"tick {TICK_HZ} Hz" in text
    # The cycles run in the nanokernel's B-scheduler thread, one per kernel tick.
    assert (f"nanokernel: tick {TICK_HZ} Hz, B-scheduler thread at priority "
            f"{B_SCHED_PRIORITY}, 1 tick per minor cycle") in text, text
    cycles = re.findall(r"^cycle (\d+):((?: p\d\.\d)*)$", text, re.M)
    assert len(cycles) == 16 * MAJOR_CYCLES, text
    for i, (t, names) in enumerate(cycles):
        assert int(t) == i % 16, f"line {i}: cycle {t}"
        assert names.strip() == TABLE2[i % 16], f"minor cycle {i}: {names!r} != Table 2 row {i % 16}"

    m = re.search(r"^ran (\d+) minor cycles in (\d+) ticks, (\d+) ticks missed$", text, re.M)
    assert m, text
    assert int(m.group(1)) == 16 * MAJOR_CYCLES
    assert int(m.group(2)) == 16 * MAJOR_CYCLES, "one minor cycle per PIT tick"
    assert int(m.group(3)) == 0

    periods = dict(re.findall(r"^period (p\d\.\d): (.*)$", text, re.M))
    assert sorted(periods) == sorted(NAMES)
    for name, pv in zip(NAMES, PV):
        runs = 16 * MAJOR_CYCLES // 2 ** pv
        assert periods[name] == f"{2 ** pv} ticks ({runs} runs)", (name, periods[name])

    # The kernel's own accounting of the B-scheduler thread agrees: every
    # cycle ran, none overran (no report line either), no console byte lost.
    m = re.search(r"^bsched thread: (\d+) minor cycles from tick (\d+), overruns: (\d+), "
                  r"longest cycle (\d+) ticks, console bytes dropped: (\d+)$", text, re.M)
    assert m, text
    assert int(m.group(1)) == 16 * MAJOR_CYCLES
    assert int(m.group(3)) == 0, "overruns"
    assert int(m.group(4)) == 0, "a minor cycle crossed a tick"
    assert int(m.group(5)) == 0, "console bytes dropped"
    assert "bsched: overrun" not in text and "still running" not in text
    assert "failed" not in text and "EXCEPTION" not in text



def test_make_run_prints_table2():
    assert BOARD in launch.BOARDS, f"K_BOARD={BOARD}: no such board"
    app = ["APP=table1"] if BOARD == "robocube" else []
    env = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MAKELEVEL")}
    r = subprocess.run(["make", "--no-print-directory", "run", f"BOARD={BOARD}", *app,
                        f"RUN_SECONDS={RUN_SECONDS}"], cwd=ROOT, env=env, capture_output=True,
                       text=True, timeout=RUN_SECONDS + 300)
    assert r.returncode == 0, r.stdout + r.stderr
    text = r.stdout.replace("\r\n", "\n")
    name, cpu = BOARD_NAMES[BOARD]
    assert f"{name} firmware: B-scheduler, Table 1 process set" in text, text
    assert f"cpu {cpu} " in text, text
    assert "table1.elf" in r.stderr     # make run's banner names the image it boots
    check_table1_text(text)
