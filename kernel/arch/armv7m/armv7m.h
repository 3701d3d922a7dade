/*
 * ARMv7-M system registers the port and the boards use (ARMv7-M ARM, B3),
 * the port's own services beyond k_arch.h (SysTick tick, start-up, fault
 * report) and the mapping of kernel interrupt vectors to NVIC lines.
 */
#ifndef ARMV7M_H
#define ARMV7M_H

#include <stdint.h>

#define ARMV7M_REG32(addr) (*(volatile uint32_t *)(uintptr_t)(addr))
#define ARMV7M_REG8(addr)  (*(volatile uint8_t *)(uintptr_t)(addr))

/* System control block */
#define SCB_ICSR   ARMV7M_REG32(0xE000ED04u)
#define SCB_VTOR   ARMV7M_REG32(0xE000ED08u)
#define SCB_AIRCR  ARMV7M_REG32(0xE000ED0Cu)
#define SCB_CCR    ARMV7M_REG32(0xE000ED14u)
#define SCB_SHPR(n) ARMV7M_REG8(0xE000ED18u + (n) - 4u) /* system handler n = 4..15 */
#define SCB_SHCSR  ARMV7M_REG32(0xE000ED24u)
#define SCB_CFSR   ARMV7M_REG32(0xE000ED28u)
#define SCB_HFSR   ARMV7M_REG32(0xE000ED2Cu)
#define SCB_MMFAR  ARMV7M_REG32(0xE000ED34u)
#define SCB_BFAR   ARMV7M_REG32(0xE000ED38u)
#define ICSR_PENDSVSET (1u << 28)
#define ICSR_PENDSTSET (1u << 26) /* SysTick pending */
#define AIRCR_VECTKEY  (0x05FAu << 16)
#define AIRCR_SYSRESETREQ (1u << 2)
#define CCR_DIV_0_TRP  (1u << 4)
#define CCR_STKALIGN   (1u << 9)
#define SHCSR_MEMFAULTENA (1u << 16)
#define SHCSR_BUSFAULTENA (1u << 17)
#define SHCSR_USGFAULTENA (1u << 18)

/* SysTick */
#define SYST_CSR   ARMV7M_REG32(0xE000E010u)
#define SYST_RVR   ARMV7M_REG32(0xE000E014u)
#define SYST_CVR   ARMV7M_REG32(0xE000E018u)
#define SYST_CSR_ENABLE    (1u << 0)
#define SYST_CSR_TICKINT   (1u << 1)
#define SYST_CSR_CLKSOURCE (1u << 2) /* the processor clock */
#define SYST_RVR_MAX       0x00FFFFFFu

/* NVIC */
#define NVIC_ISER(n) ARMV7M_REG32(0xE000E100u + 4u * (n))
#define NVIC_ICER(n) ARMV7M_REG32(0xE000E180u + 4u * (n))
#define NVIC_ISPR(n) ARMV7M_REG32(0xE000E200u + 4u * (n))
#define NVIC_IPR(irq) ARMV7M_REG8(0xE000E400u + (irq))

/* MPU (PMSAv7) */
#define MPU_TYPE   ARMV7M_REG32(0xE000ED90u)
#define MPU_CTRL   ARMV7M_REG32(0xE000ED94u)
#define MPU_RNR    ARMV7M_REG32(0xE000ED98u)
#define MPU_RBAR   ARMV7M_REG32(0xE000ED9Cu)
#define MPU_RASR   ARMV7M_REG32(0xE000EDA0u)
#define MPU_CTRL_ENABLE     (1u << 0)
#define MPU_CTRL_PRIVDEFENA (1u << 2)  /* the default map under the regions */
#define MPU_RBAR_VALID      (1u << 4)  /* RBAR's low bits select the region */
#define MPU_RASR_ENABLE     (1u << 0)
#define MPU_RASR_SIZE(log2) (((log2) - 1u) << 1)   /* 2^log2 bytes, 5..32 */
#define MPU_RASR_AP_RO      (6u << 24) /* read-only, privileged or not */
#define MPU_RASR_XN         (1u << 28)
/* The stack guards: the running thread's and the interrupt stack's lowest
 * 32 bytes are read-only (the kernel reads its guard words; a push into
 * them faults at once). The highest-numbered regions win where they overlap. */
