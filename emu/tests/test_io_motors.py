"""Motor model: TPU PWM duty + DUART direction bits make the wheel encoders
turn; the TPU counts them with QDEC or ITC; the host reads speed/encoder and
can take the encoder over."""

import math

import pytest

from io_support import FN_ITC, FN_PWM, FN_QDEC, IO, TPU, board  # noqa: F401

PWM_CH = [0, 2, 4]
ENC_A = [1, 3, 5]
ENC_B = [12, 14, 13]


def motor(m):
    return f"{IO}/motor{m}"


def run_motor(b, m, high, period=10000):
    b.tpu_setup(PWM_CH[m], FN_PWM, {0: 0x8C, 2: high, 3: period}, hsr=2)


def setup_qdec(b, pri, sec):
    for ch, hsq in ((pri, 0), (sec, 1)):
        b.tpu_setup(ch, FN_QDEC, {1: 0x8000, 4: (ch ^ pri ^ sec) * 16 + 6,
                                  5: pri * 16 + 1}, hsq=hsq, hsr=3)


def expected_position(speed, tau, t):
    """Position of a first-order system starting at rest."""
    return speed * (t - tau * (1 - math.exp(-t / tau)))


def test_channel_map(board):
    for m in range(3):
        assert board.get(motor(m), "pwm-channel") == PWM_CH[m]
        assert board.get(motor(m), "encoder-a-channel") == ENC_A[m]
        assert board.get(motor(m), "encoder-b-channel") == ENC_B[m]


@pytest.mark.parametrize("m", range(3))
def test_direction_bits_from_duart(board, m):
    b = board
    b.duart_opr(1 << (2 + 2 * m))
    assert b.get(IO, "duart-opr") == 1 << (2 + 2 * m)
    assert b.get(motor(m), "direction") == 1
    assert b.get(motor(m), "dir-bits") == 1
    b.duart_opr(1 << (3 + 2 * m))
    assert b.get(motor(m), "direction") == -1
    b.duart_opr(3 << (2 + 2 * m))
    assert b.get(motor(m), "direction") == 0                     # brake
    for other in range(3):
        if other != m:
            assert b.get(motor(other), "direction") == 0


@pytest.mark.parametrize("m", range(3))
def test_motor_turns_encoder_counted_by_qdec(board, m):
    b = board
    b.tpu_start()
    pri, sec = sorted((ENC_A[m], ENC_B[m]))
    setup_qdec(b, pri, sec)
    run_motor(b, m, 5000)
    assert b.get(motor(m), "duty") == 5000
    b.duart_opr(1 << (2 + 2 * m))                                # forward
    b.step(1_000_000_000)
    expect = expected_position(1000, 0.05, 1.0)                  # 50 % of 2000 counts/s
    enc = b.get(motor(m), "encoder")
    assert abs(enc - expect) < 10, enc
    assert abs(b.get(motor(m), "speed") - 1000) <= 1
    assert b.param(pri, 1) == (0x8000 + enc) & 0xFFFF            # TPU saw every edge
    b.duart_opr(1 << (3 + 2 * m))                                # reverse
    b.step(2_000_000_000)
    assert b.get(motor(m), "speed") == -1000
    enc2 = b.get(motor(m), "encoder")
    assert enc2 < enc - 1800
    assert b.param(pri, 1) == (0x8000 + enc2) & 0xFFFF


def test_other_motors_stay_still(board):
    b = board
    run_motor(board, 1, 10000)
    b.duart_opr(0b1111_1100 & ~(1 << 5))                         # m1 forward, m0/m2 brake
    b.step(200_000_000)
    assert b.get(motor(1), "encoder") > 200
    assert b.get(motor(0), "encoder") == 0
    assert b.get(motor(2), "encoder") == 0


def test_brake_and_time_constant(board):
    b = board
    b.set(motor(2), "time-constant-ms", 100)
    b.set(motor(2), "max-speed", 4000)
    run_motor(b, 2, 10000)
    b.duart_opr(1 << 6)
    b.step(100_000_000)                                          # one time constant
    assert abs(b.get(motor(2), "speed") - 4000 * (1 - math.exp(-1))) < 40
    b.step(900_000_000)
    assert abs(b.get(motor(2), "speed") - 4000) < 5
    b.duart_opr(3 << 6)                                          # brake: decays
    b.step(1_000_000_000)
    assert abs(b.get(motor(2), "speed")) < 5


def test_itc_counts_encoder_lines(board):
    b = board
    b.tpu_setup(ENC_A[0], FN_ITC, {0: 0x4, 2: 0xFFFF}, hsq=1, hsr=1)
    run_motor(b, 0, 10000)
    b.duart_opr(1 << 2)
    b.step(500_000_000)
    enc = b.get(motor(0), "encoder")
    assert enc > 500
    assert b.param(ENC_A[0], 3) == (enc + 3) // 4                # A rises at counts 1, 5, 9, ...


def test_host_overrides_encoder(board):
    b = board
    setup_qdec(b, ENC_A[1], ENC_B[1])
    b.set(motor(1), "model-enabled", 0)
    run_motor(b, 1, 10000)
    b.duart_opr(1 << 4)
    b.step(100_000_000)
    assert b.get(motor(1), "encoder") == 0                       # model off: no motion
    b.set(motor(1), "encoder", 123)
    assert b.param(ENC_A[1], 1) == 0x8000 + 123
    b.set(motor(1), "encoder", -7)
    assert b.param(ENC_A[1], 1) == 0x8000 - 7
    with pytest.raises(Exception):
        b.set(motor(1), "encoder", 10_000_000)
    assert b.get(motor(1), "encoder") == -7


def test_motor_properties_validate(board):
    with pytest.raises(Exception):
        board.set(motor(0), "time-constant-ms", -1)
    with pytest.raises(Exception):
        board.set(motor(0), "speed", 5)                          # read-only
