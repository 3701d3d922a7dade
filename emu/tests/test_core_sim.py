"""MC68332 SIM of the robocube machine through qtest: reset values, clock
synthesiser, port E LED, periodic interrupt timer in virtual time, software
watchdog, chip selects (flash/SRAM), TPURAM placement, 24-bit address mirror."""
import time

import pytest

SIM = "/machine/sim"
INTC = "/machine/intc"
SIMCR, SYNCR, RSR = 0xFFFA00, 0xFFFA04, 0xFFFA07
PORTE, DDRE, PEPAR = 0xFFFA11, 0xFFFA15, 0xFFFA17
SYPCR, PICR, PITR, SWSR = 0xFFFA21, 0xFFFA22, 0xFFFA24, 0xFFFA27
CSPAR0, CSPAR1, CSBARBT, CSORBT = 0xFFFA44, 0xFFFA46, 0xFFFA48, 0xFFFA4A
CSBAR0, CSOR0, CSBAR1, CSOR1 = 0xFFFA4C, 0xFFFA4E, 0xFFFA50, 0xFFFA52
TRAMMCR, TRAMBAR = 0xFFFB00, 0xFFFB04
NOT_MAPPED = 2**64 - 1          # QOM value of flash-base etc. when not decoded


def test_reset_values(raw_machine):
    m = raw_machine
    assert m.readw(SIMCR) == 0x00CF
    assert m.readw(SYNCR) == 0x3F08          # Y=63, SLOCK=1
    assert m.readb(RSR) == 0xC0              # power-on (POW + EXT)
    assert m.readb(SYPCR) == 0x80            # software watchdog enabled
    assert m.readw(PICR) == 0x000F
    assert m.readw(PITR) == 0x0000
    assert m.readw(CSPAR0) == 0x3FFF
    assert m.readw(CSPAR1) == 0x03FF
    assert m.readw(CSBARBT) == 0x0007        # flash: 1 MiB block at 0
    assert m.readw(CSORBT) == 0x7870
    assert m.readw(CSBAR0) == 0 and m.readw(CSOR0) == 0
    assert m.readw(TRAMMCR) == 0x0100
    assert m.qom_get(SIM, "flash-base") == 0
    assert m.qom_get(SIM, "sram-base") == NOT_MAPPED
    assert m.qom_get(SIM, "tpuram-base") == NOT_MAPPED
    assert m.qom_get(SIM, "system-clock-hz") == 8388608


@pytest.mark.parametrize("syncr, hz", [
    (0x7F00, 16777216),      # W=0 X=1 Y=63: the board's 16.777216 MHz
    (0x1F00, 4194304),       # W=0 X=0 Y=31
    (0xBF00, 33554432),      # W=1 X=0 Y=63
])
def test_syncr_clock_and_slock(machine, syncr, hz):
    machine.writew(SYNCR, syncr)
    assert machine.readw(SYNCR) == syncr | 0x0008    # SLOCK reads 1 at once
    assert machine.qom_get(SIM, "system-clock-hz") == hz


def test_port_e_led(machine):
    m = machine
    assert m.qom_get(SIM, "led") is False
    m.writeb(DDRE, 0x08)
    m.writeb(PEPAR, 0xF7)
    m.writeb(PORTE, 0x08)
    assert m.readb(PORTE) == 0x08
    assert m.qom_get(SIM, "led") is True
    m.writeb(PORTE, 0x00)
    assert m.qom_get(SIM, "led") is False
    m.writeb(PORTE, 0x08)
    m.writeb(PEPAR, 0xFF)                    # PE3 back to its bus function
    assert m.qom_get(SIM, "led") is False


def test_pit_rate_in_virtual_time(machine):
    """PITR=8 (PTP=0): period 8*4/32768 s = 976562.5 ns, 1024 per second."""
    m = machine
    m.irq_intercept_out(INTC)
    m.writew(PICR, 0x0440)                   # level 4, vector 64
    m.writew(PITR, 0x0008)
    assert m.qom_get(SIM, "pit-period-ns") == 976562
    m.clock_step(976561)
    assert m.qom_get(SIM, "pit-count") == 0
    assert m.qom_get(INTC, "level") == 0
    m.clock_step(1)
    assert m.qom_get(SIM, "pit-count") == 1
    assert (m.qom_get(INTC, "level"), m.qom_get(INTC, "vector")) == (4, 64)
    assert (True, 3) in m.irq_events        # IPL output 3 = level 4 raised
    m.clock_step(1_000_000_000 - 976562)     # exactly 1 s after programming
    assert m.qom_get(SIM, "pit-count") == 1024


def test_pit_prescaler_and_level_zero(machine):
    m = machine
    m.writew(PICR, 0x0041)                   # level 0: timer runs, no request
    m.writew(PITR, 0x0101)                   # PTP=1, PITM=1: 4*512/32768 = 62.5 ms
    m.clock_step(1_000_000_000)
    assert m.qom_get(SIM, "pit-count") == 16
    assert m.qom_get(INTC, "level") == 0
    m.writew(PITR, 0x0000)                   # PITM=0 stops the timer
    m.clock_step(1_000_000_000)
    assert m.qom_get(SIM, "pit-count") == 16


def test_sypcr_is_write_once(raw_machine):
    m = raw_machine
    m.writeb(SYPCR, 0x06)                    # watchdog off, bus monitor on
    m.writeb(SYPCR, 0x80)                    # ignored
    assert m.readb(SYPCR) == 0x06
    m.clock_step(100_000_000)
    assert m.readb(RSR) == 0xC0              # no watchdog reset


