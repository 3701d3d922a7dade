"""PDL on the emulated RoboCube.

test_demo_*: apps/pdl_demo (the example behaviours at f0 = 100 Hz) reads the
sensor values the host sets over QMP (analog inputs, DUART binary inputs)
through the drivers' sampler, and drives motors 0 and 1, which the host reads
over QMP (duty and direction of the motor model).

test_bench_*: apps/pdl_bench: the CPU load at f0 = 1024 Hz with 20 processes
and 40 quantities (goal: at most 50 %), the cycle thread's stack, the cost of
a cycle from an exec trace (figures in build/pdl/bench.txt), and an
overloaded program whose overruns are counted and reported.

Environment (make check-pdl-target): BSCHED_QEMU, FW_DIR (build/firmware).
"""
import os
import re
import time
from pathlib import Path

import pytest

import pdl_measure
import robocube_emu

ROOT = Path(__file__).resolve().parents[3]
FW = Path(os.environ.get("FW_DIR", ROOT / "build" / "firmware"))
QEMU = os.environ.get("BSCHED_QEMU", str(ROOT / "build" / "emu" / "qemu-system-m68k"))
ICOUNT = "shift=8,sleep=off"
IO = "/machine/robocube-io"
STATUS = re.compile(rb"PDL-DEMO (t_ms=[^\r\n]*)\r?\n")


class Demo:
    def __init__(self):
        elf = FW / "pdl_demo" / "pdl_demo.elf"
        assert elf.is_file(), f"missing {elf} (make firmware APP=pdl_demo)"
        self.m = robocube_emu.Machine(kernel=str(elf), extra_args=["-icount", ICOUNT])
        self.boot = self.m.console.read_until(b"PDL-DEMO running", timeout=30).decode("latin-1")

    def close(self):
        self.m.close()

    def status(self, timeout=20.0):
        line = self.m.console.read_until(b"\n", timeout=timeout)
        while not line.startswith(b"PDL-DEMO t_ms="):
            assert b"PDL-DEMO failed" not in line, line
            line = self.m.console.read_until(b"\n", timeout=timeout)
        fields = dict(re.findall(r"(\w+)=(\S+)", line.decode("latin-1")))
        return {k: [int(x) for x in v.split(",")] if "," in v else int(v)
                for k, v in fields.items()}

    def wait_status(self, cond, what, lines=60):
        seen = []
        for _ in range(lines):
            s = self.status()
            seen.append(s)
            if cond(s):
                return s
        raise AssertionError(f"{what}: not seen in {lines} status lines; last {seen[-3:]}")

    def motor(self, m):
        """Signed power in permille as the motor model sees it (QMP)."""
        path = f"{IO}/motor{m}"
        duty = self.m.qom_get(path, "duty")
        direction = self.m.qom_get(path, "direction")
        return direction * duty // 10

    def inputs(self, light=(0, 0), ir=(0, 0), battery=255, bumpers=(1, 1)):
        for ch, v in enumerate((light[0], light[1], ir[0], ir[1], battery)):
            self.m.qom_set(IO, f"ain{ch}", v)
        ip = 0x3F & ~((0 if bumpers[0] else 1 << 1) | (0 if bumpers[1] else 1 << 2))
        self.m.qom_set("/machine/duart", "input-port", ip)


@pytest.fixture
def demo():
    d = Demo()
    try:
        yield d
    finally:
        d.close()


def settled(d, cond, what):
    """Waits for a status line meeting cond whose motors the model also shows."""
    s = d.wait_status(cond, what)
    s2 = d.status()                     # the motors had half a second to settle
    left, right = d.motor(0), d.motor(1)
    # the model shows what the runtime wrote; the QMP read comes a little
    # later in virtual time, and wandering moves the motors by up to ~100
    assert abs(left - s2["motors"][0]) <= 150 and abs(right - s2["motors"][1]) <= 150, (
        s2, left, right)
    return s2, left, right


def test_demo_phototaxis_reads_qmp_light_and_turns_the_motors(demo):
    assert "analog: 6 PCF8591" in demo.boot, demo.boot
    # light difference 210: the turn alone puts the wheels >= 420 apart,
    # wandering at most ~100
    demo.inputs(light=(230, 20))
    s, left, right = settled(demo, lambda s: s["light"] == [230, 20], "light 230,20")
    assert right > left + 200, (s, left, right)         # turning left, toward the light
    demo.inputs(light=(20, 230))
    s, left, right = settled(demo, lambda s: s["light"] == [20, 230], "light 20,230")
    assert left > right + 200, (s, left, right)
    assert s["overruns"] == 0 and s["misuse"] == 0 and s["driver_errors"] == 0, s
    assert 0 < s["stack"] < 2048, s                      # the cycle thread's stack


