"""apps/posixmeasure: the instructions a POSIX call takes against the kernel
call it stands on, from an exec trace (deterministic under -icount): an
uncontended pthread_mutex_lock + unlock against k_mutex_lock + unlock, and a
semaphore hand-off between two threads through sem_post/sem_wait against
k_sem_post/k_sem_wait. The goal is within 10 % of the k_ call. The counts go
to build/posix/measure.txt.

Environment (make check-posix, make check-NAME-posix): BSCHED_QEMU, FW_DIR, K_BOARD.
"""
import os
import statistics
from pathlib import Path

from robocube_emu import launch
from robocube_emu.exectrace import spans, symbols, trace_pcs

ROOT = Path(__file__).resolve().parents[3]
FW = Path(os.environ.get("FW_DIR", ROOT / "build" / "firmware"))
QEMU = os.environ.get("BSCHED_QEMU", str(ROOT / "build" / "emu" / "qemu-system-m68k"))
ELF = FW / "posixmeasure" / "posixmeasure.elf"
# The board (robocube_emu.launch.BOARDS): $K_BOARD, the RoboCube by default.
BOARD_NAME = os.environ.get("K_BOARD", "robocube")
BOARD = launch.board(BOARD_NAME)


def test_posix_calls_cost_within_ten_percent_of_the_kernel_calls():
    sym = symbols(ELF, BOARD["cross"])
    pcs, console = trace_pcs(QEMU, ELF, seconds=60, marker=rb"POSIX MEASURE DONE",
                             machine=BOARD["machine"], icount=BOARD["test_icount"])
    assert "POSIX MEASURE DONE" in console, console
    paths = {
        "k_mutex_lock_unlock": spans(pcs, sym["pm_k_mutex_begin"], sym["pm_k_mutex_end"]),
        "pthread_mutex_lock_unlock": spans(pcs, sym["pm_pthread_mutex_begin"],
                                                    sym["pm_pthread_mutex_end"]),
        "k_sem_handoff": spans(pcs, sym["pm_k_sem_before_post"], sym["pm_k_sem_after_wait"],
                                        must_pass=sym["k_arch_switch"]),
        "sem_handoff": spans(pcs, sym["pm_sem_before_post"], sym["pm_sem_after_wait"],
                                      must_pass=sym["k_arch_switch"]),
    }
    for name, counts in paths.items():
        assert len(counts) >= 10, (name, counts)
    med = {name: statistics.median(counts) for name, counts in paths.items()}
    # The median: a tick interrupt that lands inside a span makes it longer
    # (the first lock of the statically initialised mutex also makes the
    # kernel mutex).
    out = ROOT / "build" / "posix" / ("measure.txt" if BOARD_NAME == "robocube" else f"measure-{BOARD_NAME}.txt")
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text("".join(f"{k} {v:.0f}\n" for k, v in med.items()))
    assert med["pthread_mutex_lock_unlock"] <= 1.10 * med["k_mutex_lock_unlock"], med
    assert med["sem_handoff"] <= 1.10 * med["k_sem_handoff"], med
