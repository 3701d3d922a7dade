/* CRC-16/CCITT-FALSE, bitwise: 8 shifts per byte cost ~100 instructions on the
 * CPU32, about 25 us per byte at the emulated speed, against 520 us per
 * character at 19200 baud; a 512-byte table would buy nothing the link needs. */
#include "crc16.h"

uint16_t crc16_byte(uint16_t crc, uint8_t byte)
{
    /* In an unsigned int masked to 16 bits, so no conversion ever truncates. */
    unsigned c = (unsigned)crc ^ ((unsigned)byte << 8);
    unsigned i;
    for (i = 0; i < 8u; i++)
        c = ((c & 0x8000u) != 0u ? (c << 1) ^ 0x1021u : c << 1) & 0xFFFFu;
    return (uint16_t)c;
}

uint16_t crc16_update(uint16_t crc, const uint8_t *data, size_t len)
{
    size_t i;
    for (i = 0; i < len; i++)
        crc = crc16_byte(crc, data[i]);
    return crc;
}
