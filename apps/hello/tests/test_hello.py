"""apps/hello: an ordinary int main(void) runs as a thread once the board is up,
and newlib's printf reaches the console. Also the figure of the README: the
instructions one printf("%d\\n", x) takes (its second call, stdio already set up),
counted from an exec trace (deterministic under -icount).

Environment (make check-rtcheck): BSCHED_QEMU, FW_DIR.
"""
import os
import subprocess
from pathlib import Path

from robocube_emu.exectrace import symbols, trace_pcs
import robocube_emu

ROOT = Path(__file__).resolve().parents[3]
FW = Path(os.environ.get("FW_DIR", ROOT / "build" / "firmware"))
QEMU = os.environ.get("BSCHED_QEMU", str(ROOT / "build" / "emu" / "qemu-system-m68k"))
ELF = FW / "hello" / "hello.elf"


def test_main_runs_as_a_thread_and_prints():
    with robocube_emu.Machine(kernel=str(ELF), extra_args=["-icount", "shift=8,sleep=off"]) as m:
        text = m.console.read_until(b"42\r\n", timeout=20).decode("latin-1")
    assert "hello from the RoboCube\r\n42\r\n" in text, text


def printf_calls(elf):
    """Addresses of main's calls (its only calls are the two of printf; GCC may
    call through a register it loaded with printf) and of the instruction after each."""
    dis = subprocess.run(["m68k-linux-gnu-objdump", "-d", "--disassemble=main", str(elf)],
                         check=True, capture_output=True, text=True).stdout
    lines = [line.split("\t") for line in dis.splitlines() if line.startswith("  ")]
    assert any("<printf>" in fields[-1] for fields in lines), dis
    calls = []
    for i, fields in enumerate(lines):
        if len(fields) >= 3 and fields[2].split()[0] in ("jsr", "bsrl", "bsrw") and i + 1 < len(lines):
            calls.append((int(fields[0].strip()[:-1], 16), int(lines[i + 1][0].strip()[:-1], 16)))
    return calls


def rte_addresses(elf):
    dis = subprocess.run(["m68k-linux-gnu-objdump", "-d", str(elf)], check=True,
                         capture_output=True, text=True).stdout
    return {int(line.split(":")[0], 16) for line in dis.splitlines()
            if "\trte" in line and line.startswith("  ")}


def test_printf_instruction_count():
    sym = symbols(ELF)
    calls = printf_calls(ELF)
    assert len(calls) == 2, calls
    # QEMU is killed when the trace ends, losing the log it has not written yet:
    # trace 3 s of wall time, far past main (the idle board adds little).
    pcs, console = trace_pcs(QEMU, ELF, seconds=3, marker=rb"^$(?!)")
    assert "42" in console, console
    # The console's transmitter interrupt comes while printf runs (it queues the
    # characters and enables the interrupt): the instructions from the kernel's
    # interrupt entry to its rte are the interrupt's, not printf's.
    rte = rte_addresses(ELF)
    start, end = pcs.index(calls[1][0]), None
    count, in_isr, interrupts = 0, False, 0
    for pc in pcs[start:]:
        if pc == calls[1][1]:
            end = pc
            break
        if pc == sym["k_isr_entry"]:
            in_isr, interrupts = True, interrupts + 1
        if not in_isr:
            count += 1
        elif pc in rte:
            in_isr = False
    assert end is not None, "printf never returned in the trace"
    counts = [count]
    # Formatting one int, newlib's stdio (line buffered on a terminal) and the
    # console write of two characters: hundreds of instructions, not thousands.
    assert 200 < counts[0] < 5000, counts
    out = ROOT / "build" / "rtcheck"
    out.mkdir(parents=True, exist_ok=True)
    text = f"printf(\"%d\\n\", x): {counts[0]} instructions ({interrupts} interrupts left out)\n"
    (out / "printf-cost.txt").write_text(text)
