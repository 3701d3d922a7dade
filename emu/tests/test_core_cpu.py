"""The robocube machine with a running CPU32 (TCG): boot from the flash's
reset alias, console output on DUART B, bus errors with the CPU32 format $C
frame for unmapped accesses and flash writes, double bus fault halting the
CPU without killing QEMU, and PIT interrupts acknowledged by the CPU."""
import re
import time

import pytest

import robocube_emu

# Common program skeleton: vector table at flash offset 0 (SSP = top of
# TPURAM, which the first instructions map), bus error handler that prints
# the stacked frame, and console output helpers.  FAULT is replaced.
PROGRAM = r"""
    .text
    .long 0x00F20800                /* 0: SSP, top of TPURAM */
    .long start - 0xE00000          /* 1: PC through the reset alias at 0 */
    .long berr - 0xE00000           /* 2: bus error */
    .long aerr - 0xE00000           /* 3: address error */
    .long ill - 0xE00000            /* 4: illegal instruction */
    .org 0x100
    .long pit - 0xE00000            /* 64: PIT */
    .org 0x400
start:
    move.b  #0x00, 0xFFFA21         /* SYPCR: watchdog off */
    move.w  #0xF200, 0xFFFB04       /* TRAMBAR: TPURAM at 0xF20000 (stack) */
    move.b  #0x05, 0xFFE40A         /* CRB: console RX/TX on */
    lea     hello(%pc), %a0
    bsr     puts
    FAULT
    lea     after(%pc), %a0
    bsr     puts
halt:
    bra     halt

/* Illegal instruction: print "ILL" and the stacked format/vector word. */
ill:
    movea.l %sp, %a1
    lea     illmsg(%pc), %a0
    bsr     puts
    moveq   #0, %d0
    move.w  6(%a1), %d0
    bsr     puthex
    lea     eol(%pc), %a0
    bsr     puts
    bra     halt

/* Address error: same frame as a bus error on the CPU32. */
aerr:
    movea.l %sp, %a1
    lea     aerrmsg(%pc), %a0
    bra.s   frame

/* Bus error: print "BERR" and the format $C frame words. */
berr:
    movea.l %sp, %a1
    lea     berrmsg(%pc), %a0
frame:
    bsr     puts
    moveq   #0, %d0
    move.w  6(%a1), %d0             /* format / vector offset */
    bsr     puthex
    move.l  8(%a1), %d0             /* faulted address */
    bsr     puthex
    move.l  16(%a1), %d0            /* current instruction PC */
    bsr     puthex
    moveq   #0, %d0
    move.w  22(%a1), %d0            /* special status word */
    bsr     puthex
    lea     eol(%pc), %a0
    bsr     puts
    bra     halt

/* PIT: count ticks in %d7, print 'T' every 1024 (one second). */
pit:
    addq.l  #1, 0xF20000            /* handler entries, read by the test */
    addq.l  #1, %d7
    cmp.l   #1024, %d7
    bne.s   1f
    moveq   #0, %d7
    move.b  #'T', %d1
    bsr     putc
1:  rte

putc:                               /* %d1 -> console */
    btst    #2, 0xFFE409
    beq.s   putc
    move.b  %d1, 0xFFE40B
    rts

puts:                               /* %a0 -> NUL-terminated string */
    move.b  (%a0)+, %d1
    beq.s   2f
    bsr     putc
    bra.s   puts
2:  rts

puthex:                             /* %d0 as " XXXXXXXX" */
    move.b  #' ', %d1
    bsr     putc
    moveq   #7, %d2
3:  rol.l   #4, %d0
    move.b  %d0, %d1
    and.b   #0x0F, %d1
    add.b   #'0', %d1
    cmp.b   #'9', %d1
    ble.s   4f
    add.b   #7, %d1
4:  bsr     putc
    dbra    %d2, 3b
    rts

ok:      .asciz "RELOC OK\r\n"
bad:     .asciz "FAIL\r\n"
hello:   .asciz "HELLO\r\n"
after:   .asciz "AFTER\r\n"
berrmsg: .asciz "BERR"
aerrmsg: .asciz "AERR"
illmsg:  .asciz "ILL"
eol:     .asciz "\r\n"
"""


