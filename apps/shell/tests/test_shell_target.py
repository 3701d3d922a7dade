"""Target tests of the console shell (apps/shell): boots build/firmware/shell/shell.elf
on qemu-system-m68k -M robocube under -icount shift=8,sleep=off (deterministic),
types commands on the console (DUART B, a Unix socket) and checks every answer
against the board model over QMP: the host sets the inputs, the shell must
print them; the shell sets the outputs, the host must see them.

One machine serves the whole module (a boot costs about a second); every test
leaves the shell at its prompt. Environment (set by make check-shell-target):
  BSCHED_QEMU   qemu-system-m68k with the robocube machine
  SHELL_ELF     build/firmware/shell/shell.elf
"""
import os
import pty
import re
import select
import shutil
import signal
import subprocess
import tempfile
import time
from pathlib import Path

import pytest

import robocube_emu

ROOT = Path(__file__).resolve().parents[3]
ELF = Path(os.environ.get("SHELL_ELF", ROOT / "build" / "firmware" / "shell" / "shell.elf"))
IO = "/machine/robocube-io"
PROMPT = b"shell> "
LINE_MAX = 80          # SHELL_LINE_MAX in apps/shell/shell.h


def run_make(args, stdin=b"", timeout=120):
    """make ARGS in the tree with stdin, in a session of its own: on a timeout
    the whole group (make, its shell, timeout, QEMU) is killed, not make alone,
    so no emulator outlives the test. Returns (returncode, stdout, stderr)."""
    proc = subprocess.Popen(["make", "--no-print-directory", *args], cwd=ROOT,
                            stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, start_new_session=True)
    try:
        out, err = proc.communicate(stdin, timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        pytest.fail(f"make {' '.join(args)} still running after {timeout} s")
    return proc.returncode, out, err


class Shell:
    def __init__(self, machine):
        self.m = machine
        self.boot_text = machine.console.read_until(PROMPT, timeout=30).decode("latin-1")

    def run(self, line, timeout=20):
        """Types one line; returns the answer lines (echo and prompt removed)."""
        self.m.console.write(line.encode() + b"\r")
        out = self.m.console.read_until(PROMPT, timeout=timeout).decode("latin-1")
        lines = out.replace("\r\n", "\n").split("\n")
        # the echo of what was typed, then the answer, then the prompt
        assert lines[0] == line or len(line) > LINE_MAX, f"echo {lines[0]!r} of {line!r}"
        assert lines[-1] == PROMPT.decode()
        return lines[1:-1]

    def one(self, line):
        answer = self.run(line)
        assert len(answer) == 1, f"{line!r} answered {answer!r}"
        return answer[0]

    def error(self, line):
        """A refused line: exactly one answer line, starting with 'error:'."""
        answer = self.one(line)
        assert answer.startswith("error:"), f"{line!r} answered {answer!r}"
        return answer

    def qget(self, path, prop):
        return self.m.qom_get(path, prop)

    def qset(self, path, prop, value):
        self.m.qom_set(path, prop, value)


@pytest.fixture(scope="module")
def shell():
    qemu = robocube_emu.qemu_binary()
    assert os.access(qemu, os.X_OK)
    assert ELF.is_file(), f"missing {ELF} (make firmware APP=shell)"
    with robocube_emu.start(kernel=ELF, extra_args=["-icount", "shift=8,sleep=off"]) as m:
        yield Shell(m)


def test_boot_report_and_prompt(shell):
    text = shell.boot_text
    assert "RoboCube shell" in text
    # the drivers' boot report names the I/O board's chips on bus A
    for addr in ("0x38", "0x39", "0x48", "0x4d"):
        assert addr in text.lower(), text


def test_help_lists_every_command(shell):
    answer = shell.run("help")
    names = [line.split()[0] for line in answer]
    for cmd in ("help", "ad", "da", "bio", "bin", "fast", "pwm", "motor", "enc", "led",
                "ps", "uptime", "i2c", "console", "speed", "sleep", "net"):
        assert cmd in names, answer


@pytest.mark.parametrize("ch", [0, 5, 13, 23])
def test_ad_reads_what_the_host_set(shell, ch):
    for value in (0, 200, 255, 17):
        shell.qset(IO, f"ain{ch}", value)
        assert shell.one(f"ad {ch}") == f"ad {ch} = {value}"


def test_da_is_seen_by_the_host(shell):
    for ch, value in ((0, 0), (2, 100), (5, 255), (2, 37)):
        assert shell.one(f"da {ch} {value}") == f"da {ch} = {value}"
        assert shell.qget(IO, f"aout{ch}") == value
        assert shell.qget(IO, f"aout{ch}-enabled") == 1


def test_bio_write_and_read(shell):
    assert shell.one("bio 12 0") == "bio 12 = 0"
    assert (shell.qget(IO, "bio-out") >> 12) & 1 == 0
    assert shell.one("bio 12") == "bio 12 = 0"          # driven low by the latch
    assert shell.one("bio 12 1") == "bio 12 = 1"
    assert (shell.qget(IO, "bio-out") >> 12) & 1 == 1
    # released lines read what the outside drives
    shell.qset(IO, "bio-in", 0xFFFF & ~(1 << 3))
    assert shell.one("bio 3") == "bio 3 = 0"
    assert shell.one("bio 4") == "bio 4 = 1"
    shell.qset(IO, "bio-in", 0xFFFF)
    assert shell.one("bio 3") == "bio 3 = 1"


def test_bin_follows_the_host(shell):
    for n in range(1, 6):
        shell.qset("/machine/duart", "input-port", 0x3F & ~(1 << n))
        assert shell.one(f"bin {n}") == f"bin {n} = 0"
        other = n % 5 + 1
        assert shell.one(f"bin {other}") == f"bin {other} = 1"
    shell.qset("/machine/duart", "input-port", 0x3F)


def test_fast_is_seen_by_the_host(shell):
    assert shell.one("fast 7 1") == "fast 7 = 1"
    assert shell.qget(IO, "fastbin") & 0x80
    assert shell.one("fast 15 1") == "fast 15 = 1"
    assert shell.qget(IO, "fastbin") & 0x8080 == 0x8080
    assert shell.one("fast 7 0") == "fast 7 = 0"
    assert shell.qget(IO, "fastbin") & 0x8080 == 0x8000


def test_pwm_duty_and_frequency(shell):
    tpu = IO + "/tpu"
    assert shell.one("pwm 6 250 50") == "pwm 6 = 250 per-mille at 50 Hz"
    assert shell.qget(tpu, "ch6-duty") == 2500
    hz = shell.qget(tpu, "tcr1-hz") / shell.qget(tpu, "ch6-pwm-period")
    assert abs(hz - 50) < 0.5
    # without HZ the channel keeps its frequency
    assert shell.one("pwm 6 750") == "pwm 6 = 750 per-mille at 50 Hz"
    assert shell.qget(tpu, "ch6-duty") == 7500
    # the shell reports the frequency the TPU makes: 1048576 / 524 ticks = 2001 Hz
    m = re.match(r"pwm 9 = 1000 per-mille at (\d+) Hz$", shell.one("pwm 9 1000 2000"))
    assert m
    model_hz = shell.qget(tpu, "tcr1-hz") / shell.qget(tpu, "ch9-pwm-period")
    assert int(m.group(1)) == round(model_hz)
    assert abs(model_hz - 2000) < 2000 * 0.002
    assert shell.qget(tpu, "ch9-duty") == 10000


def test_motor_power_and_direction(shell):
    # duty in 1/10000 as the TPU makes it (1000 Hz = 1049 TCR1 ticks: steps of ~0.1 %)
    assert shell.one("motor 1 -500") == "motor 1 = -500 per-mille"
    assert abs(shell.qget(IO + "/motor1", "duty") - 5000) <= 10
    assert shell.qget(IO + "/motor1", "direction") == -1
    assert shell.one("motor 1 250") == "motor 1 = 250 per-mille"
    assert abs(shell.qget(IO + "/motor1", "duty") - 2500) <= 10
    assert shell.qget(IO + "/motor1", "direction") == 1
    assert shell.one("motor 1 0") == "motor 1 = 0 per-mille"
    assert shell.qget(IO + "/motor1", "direction") == 0


def test_enc_position_and_speed(shell):
    motor = IO + "/motor2"
    shell.qset(motor, "model-enabled", 0)        # the host alone moves the encoder
    start = int(re.match(r"enc 2 = (-?\d+) counts, (-?\d+) counts/s$",
                         shell.one("enc 2")).group(1))
    shell.qset(motor, "encoder", shell.qget(motor, "encoder") + 1234)
    m = re.match(r"enc 2 = (-?\d+) counts, (-?\d+) counts/s$", shell.one("enc 2"))
    assert int(m.group(1)) - start == 1234
    shell.qset(motor, "model-enabled", 1)
    # a running motor: position and speed follow the model
    shell.one("motor 0 1000")
    assert shell.one("sleep 300") == "slept 300 ms"   # six time constants of the model
    m = re.match(r"enc 0 = (-?\d+) counts, (-?\d+) counts/s$", shell.one("enc 0"))
    model_speed = shell.qget(IO + "/motor0", "speed")
    assert int(m.group(1)) > 0
    assert abs(int(m.group(2)) - model_speed) <= 0.1 * model_speed + 20, (m.group(0), model_speed)
    shell.one("motor 0 0")


def test_speed_closed_loop_reaches_its_set_point(shell):
    assert shell.one("speed 1 1000") == "speed 1 = 1000 counts/s"
    shell.one("sleep 500")
    m = re.match(r"enc 1 = (-?\d+) counts, (-?\d+) counts/s$", shell.one("enc 1"))
    assert abs(int(m.group(2)) - 1000) <= 50, m.group(0)
    assert abs(shell.qget(IO + "/motor1", "speed") - 1000) <= 50
    assert shell.qget(IO + "/motor1", "direction") == 1
    assert shell.one("motor 1 0") == "motor 1 = 0 per-mille"   # back to open loop, braked
    assert shell.qget(IO + "/motor1", "direction") == 0


def test_sleep_waits_in_virtual_time(shell):
    before = shell.qget("/machine/sim", "virtual-time-ns")
    assert shell.one("sleep 400") == "slept 400 ms"
    assert shell.qget("/machine/sim", "virtual-time-ns") - before >= 400_000_000


def test_led_is_seen_by_the_host(shell):
    assert shell.one("led on") == "led = on"
    assert shell.qget("/machine/sim", "led") is True
    assert shell.one("led") == "led = on"
    assert shell.one("led off") == "led = off"
    assert shell.qget("/machine/sim", "led") is False


def test_ps_lists_the_threads(shell):
    answer = shell.run("ps")
    assert answer[0].split()[:3] == ["thread", "prio", "state"]
    rows = {}
    irq = re.match(r"interrupt stack (\d+)/(\d+)$", answer[-1])
    assert irq and 0 < int(irq.group(1)) < int(irq.group(2)), answer[-1]
    for line in answer[1:-1]:
        m = re.match(r"(\S+)\s+(\d+) (\w+)\s+(\d+)/(\d+)\s+(\d+)$", line)
        assert m, line
        rows[m.group(1)] = m.groups()
    assert rows["shell"][1:3] == ("10", "run")
    assert rows["idle"][1] == "0"
    assert "motor" in " ".join(rows)
    for name, (_, prio, state, used, size, switches) in rows.items():
        assert 0 < int(used) <= int(size), name
        assert state in ("run", "ready", "blocked", "dead")


def test_uptime_follows_virtual_time(shell):
    def uptime():
        m = re.match(r"uptime (\d+)\.(\d{3}) s \((\d+) ticks at 1024 Hz\)$", shell.one("uptime"))
        assert m
        return int(m.group(1)) * 1000 + int(m.group(2)), int(m.group(3))
    ms1, ticks1 = uptime()
    vt = shell.qget("/machine/sim", "virtual-time-ns") / 1e6
    ms2, ticks2 = uptime()
    # uptime counts ticks from k_start and lags by up to one tick (0.98 ms);
    # virtual time counts from reset, and the boot before k_start (probing both
    # I2C buses, the boot report at 38400 baud) takes 10-15 ms of it (measured:
    # vt - uptime >= 9.6 ms right after boot, 13 ms in another run)
    assert ms1 <= vt <= ms2 + 25
    assert ms2 - ms1 >= 0
    assert ticks2 > ticks1
    assert abs(ticks2 * 1000 / 1024 - ms2) <= 2


def test_i2c_scan(shell):
    answer = shell.run("i2c scan")
    assert answer[0] == "i2c bus A: 8 devices 0x38 0x39 0x48 0x49 0x4a 0x4b 0x4c 0x4d"
    assert answer[1] == "i2c bus B: 0 devices"


BAD_LINES = [
    "frobnicate", "AD 5x", "ad", "ad 24", "ad -1", "ad x", "ad 5 6", "da 6 10", "da 1 256",
    "da 1 -1", "da 1 ten", "bio 16", "bio 3 2", "bin 0", "bin 6", "bin 1 1", "fast 16 1",
    "fast 1 2", "fast 1", "pwm 16 100", "pwm 3 1001", "pwm 3 100 10", "pwm 3 100 20001",
    "pwm 3", "motor 3 0", "motor 0 1001", "motor 0 -1001", "motor 0 99999999999",
    "enc 3", "led blink", "led on off", "i2c", "i2c probe", "ps now", "help me",
    "uptime 1", "console x", "speed 3 100", "speed 0 fast", "speed 0 99999999",
    "sleep", "sleep -1", "sleep 60001", "sleep x", "a b c d e f g h",
]


def test_bad_lines_answer_one_error_and_the_shell_goes_on(shell):
    shell.one("fast 2 0")
    for line in BAD_LINES:
        shell.error(line)
    # nothing was changed by the refused lines, and the shell still works
    assert shell.qget(IO, "fastbin") & 0x6 == 0
    assert shell.one("fast 2 1") == "fast 2 = 1"
    assert shell.one("fast 2 0") == "fast 2 = 0"


def test_errors_name_the_problem(shell):
    assert "unknown command" in shell.error("frobnicate")
    assert "no such channel" in shell.error("ad 24")
    assert "out of range" in shell.error("da 1 256")
    assert "not a number" in shell.error("da 1 ten")
    assert "usage" in shell.error("ad")


def test_empty_and_blank_lines_answer_nothing(shell):
    assert shell.run("") == []
    assert shell.run("   ") == []
    assert shell.one("  led   off  ") == "led = off"


def test_overlong_line_is_refused_whole(shell):
    shell.one("led off")
    # 'led on' followed by blanks: cut at the buffer it would switch the LED on
    line = "led on" + " " * (LINE_MAX + 10) + "x"
    answer = shell.error(line)
    assert "too long" in answer
    assert shell.qget("/machine/sim", "led") is False
    line = "fast 3 1" + "0" * LINE_MAX
    shell.error(line)
    assert shell.qget(IO, "fastbin") & 0x8 == 0
    # a line of exactly LINE_MAX characters is accepted
    exact = "led on" + " " * (LINE_MAX - 6)
    assert len(exact) == LINE_MAX
    assert shell.one(exact) == "led = on"
    shell.one("led off")


def test_line_editing_and_crlf(shell):
    shell.m.console.write(b"lex\bd of\x7f\x7fon\r\n")
    out = shell.m.console.read_until(PROMPT).decode("latin-1")
    assert "led = on" in out
    assert shell.qget("/machine/sim", "led") is True
    # a cancelled line (Ctrl-C) does nothing
    shell.m.console.write(b"led off\x03")
    out = shell.m.console.read_until(PROMPT).decode("latin-1")
    assert "led =" not in out
    assert shell.qget("/machine/sim", "led") is True
    shell.one("led off")


def write_while_stopped(shell, data):
    """Writes data with the VM stopped until the DUART has taken all of it, so
    the guest meets the whole burst at the same virtual times on a loaded host."""
    shell.m.qmp_cmd("stop")
    try:
        shell.m.console_write_taken(data, timeout=20)
    finally:
        shell.m.qmp_cmd("cont")


def test_many_lines_at_once_lose_nothing(shell):
    """A burst far larger than the receive ring: the shell pauses reception
    instead of dropping bytes, so every command is answered."""
    count = 60
    burst = b"".join(f"ad {i % 24}\n".encode() for i in range(count))
    for i in range(24):
        shell.qset(IO, f"ain{i}", i + 100)
    write_while_stopped(shell, burst)
    answers = []
    for _ in range(count):
        out = shell.m.console.read_until(PROMPT).decode("latin-1")
        answers += re.findall(r"^ad (\d+) = (\d+)\r?$", out, re.M)
    assert [(int(a), int(b)) for a, b in answers] == [(i % 24, i % 24 + 100) for i in range(count)]
    # the ring did fill (reception paused), and no byte was lost in the chip
    m = re.match(r"console: (\d+) bytes, (\d+) lines, (\d+) too long, ring full (\d+) times, "
                 r"(\d+) overruns, (\d+) errors$", shell.one("console"))
    assert m, "console counters"
    assert int(m.group(4)) >= 1
    assert int(m.group(5)) == 0 and int(m.group(6)) == 0


def test_bytes_above_ascii_are_not_echoed(shell):
    """C1 controls (0x9B CSI, 0x90 DCS, ...) and every other byte above 0x7F are
    dropped by the line editor: never echoed to the terminal, never in a command."""
    shell.one("led off")
    shell.m.console.write(b"le\x9bd \x90\xc2\x9bo\x9dn\xff\r")
    out = shell.m.console.read_until(PROMPT)
    assert all(b < 0x80 for b in out), out
    assert b"led on" in out and b"led = on" in out
    assert shell.qget("/machine/sim", "led") is True
    shell.one("led off")


def test_exit_stops_the_motors_and_switches_the_board_off():
    """On a board of its own, with -no-shutdown so that the machine stays for
    QMP after the power-off: exit leaves every motor at 0 and the board off
    (QEMU's run state "shutdown"), and nothing typed afterwards is answered."""
    with robocube_emu.start(kernel=ELF, extra_args=["-icount", "shift=8,sleep=off",
                                                "-no-shutdown"]) as m:
        sh = Shell(m)
        assert sh.one("motor 0 600") == "motor 0 = 600 per-mille"
        assert sh.one("speed 1 500").startswith("speed 1 = ")
        assert "exit" in sh.run("help")[-1]
        assert m.qmp_cmd("query-status")["status"] == "running"
        m.console.write(b"exit\r")
        out = m.console.read_until(b"board off\r\n", timeout=20)
        assert b"shell: exit: motors stopped, board off" in out
        deadline = time.monotonic() + 20
        while m.qmp_cmd("query-status")["status"] != "shutdown":
            assert time.monotonic() < deadline, m.qmp_cmd("query-status")
            time.sleep(0.05)
        for i in range(3):
            assert m.qom_get(IO + f"/motor{i}", "direction") == 0, i
        m.console.write(b"led on\r")
        time.sleep(0.5)
        m.console.poll()
        assert bytes(m.console.received) == b""        # no echo, no answer, no prompt
        assert m.qom_get("/machine/sim", "led") is False


def test_make_run_ends_when_the_shell_exits():
    """exit switches the board off and the emulator with it: make run returns
    0 by itself, long before any time limit, and answers nothing after exit."""
    start = time.monotonic()
    rc, stdout, stderr = run_make(["run", "APP=shell"], b"uptime\nexit\nled on\nuptime\n",
                                  timeout=90)
    out = stdout.decode("latin-1").replace("\r\n", "\n")
    assert rc == 0, stderr.decode("latin-1")[-2000:]
    assert re.search(r"^uptime \d+\.\d{3} s", out, re.M), out
    assert out.endswith("shell> exit\nshell: exit: motors stopped, board off\n"), out[-500:]
    assert "the shell's exit ends the run" in stderr.decode("latin-1")
    assert time.monotonic() - start < 90


def test_make_run_with_piped_stdin_ends_by_itself():
    """printf 'help\\nuptime\\n' | make run APP=shell RUN_SECONDS=N: the commands
    are answered from stdin and the run stops at the time limit."""
    start = time.monotonic()
    rc, stdout, stderr = run_make(["run", "APP=shell", "RUN_SECONDS=5"],
                                  b"help\nuptime\nled on\n")
    elapsed = time.monotonic() - start
    out = stdout.decode("latin-1").replace("\r\n", "\n")
    assert rc == 0, stderr.decode("latin-1")[-2000:]
    assert "shell> help\n" in out
    assert "  i2c scan" in out
    assert re.search(r"shell> uptime\nuptime \d+\.\d{3} s", out), out
    assert "led = on" in out
    assert elapsed < 100


def test_absent_chip_and_stuck_bus_answer_errors_and_the_shell_goes_on(shell):
    # input 5 lives on the second PCF8591 (adc1: inputs 4..7)
    shell.qset(IO, "ain5", 77)
    shell.qset(IO + "/adc1", "nack", 1)
    try:
        answer = shell.error("ad 5")
        assert "device absent" in answer and "(-3)" in answer, answer
        assert "device absent" in shell.error("da 1 10")
        assert shell.one("ad 0") == f"ad 0 = {shell.qget(IO, 'ain0')}"   # other chips still answer
    finally:
        shell.qset(IO + "/adc1", "nack", 0)
    assert shell.one("ad 5") == "ad 5 = 77"
    shell.qset(IO + "/i2c-a", "bus-stuck", 1)
    try:
        answer = shell.error("ad 5")
        assert "timeout" in answer and "(-4)" in answer, answer
        scan = shell.run("i2c scan")
        assert scan[0].startswith("i2c bus A: timeout"), scan
        assert scan[1] == "i2c bus B: 0 devices"
        assert shell.one("led on") == "led = on"          # the rest of the board still works
    finally:
        shell.qset(IO + "/i2c-a", "bus-stuck", 0)
    assert shell.one("ad 5") == "ad 5 = 77"
    assert shell.run("i2c scan")[0] == "i2c bus A: 8 devices 0x38 0x39 0x48 0x49 0x4a 0x4b 0x4c 0x4d"
    shell.one("led off")


def test_net_statistics_and_start(shell):
    """`net` prints the radio stack's counters (the radio stack's shell command); the
    stack runs only after `net start N`, once, with N a station number."""
    assert shell.one("net") == "net: not started (net start STATION)"
    for bad in ("net bogus", "net start", "net start 256", "net start x", "net start 1 2"):
        shell.error(bad)
    # the link layer's stations are 0..15: the range is named, no bare error code
    for bad in ("16", "255", "-1", "99999999999"):
        answer = shell.error(f"net start {bad}")
        assert "0..15" in answer and "(-" not in answer, answer
    assert shell.error("net start 16") == "error: net: station 16 out of range 0..15"
    assert shell.one("net") == "net: not started (net start STATION)"
    assert shell.one("net start 2") == "net: station 2 started"
    stats = shell.run("net")
    assert stats[0] == "net: station 2"
    assert re.match(r"  frames sent \d+, received \d+, crc errors \d+, malformed \d+$", stats[1])
    assert re.match(r"  retransmissions \d+, collisions \d+, deferrals \d+, mac drops \d+$", stats[2])
    assert stats[3].startswith("  messages delivered 0, duplicates dropped 0, unreachable 0")
    # On by default, with the development key (net/README.md, "Authentication").
    assert "  radio 19200 baud, auth" in stats, stats
    assert any(re.match(r"  auth: epoch \d+, forged 0, replayed 0, malformed 0, seal failed 0$", l)
               for l in stats), stats
    assert "already started" in shell.error("net start 3")


def test_make_run_console_carries_bytes_only():
    """The console of make run is the emulator's stdio and nothing else: Ctrl-A
    c used to open QEMU's monitor (-nographic multiplexes it onto stdin), and
    its migrate "exec:..." ran a command on the host; Ctrl-A x ended QEMU.
    Now those bytes reach the shell like any others."""
    # a short folder: the monitor command must fit the shell's 80-character line,
    # so that the shell's answer to it shows that it arrived whole
    folder = Path(tempfile.mkdtemp(prefix="bsched-"))
    target = folder / "pwned"
    attack = (b"uptime\n\x01cmigrate \"exec:id > " + str(target).encode() + b"\"\n"
              b"\x01c\x01x\nled on\nuptime\n")
    rc, stdout, stderr = run_make(["run", "APP=shell", "RUN_SECONDS=8"], attack)
    out = stdout.decode("latin-1").replace("\r\n", "\n")
    created = target.exists()
    shutil.rmtree(folder)
    assert not created, "the monitor ran a command on the host"
    assert rc == 0, stderr.decode("latin-1")[-2000:]
    assert "error: unknown command 'cmigrate'" in out, out      # the bytes went to the shell
    assert "led = on" in out                                    # Ctrl-A x did not end QEMU
    assert len(re.findall(r"^uptime \d+\.\d{3} s", out, re.M)) == 2, out
    assert "(qemu)" not in out and "QEMU" not in out
    banner = stderr.decode("latin-1")
    assert "quit with Ctrl-C" in banner and "Ctrl-A" not in banner, banner


MAKE_RUN_BAD = [
    ("RUN_SECONDS=0", "RUN_SECONDS=0: out of range 1..86400"),
    ("RUN_SECONDS=abc", "RUN_SECONDS='abc': not a whole number"),
    ("RUN_SECONDS=-3", "RUN_SECONDS='-3': not a whole number"),
    ("RUN_SECONDS=2.5", "RUN_SECONDS='2.5': not a whole number"),
    ("RUN_SECONDS=1 2", "RUN_SECONDS='1 2': not a whole number"),
    ("RUN_SECONDS=100000", "RUN_SECONDS=100000: out of range 1..86400"),
]


@pytest.mark.parametrize("option, names", MAKE_RUN_BAD, ids=[o for o, _ in MAKE_RUN_BAD])
def test_make_run_bad_run_seconds_is_one_line_and_exit_2(option, names):
    rc, stdout, stderr = run_make(["run", "APP=shell", option], timeout=60)
    assert rc == 2
    lines = stderr.decode().splitlines()
    assert len(lines) == 1, stderr
    assert f"make run: {names}" in lines[0] and "usage: make run " in lines[0], lines[0]
    assert stdout == b""


def test_no_emulator_is_started_with_the_monitor_on_a_console():
    """Every place that starts QEMU (make run, the runners, the tests, the
    tools): no -nographic, no mon:stdio, no muxed chardev, and make run's
    console arguments are -display none -monitor none -serial stdio."""
    here = Path(__file__).resolve()
    bad = []
    for path in ROOT.rglob("*"):
        if (path.suffix not in (".py", ".mk", ".sh") and path.name != "Makefile") \
                or "build" in path.relative_to(ROOT).parts or path == here \
                or not path.is_file():
            continue
        text = path.read_text(errors="replace")
        for needle in ("-nographic", "mon:stdio", "mux=on"):
            if needle in text:
                bad.append(f"{path.relative_to(ROOT)}: {needle}")
    assert bad == []
    apps_mk = (ROOT / "apps" / "apps.mk").read_text()
    assert "QEMU_CONSOLE_ARGS := -display none -monitor none -serial stdio" in apps_mk
    p = subprocess.run(["make", "--no-print-directory", "-n", "run", "APP=shell"], cwd=ROOT,
                       capture_output=True, text=True, timeout=60, stdin=subprocess.DEVNULL,
                       env=dict(os.environ, MAKEFLAGS=""))
    qemu_line = [ln for ln in p.stdout.splitlines() if "-M robocube -icount" in ln]
    assert len(qemu_line) == 1, p.stdout
    assert "-display none -monitor none -serial stdio" in qemu_line[0]


def test_make_run_at_a_terminal_ends_with_ctrl_c():
    """What the banner says: at a terminal, Ctrl-C ends the emulator and make
    run (the stdio chardev keeps signal=on), and no emulator is left behind."""
    master, slave = pty.openpty()

    def controlling_terminal():
        import fcntl
        import termios
        fcntl.ioctl(0, termios.TIOCSCTTY, 0)

    proc = subprocess.Popen(["make", "--no-print-directory", "run", "APP=shell"], cwd=ROOT,
                            stdin=slave, stdout=slave, stderr=slave, start_new_session=True,
                            preexec_fn=controlling_terminal)
    os.close(slave)
    seen = b""

    def pump(seconds, marker):
        nonlocal seen
        deadline = time.monotonic() + seconds
        while marker not in seen and time.monotonic() < deadline:
            if select.select([master], [], [], 0.2)[0]:
                try:
                    seen += os.read(master, 4096)
                except OSError:
                    return
    try:
        pump(90, PROMPT)
        assert PROMPT in seen, seen[-2000:]
        assert b"quit with Ctrl-C" in seen
        emulators = subprocess.run(["pgrep", "-s", str(proc.pid), "-f", "qemu-system-m68k"],
                                   capture_output=True, text=True).stdout.split()
        assert emulators, "no emulator in make run's session"
        os.write(master, b"\x03")
        proc.wait(timeout=20)
        deadline = time.monotonic() + 20
        while any(os.path.exists(f"/proc/{pid}") for pid in emulators) \
                and time.monotonic() < deadline:
            time.sleep(0.1)
        assert not any(os.path.exists(f"/proc/{pid}") for pid in emulators)
    finally:
        try:
            os.killpg(proc.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        proc.wait()
        os.close(master)
