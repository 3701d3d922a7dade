/*
 * Reset entry, vector table and exception entry of the RoboCube firmware
 * (MC68332 / CPU32, RoboCube v2.0 memory map: see emu/README.md and
 * boards/robocube/robocube.ld).
 *
 * At reset CSBOOT maps the flash at address 0 and nothing else is mapped;
 * the CPU takes SSP and PC from flash offsets 0 and 4. The reset code
 * therefore starts at a low flash offset and may only use PC-relative
 * addressing and no stack until it has
 *   1. set up the SIM (watchdog off, bus monitor on, 16.777216 MHz clock),
 *   2. enabled the TPURAM at 0xF20000 and copied a small stub there,
 *   3. jumped to the stub, which moves the flash to 0xE00000 (CSBARBT) and
 *      jumps into the relocated flash at the link address,
 * after which the code runs where it is linked, maps the SRAM at 0, sets
 * SP, VBR, copies .data, clears .bss and calls firmware_entry (main, or
 * drivers/board_main.c's start-up that runs main as a thread).
 */

/* SIM and TPURAM control registers (MC68332, SIMCR.MM = 1). */
#define SIMCR    0xFFFA00
#define SYNCR    0xFFFA04
#define SYPCR    0xFFFA21
#define CSPAR0   0xFFFA44
#define CSPAR1   0xFFFA46
#define CSBARBT  0xFFFA48
#define CSORBT   0xFFFA4A
#define CSBAR0   0xFFFA4C
#define CSOR0    0xFFFA4E
#define CSBAR1   0xFFFA50
#define CSOR1    0xFFFA52
#define TRAMMCR  0xFFFB00
#define TRAMBAR  0xFFFB04

/* SYPCR (write-once): software watchdog off (SWE = 0), halt monitor off,
 * bus monitor on with a 16-clock timeout, so an access nothing answers
 * ends in a bus error instead of a hang. */
#define SYPCR_VALUE   0x06
/* SYNCR: W = 0, X = 1, Y = 63 -> 32768 Hz * 4 * 64 * 2 = 16.777216 MHz. */
#define SYNCR_VALUE   0x7F00
#define SYNCR_SLOCK   3        /* bit number */
/* SIMCR: reset value 0x00CF (SUPV = 1: SIM registers supervisor-only,
 * MM = 1, IARB = 15) plus FRZSW/FRZBM so the watchdog and bus monitor stop
 * while a BDM debugger holds the CPU. */
#define SIMCR_VALUE   0x60CF
/* TPURAM: supervisor-only, enabled at 0xF20000 (TRAMBAR address bits 23..11). */
#define TRAMMCR_VALUE 0x0100
#define TRAMBAR_VALUE 0xF200
#define TPURAM_BASE   0xF20000
/* Flash: 1 MiB block at 0xE00000, read-only, both bytes, 1 wait state,
 * supervisor and user space (CSORBT = 0x6870). */
#define CSBARBT_VALUE 0xE007
#define CSORBT_VALUE  0x6870
/* SRAM: 2 x 512K x 8, 1 MiB block at 0. CS0 strobes the upper byte
 * (D15-D8), CS1 the lower byte; async, read/write, 0 wait states. */
#define CSBAR_SRAM    0x0007
#define CSOR0_VALUE   0x5C3E
#define CSOR1_VALUE   0x3C3E
/* Pin assignment: CS5 8-bit port, other chip selects 16-bit;
 * CSPAR1 turns the CS6 pin into address line A19 (1 MiB devices). */
#define CSPAR0_VALUE  0x2FFF
#define CSPAR1_VALUE  0x03FD

    .section .vectors, "a"
    .globl  cpu32_vectors
cpu32_vectors:
    .long   __stack_top                   /* 0: SSP, top of SRAM (used once SRAM is mapped) */
    .long   cpu32_reset - cpu32_vectors   /* 1: PC at reset = flash offset (flash sits at 0) */

/*
 * Vectors 2..255 point at weak symbols cpu32_vector_<n>, all aliases of the
 * generic exception entry. A driver claims vector n by defining a function
 * named cpu32_vector_<n> (e.g. the PIT driver defines cpu32_vector_64);
 * the linker then puts it into this table. No run-time patching, and the
 * table stays in flash.
 */
    .altmacro
    .macro  vector n
    .weak   cpu32_vector_\n
    .set    cpu32_vector_\n, cpu32_exception
    .long   cpu32_vector_\n
    .endm
    .set    vecno, 2
    .rept   254
    vector  %vecno
    .set    vecno, vecno + 1
    .endr
    .noaltmacro

