/* printf-style formatting without libc; see kprintf.h. */
#include "kprintf.h"

#include <stdint.h>

static void (*kprintf_putc)(char c);

void kprintf_set_output(void (*putc)(char c))
{
    kprintf_putc = putc;
}

struct field {
    int left;       /* '-' flag */
    char pad;       /* ' ' or '0' */
    unsigned width; /* minimum field width */
};

static int emit_padding(kformat_emit_fn emit, void *context, char pad, unsigned count)
{
    unsigned i;
    for (i = 0; i < count; i++) {
        emit(context, pad);
    }
    return (int)count;
}

/* Emits text[0..len-1] in a field, with the sign (if any) ahead of zero padding. */
static int emit_field(kformat_emit_fn emit, void *context, const struct field *f,
                      char sign, const char *text, unsigned len)
{
    unsigned total = len + (sign ? 1u : 0u);
    unsigned padding = f->width > total ? f->width - total : 0u;
    int count = 0;
    unsigned i;

    if (!f->left && f->pad == ' ') {
        count += emit_padding(emit, context, ' ', padding);
    }
    if (sign) {
        emit(context, sign);
        count++;
    }
    if (!f->left && f->pad == '0') {
        count += emit_padding(emit, context, '0', padding);
    }
    for (i = 0; i < len; i++) {
        emit(context, text[i]);
    }
    count += (int)len;
    if (f->left) {
        count += emit_padding(emit, context, ' ', padding);
    }
    return count;
}

/* Digits of value in base 10 or 16, most significant first, into buf (>= 11 chars). */
static unsigned format_unsigned(char *buf, uint32_t value, unsigned base, int upper)
{
    const char *digits = upper ? "0123456789ABCDEF" : "0123456789abcdef";
    char reversed[11];
    unsigned n = 0, i;

    do {
        reversed[n++] = digits[value % base];
        value /= base;
    } while (value != 0);
    for (i = 0; i < n; i++) {
        buf[i] = reversed[n - 1 - i];
    }
    return n;
}

int kvformat(kformat_emit_fn emit, void *context, const char *fmt, va_list args)
{
    int count = 0;

    while (*fmt != '\0') {
        struct field f = {0, ' ', 0};
        char digits[11];
        const char *p;

        if (*fmt != '%') {
            emit(context, *fmt++);
            count++;
            continue;
        }
        p = fmt + 1;
        for (;; p++) {
            if (*p == '-') {
                f.left = 1;
            } else if (*p == '0') {
                f.pad = '0';
            } else {
                break;
            }
        }
        if (f.left) {
            f.pad = ' ';
        }
        if (*p == '*') {
            int w = va_arg(args, int);
            if (w < 0) {
                f.left = 1;
                f.pad = ' ';
                w = -w;
            }
            f.width = (unsigned)w;
            p++;
        } else {
            while (*p >= '0' && *p <= '9') {
                f.width = f.width * 10u + (unsigned)(*p - '0');
                p++;
            }
        }
        /* 'l' reads a long, 'h' (promoted to int anyway) is accepted and ignored. */
        int long_arg = 0;
        while (*p == 'l' || *p == 'h') {
            long_arg |= *p == 'l';
            p++;
        }

        switch (*p) {
        case 'c': {
            char c = (char)va_arg(args, int);
            count += emit_field(emit, context, &f, 0, &c, 1);
            break;
        }
        case 's': {
            const char *s = va_arg(args, const char *);
            unsigned len = 0;
            if (s == NULL) {
                s = "(null)";
            }
            while (s[len] != '\0') {
                len++;
            }
            f.pad = ' ';
            count += emit_field(emit, context, &f, 0, s, len);
            break;
        }
        case 'd':
        case 'i': {
            int32_t v = long_arg ? (int32_t)va_arg(args, long) : (int32_t)va_arg(args, int);
            /* Negate in unsigned arithmetic: INT32_MIN has no positive int32_t. */
            uint32_t magnitude = v < 0 ? 0u - (uint32_t)v : (uint32_t)v;
            unsigned len = format_unsigned(digits, magnitude, 10, 0);
            count += emit_field(emit, context, &f, v < 0 ? '-' : 0, digits, len);
            break;
        }
        case 'u': {
            uint32_t v = long_arg ? (uint32_t)va_arg(args, unsigned long)
                                  : (uint32_t)va_arg(args, unsigned);
            unsigned len = format_unsigned(digits, v, 10, 0);
            count += emit_field(emit, context, &f, 0, digits, len);
            break;
        }
        case 'x':
        case 'X': {
            uint32_t v = long_arg ? (uint32_t)va_arg(args, unsigned long)
                                  : (uint32_t)va_arg(args, unsigned);
            unsigned len = format_unsigned(digits, v, 16, *p == 'X');
            count += emit_field(emit, context, &f, 0, digits, len);
            break;
        }
        case 'p': {
            unsigned len = format_unsigned(digits, (uint32_t)(uintptr_t)va_arg(args, void *),
                                           16, 0);
            emit(context, '0');
            emit(context, 'x');
            count += 2;
            count += emit_field(emit, context, &f, 0, digits, len);
            break;
        }
        case '%':
            emit(context, '%');
            count++;
            break;
        case '\0':
            /* A lone '%' at the end: print it and stop. */
            emit(context, '%');
            return count + 1;
        default:
            /* Unknown conversion: show it verbatim so the mistake is visible. */
            emit(context, '%');
            emit(context, *p);
            count += 2;
            break;
        }
        fmt = p + 1;
    }
    return count;
}

struct buffer_sink {
    char *buf;
    size_t size;
    size_t used; /* characters produced so far, may exceed size */
};

static void emit_to_buffer(void *context, char c)
{
    struct buffer_sink *sink = context;
    if (sink->size > 0 && sink->used < sink->size - 1) {
        sink->buf[sink->used] = c;
    }
    sink->used++;
}

int ksnprintf(char *buf, size_t size, const char *fmt, ...)
{
    struct buffer_sink sink = {buf, size, 0};
    va_list args;
    int count;

    va_start(args, fmt);
    count = kvformat(emit_to_buffer, &sink, fmt, args);
    va_end(args);
    if (size > 0) {
        buf[sink.used < size ? sink.used : size - 1] = '\0';
    }
    return count;
}

static void emit_to_output(void *context, char c)
{
    (void)context;
    if (kprintf_putc != NULL) {
        kprintf_putc(c);
    }
}

int kvprintf(const char *fmt, va_list args)
{
    return kvformat(emit_to_output, NULL, fmt, args);
}

int kprintf(const char *fmt, ...)
{
    va_list args;
    int count;

    va_start(args, fmt);
    count = kvprintf(fmt, args);
    va_end(args);
    return count;
}
