"""The firmware on the stm32f405 board (qemu-system-arm -M netduinoplus2):
table1 in virtual time (its Table 2 through `make run`: apps/table1/tests), the
shell through `make run`, the fault reports of the ARMv7-M
port, PDL on the board's ports, and make's refusals (an unknown board, an
image that needs what the board lacks, an image for another board).

Environment (set by `make check-stm32f405-firmware`):
  STM32_BUILD    build/stm32f405 (images)
  QEMU_ARM       qemu-system-arm
  STM32_ICOUNT   the -icount setting of make run on this board
"""
import os
import re
import subprocess
import time
from pathlib import Path

import pytest

import robocube_emu

ROOT = Path(__file__).resolve().parents[3]
BUILD = Path(os.environ.get("STM32_BUILD", ROOT / "build" / "stm32f405"))
QEMU = os.environ.get("QEMU_ARM", "qemu-system-arm")
ICOUNT = os.environ.get("STM32_ICOUNT", "shift=3,sleep=off")


def make(*args, timeout=120, stdin=""):
    env = dict(os.environ)
    env.pop("MAKEFLAGS", None)
    env.pop("MAKELEVEL", None)
    return subprocess.run(["make", "--no-print-directory", *args], cwd=ROOT, env=env,
                          input=stdin, capture_output=True, text=True, timeout=timeout)


def boot(elf):
    """The image on netduinoplus2, its console (USART1) on a robocube_emu socket,
    read as it comes (robocube_emu.SerialPort), started once every socket is in
    place (robocube_emu.Machine)."""
    return robocube_emu.Machine(kernel=elf, qemu=QEMU, machine="netduinoplus2",
                                serial_names=("console",), extra_args=["-icount", ICOUNT])


def symbol(elf, name):
    out = subprocess.run(["arm-none-eabi-nm", str(elf)], check=True, capture_output=True,
                         text=True).stdout
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 3 and parts[2] == name:
            return int(parts[0], 16)
    raise AssertionError(f"symbol {name} not in {elf}")


def test_table1_runs_in_virtual_time():
    """Under -icount the run repeats exactly: the same console text twice."""
    elf = BUILD / "table1" / "table1.elf"
    texts = []
    for _ in range(2):
        with boot(elf) as m:
            texts.append(m.console.read_until(b"table1 done at tick", 20.0))
    assert texts[0] == texts[1]


def test_qmp_answers_while_the_console_is_not_read():
    """QMP answers while the board prints and the test reads neither: table1's
    first 2 KB leave QEMU's USART faster than its console socket holds them
    (~280 one-byte sends), and QEMU writes each byte holding its big lock. With
    the console read only when the test asks (before robocube_emu's pump), the
    second QMP command never got an answer: the vCPU waited for the reader, the
    main loop for the vCPU."""
    elf = BUILD / "table1" / "table1.elf"
    with boot(elf) as m:
        m.qmp.sock.settimeout(20.0)
        m.qmp.timeout = 20.0
        # Until the board has printed more than a socket's worth; virtual time
        # runs only as the host gives QEMU the CPU, so wait for the bytes, not a time.
        deadline = time.monotonic() + 60
        while len(m.console.received) < 1024:
            assert time.monotonic() < deadline, f"table1 printed {len(m.console.received)} bytes in 60 s"
            time.sleep(0.05)
        assert m.qmp_cmd("query-status")["running"]
        text = m.console.read_until(b"table1 done at tick", 60.0)
    assert b"major cycle" in text


FAULTS = {
    # kind: (exception number, name, CFSR bit, what the reporter says, stack)
    "unmapped": (5, "BusFault", 1 << 9, "precise data bus error", "main"),
    "undef": (6, "UsageFault", 1 << 16, "undefined instruction", "main"),
    "divzero": (6, "UsageFault", 1 << 25, "divide by zero", "main"),
    "thread": (5, "BusFault", 1 << 9, "precise data bus error", "thread, process"),
}
REPORT = (r"\*\*\* EXCEPTION vector=(\d+) \((\w+)\) pc=0x([0-9a-f]{8}) xpsr=0x([0-9a-f]{8}) "
          r"lr=0x([0-9a-f]{8}) cfsr=0x([0-9a-f]{8}) hfsr=0x([0-9a-f]{8})")


