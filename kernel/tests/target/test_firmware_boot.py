"""Boots the RoboCube firmware images on qemu-system-m68k -M robocube and
checks what they print on the console (DUART channel B = first -serial).

Environment (set by `make check-firmware-boot`):
  BSCHED_QEMU   the qemu-system-m68k with the robocube machine
  FW_DIR        build/firmware (tests/fault-*.elf)
  FW_ELF        the Table 1 image (build/firmware/table1/table1.elf)
  CROSS_PREFIX  m68k-linux-gnu- (objdump, nm, readelf)
  FW_ICOUNT     the -icount setting `make run` uses
"""
import os
import re
import select
import subprocess
import time
from pathlib import Path

import pytest

import robocube_emu


QEMU = os.environ.get("BSCHED_QEMU", "")
FW_DIR = Path(os.environ.get("FW_DIR", Path(__file__).resolve().parents[3] / "build" / "firmware"))
CROSS = os.environ.get("CROSS_PREFIX", "m68k-linux-gnu-")
ICOUNT = os.environ.get("FW_ICOUNT", "shift=8,sleep=off")   # as `make run` (boards/robocube/board.mk)
FIRMWARE = Path(os.environ.get("FW_ELF", FW_DIR / "table1" / "table1.elf"))
FAULT_IMAGES = {kind: FW_DIR / "tests" / f"fault-{kind}.elf"
                for kind in ("unmapped", "flashwrite", "illegal", "zerodivide")}

FLASH_BASE, FLASH_END = 0xE00000, 0xF00000

BOOT_TIME_LIMIT = 20.0    # seconds of wall time for the whole Table 1 run
FAULT_TIME_LIMIT = 10.0


class Board:
    """One qemu-system-m68k -M robocube run with the console on a pipe."""

    def __init__(self, elf, qmp_path=None):
        assert QEMU and os.access(QEMU, os.X_OK), f"BSCHED_QEMU not executable: {QEMU!r}"
        assert Path(elf).is_file(), f"missing image {elf} (make firmware-tests)"
        extra = ["-qmp", f"unix:{qmp_path},server=on,wait=off"] if qmp_path else []
        self.start = time.monotonic()
        self.proc = robocube_emu.popen(["-serial", "stdio"] + extra, kernel=elf,
                                       icount=ICOUNT, qemu=QEMU)
        self.output = b""
        self.qmp = None
        if qmp_path:
            self.qmp = robocube_emu.connect(qmp_path, self.proc)

    def qmp_command(self, name, **args):
        return self.qmp.command(name, **args)

    def read_until(self, pattern, timeout):
        """Reads the console until `pattern` (regex, bytes) matches; returns the match."""
        regex = re.compile(pattern)
        deadline = time.monotonic() + timeout
        while True:
            m = regex.search(self.output)
            if m:
                return m
            left = deadline - time.monotonic()
            if left <= 0 or self.proc.poll() is not None:
                # drain what is left, then give up
                ready, _, _ = select.select([self.proc.stdout], [], [], 0)
                if ready:
                    chunk = os.read(self.proc.stdout.fileno(), 65536)
                    if chunk:
                        self.output += chunk
                        continue
                raise AssertionError(
                    f"no {pattern!r} within {timeout} s (qemu exit code {self.proc.poll()}); "
                    f"console so far:\n{self.text()}\nstderr:\n{self.stderr()}")
            ready, _, _ = select.select([self.proc.stdout], [], [], min(left, 0.2))
            if ready:
                chunk = os.read(self.proc.stdout.fileno(), 65536)
                if chunk:
                    self.output += chunk

    def text(self):
        return self.output.decode("latin-1").replace("\r\n", "\n")

    def stderr(self):
        if self.proc.poll() is None:
            return "(running)"
        return self.proc.stderr.read().decode("latin-1", "replace")

    def close(self):
        if self.qmp:
            self.qmp.close()
        if self.proc.poll() is None:
            self.proc.kill()
        self.proc.wait(timeout=10)


