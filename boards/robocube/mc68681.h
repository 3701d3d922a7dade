/*
 * MC68681 DUART of the RoboCube v2.0: 16 byte registers at consecutive
 * addresses from 0xFFE400 (RS1-RS4 on A0-A3), 3.6864 MHz crystal,
 * interrupt level 5 (vectored through IVR). Channel B is the console,
 * channel A the radio link.
 */
#ifndef DRIVERS_MC68681_H
#define DRIVERS_MC68681_H

#include <stdint.h>

#define DUART_BASE 0xFFE400u
#define DUART_REG(offset) (*(volatile uint8_t *)(uintptr_t)(DUART_BASE + (offset)))

/* Offsets that mean the same for read and write. */
#define DUART_MRA   0x0 /* MR1A, then MR2A after the first access */
#define DUART_MRB   0x8
#define DUART_IVR   0xC
/* Read side. */
#define DUART_SRA   0x1
#define DUART_RBA   0x3
#define DUART_IPCR  0x4
#define DUART_ISR   0x5
#define DUART_SRB   0x9
#define DUART_RBB   0xB
#define DUART_IP    0xD
#define DUART_START_COUNTER 0xE /* a read starts the counter/timer */
#define DUART_STOP_COUNTER  0xF
/* Write side. */
#define DUART_CSRA  0x1
#define DUART_CRA   0x2
#define DUART_TBA   0x3
#define DUART_ACR   0x4
#define DUART_IMR   0x5
#define DUART_CTUR  0x6
#define DUART_CTLR  0x7
#define DUART_CSRB  0x9
#define DUART_CRB   0xA
#define DUART_TBB   0xB
#define DUART_OPCR  0xD
#define DUART_OPR_SET   0xE /* 1 bits drive OPn low */
#define DUART_OPR_RESET 0xF /* 1 bits drive OPn high */

/* Status register bits (SRA/SRB). */
#define DUART_SR_RXRDY   0x01u
#define DUART_SR_FFULL   0x02u
#define DUART_SR_TXRDY   0x04u
#define DUART_SR_TXEMT   0x08u
#define DUART_SR_OVERRUN 0x10u

/* Command register values (CRA/CRB). */
#define DUART_CR_RX_ENABLE   0x01u
#define DUART_CR_RX_DISABLE  0x02u
#define DUART_CR_TX_ENABLE   0x04u
#define DUART_CR_TX_DISABLE  0x08u
#define DUART_CR_RESET_MR    0x10u
#define DUART_CR_RESET_RX    0x20u
#define DUART_CR_RESET_TX    0x30u
#define DUART_CR_RESET_ERROR 0x40u

/* Crystal and the counter/timer baud source used for 57600 baud. */
#define DUART_XTAL_HZ 3686400u

#endif /* DRIVERS_MC68681_H */