@pytest.mark.parametrize("kind", sorted(FAULTS))
def test_fault_report_names_the_instruction(kind):
    exc, name, bit, what, stack = FAULTS[kind]
    elf = BUILD / "tests" / f"fault-{kind}.elf"
    insn = symbol(elf, "fault_instruction")
    with boot(elf) as m:
        text = m.console.read_until(b"*** halted", 10.0).decode("latin-1").replace("\r\n", "\n")
        # QEMU answers after the report, so the halt is the firmware's, not QEMU's end.
        assert m.qmp_cmd("query-status")["running"], "QEMU stopped the CPU: " + m.stderr()
        assert m.proc.poll() is None, "QEMU itself stopped: " + m.stderr()
    assert f"faulting instruction at 0x{insn:08x}" in text
    assert "no exception was taken" not in text
    # start.c copied .data and cleared .bss
    assert "startup: data_check=0x5a17c0de bss_check=0x00000000" in text
    r = re.search(REPORT, text)
    assert r, text
    assert int(r.group(1)) == exc and r.group(2) == name
    assert int(r.group(3), 16) == insn, "the stacked PC is the faulting instruction"
    assert int(r.group(4), 16) & (1 << 24), "xPSR Thumb bit"
    assert int(r.group(6), 16) & bit and f"  {what}\n" in text
    assert f"{stack} stack)" in text
    if name == "BusFault":
        assert "BusFault address 0x5a000000" in text
        assert "R0=5a000000" in text                  # the stacked R0: the address loaded
    if kind == "thread":
        assert "in thread 'faulter'" in text


SHELL_PROMPT = "shell> "


def shell_session(lines, seconds=30):
    """`printf LINES | make run BOARD=stm32f405 APP=shell RUN_SECONDS=seconds`:
    (make's status, {command: its answer lines}, the whole console text)."""
    r = make("run", "BOARD=stm32f405", "APP=shell", f"RUN_SECONDS={seconds}",
             stdin="".join(line + "\n" for line in lines), timeout=seconds + 60)
    text = r.stdout.replace("\r\n", "\n")
    answers = []
    for chunk in text.split(SHELL_PROMPT)[1:]:
        echo, _, rest = chunk.partition("\n")
        answers.append((echo, [a for a in rest.split("\n") if a]))
    return r, answers, text


def test_shell_runs_its_common_commands():
    """The shell on this board: the commands that need no RoboCube I/O board
    (help, led, ps, uptime, sleep, console, exit); the I/O board's are unknown
    here; exit switches the board off, which ends make run with status 0."""
    r, answers, text = shell_session(["help", "led on", "led", "led off", "ad 5", "uptime",
                                      "sleep 500", "uptime", "ps", "x" * 81, "led blink",
                                      "console", "exit"])
    assert r.returncode == 0, (r.stderr, text)
    assert "STM32F405 shell: 'help' lists the commands" in text
    said = dict(answers)
    # the echo of the over-long line stops at the 80 characters a line may have
    assert [echo for echo, _ in answers] == ["help", "led on", "led", "led off", "ad 5", "uptime",
                                             "sleep 500", "uptime", "ps", "x" * 80, "led blink",
                                             "console", "exit"], text
    assert [a.split()[0] for a in said["help"]] == ["help", "led", "ps", "uptime", "sleep",
                                                    "console", "exit"]
    assert said["led on"] == ["led = on"] and said["led"] == ["led = on"]
    assert said["led off"] == ["led = off"]
    assert said["ad 5"] == ["error: unknown command 'ad' (try help)"]
    uptimes = [int(m.group(1)) for _, a in answers if a and (m := re.match(
        r"uptime \d+\.\d{3} s \((\d+) ticks at 1024 Hz\)$", a[0]))]
    assert len(uptimes) == 2 and uptimes[1] - uptimes[0] >= 512, answers   # slept 500 ms
    assert said["sleep 500"] == ["slept 500 ms"]
    ps = said["ps"]
    assert ps[0].split() == ["thread", "prio", "state", "stack", "used", "switches"]
    assert re.match(r"shell +10 run +\d+/4096 +\d+$", ps[1]) and ps[2].startswith("idle ")
    assert re.match(r"interrupt stack \d+/\d+$", ps[-1])
    assert said["x" * 80] == ["error: line too long (more than 80 characters), ignored"]
    assert said["led blink"] == ["error: led: 'blink': say on or off"]
    m = re.match(r"console: (\d+) bytes, (\d+) lines, 1 too long, ring full 0 times, "
                 r"0 overruns, 0 errors$", said["console"][0])
    assert m and int(m.group(2)) == 11, said["console"]
    assert said["exit"] == ["shell: exit: board off"]


