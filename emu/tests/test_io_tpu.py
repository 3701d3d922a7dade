"""MC68332 TPU: registers, parameter RAM, and the PWM, DIO, ITC and QDEC
functions with channel interrupts, checked from the CPU side (qtest memory
accesses) and the host side (QOM properties, interrupt arbiter state)."""

import pytest

from io_support import (CFSR0, CIER, CISR, CPR0, FN_DIO, FN_ITC, FN_PWM, FN_QDEC,
                        HSQR0, HSRR0, IO, TICR, TPU, TPU_BASE, TPUMCR, board)  # noqa: F401


def tick_ns(board):
    return 1e9 / board.get(TPU, "tcr1-hz")


def test_reset_values_and_register_readback(board):
    b = board
    assert b.readw(TPU_BASE + TPUMCR) == 0x0080
    for off in (TICR, CIER, CFSR0, CFSR0 + 6, HSQR0, HSRR0, CPR0, CISR):
        assert b.readw(TPU_BASE + off) == 0, hex(off)
    b.writew(TPU_BASE + TICR, 0x0480)
    b.writew(TPU_BASE + CIER, 0x8001)
    b.writew(TPU_BASE + CFSR0, 0x9A86)
    b.writew(TPU_BASE + HSQR0 + 2, 0x1234)
    assert b.readw(TPU_BASE + TICR) == 0x0480
    assert b.readw(TPU_BASE + CIER) == 0x8001
    assert b.readw(TPU_BASE + CFSR0) == 0x9A86
    assert b.readw(TPU_BASE + HSQR0 + 2) == 0x1234
    assert b.readb(TPU_BASE + CFSR0) == 0x9A                     # byte access, big endian
    b.writeb(TPU_BASE + CFSR0 + 1, 0x55)
    assert b.readw(TPU_BASE + CFSR0) == 0x9A55


def test_tcr1_follows_tpumcr(board):
    b = board
    base = b.get(TPU, "tcr1-hz")                                 # PSCK = 0: fsys/32
    b.tpu_start()                                                # 0x4ACD: fsys/4/4
    assert b.get(TPU, "tcr1-hz") == base * 2


def test_parameter_ram_word_and_byte(board):
    b = board
    for ch in range(16):
        for k in range(8):
            b.set_param(ch, k, ch * 0x1000 + k * 0x11)
    for ch in range(16):
        for k in range(8):
            assert b.param(ch, k) == ch * 0x1000 + k * 0x11
    b.writeb(0xFFFF00 + 16 * 3 + 5, 0xAB)
    assert b.param(3, 2) == 0x3022 & 0xFF00 | 0xAB


def setup_pwm(b, ch, high, period):
    b.tpu_setup(ch, FN_PWM, {0: 0x8C, 2: high, 3: period}, hsr=2)