#define ARMV7M_GUARD_LOG2          5u
#define ARMV7M_GUARD_BYTES         (1u << ARMV7M_GUARD_LOG2)
#define ARMV7M_MPU_REGION_IRQ      6u
#define ARMV7M_MPU_REGION_THREAD   7u
#define CFSR_MMARVALID (1u << 7)
#define CFSR_MSTKERR   (1u << 4)
#define CFSR_DACCVIOL  (1u << 1)

/* Exception numbers of the system handlers. */
#define ARMV7M_EXC_HARDFAULT 3u
#define ARMV7M_EXC_MEMMANAGE 4u
#define ARMV7M_EXC_BUSFAULT  5u
#define ARMV7M_EXC_USAGEFAULT 6u
#define ARMV7M_EXC_SVC       11u
#define ARMV7M_EXC_PENDSV    14u
#define ARMV7M_EXC_SYSTICK   15u
#define ARMV7M_EXC_IRQ0      16u

/* k_irq_register's vectors on this port: 64 + the NVIC line (IRQ 0..191),
 * the range the kernel gives device interrupts (its user vectors 64..255). */
#define ARMV7M_IRQ_VECTOR(irq) (64u + (irq))
#define ARMV7M_VECTOR_IRQ(vector) ((vector) - 64u)
/* The board's vector table: initial MSP, reset, the system handlers, then
 * one entry per NVIC line (boards/NAME/). */
extern void (*const armv7m_vectors[])(void);
/* How many NVIC lines the board's vector table has (set by the board's
 * vector table, boards/NAME/). */
extern const unsigned armv7m_irq_lines;

/* Level of the SysTick tick among the kernel's interrupt levels (1..7): below
 * the console (the board's USART at level 5), as the PIT on the RoboCube. */
#define ARMV7M_TICK_LEVEL 4u

/* Starts SysTick from the processor clock at tick_hz (the nearest whole
 * count of cpu_hz); fn runs in the tick interrupt (between k_isr_enter and
 * k_isr_exit). Returns 0, or -1 when the count does not fit SysTick's
 * 24 bits. */
int armv7m_systick_start(uint32_t cpu_hz, uint32_t tick_hz, void (*fn)(void));
/* Processor clocks since armv7m_systick_start, modulo 2^32 (25.6 s at
 * 168 MHz), from SysTick: its wraps, counted by the tick interrupt, times
 * its period, plus the current count. Any context; valid while no wrap goes
 * unserved for a whole period (interrupts masked for less than a tick). A
 * board registers it as the kernel's fine time stamp (k_timestamp_register)
 * at its processor clock. */
uint32_t armv7m_systick_cycles(void);

/* Every device interrupt's vector entry: dispatches the handler registered
 * for the active NVIC line through k_isr_enter/k_isr_exit. */
void k_arch_irq_entry(void);
/* The reset entry: copies .data, clears .bss, masks the kernel levels
 * (BASEPRI), enables the fault handlers and calls firmware_entry. */
void armv7m_reset(void) __attribute__((noreturn));
/* PendSV and SVC: the context switch (switch.S); SysTick; the fault entry. */
void armv7m_pendsv(void);
void armv7m_svc(void);
void armv7m_systick(void);
void armv7m_fault(void);
/* Masks every interrupt and waits for good. */
void armv7m_halt(void) __attribute__((noreturn));

/* What armv7m_fault hands the reporter (pushed by the entry, in this order):
 * MSP at entry, R4-R11 as they were, EXC_RETURN; and the frame the CPU
 * stacked. */
struct armv7m_fault_regs {
    uint32_t msp_at_entry;
    uint32_t r4_r11[8];
    uint32_t exc_return;
};
struct armv7m_frame {
    uint32_t r0, r1, r2, r3, r12, lr, pc, xpsr;
};
void armv7m_fault_report(const struct armv7m_frame *frame, const struct armv7m_fault_regs *regs)
    __attribute__((noreturn));

/* The MPU's guard regions (k_arch_armv7m.c): the interrupt stack's, and the
 * running thread's (switch.S moves it at every switch). */
void armv7m_mpu_start(void);
/* Whether addr lies in the guard of the stack whose base is given. */
int armv7m_in_guard(uintptr_t addr, const uint32_t *stack_base);
/* A fault taken from thread mode (exc_return, the CFSR as it was): when the
 * running thread ran into its guard outside a critical section, its PSP is
 * set to a frame that stops it (k_stack_overflow_stop_current) and 1 is
 * returned; 0 for any other fault (the reporter then halts). */
int armv7m_guard_fault(uint32_t exc_return, uint32_t cfsr);

#endif /* ARMV7M_H */
