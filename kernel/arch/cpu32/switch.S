/*
 * CPU32 context switch and interrupt entry of the nanokernel.
 *
 * k_arch_switch(from, to) is an ordinary C call made with the interrupt mask
 * at 7. It pushes what a C caller expects preserved (D2-D7, A2-A6; D0-D1,
 * A0-A1 are the caller's to save) plus SR, stores SP in from->ctx.sp
 * (offset 0), loads to->ctx.sp and pops the same frame, returning into
 * whatever call of k_arch_switch `to` was suspended in. Every thread enters
 * the switch with the mask at 7, so the saved SR is always "supervisor,
 * mask 7"; the mask the thread had before is restored by the C code that
 * called it (k_arch_irq_restore) or by the RTE of the interrupt it was
 * pre-empted in.
 *
 * Pre-emption from an interrupt: the interrupt frame and the registers the
 * entry saved stay on the pre-empted thread's stack, below the switch frame;
 * when the thread is switched back, k_isr_exit returns, the entry restores
 * D0-D1/A0-A1 and RTE restores the thread's own SR and PC.
 */
    .text

    .globl  k_arch_switch
    .type   k_arch_switch, @function
k_arch_switch:
    move.l  4(%sp), %a0                 /* from */
    move.l  8(%sp), %a1                 /* to */
    move.w  %sr, -(%sp)
    movem.l %d2-%d7/%a2-%a6, -(%sp)
    move.l  %sp, (%a0)
    move.l  (%a1), %sp
    movem.l (%sp)+, %d2-%d7/%a2-%a6
    move.w  (%sp)+, %sr
    rts
    .size   k_arch_switch, . - k_arch_switch

/* Where a new thread's first switch "returns" to (k_arch_thread_init puts
 * its address on the initial stack). k_thread_start never returns. */
    .globl  k_arch_thread_trampoline
    .type   k_arch_thread_trampoline, @function
k_arch_thread_trampoline:
    jsr     k_thread_start
1:  stop    #0x2700
    bra.s   1b
    .size   k_arch_thread_trampoline, . - k_arch_thread_trampoline

/*
 * Common entry of every vector routed to the kernel (k_irq_register). The
 * CPU has pushed SR, PC and the format/vector word and raised the mask to
 * the interrupt's level. Saves the scratch registers C may clobber, passes
 * the vector number to k_isr_run (k_isr_enter, the handler, k_isr_exit,
 * which may switch threads) and returns with RTE.
 */
    .globl  k_isr_entry
    .type   k_isr_entry, @function
k_isr_entry:
    movem.l %d0-%d1/%a0-%a1, -(%sp)
    move.w  22(%sp), %d0                /* format/vector word: 16 + SR 2 + PC 4 */
    andi.l  #0x0FFF, %d0
    lsr.l   #2, %d0                     /* vector offset -> vector number */
    move.l  %d0, -(%sp)
    jsr     k_isr_run
    addq.l  #4, %sp
    movem.l (%sp)+, %d0-%d1/%a0-%a1
    rte
    .size   k_isr_entry, . - k_isr_entry

    .section .note.GNU-stack, "", %progbits
