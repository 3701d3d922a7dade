"""Target tests of the nanokernel: boots build/kernel/target/ktest-<mode>.elf
on qemu-system-m68k -M robocube and judges what the image prints on the
console (DUART B). The figures the image reports are checked here too, so a
test image that wrongly claims PASS still fails.

QEMU runs with -icount shift=8,sleep=off: every guest instruction takes
256 ns of virtual time (about 3.9 MIPS, near what a 16.78 MHz CPU32 does),
so tick counts are deterministic, and idle time is skipped.

Environment (set by `make check-kernel-target`):
  BSCHED_QEMU    qemu-system-m68k with the robocube machine
  K_TARGET_DIR   build/kernel/target
  CROSS_PREFIX   m68k-linux-gnu-
  K_BOARD        robocube (default) or another board of
                 robocube_emu.launch.BOARDS: the same images built for it, on
                 its machine (make check-NAME-kernel: stm32f405 on
                 qemu-system-arm -M netduinoplus2, mps2-an385 on -M mps2-an385)
"""
import os
import re
from pathlib import Path

from robocube_emu import launch
from robocube_emu.exectrace import run_until_result

import kmeasure

ROOT = Path(__file__).resolve().parents[3]
QEMU = os.environ.get("BSCHED_QEMU", "")
IMAGES = Path(os.environ.get("K_TARGET_DIR", ROOT / "build" / "kernel" / "target"))
CROSS = os.environ.get("CROSS_PREFIX", "m68k-linux-gnu-")
MACHINE = kmeasure.BOARD["machine"]
TIME_LIMIT = 60.0  # wall seconds per image
# The fine counter each board registers (k_timestamp_register): the RoboCube's
# TCR1 at fsys/16, the STM32F405's processor clock through SysTick.
TIMESTAMP_HZ = {"robocube": 1_048_576, "netduinoplus2": 168_000_000, "mps2-an385": 25_000_000}


def run_image(mode, limit, extra=()):
    """Runs one image until it prints its result line or `limit` wall seconds
    pass; returns (console text, qemu stderr)."""
    assert QEMU and os.access(QEMU, os.X_OK), f"BSCHED_QEMU not executable: {QEMU!r}"
    elf = IMAGES / f"ktest-{mode}.elf"
    assert elf.is_file(), f"missing {elf} (make kernel-target)"
    cmd = launch.command(["-serial", "stdio", *extra], kernel=elf, qemu=QEMU, machine=MACHINE,
                         icount=kmeasure.BOARD["test_icount"])
    out, err = run_until_result(cmd, limit)
    return out.decode("latin-1").replace("\r\n", "\n"), err


def boot(mode, extra=(), limit=TIME_LIMIT):
    """Runs one image until it prints its result line; returns the console text."""
    text, err = run_image(mode, limit, extra)
    assert "KTEST RESULT" in text, (
        f"{mode}: no result line within {limit} s; console:\n{text}\nqemu stderr:\n"
        f"{err.decode('latin-1')}")
    return text


def facts(text):
    """key=value pairs from the KTEST lines (values as int when they are)."""
    found = {}
    for line in text.splitlines():
        if line.startswith("KTEST "):
            for key, value in re.findall(r"(\w+)=(\S+)", line):
                try:
                    found[key] = int(value)
                except ValueError:
                    found[key] = value
    return found


def passed(text):
    results = re.findall(r"KTEST RESULT (.*)", text)
    assert results == ["PASS"], f"image reported {results}; console:\n{text}"


# Kernel status codes (kernel/include/kernel.h).
K_EPERM, K_EAGAIN, K_EINVAL, K_EDEADLK = -1, -11, -22, -35
K_ETIMEDOUT, K_EISR, K_ESTACK = -110, -200, -201


def test_preemption_of_busy_threads():
    text = boot("preempt")
    f = facts(text)
    passed(text)
    assert f["slept"] == 200           # the sleeper woke on time although nobody yields
    assert f["spins_a"] > 0 and f["spins_b"] > 0
    assert f["spinner_switches"] >= 15  # ~200 ticks in 10-tick slices


def test_priority_order():
    text = boot("priority")
    passed(text)
    assert facts(text)["order"] == "HML"


