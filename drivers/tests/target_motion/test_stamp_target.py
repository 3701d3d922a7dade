"""The kernel's fine time stamp on the RoboCube takes TPU channel 15 only when
it starts (k_timestamp_start, motiontest's "stamp"): before, TP15 is the TPU
driver's like every channel; after, the driver refuses it; and the start is
refused while the driver runs a function there. A board of its own for each
(the start happens once a boot)."""
import pytest

from conftest import MotionBoard

TCR1_HZ = 1048576


@pytest.fixture
def fresh_board(tmp_path):
    b = MotionBoard(tmp_path / "qmp.sock")
    yield b
    b.close()


def test_tp15_is_the_drivers_until_the_stamp_starts(fresh_board):
    b = fresh_board
    assert b.cmd("pwm 15 1000 500") == []             # an ordinary channel before
    assert b.get("/tpu", "ch15-duty") == pytest.approx(5000, abs=20)
    assert b.cmd("release 15") == []
    assert b.cmd("stamp") == [TCR1_HZ]
    assert b.cmd("stamp") == [TCR1_HZ]                 # once started, started
    assert b.send("pwm 15 1000 500") == "err -1"       # the board's now
    assert b.send("dout 15 1") == "err -1"
    assert b.send("qdec 14 15") == "err -1"
    assert b.get("/tpu", "ch15-duty") == 0
    assert b.cmd("pwm 14 1000 500") == []              # the others are not


def test_the_stamp_does_not_take_a_busy_tp15(fresh_board):
    b = fresh_board
    assert b.cmd("pwm 15 2000 250") == []
    assert b.send("stamp") == "err -16"                 # K_EBUSY: whole ticks instead
    assert b.send("stamp") == "err -16"
    assert b.get("/tpu", "ch15-duty") == pytest.approx(2500, abs=20)   # the PWM runs on
    assert b.cmd("pwm 15 1000 500") == []
