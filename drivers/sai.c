/* The uniform access layer: channel names, checks and dispatch; see sai.h. */
#include "sai.h"

#include "drivers/analog.h"
#include "drivers/binin.h"
#include "drivers/bio.h"
#include "drivers/drv_err.h"
#include "drivers/fastout.h"
#include "boards/include/board_led.h"
#include "drivers/motor.h"
#include "drivers/tpu.h"

/* A driver's int result: a value (>= 0) into *value, or its error. */
static int take(int rc, int32_t *value)
{
    if (rc < 0)
        return rc;
    *value = rc;
    return DRV_OK;
}

/* ---- each kind's read and write ---- */
static int sai_port_analog_read(unsigned i, int32_t *v) { return take(analog_read(i), v); }
static int sai_port_analog_write(unsigned i, int32_t v) { return analog_write(i, (int)v); }
static int sai_port_bio_read(unsigned i, int32_t *v) { return take(bio_read(i), v); }
static int sai_port_bio_write(unsigned i, int32_t v) { return bio_write(i, (int)v); }
static int sai_port_binin_read(unsigned i, int32_t *v) { return take(binin_read(i), v); }
static int sai_port_fastout_read(unsigned i, int32_t *v)
{
    *v = (int32_t)((fastout_get() >> i) & 1u);
    return DRV_OK;
}
static int sai_port_fastout_write(unsigned i, int32_t v) { return fastout_write(i, (int)v); }
static int sai_port_pwm_read(unsigned i, int32_t *v)
{
    int permille, rc = tpu_pwm_get(i, NULL, &permille);
    if (rc < 0)
        return rc;
    *v = permille;
    return DRV_OK;
}
/* 0: keep the channel's frequency (TPU_PWM_HZ_DEFAULT for a channel that ran no PWM). */
static int sai_port_pwm_write(unsigned i, int32_t v) { return tpu_pwm(i, 0, (int)v); }
static int sai_port_motor_read(unsigned i, int32_t *v)
{
    int permille, rc = motor_power(i, &permille);
    if (rc < 0)
        return rc;
    *v = permille;
    return DRV_OK;
}
static int sai_port_motor_write(unsigned i, int32_t v) { return motor_set(i, (int)v); }
static int sai_port_encoder_read(unsigned i, int32_t *v)
{
    int32_t counts;
    int rc = motor_position(i, &counts);
    if (rc < 0)
        return rc;     /* *v untouched on error */
    *v = counts;
    return DRV_OK;
}
static int sai_port_led_read(unsigned i, int32_t *v)
{
    (void)i;
    *v = led_is_on() ? 1 : 0;
    return DRV_OK;
}
static int sai_port_led_write(unsigned i, int32_t v)
{
    (void)i;
    led_set(v != 0);
    return DRV_OK;
}

#define SAI_KIND(kind, read, write) [kind] = {&board_ports[kind], read, write}
static const struct sai_kind_info kinds[BOARD_PORT_KINDS] = {
    SAI_KIND(BOARD_PORT_ANALOG_IN, sai_port_analog_read, NULL),
    SAI_KIND(BOARD_PORT_ANALOG_OUT, NULL, sai_port_analog_write),
    SAI_KIND(BOARD_PORT_BINARY_IO, sai_port_bio_read, sai_port_bio_write),
    SAI_KIND(BOARD_PORT_BINARY_IN, sai_port_binin_read, NULL),
    SAI_KIND(BOARD_PORT_FAST_OUT, sai_port_fastout_read, sai_port_fastout_write),
    SAI_KIND(BOARD_PORT_PWM, sai_port_pwm_read, sai_port_pwm_write),
    SAI_KIND(BOARD_PORT_MOTOR, sai_port_motor_read, sai_port_motor_write),
    SAI_KIND(BOARD_PORT_ENCODER, sai_port_encoder_read, NULL),
    SAI_KIND(BOARD_PORT_LED, sai_port_led_read, sai_port_led_write),
};
#undef SAI_KIND

const struct sai_kind_info *sai_kind_info(unsigned kind)
{
    return kind < BOARD_PORT_KINDS ? &kinds[kind] : NULL;
}

static int is_blank(char c)
{
    return c == ' ' || c == '\t';
}

static const char *skip_blanks(const char *s)
{
    while (is_blank(*s))
        s++;
    return s;
}

static char lower(char c)
{
    return (c >= 'A' && c <= 'Z') ? (char)(c - 'A' + 'a') : c;
}

/* If text starts with name (word by word, any run of blanks between words,
 * case-insensitive) followed by a blank or the end: the text after it. */
static const char *match_name(const char *text, const char *name)
{
    while (*name != '\0') {
        if (*name == ' ') {
            if (!is_blank(*text))
                return NULL;
            text = skip_blanks(text);
            name++;
            continue;
        }
        if (lower(*text) != *name)
            return NULL;
        text++;
        name++;
    }
    return (*text == '\0' || is_blank(*text)) ? text : NULL;
}

