"""Firmware in the loop: a small CPU32 program runs on the emulated board
(TCG, no qtest) and drives the I/O like a real driver, while the host changes
sensor inputs and reads actuator outputs over QMP."""

import time

import robocube_emu

from io_support import IO

# Copies AIN0 to AOUT0 over I2C bus A (PCF8591 at 0x48), runs motor 0 at
# 30 % forward (TPU PWM on TP0, DUART OP2) and copies the QDEC position of
# its encoder (TP1 primary, TP12 secondary) to the fast binary outputs.
PROGRAM = r"""
        .macro  waitpin
1:      btst    #7, 0xFFE201
        bne.s   1b
        .endm

        .long   0x00F20800
        .long   start - 0xE00000
start:
        move.b  #0x00, 0xFFFA21         | SYPCR: software watchdog off
        move.w  #0x4ACD, 0xFFFE00       | TPUMCR as CubeOS
        move.w  #0x0069, 0xFFFE12       | CFSR3: ch0 PWM, ch1 QDEC
        move.w  #0x0006, 0xFFFE0C       | CFSR0: ch12 QDEC
        move.w  #0x0100, 0xFFFE14       | HSQR0: ch12 secondary (01)
        move.w  #0x008C, 0xFFFF00       | ch0 PWM: control, PWMHI, PWMPER
        move.w  #3000, 0xFFFF04
        move.w  #10000, 0xFFFF06
        move.w  #0x8000, 0xFFFF12       | ch1 POSITION_COUNT
        move.w  #0x00C6, 0xFFFF18       | ch1 CORR_PINSTATE_ADDR -> ch12 param3
        move.w  #0x0011, 0xFFFF1A       | ch1 EDGE_TIME_LSB_ADDR -> ch1
        move.w  #0x0016, 0xFFFFC8       | ch12 CORR_PINSTATE_ADDR -> ch1 param3
        move.w  #0x0011, 0xFFFFCA       | ch12 EDGE_TIME_LSB_ADDR -> ch1
        move.w  #0x000E, 0xFFFE1A       | HSRR1: ch0 init (10), ch1 init (11)
        move.w  #0x0300, 0xFFFE18       | HSRR0: ch12 init (11)
        move.w  #0x000A, 0xFFFE1E       | CPR1: ch0, ch1 priority 2
        move.w  #0x0200, 0xFFFE1C       | CPR0: ch12 priority 2
        move.b  #0x04, 0xFFE40E         | DUART OPR-set: OP2 -> motor 0 forward

        move.b  #0x80, 0xFFE201         | PCF8584 bus A init
        move.b  #0x55, 0xFFE200
        move.b  #0xA0, 0xFFE201
        move.b  #0x1C, 0xFFE200
        move.b  #0xC1, 0xFFE201
loop:
        move.b  #0x90, 0xFFE200         | write control byte 0x40 (AOUT on, ch0)
        move.b  #0xC5, 0xFFE201
        waitpin
        move.b  #0x40, 0xFFE200
        waitpin
        move.b  #0xC3, 0xFFE201
        move.b  #0x91, 0xFFE200         | read two bytes, keep the second
        move.b  #0xC5, 0xFFE201
        waitpin
        move.b  0xFFE200, %d0           | dummy read
        waitpin
        move.b  #0x40, 0xFFE201         | NACK the last byte
        move.b  0xFFE200, %d0
        waitpin
        move.b  #0xC3, 0xFFE201
        move.b  0xFFE200, %d1           | AIN0
        move.b  #0x90, 0xFFE200         | write [0x40, AIN0]: DAC
        move.b  #0xC5, 0xFFE201
        waitpin
        move.b  #0x40, 0xFFE200
        waitpin
        move.b  %d1, 0xFFE200
        waitpin
        move.b  #0xC3, 0xFFE201
        move.w  0xFFFF12, 0xFE0000      | QDEC position -> fast outputs
        bra     loop
"""


def wait_for(cond, timeout=10.0):
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if cond():
            return True
        time.sleep(0.02)
    return False


def test_firmware_loop_with_host_io(build_elf):
    elf = build_elf(PROGRAM, name="io_loop")
    with robocube_emu.start(kernel=elf) as m:
        m0 = IO + "/motor0"
        assert wait_for(lambda: m.qom_get(m0, "duty") == 3000), m.stderr()
        assert m.qom_get(m0, "direction") == 1
        for value in (0x5A, 0xC3, 0x07):
            m.qom_set(IO, "ain0", value)
            assert wait_for(lambda: m.qom_get(IO, "aout0") == value), value
            assert m.qom_get(IO, "aout0-enabled") == 1
        # The motor turns and the firmware's QDEC count follows the encoder.
        assert wait_for(lambda: m.qom_get(m0, "encoder") > 100)
        assert wait_for(lambda: abs(((m.qom_get(IO, "fastbin") - 0x8000) & 0xFFFF)
                                    - m.qom_get(m0, "encoder")) < 50)
