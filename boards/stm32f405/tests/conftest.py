# The Table 1 checks these tests share with the RoboCube's suite
# (kernel/tests/target/test_firmware_boot.py).
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[3] / "kernel" / "tests" / "target"))
