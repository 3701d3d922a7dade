/*
 * STM32F405 registers the board support uses (RM0090), at the addresses
 * QEMU's netduinoplus2 machine maps them. QEMU models the USARTs, TIM2-5,
 * the ADCs, SYSCFG and EXTI; RCC and the GPIO ports are "unimplemented
 * devices" there (writes ignored, reads 0), which the board code allows for.
 */
#ifndef STM32F405_H
#define STM32F405_H

#include <stdint.h>

#define STM32_REG32(addr) (*(volatile uint32_t *)(uintptr_t)(addr))

/* The core clock the netduinoplus2 model runs at (and a real board after
 * the PLL set-up of ST's reference start-up): 168 MHz. */
#define STM32F405_CPU_HZ 168000000u

/* RCC: clock enables (no effect in QEMU, needed on a real chip). */
#define RCC_BASE     0x40023800u
#define RCC_AHB1ENR  STM32_REG32(RCC_BASE + 0x30u)
#define RCC_APB1ENR  STM32_REG32(RCC_BASE + 0x40u)
#define RCC_APB2ENR  STM32_REG32(RCC_BASE + 0x44u)
#define RCC_AHB1ENR_GPIOAEN (1u << 0)
#define RCC_APB2ENR_USART1EN (1u << 4)
#define RCC_APB2ENR_ADC1EN   (1u << 8)

/* USART1: the console (QEMU's first serial port, -serial stdio). */
#define USART1_BASE  0x40011000u
#define USART1_IRQ   37u
#define USART_SR(b)  STM32_REG32((b) + 0x00u)
#define USART_DR(b)  STM32_REG32((b) + 0x04u)
#define USART_BRR(b) STM32_REG32((b) + 0x08u)
#define USART_CR1(b) STM32_REG32((b) + 0x0Cu)
#define USART_SR_ERRORS 0x07u     /* NE, FE, PE */
#define USART_SR_ORE   (1u << 3)
#define USART_SR_RXNE  (1u << 5)
#define USART_SR_TXE   (1u << 7)
#define USART_CR1_RE     (1u << 2)
#define USART_CR1_TE     (1u << 3)
#define USART_CR1_RXNEIE (1u << 5)
#define USART_CR1_TXEIE  (1u << 7)
#define USART_CR1_UE     (1u << 13)
/* APB2 at 84 MHz on a real board: 84e6 / 115200 = 729.2, BRR 0x2D9. */
#define CONSOLE_BAUD_STM32 115200u
#define USART1_BRR_115200 0x2D9u

/* GPIO port A: the netduinoplus2's blue LED is PA10. */
#define GPIOA_BASE   0x40020000u
#define GPIO_MODER(b) STM32_REG32((b) + 0x00u)
#define GPIO_ODR(b)   STM32_REG32((b) + 0x14u)
#define GPIO_BSRR(b)  STM32_REG32((b) + 0x18u)
#define LED_PIN 10u

/* ADC1 (QEMU models its conversions with a synthetic value sequence). */
#define ADC1_BASE    0x40012000u
#define ADC_SR(b)    STM32_REG32((b) + 0x00u)
#define ADC_CR2(b)   STM32_REG32((b) + 0x08u)
#define ADC_SQR3(b)  STM32_REG32((b) + 0x34u)
#define ADC_DR(b)    STM32_REG32((b) + 0x4Cu)
#define ADC_SR_EOC     (1u << 1)
#define ADC_CR2_ADON   (1u << 0)
#define ADC_CR2_SWSTART (1u << 30)

#endif /* STM32F405_H */
