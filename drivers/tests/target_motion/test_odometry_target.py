"""Odometry on the target (CPU32 fixed point) from the motor encoders that the
host moves (models off): left wheel = motor 0, right = motor 2. Checked
against the exact floating-point geometry."""
import math

import pytest

MM_PER_COUNT = 0.25
BASE = 112.0
Q16 = 65536


@pytest.fixture
def wheels(board):
    for m in (0, 2):
        board.set(f"/motor{m}", "model-enabled", 0)
    start = {m: board.get(f"/motor{m}", "encoder") for m in (0, 2)}
    board.cmd("wait 30")
    board.cmd(f"odo {int(MM_PER_COUNT * Q16)} {int(BASE * Q16)}")
    yield start
    for m in (0, 2):
        board.set(f"/motor{m}", "model-enabled", 1)


def drive(board, start, moves, steps):
    """Moves both wheels by (dl, dr) counts in `steps` equal steps, updating
    the odometry after each; returns the pose (mm, mm, rad)."""
    dl, dr = moves
    for i in range(1, steps + 1):
        board.set("/motor0", "encoder", start[0] + dl * i // steps)
        board.set("/motor2", "encoder", start[2] + dr * i // steps)
        board.cmd("wait 25")                  # the service samples the encoders
        x, y, heading = board.cmd("odoget")
    return x / Q16, y / Q16, (heading - (1 << 32 if heading >= 1 << 31 else 0)) / 2**32 * 2 * math.pi


def test_straight_line(board, wheels):
    x, y, th = drive(board, wheels, (2000, 2000), 10)
    assert abs(x - 500.0) < 0.01 and abs(y) < 0.01 and th == 0.0


def test_turn_in_place_quarter(board, wheels):
    n = 352                                   # 352 * 0.25 mm on a 56 mm radius: 90.03 degrees
    x, y, th = drive(board, wheels, (-n, n), 8)
    assert abs(th - 2 * n * MM_PER_COUNT / BASE) < 1e-6
    assert abs(x) < 0.01 and abs(y) < 0.01


def test_arc(board, wheels):
    dl, dr = 1200, 2000
    x, y, th = drive(board, wheels, (dl, dr), 40)
    ml, mr = dl * MM_PER_COUNT, dr * MM_PER_COUNT
    theta = (mr - ml) / BASE
    radius = BASE / 2 * (mr + ml) / (mr - ml)
    ex, ey = radius * math.sin(theta), radius * (1 - math.cos(theta))
    print(f"\narc: target ({x:.3f}, {y:.3f}, {th:.5f}) exact ({ex:.3f}, {ey:.3f}, {theta:.5f})")
    # 40 steps of 5 degrees each: the mean-heading rule's chord error is
    # below 0.1 mm here (d theta^2 / 24 of each step's 10 mm)
    assert abs(th - theta) < 1e-6
    assert abs(x - ex) < 0.1 and abs(y - ey) < 0.1
