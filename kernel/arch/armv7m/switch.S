/*
 * ARMv7-M context switch of the nanokernel, and the fault entry.
 *
 * The port keeps two pointers: k_arch_running, the thread whose registers
 * are in the CPU, and k_arch_next, the one the kernel last chose
 * (k_arch_switch). The switch itself always runs in an exception handler,
 * so the CPU has already stacked R0-R3, R12, LR, PC and xPSR on the thread's
 * PSP; the handler adds BASEPRI and R4-R11 below them, stores PSP in
 * running->ctx.sp (offset 0), and unstacks next's frame the same way.
 *
 *   - From a thread (k_resched in thread mode, BASEPRI raised): SVC #0. SVC
 *     has priority 0, above BASEPRI, so it is taken at once inside the
 *     critical section, and the thread later resumes right after the SVC
 *     with its BASEPRI (the mask) restored from its frame.
 *   - From an interrupt (k_resched at the outermost k_isr_exit): PendSV is
 *     set pending. It has the lowest priority, so it runs when the last
 *     nested handler has returned, and switches to whatever k_arch_next is
 *     then (a later decision replaces an earlier one). A thread switched
 *     out by PendSV was running unmasked, so it resumes with BASEPRI 0.
 *
 * The first switch (k_start, on the boot stack = MSP) saves nothing and
 * moves MSP to the top of the port's interrupt stack: from then on MSP
 * carries only exceptions.
 */
    .syntax unified
    .thumb
    .text

    .globl  k_arch_switch
    .type   k_arch_switch, %function
    .thumb_func
k_arch_switch:
    ldr     r2, =k_arch_next
    str     r1, [r2]
    mrs     r2, ipsr
    cbnz    r2, 1f
    svc     #0                      /* thread mode: switch now */
    bx      lr                      /* resumed: `from` runs again */
1:  ldr     r2, =0xE000ED04         /* ICSR */
    mov     r3, #0x10000000         /* PENDSVSET: switch when the handlers are done */
    str     r3, [r2]
    bx      lr
    .size   k_arch_switch, . - k_arch_switch

/* SVC and PendSV share the switch. PRIMASK is held only across the few
 * instructions that change the stacks and the two pointers, so a device
 * interrupt (which may choose a new k_arch_next and pend PendSV again) never
 * sees them half-updated. */
    .globl  armv7m_svc
    .type   armv7m_svc, %function
    .thumb_func
armv7m_svc:
    .globl  armv7m_pendsv
    .type   armv7m_pendsv, %function
    .thumb_func
armv7m_pendsv:
    cpsid   i
    ldr     r3, =k_arch_running
    ldr     r2, =k_arch_next
    ldr     r0, [r3]
    ldr     r1, [r2]
    cmp     r0, r1
    beq     3f
    cbz     r0, 1f
    mrs     r12, psp
    mrs     r2, basepri
    stmdb   r12!, {r2, r4-r11}
    str     r12, [r0]               /* running->ctx.sp */
    b       2f
1:  ldr     r2, =k_arch_irq_stack_top /* first switch: MSP onto the interrupt stack */
    ldr     r2, [r2]
    msr     msp, r2
2:  str     r1, [r3]                /* running = next */
    ldr     r2, [r1, #4]            /* next->ctx.guard_rbar: the MPU guards its stack */
    ldr     r0, =0xE000ED9C         /* MPU_RBAR */
    str     r2, [r0]
    dsb
    ldr     r12, [r1]               /* next->ctx.sp */
    ldmia   r12!, {r2, r4-r11}
    msr     psp, r12
    msr     basepri, r2
    ldr     lr, =0xFFFFFFFD         /* return to thread mode on PSP */
3:  cpsie   i
    bx      lr
    .size   armv7m_pendsv, . - armv7m_pendsv

/* Where a new thread's first switch returns to (k_arch_thread_init puts its
 * address in the initial frame). k_thread_start never returns. */
    .globl  k_arch_thread_trampoline
    .type   k_arch_thread_trampoline, %function
    .thumb_func
k_arch_thread_trampoline:
    bl      k_thread_start
    b       armv7m_halt
    .size   k_arch_thread_trampoline, . - k_arch_thread_trampoline

/* HardFault, MemManage, BusFault, UsageFault. A thread that ran into its
 * stack guard (armv7m_guard_fault) is stopped and the system goes on;
 * anything else is reported: the frame the CPU stacked is on PSP or MSP
 * (EXC_RETURN bit 2 says which); R4-R11, EXC_RETURN and MSP are pushed
 * below for the reporter, which prints and halts. */
    .globl  armv7m_fault
    .type   armv7m_fault, %function
    .thumb_func
armv7m_fault:
    tst     lr, #4                  /* from a thread: maybe its stack guard */
    beq     1f
    push    {r4, lr}
    mov     r0, lr
    ldr     r1, =0xE000ED28         /* CFSR */
    ldr     r1, [r1]
    bl      armv7m_guard_fault
    pop     {r4, lr}
    cbz     r0, 1f
    bx      lr                      /* to k_stack_overflow_stop_current in the thread */
1:  mrs     r2, msp
    tst     lr, #4
    ite     eq
    mrseq   r0, msp
    mrsne   r0, psp
    push    {r2, r4-r11, lr}
    mov     r1, sp
    b       armv7m_fault_report
    .size   armv7m_fault, . - armv7m_fault

    .globl  armv7m_halt
    .type   armv7m_halt, %function
    .thumb_func
armv7m_halt:
    cpsid   i
1:  wfi
    b       1b
    .size   armv7m_halt, . - armv7m_halt

    .section .note.GNU-stack, "", %progbits
