/*
 * CPU32 status-register and low-power helpers, and the exception frame
 * layout the startup code hands to the fault reporter.
 */
#ifndef CPU32_CPU_H
#define CPU32_CPU_H

#include <stdint.h>

#define SR_SUPERVISOR 0x2000u
#define SR_IPL_MASK   0x0700u

static inline uint16_t cpu32_read_sr(void)
{
    uint16_t sr;
    __asm__ __volatile__("move.w %%sr,%0" : "=d"(sr));
    return sr;
}

static inline void cpu32_write_sr(uint16_t sr)
{
    __asm__ __volatile__("move.w %0,%%sr" : : "d"(sr) : "memory", "cc");
}

/* Masks interrupts up to level 7 (NMI still gets through); returns the old SR
 * for cpu32_irq_restore. */
static inline uint16_t cpu32_irq_save(void)
{
    uint16_t sr = cpu32_read_sr();
    __asm__ __volatile__("ori.w #0x0700,%%sr" : : : "memory", "cc");
    return sr;
}

static inline void cpu32_irq_restore(uint16_t sr)
{
    cpu32_write_sr(sr);
}

/* Supervisor mode, interrupt mask 0: every interrupt level is accepted. */
static inline void cpu32_irq_enable(void)
{
    __asm__ __volatile__("andi.w #0xF8FF,%%sr" : : : "memory", "cc");
}

/*
 * Atomically lowers the interrupt mask to 0 and stops until an interrupt is
 * taken. Call it with interrupts masked after checking the wake-up condition,
 * so an interrupt between the check and the STOP cannot be lost. Returns with
 * the mask at 0 (the STOP operand), after the interrupt handler has run.
 */
static inline void cpu32_wait_for_interrupt(void)
{
    __asm__ __volatile__("stop #0x2000" : : : "memory", "cc");
}

/* Masks all interrupts and stops for good (never returns). */
void cpu32_halt(void) __attribute__((noreturn));

/*
 * What the exception entry in start.S pushes before calling
 * cpu32_exception_report: D0-D7 and A0-A6 (MOVEM order), then the
 * CPU-built frame. The frame starts with SR, PC, format/vector word; its
 * format ($0 four words, $2 six words, $C twelve-word bus error frame) says
 * what follows. Accessed as 16-bit words because the PC sits at an odd word.
 */
struct cpu32_saved_regs {
    uint32_t d[8];
    uint32_t a[7];
    uint16_t frame[12];
};

/* Frame word indices (each word is 16 bits). */
#define CPU32_FRAME_SR        0
#define CPU32_FRAME_PC        1  /* 2 words */
#define CPU32_FRAME_FMT_VEC   3  /* format in bits 15..12, vector offset (= 4 * vector) in 11..0 */
#define CPU32_FRAME2_FAULT_PC 4  /* format $2: address of the faulted instruction */
#define CPU32_FRAMEC_ADDRESS  4  /* format $C: faulted address */
#define CPU32_FRAMEC_DBUF     6  /* format $C: data output buffer */
#define CPU32_FRAMEC_CURR_PC  8  /* format $C: current instruction PC */
#define CPU32_FRAMEC_XFER     10 /* format $C: internal transfer count */
#define CPU32_FRAMEC_SSW      11 /* format $C: special status word */

/* Called by the exception entry in start.S for every vector nothing else
 * claims: prints vector, PC, SR and the frame details on the console, halts. */
void cpu32_exception_report(const struct cpu32_saved_regs *regs) __attribute__((noreturn));

#endif /* CPU32_CPU_H */
