/*
 * The registers of ARM's MPS2 board with the AN385 FPGA image (a Cortex-M3)
 * that the board support uses, at the addresses QEMU's mps2-an385 machine
 * maps them (AN385 application note; QEMU's hw/arm/mps2.c): the CMSDK APB
 * UART0 and the FPGA's LED register. The core's own registers (NVIC,
 * SysTick, MPU) are the ARMv7-M port's (kernel/arch/armv7m/armv7m.h).
 */
#ifndef MPS2_AN385_H
#define MPS2_AN385_H

#include <stdint.h>

#define MPS2_REG32(addr) (*(volatile uint32_t *)(uintptr_t)(addr))

/* SYSCLK, the core's clock and the peripherals': 25 MHz. */
#define MPS2_AN385_CPU_HZ 25000000u

/* CMSDK APB UART0: the console (QEMU's first serial port). Separate
 * interrupt lines for received and sent bytes. */
#define UART0_BASE      0x40004000u
#define UART0_RX_IRQ    0u
#define UART0_TX_IRQ    1u
#define UART_DATA(b)    MPS2_REG32((b) + 0x00u)
#define UART_STATE(b)   MPS2_REG32((b) + 0x04u)
#define UART_CTRL(b)    MPS2_REG32((b) + 0x08u)
#define UART_INT(b)     MPS2_REG32((b) + 0x0Cu)   /* read: status; write 1: clear */
#define UART_BAUDDIV(b) MPS2_REG32((b) + 0x10u)
#define UART_STATE_TXFULL    (1u << 0)
#define UART_STATE_RXFULL    (1u << 1)
#define UART_STATE_RXOVERRUN (1u << 3)
#define UART_CTRL_TX_EN      (1u << 0)
#define UART_CTRL_RX_EN      (1u << 1)
#define UART_CTRL_TX_INTEN   (1u << 2)
#define UART_CTRL_RX_INTEN   (1u << 3)
#define UART_INT_TX          (1u << 0)
#define UART_INT_RX          (1u << 1)
/* 25 MHz / 115200 baud: 217 (the model needs at least 16 to send at all). */
#define UART0_BAUDDIV_115200 217u

/* The FPGA's I/O block: LED0 is bit 0 of its LED register (user LEDs 0-1). */
#define FPGAIO_BASE 0x40028000u
#define FPGAIO_LED  MPS2_REG32(FPGAIO_BASE + 0x00u)

#endif /* MPS2_AN385_H */
