# Lets the tests import kmeasure (kernel/tests/target-kernel).
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
sys.path.insert(0, str(ROOT / "kernel" / "tests" / "target-kernel"))