@pytest.mark.parametrize("ch", range(16))
def test_pwm_duty_visible_to_host(board, ch):
    b = board
    b.tpu_start()
    setup_pwm(b, ch, 2500, 10000)
    assert b.readw(TPU_BASE + HSRR0 + 2 * (1 - ch // 8)) == 0    # request serviced
    assert b.get(TPU, f"ch{ch}-duty") == 2500
    assert b.get(TPU, f"ch{ch}-pwm-period") == 10000
    assert b.get(TPU, f"ch{ch}-pwm-high") == 2500
    # Normal update: the new high time applies from the next period on.
    b.set_param(ch, 2, 7500)
    assert b.get(TPU, f"ch{ch}-duty") == 2500
    b.step(int(10000 * tick_ns(b)) + 1000)
    assert b.get(TPU, f"ch{ch}-duty") == 7500


def test_pwm_pin_waveform_and_immediate_update(board):
    b = board
    b.tpu_start()
    setup_pwm(b, 6, 3000, 10000)
    t = tick_ns(b)
    b.step(int(1000 * t))
    assert b.get(TPU, "ch6-pin") == 1                            # inside the high time
    b.step(int(3000 * t))
    assert b.get(TPU, "ch6-pin") == 0                            # after it
    b.set_param(6, 2, 10000)
    b.tpu_hsr(6, 1)                                              # immediate update
    assert b.get(TPU, "ch6-duty") == 10000
    assert b.get(TPU, "ch6-pin") == 1


def test_pwm_disabled_by_priority_zero(board):
    b = board
    setup_pwm(b, 2, 500, 1000)
    assert b.get(TPU, "ch2-duty") == 5000
    b.tpu_field2(CPR0, 2, 0)
    assert b.get(TPU, "ch2-duty") == 0


def test_hsr_waits_for_priority(board):
    b = board
    b.tpu_field4(CFSR0, 4, FN_PWM)
    b.set_param(4, 2, 100)
    b.set_param(4, 3, 400)
    b.tpu_hsr(4, 2)
    assert (b.readw(TPU_BASE + HSRR0 + 2) >> 8) & 3 == 2          # pending: priority 0
    assert b.get(TPU, "ch4-duty") == 0
    b.tpu_field2(CPR0, 4, 1)
    assert (b.readw(TPU_BASE + HSRR0 + 2) >> 8) & 3 == 0
    assert b.get(TPU, "ch4-duty") == 2500


def test_pwm_interrupt_each_period(board):
    b = board
    b.tpu_start()
    b.writew(TPU_BASE + TICR, 0x0480)                            # level 4, base vector 0x80
    setup_pwm(b, 0, 5000, 10000)
    b.writew(TPU_BASE + CISR, 0)
    assert b.irq()[0] == 0                                       # CIER still 0
    b.writew(TPU_BASE + CIER, 0x0001)
    b.step(int(10000 * tick_ns(b)) + 1000)
    assert b.readw(TPU_BASE + CISR) & 1
    assert b.irq() == (4, 0x80)
    b.writew(TPU_BASE + CISR, 0xFFFE)                            # clear by writing 0
    assert b.readw(TPU_BASE + CISR) & 1 == 0
    assert b.irq()[0] == 0


def test_interrupt_vector_of_highest_channel(board):
    b = board
    b.writew(TPU_BASE + TICR, 0x06A0)                            # level 6, base 0xA0
    b.writew(TPU_BASE + CIER, 0xFFFF)
    for ch in (3, 9):
        b.tpu_setup(ch, FN_DIO, {0: 0x0F}, hsq=0, hsr=3)         # init records + raises
    assert b.readw(TPU_BASE + CISR) == (1 << 3) | (1 << 9)
    assert b.irq() == (6, 0xA9)
    b.writew(TPU_BASE + CISR, ~(1 << 9) & 0xFFFF)
    assert b.irq() == (6, 0xA3)


@pytest.mark.parametrize("ch", [0, 7, 15])
def test_dio_output(board, ch):
    b = board
    b.tpu_setup(ch, FN_DIO, {0: 0x0F}, hsr=1)                    # drive high
    assert b.get(TPU, f"ch{ch}-pin") == 1
    assert (b.get(TPU, "pins") >> ch) & 1 == 1
    b.tpu_hsr(ch, 2)                                             # drive low
    assert b.get(TPU, f"ch{ch}-pin") == 0
    assert b.param(ch, 1) & 0xC000 == 0x4000                     # history: low, then high


def test_dio_input_transitions(board):
    b = board
    b.tpu_setup(5, FN_DIO, {0: 0x0F, 1: 0}, hsq=0, hsr=3)
    assert b.param(5, 1) == 0x0000
    b.writew(TPU_BASE + CISR, 0)
    b.set(TPU, "ch5-pin", 1)
    assert b.param(5, 1) == 0x8000
    assert b.readw(TPU_BASE + CISR) == 1 << 5
    b.set(TPU, "ch5-pin", 0)
    assert b.param(5, 1) == 0x4000


def test_dio_match_rate_sampling(board):
    b = board
    b.tpu_setup(9, FN_DIO, {0: 0x0F, 1: 0, 2: 1000}, hsq=1, hsr=3)
    b.set(TPU, "ch9-pin", 1)                                     # no record on the edge
    assert b.param(9, 1) == 0
    b.step(int(1000 * tick_ns(b)) + 100)
    assert b.param(9, 1) == 0x8000


def toggle(b, ch, n):
    for _ in range(n):
        b.set(TPU, f"ch{ch}-pin", 1)
        b.set(TPU, f"ch{ch}-pin", 0)


@pytest.mark.parametrize("ch", [1, 3, 5, 11])
def test_itc_counts_rising_edges(board, ch):
    b = board
    b.tpu_setup(ch, FN_ITC, {0: 0x4, 2: 0xFFFF}, hsq=1, hsr=1)
    toggle(b, ch, 37)
    assert b.param(ch, 3) == 37
    b.tpu_hsr(ch, 1)                                             # re-init clears
    assert b.param(ch, 3) == 0


def test_itc_max_count_interrupt_and_single_shot(board):
    b = board
    b.writew(TPU_BASE + TICR, 0x0480)
    b.writew(TPU_BASE + CIER, 1 << 7)
    b.tpu_setup(7, FN_ITC, {0: 0xC, 2: 6}, hsq=0, hsr=1)          # both edges, single shot
    toggle(b, 7, 2)
    assert b.param(7, 3) == 4
    assert b.irq()[0] == 0
    toggle(b, 7, 1)
    assert b.param(7, 3) == 6
    assert b.irq() == (4, 0x87)
    final = b.param(7, 4)
    assert final == b.param(7, 5)                                # FINAL = LAST transition time
    toggle(b, 7, 3)
    assert b.param(7, 3) == 6                                    # stopped


def test_itc_continuous_restarts(board):
    b = board
    b.tpu_setup(8, FN_ITC, {0: 0x8, 2: 4}, hsq=1, hsr=1)          # falling edges
    toggle(b, 8, 10)
    assert b.param(8, 3) == 10 % 4
    assert b.readw(TPU_BASE + CISR) & (1 << 8)


def setup_qdec(b, pri, sec):
    for ch, hsq in ((pri, 0), (sec, 1)):
        b.tpu_setup(ch, FN_QDEC, {1: 0x8000, 4: (ch ^ pri ^ sec) * 16 + 6,
                                  5: pri * 16 + 1}, hsq=hsq, hsr=3)


def quad(b, a_ch, b_ch, steps):
    """Drives a quadrature sequence; positive steps: A leads B."""
    seq = [(0, 0), (1, 0), (1, 1), (0, 1)]
    pos = 0
    for _ in range(abs(steps)):
        pos = (pos + (1 if steps > 0 else -1)) % 4
        b.set(TPU, f"ch{a_ch}-pin", seq[pos][0])
        b.set(TPU, f"ch{b_ch}-pin", seq[pos][1])


def test_qdec_counts_both_directions(board):
    b = board
    setup_qdec(b, 8, 9)
    quad(b, 8, 9, 40)
    assert b.param(8, 1) == 0x8000 + 40
    quad(b, 8, 9, -60)
    assert b.param(8, 1) == 0x8000 - 20
    assert b.param(9, 1) == 0x8000                               # secondary's copy untouched


def test_qdec_edge_time(board):
    b = board
    b.tpu_start()
    setup_qdec(b, 8, 9)
    quad(b, 8, 9, 1)
    t0 = b.param(8, 0)
    b.step(2_000_000)
    quad(b, 8, 9, 2)
    expect = 2_000_000 / tick_ns(b)
    assert abs(((b.param(8, 0) - t0) & 0xFFFF) - expect) < 3


def test_qdec_tcr1_read_request(board):
    b = board
    b.tpu_start()
    setup_qdec(b, 10, 11)
    b.tpu_hsr(10, 1)
    t0 = b.param(10, 2)
    b.step(1_000_000)
    b.tpu_hsr(10, 1)
    assert abs(((b.param(10, 2) - t0) & 0xFFFF) - 1_000_000 / tick_ns(b)) < 3


def test_host_input_mask(board):
    b = board
    b.set(TPU, "inputs", 0xA5A5)
    assert b.get(TPU, "inputs") == 0xA5A5
    assert b.get(TPU, "pins") == 0xA5A5                          # no channel drives its pin
    with pytest.raises(Exception):
        b.set(TPU, "inputs", 0x10000)


def test_channel_interrupt_seen_by_qtest_intercept(board):
    """The TPU request reaches the CPU's IPL lines (arbiter gpio-out n = IPL n+1)."""
    b = board
    b.m.irq_intercept_out("/machine/intc")
    b.writew(TPU_BASE + TICR, 0x0580)                            # level 5
    b.writew(TPU_BASE + CIER, 1 << 2)
    b.tpu_setup(2, FN_ITC, {0: 0x4, 2: 3}, hsq=1, hsr=1)
    toggle(b, 2, 2)
    b.readw(TPU_BASE + CISR)                                     # flush IRQ messages
    assert (True, 4) not in b.m.irq_events
    toggle(b, 2, 1)
    b.readw(TPU_BASE + CISR)
    assert (True, 4) in b.m.irq_events
    b.writew(TPU_BASE + CISR, 0)
    b.readw(TPU_BASE + CISR)
    assert b.m.irq_events[-1] == (False, 4)
