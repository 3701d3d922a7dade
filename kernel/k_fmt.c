/* printf-style formatting without libc, and the kernel's console printf. */
#include <stdarg.h>
#include "kernel.h"

struct k_fmt_spec {
    int left;      /* '-' */
    int zero;      /* '0' */
    unsigned width;
};

static int k_emit_padded(k_putc_fn out, void *ctx, const char *s, unsigned len,
                         const struct k_fmt_spec *sp, char sign)
{
    unsigned total = len + (sign != 0 ? 1u : 0u);
    unsigned pad = sp->width > total ? sp->width - total : 0u;
    int n = 0;
    if (!sp->left && !sp->zero)
        for (; pad > 0u; pad--, n++)
            out(ctx, ' ');
    if (sign != 0) {
        out(ctx, sign);
        n++;
    }
    if (!sp->left && sp->zero)
        for (; pad > 0u; pad--, n++)
            out(ctx, '0');
    for (; len > 0u; len--, n++)
        out(ctx, *s++);
    for (; pad > 0u; pad--, n++)
        out(ctx, ' ');
    return n;
}

static unsigned k_utoa(char *end, uint32_t v, unsigned base, int upper)
{
    const char *digits = upper ? "0123456789ABCDEF" : "0123456789abcdef";
    unsigned n = 0;
    do {
        *--end = digits[v % base];
        v /= base;
        n++;
    } while (v != 0u);
    return n;
}

int k_vformat(k_putc_fn out, void *ctx, const char *fmt, va_list ap)
{
    int n = 0;
    char num[12];
    while (*fmt != '\0') {
        struct k_fmt_spec sp = {0, 0, 0};
        char c = *fmt++;
        int is_long = 0;
        if (c != '%') {
            out(ctx, c);
            n++;
            continue;
        }
        for (;; fmt++) {
            if (*fmt == '-')
                sp.left = 1;
            else if (*fmt == '0')
                sp.zero = 1;
            else
                break;
        }
        while (*fmt >= '0' && *fmt <= '9')
            sp.width = sp.width * 10u + (unsigned)(*fmt++ - '0');
        while (*fmt == 'l' || *fmt == 'h') {
            is_long |= *fmt == 'l';
            fmt++;
        }
        c = *fmt;
        if (c == '\0')
            break;
        fmt++;
        switch (c) {
        case 'd':
        case 'i': {
            long v = is_long ? va_arg(ap, long) : (long)va_arg(ap, int);
            uint32_t mag = v < 0 ? (uint32_t)0u - (uint32_t)v : (uint32_t)v;
            unsigned len = k_utoa(num + sizeof num, mag, 10u, 0);
            n += k_emit_padded(out, ctx, num + sizeof num - len, len, &sp, v < 0 ? '-' : 0);
            break;
        }
        case 'u':
        case 'x':
        case 'X': {
            uint32_t v = is_long ? (uint32_t)va_arg(ap, unsigned long) : (uint32_t)va_arg(ap, unsigned);
            unsigned len = k_utoa(num + sizeof num, v, c == 'u' ? 10u : 16u, c == 'X');
            n += k_emit_padded(out, ctx, num + sizeof num - len, len, &sp, 0);
            break;
        }
        case 'p': {
            uint32_t v = (uint32_t)(uintptr_t)va_arg(ap, void *);
            unsigned len = k_utoa(num + sizeof num, v, 16u, 0);
            sp.zero = 1;
            sp.width = 8;
            n += k_emit_padded(out, ctx, "0x", 2u, &(struct k_fmt_spec){0, 0, 0}, 0);
            n += k_emit_padded(out, ctx, num + sizeof num - len, len, &sp, 0);
            break;
        }
        case 'c': {
            char ch = (char)va_arg(ap, int);
            n += k_emit_padded(out, ctx, &ch, 1u, &sp, 0);
            break;
        }
        case 's': {
            const char *s = va_arg(ap, const char *);
            unsigned len = 0;
            if (s == NULL)
                s = "(null)";
            while (s[len] != '\0')
                len++;
            sp.zero = 0;
            n += k_emit_padded(out, ctx, s, len, &sp, 0);
            break;
        }
        case '%':
            out(ctx, '%');
            n++;
            break;
        default: /* unknown conversion: show it rather than guess */
            out(ctx, '%');
            out(ctx, c);
            n += 2;
            break;
        }
    }
    return n;
}

struct k_buf_sink {
    char *buf;
    size_t size;
    size_t len;
};

static void k_buf_putc(void *ctx, char c)
{
    struct k_buf_sink *b = ctx;
    if (b->len + 1u < b->size)
        b->buf[b->len] = c;
    b->len++;
}

int k_vsnprintf(char *buf, size_t size, const char *fmt, va_list ap)
{
    struct k_buf_sink b;
    int n;
    b.buf = buf;
    b.size = size;
    b.len = 0;
    n = k_vformat(k_buf_putc, &b, fmt, ap);
    if (size > 0u)
        buf[b.len < size ? b.len : size - 1u] = '\0';
    return n;
}

int k_snprintf(char *buf, size_t size, const char *fmt, ...)
{
    va_list ap;
    int n;
    va_start(ap, fmt);
    n = k_vsnprintf(buf, size, fmt, ap);
    va_end(ap);
    return n;
}

/* Console output goes out in chunks so a long line needs no big buffer. */
struct k_console_sink {
    char chunk[32];
    size_t len;
};

static void k_console_flush(struct k_console_sink *c)
{
    /* k_console_write waits for room when it can; what it cannot take is
     * dropped (and counted) by the console, never spun on here. */
    (void)k_console_write(c->chunk, c->len);
    c->len = 0;
}

static void k_console_putc(void *ctx, char c)
{
    struct k_console_sink *s = ctx;
    s->chunk[s->len++] = c;
    if (s->len == sizeof s->chunk)
        k_console_flush(s);
}

int k_printf(const char *fmt, ...)
{
    struct k_console_sink s;
    va_list ap;
    int n;
    s.len = 0;
    va_start(ap, fmt);
    n = k_vformat(k_console_putc, &s, fmt, ap);
    va_end(ap);
    k_console_flush(&s);
    return n;
}