def test_shell_burst_larger_than_the_ring_loses_nothing():
    """Far more than the 256-byte receive ring at once: the USART's receive
    interrupt pauses while the ring is full (the byte waits in the chip) and
    resumes as the shell drains it, so every line is answered, in order."""
    # the shell sleeps first, so the burst piles up in the ring
    lines = ["sleep 2000"] + [f"led {'on' if i % 2 else 'off'}" for i in range(80)] + ["console", "exit"]
    r, answers, text = shell_session(lines)
    assert r.returncode == 0, (r.stderr, text)
    assert [echo for echo, _ in answers] == lines, text
    for i, (_echo, answer) in enumerate(answers[1:81]):
        assert answer == [f"led = {'on' if i % 2 else 'off'}"], (i, answer)
    m = re.match(r"console: (\d+) bytes, 82 lines, 0 too long, ring full (\d+) times, "
                 r"0 overruns, 0 errors$", answers[81][1][0])
    assert m and int(m.group(2)) >= 1, answers[81]


def test_make_run_with_a_reader_that_goes_away_leaves_no_emulator():
    """`make run BOARD=stm32f405 | head`, piped input: when the reader goes
    away, the console gate stops the board (an emulator once ran on, orphaned,
    for 45 minutes at most of a core)."""
    elf = str(BUILD / "table1" / "table1.elf")
    env = {k: v for k, v in os.environ.items() if k not in ("MAKEFLAGS", "MAKELEVEL")}
    r = subprocess.run(["bash", "-c", "make --no-print-directory run BOARD=stm32f405 APP=table1 "
                        "RUN_SECONDS=60 </dev/null | head -c 100"], cwd=ROOT, env=env,
                       capture_output=True, text=True, timeout=120)
    assert "STM32F405 firmware" in r.stdout, r.stdout + r.stderr
    deadline = time.monotonic() + 10
    while time.monotonic() < deadline:
        left = subprocess.run(["pgrep", "-f", f"qemu-system-arm.*{elf}"], capture_output=True,
                              text=True).stdout.split()
        if not left:
            break
        time.sleep(0.2)
    assert not left, f"emulators left running: {left}"


def test_make_run_refuses_an_unknown_board():
    r = make("run", "BOARD=pdp11", "APP=table1")
    assert r.returncode == 2
    lines = [line for line in r.stderr.splitlines() if line.strip()]
    assert len(lines) == 1, r.stderr
    assert "BOARD=pdp11: no such board" in lines[0] and "robocube|stm32f405" in lines[0]


def test_image_that_needs_what_the_board_lacks_says_so():
    """netnode needs the radio channel this board lacks: make stops before
    compiling anything, in one line naming the board and what it lacks."""
    r = make("firmware", "BOARD=stm32f405", "APP=netnode")
    assert r.returncode == 2
    lines = [line for line in r.stderr.splitlines() if line.strip()]
    assert len(lines) == 1, r.stderr
    assert "APP=netnode needs radio: BOARD=stm32f405 lacks it" in lines[0], lines[0]
    assert not (BUILD / "netnode").exists()


