"""TPU driver on the emulated board: PWM duty and frequency as the TPU model
reports them, DIO out and in, ITC counts (past the 16-bit hardware count),
QDEC on a host-driven pair, channel interrupts, bad arguments."""
import math
import pytest

TCR1_HZ = 1048576


def expected_pwm(hz, permille):
    period = (TCR1_HZ + hz // 2) // hz
    high = (period * permille + 500) // 1000
    return period, high, 10000 if high >= period else high * 10000 // period


@pytest.mark.parametrize("ch,hz,permille", [
    (6, 1000, 250), (7, 50, 500), (15, 20000, 1000), (8, 17, 0), (9, 400, 333), (11, 100, 999)])
def test_pwm_duty_and_frequency(board, ch, hz, permille):
    assert board.cmd(f"pwm {ch} {hz} {permille}") == []
    period, high, duty = expected_pwm(hz, permille)
    assert board.get("/tpu", "tcr1-hz") == TCR1_HZ
    assert board.get("/tpu", f"ch{ch}-pwm-period") == period
    assert board.get("/tpu", f"ch{ch}-pwm-high") == high
    assert board.get("/tpu", f"ch{ch}-duty") == duty
    assert abs(duty - permille * 10) <= 10000 // period + 1
    got_hz, got_pm = board.cmd(f"pwmget {ch}")
    # the frequency the period really gives (20 kHz is 52 ticks: 20165 Hz)
    assert got_hz == (TCR1_HZ + period // 2) // period
    assert abs(got_hz - hz) <= hz // 100 + 1
    assert got_pm == (high * 1000 + period // 2) // period


def test_pwm_update_keeps_frequency_and_changes_duty(board):
    board.cmd("pwm 10 2000 100")
    assert board.get("/tpu", "ch10-duty") == expected_pwm(2000, 100)[2]
    board.cmd("pwm 10 0 900")                 # hz 0: keep the frequency
    period, _, duty = expected_pwm(2000, 900)
    assert board.get("/tpu", "ch10-pwm-period") == period
    assert board.get("/tpu", "ch10-duty") == duty
    board.cmd("ticks 10 300 1200")            # raw ticks
    assert board.get("/tpu", "ch10-pwm-period") == 1200
    assert board.get("/tpu", "ch10-duty") == 2500


def test_pwm_bad_arguments(board):
    assert board.send("pwm 16 1000 10") == "err -1"
    assert board.send("pwm 6 16 10") == "err -2"
    assert board.send("pwm 6 20001 10") == "err -2"
    assert board.send("pwm 6 1000 1001") == "err -2"
    assert board.send("pwm 6 1000 -1") == "err -2"
    assert board.send("ticks 6 10 0") == "err -2"
    assert board.send("ticks 6 11 10") == "err -2"
    assert board.send("pwmget 12") == "err -8"       # not running PWM


def test_dio_output(board):
    for v in (1, 0, 1):
        board.cmd(f"dout 7 {v}")
        assert board.get("/tpu", "ch7-pin") == v
        assert board.cmd("din 7") == [v]          # an output reads its own level
    assert board.get("/tpu", "ch7-duty") == 0     # no longer PWM


def test_dio_input_follows_host(board):
    for v in (1, 0, 0, 1, 0):
        board.set("/tpu", "ch8-pin", v)
        assert board.cmd("din 8") == [v]


def test_itc_counts_rising_edges_of_host_pulses(board):
    board.set("/tpu", "ch9-pin", 0)
    board.cmd("itc 9 1")
    for _ in range(25):
        board.set("/tpu", "ch9-pin", 1)
        board.set("/tpu", "ch9-pin", 0)
    assert board.cmd("itcget 9") == [25]
    board.cmd("itcclr 9")
    assert board.cmd("itcget 9") == [0]
    board.cmd("itc 9 3")                          # both edges
    for _ in range(7):
        board.set("/tpu", "ch9-pin", 1)
        board.set("/tpu", "ch9-pin", 0)
    assert board.cmd("itcget 9") == [14]
    assert board.send("itc 9 4") == "err -2"


def test_itc_extends_past_16_bits(board):
    """The motor 2 encoder's phase A (TP5) with ITC on it, moved by the host:
    every count is an edge, one rising A edge per 4 counts; 200000 counts make
    50000 rising edges, past the TPU's 16-bit TRANS_COUNT and several chunk
    interrupts."""
    board.set("/motor2", "model-enabled", 0)
    start = board.get("/motor2", "encoder")
    board.cmd("itc 5 1")
    try:
        for step in range(1, 5):
            board.set("/motor2", "encoder", start + 50000 * step)
            # let the CPU serve the chunk interrupt before the next 12500 edges
            # (a CPU that holds it off for a whole chunk would lose one)
            assert board.cmd("itcget 5") == [12500 * step]
    finally:
        board.set("/motor2", "model-enabled", 1)
    irqs, served = board.cmd("irqget 5")
    assert served >= 50000 // 0x4000


def test_qdec_pair_driven_by_host(board):
    """TP6 = A (primary), TP7 = B: A leading B counts up, 4 counts a cycle."""
    board.set("/tpu", "ch6-pin", 0)
    board.set("/tpu", "ch7-pin", 0)
    board.cmd("qdec 6 7")
    assert board.cmd("qpos 6") == [0]
    forward = [(1, 0), (1, 1), (0, 1), (0, 0)]
    for _ in range(10):
        for a, b in forward:
            board.set("/tpu", "ch6-pin", a)
            board.set("/tpu", "ch7-pin", b)
    assert board.cmd("qpos 6") == [40]
    for _ in range(15):
        for a, b in reversed([(0, 0)] + forward[:3]):
            board.set("/tpu", "ch6-pin", a)
            board.set("/tpu", "ch7-pin", b)
    assert board.cmd("qpos 6") == [-20]
    board.cmd("qset 6 1000")
    assert board.cmd("qpos 6") == [1000]
    assert board.send("qdec 6 6") == "err -1"
    assert board.send("qdec 6 16") == "err -1"
    assert board.send("qpos 7") == "err -8"       # the secondary has no position


def pwm_edges_bounds(board, ch, ms):
    """The rising edges of channel ch's PWM in a sleep of ms: the sleep lasts
    ms rounded up to whole ticks, less at most one tick (1 ms or less) for the
    tick the command lands in; the period is the model's, in TCR1 ticks (2000 Hz
    asked for is 2001.1 Hz at the board's TCR1 rate)."""
    period_s = board.get("/tpu", f"ch{ch}-pwm-period") / board.get("/tpu", "tcr1-hz")
    return math.floor((ms - 1) / 1000 / period_s), math.ceil(ms / 1000 / period_s)


def test_channel_interrupt_every_pwm_period(board):
    """A PWM channel interrupts at every period start, counted by the attached
    handler over a sleep of virtual time: 500 Hz for 200 ms is 100 interrupts.
    None is lost at 2000 Hz over 2 s either, with the CPU idle between edges (an
    idle warp from inside the edge's timer callback lost bursts of them)."""
    board.cmd("irq 11")
    for hz, ms in ((500, 200), (2000, 200), (2000, 2000)):
        board.cmd(f"pwm 11 {hz} 500")
        low, high = pwm_edges_bounds(board, 11, ms)
        assert low <= board.cmd(f"irqwait 11 {ms}")[0] <= high, (hz, ms, low, high)
    board.cmd("release 11")
    assert board.get("/tpu", "ch11-duty") == 0
    assert board.cmd("irqwait 11 50") == [0]