def run(build_elf, fault, extra_args=()):
    elf = build_elf(PROGRAM.replace("FAULT", fault))
    return robocube_emu.start(kernel=elf, extra_args=extra_args)


def berr_frame(m):
    line = m.console.read_until(b"\r\n", timeout=10).decode()
    match = re.fullmatch(r"BERR ([0-9A-F]{8}) ([0-9A-F]{8}) ([0-9A-F]{8}) ([0-9A-F]{8})\r\n",
                         line)
    assert match, line
    return [int(x, 16) for x in match.groups()]


def test_boot_prints_on_console(build_elf):
    with run(build_elf, "nop") as m:
        assert m.console.read_until(b"HELLO\r\n", timeout=10) == b"HELLO\r\n"
        assert m.console.read_until(b"AFTER\r\n", timeout=10) == b"AFTER\r\n"
        m.radio.poll()
        assert m.radio.received == b""


@pytest.mark.parametrize("fault, address, ssw", [
    # long read from an undecoded address: RW=1, LG=1, SIZ=00, FUNC=5 (S data)
    ("tst.l 0x00200000", 0x00200000, 0x0065),
    # byte write to the flash, here at its reset alias (read-only): RW=0, SIZ=01
    ("move.b #1, 0x00000010", 0x00000010, 0x000D),
    # the same address range before relocation is simply not decoded
    ("move.b #1, 0x00E00010", 0x00E00010, 0x000D),
    # word read of SRAM space above the boot flash block (CS0/CS1 not programmed)
    ("tst.w 0x00100000", 0x00100000, 0x0055),
    # an address above the 24-bit bus that is not the 0xFF mirror
    ("tst.b 0x01000000", 0x01000000, 0x004D),
])
def test_bus_error_frame(build_elf, fault, address, ssw):
    with run(build_elf, fault) as m:
        m.console.read_until(b"HELLO\r\n", timeout=10)
        fmt, fault_addr, pc, status = berr_frame(m)
        assert fmt == 0xC008                 # format $C, vector 2 (offset 8)
        assert fault_addr == address
        assert pc < 0x100000                 # running through the reset alias
        assert status == ssw
        assert m.qmp_cmd("query-status")["status"] == "running"


def test_unmapped_instruction_fetch_is_a_bus_error(build_elf):
    with run(build_elf, "jmp 0x00300000") as m:
        m.console.read_until(b"HELLO\r\n", timeout=10)
        fmt, fault_addr, _, status = berr_frame(m)
        assert fmt == 0xC008
        assert fault_addr == 0x00300000
        assert status & 0x7 == 6             # FUNC = supervisor program


def test_odd_program_counter_is_an_address_error(build_elf):
    with run(build_elf, "jmp 0x00000401") as m:
        m.console.read_until(b"HELLO\r\n", timeout=10)
        line = m.console.read_until(b"\r\n", timeout=10).decode()
        match = re.fullmatch(r"AERR ([0-9A-F]{8}) ([0-9A-F]{8}) ([0-9A-F]{8}) ([0-9A-F]{8})\r\n",
                             line)
        assert match, line
        fmt, fault_addr, pc, ssw = (int(x, 16) for x in match.groups())
        assert fmt == 0xC00C                 # format $C, vector 3 (offset 0x0C)
        assert fault_addr == pc == 0x401
        assert ssw == 0x0056                 # read, word, supervisor program


@pytest.mark.parametrize("fault, address, ssw", [
    ("move.w 0x00F20001, %d0", 0x00F20001, 0x0055),   # read, S data
    ("move.l %d0, 0x00F20003", 0x00F20003, 0x0015),   # write, S data
])
def test_odd_data_address_is_an_address_error(build_elf, fault, address, ssw):
    # A long at a word boundary is fine on the CPU32; only odd addresses fault.
    prologue = "move.l #0x11223344, 0x00F20002\n    tst.l 0x00F20002\n    "
    with run(build_elf, prologue + fault) as m:
        m.console.read_until(b"HELLO\r\n", timeout=10)
        line = m.console.read_until(b"\r\n", timeout=10).decode()
        match = re.fullmatch(r"AERR ([0-9A-F]{8}) ([0-9A-F]{8}) ([0-9A-F]{8}) ([0-9A-F]{8})\r\n",
                             line)
        assert match, line
        fmt, fault_addr, pc, status = (int(x, 16) for x in match.groups())
        assert (fmt, fault_addr, status) == (0xC00C, address, ssw)
        assert 0x400 < pc < 0x1000           # the faulting instruction (boot alias)


