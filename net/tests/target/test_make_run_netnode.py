"""make run APP=netnode: three boards on the radio medium, and the messages
going between them shown as they come (each board's console, live)."""
import re
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]


def test_make_run_netnode_shows_three_boards_exchanging_messages():
    r = subprocess.run(["make", "--no-print-directory", "-C", str(ROOT), "run", "APP=netnode"],
                       capture_output=True, text=True, timeout=600, stdin=subprocess.DEVNULL)
    assert r.returncode == 0, r.stdout + r.stderr
    for station in (0, 1, 2):
        assert f"station {station}: netnode: station {station} up" in r.stdout, r.stdout
        heard = re.findall(rf"station {station}: netnode: from (\d+): 5 in order, 0 duplicates, 0 lost",
                           r.stdout)
        assert sorted(int(h) for h in heard) == sorted({0, 1, 2} - {station}), r.stdout
    assert "net-soak: sent 30, delivered 30, in order, 0 duplicates, 0 lost" in r.stdout
    assert "terminating on signal" not in r.stdout
