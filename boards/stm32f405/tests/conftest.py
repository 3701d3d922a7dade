# The helpers these tests share with the RoboCube's: qtestlib (emu/tests) and
# the Table 1 checks (kernel/tests/target).
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
for sub in ("emu/tests", "kernel/tests/target"):
    sys.path.insert(0, str(ROOT / sub))