/* ------------------------------------------------------------------------ */
    .section .text.reset, "ax"
    .globl  cpu32_reset
    .type   cpu32_reset, @function
cpu32_reset:
    move.w  #0x2700, %sr                  /* supervisor, all interrupts masked */
    move.b  #SYPCR_VALUE, SYPCR
    move.w  #SYNCR_VALUE, SYNCR
1:  btst    #SYNCR_SLOCK, SYNCR + 1       /* wait until the synthesiser locks */
    beq.s   1b
    move.w  #SIMCR_VALUE, SIMCR
    move.w  #CSPAR0_VALUE, CSPAR0
    move.w  #CSPAR1_VALUE, CSPAR1
    move.w  #TRAMMCR_VALUE, TRAMMCR
    move.w  #TRAMBAR_VALUE, TRAMBAR

    /* Copy the relocation stub to TPURAM and run it from there: the low
     * flash alias we are executing from vanishes when CSBARBT changes. */
    lea     reloc_stub(%pc), %a0
    lea     TPURAM_BASE, %a1
    moveq   #(reloc_stub_end - reloc_stub) / 2 - 1, %d0
2:  move.w  (%a0)+, (%a1)+
    dbf     %d0, 2b
    jmp     TPURAM_BASE

    /* Position-independent except for the absolute jump target. */
    .balign 2
reloc_stub:
    move.w  #CSBARBT_VALUE, CSBARBT
    movea.l #cpu32_relocated, %a0         /* absolute: the link address in flash */
    jmp     (%a0)
reloc_stub_end:

/* From here on the code runs at its link address in flash. */
cpu32_relocated:
    move.w  #CSORBT_VALUE, CSORBT
    move.w  #CSOR0_VALUE, CSOR0
    move.w  #CSBAR_SRAM, CSBAR0
    move.w  #CSOR1_VALUE, CSOR1
    move.w  #CSBAR_SRAM, CSBAR1

    lea     __stack_top, %sp
    lea     cpu32_vectors, %a0
    movec   %a0, %vbr

    /* .data: copy its initial image from flash to SRAM. */
    lea     __data_load, %a0
    lea     __data_start, %a1
    lea     __data_end, %a2
3:  cmpa.l  %a2, %a1
    bcc.s   4f
    move.l  (%a0)+, (%a1)+
    bra.s   3b
    /* .bss: clear. */
4:  lea     __bss_start, %a1
    lea     __bss_end, %a2
5:  cmpa.l  %a2, %a1
    bcc.s   6f
    clr.l   (%a1)+
    bra.s   5b

6:  jsr     firmware_entry
    jmp     cpu32_halt                    /* it returned: nothing left to do */
    .size   cpu32_reset, . - cpu32_reset

/* The C entry. An image whose main starts the board itself (board_start ...
 * k_start) is entered at main; an image that links drivers/board_main.c gets
 * that file's firmware_entry, which starts the board and runs main as a thread. */
    .weak   firmware_entry
    .type   firmware_entry, @function
firmware_entry:
    jmp     main
    .size   firmware_entry, . - firmware_entry

/* ------------------------------------------------------------------------ */
    .text
/* Masks interrupts and stops for good. STOP with mask 7 only wakes for an
 * NMI; go back to sleep if one arrives. */
    .globl  cpu32_halt
    .type   cpu32_halt, @function
cpu32_halt:
    move.w  #0x2700, %sr
1:  stop    #0x2700
    bra.s   1b
    .size   cpu32_halt, . - cpu32_halt

/* Generic exception entry: saves D0-D7/A0-A6 below the CPU's frame and hands
 * a pointer to both to the C reporter, which prints and halts. */
    .globl  cpu32_exception
    .type   cpu32_exception, @function
cpu32_exception:
    ori.w   #0x0700, %sr
    movem.l %d0-%d7/%a0-%a6, -(%sp)
    move.l  %sp, -(%sp)
    jsr     cpu32_exception_report
    jmp     cpu32_halt
    .size   cpu32_exception, . - cpu32_exception

/* No executable stack: this is bare-metal code. */
    .section .note.GNU-stack, "", %progbits
