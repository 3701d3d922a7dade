/*
 * Fault reporter: every exception vector nobody claims ends here (via
 * cpu32_exception in start.S). Prints one summary line that tests parse,
 * the frame details of the CPU32 frame formats and the registers, then halts.
 *
 * Summary line (fixed format):
 *   EXCEPTION vector=<n> (<name>) format=$<f> pc=0x<8 hex> sr=0x<4 hex> fault_pc=0x<8 hex>
 * pc is the PC the CPU stacked (where RTE would return); fault_pc is the
 * address of the instruction that caused the exception: the format $2
 * "faulted instruction PC", the format $C "current instruction PC", and
 * the stacked PC for format $0 (which for illegal instructions, privilege
 * violations and A/F-line traps is the offending instruction itself).
 */
#include "cpu.h"
#include "kernel/lib/kprintf.h"

static uint32_t frame_long(const uint16_t *frame, unsigned word)
{
    return ((uint32_t)frame[word] << 16) | frame[word + 1];
}

static const char *vector_name(unsigned vector)
{
    static const char *const names[] = {
        "reset SSP", "reset PC", "bus error", "address error",
        "illegal instruction", "zero divide", "CHK/CHK2", "TRAPcc/TRAPV",
        "privilege violation", "trace", "line A", "line F",
        "hardware breakpoint", "reserved", "format error", "uninitialized interrupt",
    };
    if (vector < sizeof names / sizeof names[0]) {
        return names[vector];
    }
    if (vector == 24) {
        return "spurious interrupt";
    }
    if (vector >= 25 && vector <= 31) {
        return "autovector interrupt";
    }
    if (vector >= 32 && vector <= 47) {
        return "TRAP #n";
    }
    if (vector >= 64) {
        return "user interrupt";
    }
    return "reserved";
}

/* Describes a format $C special status word (CPU32RM 6.4.3): TP(15) MV(14)
 * TR(12) B1 B0 RR RM IN(7) RW(6) LG(5) SIZ(4..3) FUNC(2..0). */
static void report_ssw(uint16_t ssw)
{
    static const char *const sizes[] = {"long", "byte", "word", "3-byte"};
    kprintf("  SSW 0x%04x: %s %s cycle, function code %u%s%s\n", ssw,
            (ssw & 0x0040u) ? "read" : "write", sizes[(ssw >> 3) & 3u], ssw & 7u,
            (ssw & 0x0080u) ? ", instruction prefetch" : "",
            (ssw & 0x8000u) ? ", during exception processing" : "");
}

void cpu32_exception_report(const struct cpu32_saved_regs *regs)
{
    const uint16_t *frame = regs->frame;
    uint16_t sr = frame[CPU32_FRAME_SR];
    uint32_t pc = frame_long(frame, CPU32_FRAME_PC);
    unsigned format = frame[CPU32_FRAME_FMT_VEC] >> 12;
    unsigned vector = (frame[CPU32_FRAME_FMT_VEC] & 0x0FFFu) / 4u;
    uint32_t fault_pc = pc;
    unsigned frame_bytes = 8;
    unsigned i;

    /* A fault inside the reporter (say, a broken console) must not recurse
     * down the stack: report once, halt on the second entry. */
    static volatile int reporting;
    if (reporting) {
        cpu32_halt();
    }
    reporting = 1;

    if (format == 0x2u) {
        fault_pc = frame_long(frame, CPU32_FRAME2_FAULT_PC);
        frame_bytes = 12;
    } else if (format == 0xCu) {
        fault_pc = frame_long(frame, CPU32_FRAMEC_CURR_PC);
        frame_bytes = 24;
    }

    kprintf("\n*** EXCEPTION vector=%u (%s) format=$%X pc=0x%08lx sr=0x%04x fault_pc=0x%08lx\n",
            vector, vector_name(vector), format, (unsigned long)pc, sr,
            (unsigned long)fault_pc);
    if (format == 0xCu) {
        kprintf("  bus error: fault address 0x%08lx, data buffer 0x%08lx, transfer count 0x%04x\n",
                (unsigned long)frame_long(frame, CPU32_FRAMEC_ADDRESS),
                (unsigned long)frame_long(frame, CPU32_FRAMEC_DBUF), frame[CPU32_FRAMEC_XFER]);
        report_ssw(frame[CPU32_FRAMEC_SSW]);
    } else if (format != 0x0u && format != 0x2u) {
        kprintf("  unexpected frame format $%X for a CPU32\n", format);
    }
    for (i = 0; i < 8; i++) {
        kprintf("  D%u=%08lx%s", i, (unsigned long)regs->d[i], i == 3 || i == 7 ? "\n" : "");
    }
    for (i = 0; i < 7; i++) {
        kprintf("  A%u=%08lx%s", i, (unsigned long)regs->a[i], i == 3 ? "\n" : "");
    }
    /* The SSP before the exception: just above the CPU's frame. */
    kprintf("  SP=%08lx\n*** halted\n",
            (unsigned long)((uintptr_t)frame + frame_bytes));
    cpu32_halt();
}