def test_demo_avoids_obstacles_and_backs_up_on_a_bumper(demo):
    demo.inputs(ir=(220, 10))
    s, left, right = settled(demo, lambda s: s["ir"] == [220, 10], "ir 220,10")
    assert left > right + 300, (s, left, right)         # obstacle left: turn right
    demo.inputs(bumpers=(1, 0))                          # right bumper pressed (IP2 low)
    s, left, right = settled(demo, lambda s: s["bumpers"] == [1, 0], "bumper")
    assert left < 0 and right < 0, (s, left, right)     # backing up
    assert demo.m.qom_get(f"{IO}/motor0", "direction") == -1
    demo.inputs()
    s, left, right = settled(demo, lambda s: s["bumpers"] == [1, 1] and s["ir"] == [0, 0], "free")
    assert left > 250 and right > 250, (s, left, right)  # cruising again


def test_demo_low_battery_raises_the_motivation(demo):
    demo.inputs(battery=40)
    first = demo.wait_status(lambda s: s["battery"] == 40, "battery 40")
    later = demo.wait_status(lambda s: s["hunger"] >= first["hunger"] + 200, "hunger rising",
                             lines=30)
    assert later["cycles"] > first["cycles"]
    demo.inputs(battery=250)
    demo.wait_status(lambda s: s["hunger"] < later["hunger"], "hunger falling", lines=30)


@pytest.fixture(scope="module")
def bench_console():
    elf = FW / "pdl_bench" / "pdl_bench.elf"
    assert elf.is_file(), f"missing {elf} (make firmware APP=pdl_bench)"
    return pdl_measure.run_bench(QEMU, elf)


def test_bench_load_at_1khz_within_half_the_cpu(bench_console):
    assert "PDL-BENCH RESULT PASS" in bench_console, bench_console
    load = pdl_measure.facts(bench_console, "load")[0]
    assert load["f0_mhz"] == 1024000
    assert load["cycles"] >= 250 and load["overruns"] == 0
    assert 0 < load["load_permille"] <= 500, load
    assert 0 < load["stack_used"] < load["stack_size"] // 2, load
    for sweep in pdl_measure.facts(bench_console, "sweep"):
        assert sweep["overruns"] == 0 and sweep["commits"] == 2 * sweep["runs"], sweep


def test_bench_overloaded_program_reports_overruns(bench_console):
    over = pdl_measure.facts(bench_console, "overload")[0]
    assert over["overruns"] >= over["cycles"] > 0 and over["overrun_events"] == over["cycles"]
    assert over["max_cycle_ticks"] > 16            # longer than its 16-tick period
    reports = re.findall(r"bsched: overrun in minor cycle (\d+): (\d+) ticks late, "
                         r"(\d+) overruns in (\d+) cycles", bench_console)
    # the kernel's reporter prints at most one burst a second and sums the rest:
    # at least one line, and the last one carries the totals the image counted
    assert 1 <= len(reports) <= over["cycles"], bench_console
    assert all(int(late) >= 1 for _, late, _, _ in reports)
    assert int(reports[-1][2]) == over["overruns"], bench_console
    assert int(reports[-1][3]) == over["overrun_events"], bench_console


def test_bench_cycle_costs(bench_console):
    elf = FW / "pdl_bench" / "pdl_bench.elf"
    cycles, _ = pdl_measure.cycle_costs(QEMU, elf)
    assert {c["n"] for c in cycles} == set(pdl_measure.SWEEP)
    summary = pdl_measure.summarise(cycles)
    # sanity: a process run costs tens of instructions, a commit a couple dozen
    assert 40 < summary["per_process_run"] < 300, summary
    assert 10 < summary["per_commit"] < 80, summary
    per_n = summary["per_n"]
    assert per_n[5]["mean"] < per_n[10]["mean"] < per_n[20]["mean"] < per_n[30]["mean"]
    text = pdl_measure.report(bench_console, summary,
                              pdl_measure.footprint(elf.with_suffix(".map")))
    out = ROOT / "build" / "pdl" / "bench.txt"
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(text + "\n")