def test_invalid_effective_address_is_illegal_instruction(build_elf):
    # 0x41C0 would be LEA %d0,%a0: no such addressing mode.
    with run(build_elf, ".word 0x41C0") as m:
        m.console.read_until(b"HELLO\r\n", timeout=10)
        assert m.console.read_until(b"\r\n", timeout=10) == b"ILL 00000010\r\n"


def test_double_bus_fault_halts_cpu_not_qemu(build_elf):
    # Stack pointer into undecoded space, then a fault: stacking the bus
    # error frame faults again; the CPU32 halts.
    with run(build_elf, "movea.l #0x00400000, %sp\n    tst.l 0x00200000") as m:
        m.console.read_until(b"HELLO\r\n", timeout=10)
        deadline_text = ""
        for _ in range(200):
            deadline_text = m.stderr()
            if "double bus fault" in deadline_text:
                break
            time.sleep(0.02)
        assert "double bus fault" in deadline_text
        assert m.proc.poll() is None         # QEMU still alive
        assert m.qmp_cmd("query-status")["status"] == "running"
        m.console.poll()
        assert b"BERR" not in m.console.received


def test_lpstop_with_mask_7_switches_the_board_off(build_elf):
    # CPU32 LPSTOP (F800 01C0 #imm) with the interrupt mask at 7: the board
    # model's power-off (board_power_off, the shell's exit): QEMU ends, status 0.
    with run(build_elf, "lpstop #0x2700") as m:
        m.console.read_until(b"HELLO\r\n", timeout=10)
        assert m.proc.wait(timeout=20) == 0
        m.console.poll()
        assert b"AFTER" not in m.console.received


def test_lpstop_below_mask_7_sleeps_like_stop(build_elf):
    # Mask 6 (nothing pending in this program): the CPU sleeps, the machine
    # runs on; LPSTOP is no longer an unimplemented line-F instruction.
    with run(build_elf, "lpstop #0x2600") as m:
        m.console.read_until(b"HELLO\r\n", timeout=10)
        time.sleep(1.0)
        assert m.proc.poll() is None
        assert m.qmp_cmd("query-status")["status"] == "running"
        m.console.poll()
        assert b"AFTER" not in m.console.received and b"ILL" not in m.console.received


def test_pit_interrupts_acknowledged_by_cpu(build_elf):
    """PIT at level 4 / vector 64, 1024 Hz, under -icount (deterministic
    virtual time whatever the host load): the handler counts its entries in
    TPURAM and prints 'T' every 1024.  Each PIT period must enter the handler
    exactly once: the interrupt-acknowledge cycle clears the request (without
    it the CPU would re-enter the handler back to back)."""
    setup = ("clr.l 0xF20000\n"
             "    move.w #0x0440, 0xFFFA22\n"  # PICR
             "    move.w #0x0008, 0xFFFA24\n"  # PITR: 976.5625 us
             "    moveq #0, %d7\n"
             "    move.w #0x2000, %sr")
    with run(build_elf, setup, extra_args=["-icount", "shift=6,sleep=off"]) as m:
        m.console.read_until(b"AFTER\r\n", timeout=10)
        m.console.read_until(b"TT", timeout=60)
        m.qmp_cmd("stop")
        ticks = m.qom_get("/machine/sim", "pit-count")
        out = m.qmp_cmd("human-monitor-command", **{"command-line": "xp /1wx 0xF20000"})
        entries = int(out.split(":")[1].split()[0], 16)
        assert ticks >= 2048
        assert entries in (ticks, ticks - 1), (entries, ticks)