def wait_reset(m, timeout=5.0):
    """The reset requested by the watchdog runs in QEMU's main loop."""
    deadline = time.monotonic() + timeout
    while m.readb(RSR) != 0x20:
        assert time.monotonic() < deadline, "no watchdog reset"
        time.sleep(0.01)


def test_watchdog_resets_unless_serviced(raw_machine):
    """SWE=1, SWP=0, SWT=0: timeout 2^9/32768 s = 15.625 ms."""
    m = raw_machine
    m.writeb(SYPCR, 0x80)
    for _ in range(5):                       # 50 ms, serviced every 10 ms
        m.clock_step(10_000_000)
        m.writeb(SWSR, 0x55)
        m.writeb(SWSR, 0xAA)
    assert m.readb(RSR) == 0xC0
    m.writeb(SWSR, 0xAA)                     # wrong order does not service
    m.writeb(SWSR, 0x55)
    m.clock_step(15_000_000)
    assert m.readb(RSR) == 0xC0
    m.clock_step(1_000_000)
    wait_reset(m)
    assert m.readb(RSR) == 0x20              # reset by the software watchdog
    assert m.readb(SYPCR) == 0x80            # and SYPCR is writable again


def test_chip_selects_move_flash_and_map_sram(machine):
    m = machine
    m.writew(CSBARBT, 0xE007)                # flash to 0xE00000
    assert m.qom_get(SIM, "flash-base") == 0xE00000
    assert m.readl(0xE00000) == 0xFFFFFFFF   # blank flash
    m.writel(0x1000, 0x12345678)             # nothing decoded at 0 yet
    assert m.readl(0x1000) != 0x12345678
    m.writew(CSBAR0, 0x0007)
    m.writew(CSOR0, 0x5C3E)
    assert m.qom_get(SIM, "sram-base") == NOT_MAPPED   # CS1 not yet programmed
    m.writew(CSBAR1, 0x0007)
    m.writew(CSOR1, 0x3C3E)
    assert m.qom_get(SIM, "sram-base") == 0
    m.writel(0x1000, 0x12345678)
    m.writel(0xFFFFC, 0xCAFEF00D)
    assert m.readl(0x1000) == 0x12345678
    assert m.readl(0xFFFFC) == 0xCAFEF00D
    # 256 KiB block: the top of SRAM is no longer decoded.
    m.writew(CSBAR0, 0x0005)
    m.writew(CSBAR1, 0x0005)
    assert m.readl(0x1000) == 0x12345678
    assert m.readl(0xFFFFC) != 0xCAFEF00D
    # CSPAR0 turning CS0 into a discrete output unmaps SRAM.
    m.writew(CSPAR0, 0x3FF3)
    assert m.qom_get(SIM, "sram-base") == NOT_MAPPED


def test_flash_image_at_boot_alias_and_after_relocation(build_elf):
    import robocube_emu
    elf = build_elf("""
        .long 0x00F20800
        .long 0x00000400
        .org 0x400
        .long 0x5AA5C33C
        .org 0xFFFFC
        .long 0x0BADF00D
    """)
    with robocube_emu.start(kernel=elf, qtest=True) as m:
        assert m.readl(0x0) == 0x00F20800            # reset: flash at 0
        assert m.readl(0x400) == 0x5AA5C33C
        assert m.readl(0xFFFFC) == 0x0BADF00D
        m.writew(CSBARBT, 0xE004)                    # 128 KiB block at 0xE00000
        assert m.readl(0xE00400) == 0x5AA5C33C
        assert m.readl(0xE1FFFC) == 0                # .org fill, inside the block
        assert m.readl(0xEFFFFC) != 0x0BADF00D       # beyond the block
        m.writew(CSBARBT, 0xE007)
        assert m.readl(0xEFFFFC) == 0x0BADF00D
        m.writel(0xE00400, 0)                        # flash is read-only
        assert m.readl(0xE00400) == 0x5AA5C33C


def test_tpuram_placed_by_trambar_once(machine):
    m = machine
    m.writew(TRAMBAR, 0xF200)
    assert m.qom_get(SIM, "tpuram-base") == 0xF20000
    m.writel(0xF20000, 0x01020304)
    m.writel(0xF207FC, 0xA5A5A5A5)
    assert m.readl(0xF20000) == 0x01020304
    assert m.readl(0xF207FC) == 0xA5A5A5A5
    m.writew(TRAMBAR, 0xF300)                # write-once: ignored
    assert m.readw(TRAMBAR) == 0xF200
    assert m.readl(0xF20000) == 0x01020304


def test_short_absolute_mirror(machine):
    """$FA04.W sign-extends to 0xFFFFFA04: the 16 MiB bus repeats there."""
    assert machine.readw(0xFFFFFA04) == machine.readw(SYNCR) == 0x3F08


def test_system_reset_restores_boot_mapping(machine):
    m = machine
    m.writew(CSBARBT, 0xE007)
    m.writew(PICR, 0x0440)
    m.writew(PITR, 0x0008)
    assert m.qom_get(SIM, "flash-base") == 0xE00000
    m.system_reset()
    deadline = time.monotonic() + 5
    while m.readw(CSBARBT) != 0x0007:
        assert time.monotonic() < deadline, "reset did not happen"
        time.sleep(0.01)
    assert m.qom_get(SIM, "flash-base") == 0
    assert m.readw(PITR) == 0 and m.readw(PICR) == 0x000F
    assert m.readb(RSR) == 0x80              # external reset
    m.clock_step(10_000_000)
    assert m.qom_get(SIM, "pit-count") == 0