@pytest.fixture
def board_factory():
    boards = []

    def boot(elf, qmp_path=None):
        b = Board(elf, qmp_path)
        boards.append(b)
        return b
    yield boot
    for b in boards:
        b.close()


def symbol(elf, name):
    out = subprocess.run([CROSS + "nm", str(elf)], check=True, capture_output=True, text=True).stdout
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 3 and parts[2] == name:
            return int(parts[0], 16)
    raise AssertionError(f"symbol {name} not in {elf}")


# ---------------------------------------------------------------- the default image

def test_led_blinks_after_table1(board_factory, tmp_path):
    """After the run a kernel thread toggles the port E LED every 64 ticks
    (0.5 s; the CPU idles in STOP in between). Measured in the board's own
    virtual time, which does not follow the host's clock (-icount sleep=off):
    LED transitions counted by the board model against its virtual clock."""
    board = board_factory(FIRMWARE, qmp_path=tmp_path / "qmp.sock")
    board.read_until(rb"table1 done", BOOT_TIME_LIMIT)

    def sample():
        return (board.qmp_command("qom-get", path="/machine/sim", property="led-changes"),
                board.qmp_command("qom-get", path="/machine/sim", property="virtual-time-ns"))
    changes0, t0 = sample()
    deadline = time.monotonic() + 20
    while True:
        changes, t = sample()
        if t - t0 >= 3_000_000_000 or time.monotonic() > deadline:
            break
        time.sleep(0.02)
    seconds = (t - t0) / 1e9
    assert seconds >= 3, f"virtual time advanced only {seconds:.3f} s in 20 s of wall time"
    # One transition every 0.5 s of virtual time, +-1 for where the window falls.
    expected = seconds / 0.5
    assert abs((changes - changes0) - expected) <= 1.5, \
        f"LED changed {changes - changes0} times in {seconds:.3f} s of virtual time"
    assert board.proc.poll() is None
    assert "EXCEPTION" not in board.text()


# ---------------------------------------------------------------- faults

FAULTS = {
    # kind: (vector, name, format, fault address or None, SSW direction or None)
    "unmapped": (2, "bus error", "C", 0x400000, "read"),
    "flashwrite": (2, "bus error", "C", 0xE00100, "write"),
    "illegal": (4, "illegal instruction", "0", None, None),
    "zerodivide": (5, "zero divide", "2", None, None),
}

REPORT = (rb"\*\*\* EXCEPTION vector=(\d+) \(([^)]*)\) format=\$([0-9A-F]) "
          rb"pc=0x([0-9a-f]{8}) sr=0x([0-9a-f]{4}) fault_pc=0x([0-9a-f]{8})")


@pytest.mark.parametrize("kind", sorted(FAULTS))
def test_fault_is_reported_with_vector_and_pc(board_factory, kind):
    vector, name, fmt, address, direction = FAULTS[kind]
    elf = FAULT_IMAGES[kind]
    insn = symbol(elf, "fault_instruction")
    board = board_factory(elf)
    board.read_until(rb"\*\*\* halted", FAULT_TIME_LIMIT)
    text = board.text()
    assert f"faulting instruction at 0x{insn:08x}" in text
    assert "no exception was taken" not in text
    # .data copied from flash into SRAM, .bss cleared by start.S
    startup = re.search(r"startup: data_check=0x([0-9a-f]{8}) at 0x([0-9a-f]+), "
                        r"bss_check=0x([0-9a-f]{8}) at 0x([0-9a-f]+)", text)
    assert startup, text
    assert int(startup.group(1), 16) == 0x5A17C0DE and int(startup.group(3), 16) == 0
    assert int(startup.group(2), 16) < 0x100000 and int(startup.group(4), 16) < 0x100000
    m = re.search(REPORT.decode(), text)
    assert m, text
    assert int(m.group(1)) == vector, text
    assert m.group(2) == name
    assert m.group(3) == fmt, f"CPU32 frame format for {name}"
    sr = int(m.group(5), 16)
    assert sr & 0x2000, "the fault happened in supervisor mode"
    assert int(m.group(6), 16) == insn, f"fault_pc must be the faulting instruction 0x{insn:08x}"
    pc = int(m.group(4), 16)
    if kind == "illegal":
        assert pc == insn            # format $0: PC of the illegal opcode
    if kind == "zerodivide":
        assert pc == insn + 2        # format $2: next instruction after DIVU.W Dn,Dn
    if address is not None:
        fa = re.search(r"bus error: fault address 0x([0-9a-f]{8})", text)
        assert fa and int(fa.group(1), 16) == address, text
        assert re.search(rf"SSW 0x[0-9a-f]{{4}}: {direction} ", text), text
    # The CPU halted in the handler: QEMU itself must not have crashed.
    time.sleep(0.3)
    assert board.proc.poll() is None, f"qemu exited: {board.stderr()}"


