/* The kernel's console (the writer a board registers), printf and snprintf,
 * on the firmware's formatter (kernel/lib/kprintf.c, freestanding, no libc). */
#include <stdarg.h>
#include "kernel.h"
#include "kernel/lib/kprintf.h"

/* The registered console (k_console_register); none until a board registers one. */
static k_console_write_fn k_console_writer;
static k_console_sync_fn k_console_sync_writer;

void k_console_register(k_console_write_fn write, k_console_sync_fn write_sync)
{
    k_console_writer = write;
    k_console_sync_writer = write_sync;
}

size_t k_console_write(const char *s, size_t len)
{
    k_console_write_fn w = k_console_writer;
    k_console_sync_fn ws = k_console_sync_writer;
    if (w != NULL)
        return w(s, len);
    if (ws == NULL)
        return 0u;
    ws(s, len);
    return len;
}

void k_console_write_sync(const char *s, size_t len)
{
    k_console_sync_fn ws = k_console_sync_writer;
    if (ws != NULL)
        ws(s, len);
}

int k_vformat(k_putc_fn out, void *ctx, const char *fmt, va_list ap)
{
    return kvformat(out, ctx, fmt, ap);
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