/* Longest kind name (or short name) at the start of text. */
static int match_kind(const char *text, const char **after)
{
    int best = -1;
    size_t best_len = 0;
    unsigned k;
    for (k = 0; k < BOARD_PORT_KINDS; k++) {
        const char *names[2] = {kinds[k].port->name, kinds[k].port->short_name};
        unsigned n;
        for (n = 0; n < 2u; n++) {
            const char *end = match_name(text, names[n]);
            if (end != NULL && (size_t)(end - text) > best_len) {
                best = (int)k;
                best_len = (size_t)(end - text);
                *after = end;
            }
        }
    }
    return best;
}

/* A channel number: 1 to 3 decimal digits ending at a blank or the end. */
static int parse_number(const char *s, unsigned *value, const char **after)
{
    unsigned v = 0, digits = 0;
    while (*s >= '0' && *s <= '9') {
        if (++digits > 3u)
            return 0;
        v = v * 10u + (unsigned)(*s - '0');
        s++;
    }
    if (digits == 0u || !(*s == '\0' || is_blank(*s)))
        return 0;
    *value = v;
    *after = s;
    return 1;
}

int sai_parse_prefix(const char *text, struct sai_channel *ch, const char **rest)
{
    const char *p, *after_number;
    unsigned index;
    int kind;
    if (text == NULL || ch == NULL || rest == NULL)
        return DRV_ERR_PARAM;
    kind = match_kind(skip_blanks(text), &p);
    if (kind < 0)
        return DRV_ERR_CHANNEL;
    p = skip_blanks(p);
    if (parse_number(p, &index, &after_number)) {
        p = after_number;
    } else if (kinds[kind].port->first == kinds[kind].port->last && !(*p >= '0' && *p <= '9')) {
        index = kinds[kind].port->first; /* a kind with one channel: the number is optional */
    } else {
        return DRV_ERR_CHANNEL;
    }
    if (index < kinds[kind].port->first || index > kinds[kind].port->last)
        return DRV_ERR_CHANNEL;
    ch->kind = (uint8_t)kind;
    ch->index = (uint8_t)index;
    *rest = p;
    return DRV_OK;
}

int sai_parse(const char *text, struct sai_channel *ch)
{
    struct sai_channel parsed;
    const char *rest;
    int rc;
    if (text == NULL || ch == NULL)
        return DRV_ERR_PARAM;
    rc = sai_parse_prefix(text, &parsed, &rest);
    if (rc != DRV_OK)
        return rc;
    if (*skip_blanks(rest) != '\0')
        return DRV_ERR_CHANNEL;
    *ch = parsed;
    return DRV_OK;
}

int sai_check(struct sai_channel ch)
{
    if (ch.kind >= BOARD_PORT_KINDS || ch.index < kinds[ch.kind].port->first ||
        ch.index > kinds[ch.kind].port->last)
        return DRV_ERR_CHANNEL;
    return DRV_OK;
}

int sai_check_value(struct sai_channel ch, int32_t value)
{
    if (sai_check(ch) != DRV_OK)
        return DRV_ERR_CHANNEL;
    if (!kinds[ch.kind].port->writable)
        return DRV_ERR_PARAM;
    if (value < kinds[ch.kind].port->min || value > kinds[ch.kind].port->max)
        return DRV_ERR_RANGE;
    return DRV_OK;
}

int sai_name(struct sai_channel ch, char *buf, size_t size)
{
    const char *name;
    char digits[4];
    size_t len = 0, n = 0, i;
    unsigned v;
    if (buf == NULL || size == 0u)
        return DRV_ERR_PARAM;
    if (sai_check(ch) != DRV_OK)
        return DRV_ERR_CHANNEL;
    v = ch.index;
    do {
        digits[n++] = (char)('0' + v % 10u);
        v /= 10u;
    } while (v != 0u);
    for (name = kinds[ch.kind].port->name; *name != '\0'; name++, len++)
        if (len + 1u < size)
            buf[len] = *name;
    if (len + 1u < size)
        buf[len] = ' ';
    len++;
    for (i = n; i > 0u; i--, len++)
        if (len + 1u < size)
            buf[len] = digits[i - 1u];
    buf[len + 1u < size ? len : size - 1u] = '\0';
    return (int)len;
}

int sai_read(struct sai_channel ch, int32_t *value)
{
    if (value == NULL)
        return DRV_ERR_PARAM;
    if (sai_check(ch) != DRV_OK)
        return DRV_ERR_CHANNEL;
    if (!kinds[ch.kind].port->readable || kinds[ch.kind].read == NULL)
        return DRV_ERR_PARAM;
    return kinds[ch.kind].read(ch.index, value);
}

int sai_write(struct sai_channel ch, int32_t value)
{
    int rc = sai_check_value(ch, value);
    if (rc != DRV_OK)
        return rc;
    if (kinds[ch.kind].write == NULL)
        return DRV_ERR_PARAM;
    rc = kinds[ch.kind].write(ch.index, value);
    return rc < 0 ? rc : DRV_OK;
}
