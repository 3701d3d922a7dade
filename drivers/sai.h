/*
 * The uniform access layer (in the spirit of CubeOS' SAI, facts 3.5): every
 * port of the board is a channel, named by its kind and a number, and
 * sai_read / sai_write work on any channel by dispatching to its driver.
 * The names, numbers and ranges are the board's port table
 * (boards/include/board_ports.h, which PDL uses too); on the RoboCube:
 *
 *   kind         short   numbers  read                      write
 *   analog in    ad      0..23    0..255 (PCF8591 input)    -
 *   analog out   da      0..5     -                         0..255 (DAC)
 *   binary io    bio     0..15    pin level 0/1             latch 0/1 (1 = input)
 *   binary in    bin     1..5     DUART IPn level 0/1       -
 *   fast out     fast    0..15    the bit's shadow 0/1      0/1
 *   pwm          pwm     0..15    duty, per-mille           duty 0..1000 (frequency kept)
 *   motor        motor   0..2     power, signed per-mille   power -1000..1000 (open loop)
 *   encoder      enc     0..2     position, counts          -
 *   led          led     0        0/1                       0/1
 *
 * A channel is written as text "analog in 5", "ad 5", "motor 1", "led"
 * (kind names are case-insensitive; words may be separated by any run of
 * blanks; the led's number may be left out).
 *
 * Results: >= 0 success, otherwise a distinct negative code (drv_err.h):
 *   DRV_ERR_CHANNEL  no such kind or number (sai_parse, any call);
 *   DRV_ERR_RANGE    a value outside the channel's write range;
 *   DRV_ERR_PARAM    a read of a write-only channel or a write of a
 *                    read-only one, a NULL pointer;
 *   DRV_ERR_ABSENT, DRV_ERR_TIMEOUT, ...  the driver's own result (chip
 *                    absent, bus stuck): passed through unchanged.
 * Every driver call is bounded in time, so no SAI call hangs its caller.
 */
#ifndef DRIVERS_SAI_H
#define DRIVERS_SAI_H

#include <stddef.h>
#include <stdint.h>

#include "boards/include/board_ports.h"   /* the kinds and the board's table */

struct sai_channel {
    uint8_t kind;   /* enum board_port_kind */
    uint8_t index;  /* the port's number within its kind */
};

/* What a kind is: the board's row for it (names, numbers and value ranges,
 * for help texts and checks) and the driver calls that serve it. */
struct sai_kind_info {
    const struct board_port_range *port;
    /* The driver calls (NULL where the kind has no such direction): DRV_OK
     * or the driver's error; index and value already checked. */
    int (*read)(unsigned index, int32_t *value);
    int (*write)(unsigned index, int32_t value);
};
/* NULL for a kind >= BOARD_PORT_KINDS. */
const struct sai_kind_info *sai_kind_info(unsigned kind);

/* Parses a whole channel name ("analog in 5"): DRV_OK or DRV_ERR_CHANNEL
 * (unknown kind, missing or bad number, number out of range, trailing text)
 * or DRV_ERR_PARAM (NULL). */
int sai_parse(const char *text, struct sai_channel *ch);
/* Parses a channel name at the start of text (leading blanks skipped) and
 * sets *rest to the text after it (e.g. the value in "da 2 100"). Same
 * results as sai_parse; *rest is set only on success. */
int sai_parse_prefix(const char *text, struct sai_channel *ch, const char **rest);

/* Writes the long name ("analog in 5") to buf; returns its length or
 * DRV_ERR_CHANNEL / DRV_ERR_PARAM. Truncated (NUL-terminated) if size is short. */
int sai_name(struct sai_channel ch, char *buf, size_t size);

/* DRV_OK if the channel exists, else DRV_ERR_CHANNEL. */
int sai_check(struct sai_channel ch);
/* DRV_OK if value may be written to ch: DRV_ERR_CHANNEL, DRV_ERR_PARAM
 * (read-only channel) or DRV_ERR_RANGE. */
int sai_check_value(struct sai_channel ch, int32_t value);

/* Reads the channel into *value: DRV_OK or an error (nothing written then). */
int sai_read(struct sai_channel ch, int32_t *value);
/* Writes value to the channel: DRV_OK or an error (nothing changed when the
 * channel or the value is refused). */
int sai_write(struct sai_channel ch, int32_t value);

#endif /* DRIVERS_SAI_H */