def test_image_for_another_board_says_so():
    """iotest is the RoboCube's I/O board test (its DUART's internals): make
    stops in one line naming the boards it is for."""
    r = make("firmware", "BOARD=stm32f405", "APP=iotest")
    assert r.returncode == 2
    lines = [line for line in r.stderr.splitlines() if line.strip()]
    assert len(lines) == 1, r.stderr
    assert "APP=iotest is for BOARD=robocube only" in lines[0], lines[0]
    assert not (BUILD / "iotest").exists()


def test_pdl_program_with_the_boards_ports():
    """A PDL program on this board's ports: ADC1 channel 0 copied to TIM3's
    PWM channel 0 (read back from the timer), a simulated BIO line written and
    read back every cycle, no overrun in one second of cycles."""
    with boot(BUILD / "tests" / "pdl-ports.elf") as m:
        line = m.console.read_until(b"\n", 20.0).decode()
        while "PDL-PORTS" not in line:
            line = m.console.read_until(b"\n", 20.0).decode()
    f = {k: int(v, 0) for k, v in re.findall(r"(\w+)=(\S+)", line)}
    assert "FAIL" not in line, line
    assert 100 <= f["cycles"] <= 104 and f["overruns"] == 0, line    # ~100 Hz for 1 s
    assert f["adc_max"] > f["adc_min"], "the ADC gave one value only"   # QEMU: +7 per conversion
    assert f["ccr1"] == f["pwm"] and 0 <= f["pwm"] <= 510, "TIM3 CCR1 is the PWM actuator"
    assert f["loop_ok"] == f["cycles"] and f["loop_bad"] == 0, line
    assert f["adc_no_eoc"] > 0      # documented: QEMU's ADC never sets EOC


def test_pdl_hello_as_an_ordinary_program():
    """apps/pdl_hello unchanged (printf through newlib, main as a thread)."""
    with boot(BUILD / "pdl_hello" / "pdl_hello.elf") as m:
        text = m.console.read_until(b"t=3 s", 20.0)
        text += m.console.read_until(b"\n", 5.0)
    rows = re.findall(rb"t=(\d) s wheels=(-?\d+),(-?\d+) runs: cruise=(\d+) avoid=(\d+)", text)
    assert [int(r[0]) for r in rows] == [1, 2, 3], text
    for second, _left, _right, cruise, avoid in rows:
        assert abs(int(cruise) - 102 * int(second)) <= 3, text   # every cycle, ~102.4 Hz
        assert abs(int(avoid) - 51 * int(second)) <= 2, text     # every second cycle


def test_pdl_bench_passes_on_this_board():
    """apps/pdl_bench: no overrun at f0 = 1024 Hz with 20 processes and 40
    quantities, and its overloaded program's overruns counted and reported."""
    with boot(BUILD / "pdl_bench" / "pdl_bench.elf") as m:
        text = m.console.read_until(b"PDL-BENCH RESULT", 60.0)
        text += m.console.read_until(b"\n", 5.0)
    text = text.decode("latin-1").replace("\r\n", "\n")
    assert "PDL-BENCH RESULT PASS" in text, text
    load = dict(re.findall(r"(\w+)=(\d+)", re.search(r"PDL-BENCH load .*", text).group(0)))
    assert int(load["overruns"]) == 0 and int(load["load_permille"]) <= 500
    over = dict(re.findall(r"(\w+)=(\d+)", re.search(r"PDL-BENCH overload .*", text).group(0)))
    assert int(over["overruns"]) >= int(over["cycles"]) > 0
    assert int(over["max_cycle_ticks"]) > 16            # longer than its 16-tick period
    assert re.search(r"bsched: overrun in minor cycle \d+: \d+ ticks late", text), text
