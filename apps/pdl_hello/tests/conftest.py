# Lets the tests import qtestlib (emu/tests) and kmeasure (kernel/tests/target-kernel).
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
for p in (ROOT / "emu" / "tests", ROOT / "kernel" / "tests" / "target-kernel"):
    sys.path.insert(0, str(p))