# ---------------------------------------------------------------- image layout

def all_images():
    return [FIRMWARE] + [FAULT_IMAGES[k] for k in sorted(FAULT_IMAGES)]


# Every image uses only CPU32 instructions: assure/cpu32_isa.py (make check-cpu32-isa)
# scans them all.


def test_console_baud_variants_compile(tmp_path):
    """The console rates the driver offers all build; anything else is a clear error."""
    root = Path(__file__).resolve().parents[3]
    src = root / "boards" / "robocube" / "duart_console.c"
    base = [CROSS + "gcc", "-std=c99", "-mcpu=cpu32", "-Os", "-ffreestanding", "-nostdlib",
            "-Wall", "-Wextra", "-Werror", f"-I{root}", f"-I{root}/kernel/arch/cpu32", "-c",
            "-o", str(tmp_path / "console.o"), str(src)]
    for baud in (57600, 38400, 9600):
        subprocess.run(base + [f"-DCONSOLE_BAUD={baud}"], check=True)
    bad = subprocess.run(base + ["-DCONSOLE_BAUD=115200"], capture_output=True, text=True)
    assert bad.returncode != 0 and "CONSOLE_BAUD must be" in bad.stderr


def test_load_addresses_and_reset_vectors(tmp_path):
    for elf in all_images():
        out = subprocess.run([CROSS + "readelf", "-lW", str(elf)], check=True,
                             capture_output=True, text=True).stdout
        loads = [line.split() for line in out.splitlines() if line.strip().startswith("LOAD")]
        assert loads
        for fields in loads:
            paddr, filesz = int(fields[3], 16), int(fields[4], 16)
            if filesz:
                assert FLASH_BASE <= paddr and paddr + filesz <= FLASH_END, \
                    f"{elf.name}: segment at 0x{paddr:x} is not in flash"
        # SRAM below 0x400 stays unallocated: no object may sit at address 0 (NULL).
        assert symbol(elf, "__data_start") >= 0x400 and symbol(elf, "__bss_start") >= 0x400
        # Vector 1 (reset PC) is a flash offset: at reset the flash sits at 0.
        flat = tmp_path / (elf.stem + ".bin")
        subprocess.run([CROSS + "objcopy", "-O", "binary", "-j", ".text", str(elf), str(flat)],
                       check=True)
        raw = flat.read_bytes()
        ssp, reset_pc = int.from_bytes(raw[0:4], "big"), int.from_bytes(raw[4:8], "big")
        assert ssp == 0x100000
        assert reset_pc == symbol(elf, "cpu32_reset") - FLASH_BASE
        assert reset_pc < 0x10000, "reset code must lie in the first 64 KiB of flash"
        # Vector 64 is the PIT interrupt, vector 2 the generic fault entry.
        assert int.from_bytes(raw[64 * 4:65 * 4], "big") == symbol(elf, "cpu32_vector_64")
        assert int.from_bytes(raw[2 * 4:3 * 4], "big") == symbol(elf, "cpu32_exception")