RELOCATION = r"""
    .text
    .long 0x00F20800                /* SSP: top of TPURAM */
    .long start - 0xE00000          /* reset PC through the boot alias */
    .long berr                      /* used after relocation (VBR = 0xE00000) */
    .org 0x400
start:
    move.b  #0x00, 0xFFFA21         /* SYPCR: watchdog off */
    move.w  #0xF200, 0xFFFB04       /* TPURAM at 0xF20000 */
    move.b  #0x05, 0xFFE40A
    lea     stub(%pc), %a0          /* copy the relocation stub into TPURAM */
    lea     0xF20400, %a2
    move.w  #(stub_end - stub) / 2 - 1, %d0
1:  move.w  (%a0)+, (%a2)+
    dbra    %d0, 1b
    move.l  #relocated, %a1         /* link address 0xE0xxxx */
    jmp     0xF20400
stub:                               /* runs from TPURAM: the low alias vanishes */
    move.w  #0xE007, 0xFFFA48       /* CSBARBT: flash to 0xE00000, 1 MiB */
    jmp     (%a1)
stub_end:
relocated:
    move.w  #0x0007, 0xFFFA4C       /* CSBAR0 */
    move.w  #0x5C3E, 0xFFFA4E       /* CSOR0 */
    move.w  #0x0007, 0xFFFA50       /* CSBAR1 */
    move.w  #0x3C3E, 0xFFFA52       /* CSOR1: SRAM at 0 */
    move.l  #0x12345678, 0x00001000
    cmp.l   #0x12345678, 0x00001000
    bne     fail
    move.l  #0xCAFEF00D, 0x000FFFFC /* top of the 1 MiB SRAM */
    cmp.l   #0xCAFEF00D, 0x000FFFFC
    bne     fail
    lea     0xE00000, %a0
    movec   %a0, %vbr
    lea     ok(%pc), %a0
    bsr     puts
    FAULT2
fail:
    lea     bad(%pc), %a0
    bsr     puts
halt:
    bra     halt
"""


@pytest.mark.parametrize("fault, address, ssw", [
    ("tst.l 0x00100000", 0x00100000, 0x0065),       # just above the 1 MiB SRAM
    ("move.w #1, 0x00E00010", 0x00E00010, 0x0015),  # word write to relocated flash
])
def test_relocation_through_tpuram_then_sram_and_vbr(build_elf, fault, address, ssw):
    """The boot dance of BOARD.md with the CPU running: flash at 0 after reset,
    a stub in TPURAM moves it to 0xE00000, SRAM appears at 0 with CS0/CS1,
    VBR points into the relocated flash and a bus error finds its handler there."""
    tail = PROGRAM[PROGRAM.index("/* Bus error: print"):]
    with robocube_emu.start(kernel=build_elf(RELOCATION.replace("FAULT2", fault) + tail)) as m:
        assert m.console.read_until(b"RELOC OK\r\n", timeout=10).endswith(b"RELOC OK\r\n")
        fmt, fault_addr, pc, status = berr_frame(m)
        assert (fmt, fault_addr, status) == (0xC008, address, ssw)
        assert 0xE00000 <= pc < 0xF00000    # executing from the relocated flash
        assert m.qom_get("/machine/sim", "flash-base") == 0xE00000
        assert m.qom_get("/machine/sim", "sram-base") == 0
        m.console.poll()
        assert b"FAIL" not in m.console.received


def test_bus_error_on_vector_fetch_is_a_double_fault(build_elf):
    """VBR pointing at undecoded space: the bus error cannot fetch its own
    vector, which the CPU32 treats as a double bus fault (halt)."""
    with run(build_elf, "move.l #0x00400000, %a0\n    movec %a0, %vbr\n"
                        "    tst.l 0x00200000") as m:
        m.console.read_until(b"HELLO\r\n", timeout=10)
        deadline = time.monotonic() + 10
        while "double bus fault at 0x00400008" not in m.stderr():
            assert time.monotonic() < deadline, m.stderr()
            time.sleep(0.02)
        assert m.qmp_cmd("query-status")["status"] == "running"
