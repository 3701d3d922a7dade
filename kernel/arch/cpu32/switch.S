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
 * when the thread is switched back, k_resched returns into the entry, which
 * restores D0-D1/A0-A1, and RTE restores the thread's own SR and PC.
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
 * CPU has pushed SR, PC and the format/vector word on the running stack and
 * raised the mask to the interrupt's level. The CPU32 has one supervisor
 * stack, so the entry moves to the kernel's interrupt stack itself: a thread
 * stack then carries only this entry's frame (8 + 2 + 16 bytes) and the
 * scheduling decision at the outermost exit, never a handler or a nested
 * interrupt.
 *
 *   1. the SR as the CPU set it (its mask = this interrupt's level) is kept,
 *      then the mask goes to 7 while the stack is chosen: an interrupt
 *      nesting before that would find isr_nesting still 0 and take the
 *      interrupt stack from its top again;
 *   2. outermost (isr_nesting 0): SP = the interrupt stack's top, the
 *      interrupted SP saved there; nested: stay on the interrupt stack;
 *   3. k_arch_isr_run(vector, sr) runs the handler at the interrupt's own
 *      level (higher levels nest on the interrupt stack) and returns with
 *      the mask at 7;
 *   4. back on the interrupted stack; outermost: k_resched, which may switch
 *      threads right here, on the thread's own stack, with the mask at 7
 *      (the thread resumes here later; RTE restores its SR).
 * isr_nesting is k_kernel's first word (k_internal.h).
 */
    .globl  k_isr_entry
    .type   k_isr_entry, @function
k_isr_entry:
    move.w  %sr, -(%sp)                 /* mask = this interrupt's level */
    ori.w   #0x0700, %sr
    movem.l %d0-%d1/%a0-%a1, -(%sp)
    moveq   #0, %d1
    move.w  16(%sp), %d1                /* the SR for the handler */
    move.w  24(%sp), %d0                /* format/vector word: 16 + 2 + SR 2 + PC 4 */
    andi.l  #0x0FFF, %d0
    lsr.l   #2, %d0                     /* vector offset -> vector number */
    movea.l %sp, %a0                    /* the interrupted stack */
    tst.l   k_kernel                    /* isr_nesting */
    bne.s   1f
    movea.l k_arch_irq_stack_top, %sp   /* outermost: onto the interrupt stack */
1:  addq.l  #1, k_kernel
    move.l  %a0, -(%sp)
    move.l  %d1, -(%sp)
    move.l  %d0, -(%sp)
    jsr     k_arch_isr_run
    addq.l  #8, %sp
    movea.l (%sp), %sp                  /* back onto the interrupted stack */
    subq.l  #1, k_kernel
    bne.s   2f
    jsr     k_resched                   /* outermost exit: a woken thread runs now */
2:  movem.l (%sp)+, %d0-%d1/%a0-%a1
    addq.l  #2, %sp
    rte
    .size   k_isr_entry, . - k_isr_entry

/*
 * void k_isr_call(void (*fn)(void *), void *arg): for a driver's own
 * interrupt handler (a vector it claims in the flash table, not routed
 * through k_isr_entry) that has already masked all levels. Runs fn(arg) as
 * the kernel runs a registered handler: on the interrupt stack when it is
 * the outermost interrupt, counted in isr_nesting, and with the scheduling
 * decision (k_resched) back on the interrupted stack at the outermost exit.
 * So such a handler's callbacks never run on a thread's stack either.
 */
    .globl  k_isr_call
    .type   k_isr_call, @function
k_isr_call:
    movea.l 4(%sp), %a0                 /* fn */
    move.l  8(%sp), %d0                 /* arg */
    movea.l %sp, %a1
    tst.l   k_kernel                    /* isr_nesting */
    bne.s   1f
    movea.l k_arch_irq_stack_top, %sp
1:  addq.l  #1, k_kernel
    move.l  %a1, -(%sp)                 /* the caller's stack */
    move.l  %d0, -(%sp)
    jsr     (%a0)
    addq.l  #4, %sp
    movea.l (%sp), %sp
    subq.l  #1, k_kernel
    bne.s   2f
    jsr     k_resched
2:  rts
    .size   k_isr_call, . - k_isr_call

    .section .note.GNU-stack, "", %progbits
