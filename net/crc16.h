/* CRC-16/CCITT-FALSE (polynomial 0x1021, initial value 0xFFFF, no reflection,
 * no final XOR): the frame check of the radio link. Check value of
 * "123456789" = 0x29B1 (the same as Python's binascii.crc_hqx(data, 0xFFFF)). */
#ifndef NET_CRC16_H
#define NET_CRC16_H

#include <stddef.h>
#include <stdint.h>

#define CRC16_INIT 0xFFFFu

/* Continues crc over len bytes; start with CRC16_INIT. */
uint16_t crc16_update(uint16_t crc, const uint8_t *data, size_t len);
uint16_t crc16_byte(uint16_t crc, uint8_t byte);

#endif /* NET_CRC16_H */
