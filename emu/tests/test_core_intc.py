"""Interrupt arbitration of the robocube board (qtest): the highest requested
level reaches the CPU with its source's vector; ties go to the earlier source
(PIT before SCI before TPU before DUART before I2C); qtest sees the IPL lines."""

INTC = "/machine/intc"
PICR, PITR = 0xFFFA22, 0xFFFA24
QILR, QIVR, SCCR1 = 0xFFFC04, 0xFFFC05, 0xFFFC0A
DUART_IVR, DUART_IMR, DUART_CRB = 0xFFE40C, 0xFFE405, 0xFFE40A


def presented(m):
    return m.qom_get(INTC, "level"), m.qom_get(INTC, "vector")


def test_highest_level_wins_and_lines_follow(machine):
    m = machine
    m.irq_intercept_out(INTC)
    m.writew(PICR, 0x0440)
    m.writew(PITR, 0x0001)                   # 122 us
    m.clock_step(200_000)
    assert presented(m) == (4, 64)
    m.writeb(DUART_IVR, 0x50)
    m.writeb(DUART_CRB, 0x04)                # TX on: TxRDYB
    m.writeb(DUART_IMR, 0x10)
    assert presented(m) == (5, 0x50)
    m.writeb(DUART_IMR, 0x00)
    assert presented(m) == (4, 64)
    m.writew(PICR, 0x0040)                   # PIT level 0
    assert presented(m) == (0, 0)
    # IPL output n-1 follows level n: 4 up, 4 down/5 up, 5 down/4 up, 4 down
    assert m.irq_events == [(True, 3), (False, 3), (True, 4), (False, 4),
                            (True, 3), (False, 3)]


def test_same_level_goes_to_the_earlier_source(machine):
    m = machine
    m.writew(PICR, 0x0540)                   # PIT level 5, vector 64
    m.writew(PITR, 0x0001)
    m.clock_step(200_000)
    m.writeb(DUART_CRB, 0x04)
    m.writeb(DUART_IMR, 0x10)                # DUART level 5, vector 0x0F
    m.writeb(QILR, 0x05)
    m.writeb(QIVR, 0x60)
    m.writew(SCCR1, 0x0088)                  # SCI TE + TIE: level 5, vector 0x60
    assert presented(m) == (5, 64)           # PIT first
    m.writew(PICR, 0x0040)
    assert presented(m) == (5, 0x60)         # then SCI
    m.writew(SCCR1, 0x0008)
    assert presented(m) == (5, 0x0F)         # then DUART