def test_semaphore_timeouts_and_handoff():
    text = boot("semaphore")
    f = facts(text)
    passed(text)
    assert f["timeout_rc"] == K_ETIMEDOUT and f["timeout_waited"] == 100
    # one second from now, absolute, rounded up to the tick
    assert f["timedwait_rc"] == K_ETIMEDOUT and f["timedwait_waited"] in (1023, 1024)
    assert f["post_rc"] == 0 and f["latency"] == 0


def test_priority_inheritance():
    text = boot("inherit")
    f = facts(text)
    passed(text)
    assert f["low_prio_inside"] == 20 and f["low_prio_after"] == 3
    assert f["high_got"] < f["medium_done"]


def test_queue_full_and_empty():
    text = boot("queue")
    f = facts(text)
    passed(text)
    assert f["empty_rc"] == K_EAGAIN and f["full_rc"] == K_EAGAIN
    assert f["timed_full_rc"] == K_ETIMEDOUT and f["waited"] == 25 and f["count"] == 8
    assert f["received"] == 2000 and f["bad"] == 0


def test_sleep_until_drift_10000_ticks():
    text = boot("drift")
    f = facts(text)
    passed(text)
    assert f["periods"] == 10000 and f["elapsed"] == 10000
    assert f["late"] == 0 and f["max_late"] == 0
    # 10000 ticks at 1024 Hz, as clock_gettime sees it (one-tick resolution)
    assert abs(f["clock_us"] - 10000 * 1_000_000 // 1024) <= 1


def test_bsched_overrun_detected_and_reported():
    text = boot("overrun")
    f = facts(text)
    passed(text)
    assert f["overrun_events"] == 1 and f["overruns"] >= 2
    assert f["cycles"] == 40 and f["runs0"] == 40 and f["runs1"] == 10
    reports = re.findall(r"bsched: overrun in minor cycle (\d+): (\d+) ticks late, "
                         r"(\d+) overruns in (\d+) cycles", text)
    assert len(reports) == 1, text
    cycle, late, overruns, events = map(int, reports[0])
    assert cycle == 8       # process 1 (pv 2) runs in cycles 0, 4, 8: its 3rd run is slow
    assert late >= 3 and overruns == f["overruns"] and events == 1
    # announced while it still ran, at the release of cycle 9
    assert f["stuck_reports"] == 1
    assert re.search(r"bsched: minor cycle 8 still running at its successor's release", text)


def test_lower_thread_progresses_under_continuous_overrun():
    """Every B-scheduler cycle overruns (its process waits 2 ticks, period 1):
    the reporter is rate-limited, so the lowest thread keeps most of its share;
    and the interrupt handlers run on the interrupt stack, not on its stack."""
    text = boot("overload")
    f = facts(text)
    passed(text)
    assert f["overrun_events"] >= f["window"] // 4       # continuous overrun
    assert f["report_lines"] <= 2 * (f["window"] // f["interval"] + 1)
    assert f["share_permille"] >= 800, f                   # measured 898
    assert len(re.findall(r"bsched: overrun in minor cycle", text)) <= 3
    assert f["spinner_stack_used"] < 256                   # measured 116
    assert 0 < f["irq_stack_used"] < f["irq_stack_bytes"]


def test_interrupts_nest_on_the_interrupt_stack():
    """The DUART's level 5 taken inside the tick handler (level 4): it runs on
    the interrupt stack below the tick handler's frame, not on the interrupted
    thread's stack, and the system goes on."""
    text = boot("nesting")
    f = facts(text)
    passed(text)
    assert "KTEST nesting: this line leaves from inside the tick interrupt" in text
    assert f["used_before"] <= f["tick_depth"] + 64          # the refill below the handler
    assert f["used_after"] >= f["tick_depth"] + 64 + 32, f   # measured 176 (tick frame 49)
    assert f["used_after"] < f["irq_stack_bytes"]
    assert f["spinner_stack_used"] < 256                     # measured 116


def test_control_block_overwrite_detected_and_halts():
    """A stack overflowing two words past its guard words into the control
    block below it: found at the thread's next switch, reported, halted.
    On a board whose MPU guards the stacks (stm32f405) the first write into
    the guard stops the thread instead: the block stays intact, the system
    goes on."""
    text, err = run_image("tcbguard", limit=8.0)
    victim = int(facts(text)["victim"], 16)
    if kmeasure.BOARD.get("mpu_stack_guard"):
        passed(text)
        assert "kernel: stack overflow in thread 'victim'" in text, text
        assert "overwritten" not in text and "EXCEPTION" not in text
        return
    assert (f"kernel: control block of the thread at 0x{victim:08x} overwritten "
            "(a stack overflowed into it): halted") in text, text
    # the controller would print a FAIL line 50 ticks later if anything still ran
    assert "KTEST RESULT" not in text, text
    assert "EXCEPTION" not in text


def test_stack_guard():
    text = boot("stackguard")
    f = facts(text)
    passed(text)
    assert "kernel: stack overflow in thread 'deep-recursion'" in text
    assert f["join_rc"] == K_ESTACK and f["overflows"] == 1 and f["state"] == 3


def test_bad_use_gets_error_codes():
    text = boot("baduse")
    f = facts(text)
    passed(text)
    assert f["unlock_not_owner"] == K_EPERM
    assert f["full_queue"] == K_EAGAIN
    assert f["isr_wait"] == K_EISR and f["isr_lock"] == K_EISR and f["isr_send"] == K_EISR
    assert f["relock"] == K_EDEADLK and f["null_sem"] == K_EINVAL and f["self_join"] == K_EDEADLK
    assert f["console_drops"] == 0
    assert "EXCEPTION" not in text


def test_measure_instruction_counts():
    """Instruction counts of a tick with a switch and of a semaphore hand-off
    (kmeasure.py); written to build/kernel/measure.txt for the README."""
    r = kmeasure.measure(QEMU, IMAGES / "ktest-measure.elf")
    assert "KTEST RESULT PASS" in r["console"], r["console"]
    tick, handoff = r["tick_switch"], r["sem_handoff"]
    assert len(tick) >= 10 and len(handoff) >= 10, (len(tick), len(handoff))
    # sanity bounds: a switch needs more than the 20-odd instructions of
    # k_arch_switch itself, and far fewer than a tick's worth (~3800)
    for counts in (tick, handoff):
        assert 40 < min(counts) and max(counts) < 2000, counts
    out = IMAGES.parent / "measure.txt"
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(kmeasure.summary("tick interrupt with a context switch", tick) + "\n" +
                   kmeasure.summary("semaphore hand-off between two threads", handoff) + "\n")


def test_bsched_records_execution_times_and_jitter():
    """The B-scheduler thread's records on the board's fine counter: four
    processes of known work (short, short, 20x, 5x busy loops) must measure in
    that order and scale, within the bounds the image states; release jitter
    must be positive and under a quarter tick for every cycle. The figures go
    to build/.../timing.txt for MEASUREMENTS.md."""
    text = boot("timing")
    f = facts(text)
    passed(text)
    hz, per_tick = f["hz"], f["hz"] // f["tick_hz"]
    assert hz == TIMESTAMP_HZ[MACHINE], f  # the board's counter, not the tick fallback
    assert abs(f["slept_100_ticks"] - 100 * per_tick) <= per_tick // 8, f
    assert (f["runs0"], f["runs1"], f["runs2"], f["runs3"]) == (64, 64, 32, 16)
    short = max(f["worst0"], f["worst1"])
    assert 0 < min(f["worst0"], f["worst1"]) and short < 2 * min(f["worst0"], f["worst1"]), f
    assert 10 * short < f["worst2"] <= 21 * min(f["worst0"], f["worst1"]), f
    assert 2.5 * f["worst0"] < f["worst3"] <= 6 * f["worst0"] and f["worst2"] > 3 * f["worst3"], f
    assert f["jitter_samples"] == f["cycles"] == 64 and f["overruns"] == 0
    assert 0 < f["jitter_min"] <= f["jitter_mean"] <= f["jitter_max"] < per_tick // 4, f
    us = lambda counts: counts * 1e6 / hz  # noqa: E731
    out = IMAGES.parent / "timing.txt"
    out.write_text(
        f"counter {hz} Hz ({1e9 / hz:.3f} ns a count), tick {f['tick_hz']} Hz\n"
        + "".join(f"process {i} (work {w}): worst {f[f'worst{i}']} counts = {us(f[f'worst{i}']):.2f} us"
                  f" over {f[f'runs{i}']} runs\n" for i, w in enumerate(("1x", "1x", "20x", "5x")))
        + f"release jitter over {f['jitter_samples']} cycles: min {f['jitter_min']} "
          f"({us(f['jitter_min']):.2f} us), mean {f['jitter_mean']} ({us(f['jitter_mean']):.2f} us), "
          f"max {f['jitter_max']} ({us(f['jitter_max']):.2f} us)\n")
