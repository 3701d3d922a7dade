# Lets the tests import pdl_measure.py (this folder), qtestlib (emu/tests)
# and kmeasure (kernel/tests/target-kernel).
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[2]
for p in (HERE, ROOT / "emu" / "tests", ROOT / "kernel" / "tests" / "target-kernel"):
    sys.path.insert(0, str(p))
