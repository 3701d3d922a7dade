/* Console line assembly; see line_edit.h. */
#include "line_edit.h"

#define CH_CTRL_C 0x03u
#define CH_BS     0x08u
#define CH_TAB    0x09u
#define CH_LF     0x0Au
#define CH_CR     0x0Du
#define CH_CTRL_U 0x15u
#define CH_DEL    0x7Fu

void line_edit_init(struct line_edit *e, char *buf, size_t size)
{
    e->buf = buf;
    e->size = size;
    e->after_cr = 0;
    line_edit_reset(e);
}

void line_edit_reset(struct line_edit *e)
{
    e->len = 0;
    e->overflow = 0;
    e->complete = 0;
    if (e->size > 0u)
        e->buf[0] = '\0';
}

static size_t put_echo(char *echo, const char *s)
{
    size_t n = 0;
    while (s[n] != '\0') {
        echo[n] = s[n];
        n++;
    }
    return n;
}

enum line_edit_result line_edit_feed(struct line_edit *e, unsigned char c, char *echo,
                                     size_t *echo_len)
{
    int after_cr = e->after_cr;
    *echo_len = 0;
    e->after_cr = (c == CH_CR);
    if (c == CH_LF && after_cr)
        return LINE_EDIT_MORE; /* second half of CR LF: that line already ended */
    if (e->complete)
        line_edit_reset(e);
    if (c == CH_CR || c == CH_LF) {
        int overflow = e->overflow;
        *echo_len = put_echo(echo, "\n");
        if (overflow) {
            line_edit_reset(e);
            return LINE_EDIT_TOO_LONG;
        }
        e->buf[e->len] = '\0';
        e->complete = 1;
        return LINE_EDIT_DONE;
    }
    if (c == CH_CTRL_C || c == CH_CTRL_U) {
        *echo_len = put_echo(echo, c == CH_CTRL_C ? "^C\n" : "^U\n");
        line_edit_reset(e);
        return LINE_EDIT_CANCELLED;
    }
    if (e->overflow)
        return LINE_EDIT_MORE; /* the rest of a refused line */
    if (c == CH_BS || c == CH_DEL) {
        if (e->len > 0u) {
            e->len--;
            *echo_len = put_echo(echo, "\b \b");
        }
        return LINE_EDIT_MORE;
    }
    if (c == CH_TAB)
        c = ' ';
    if (c < 0x20u)
        return LINE_EDIT_MORE; /* other control characters mean nothing here */
    if (c >= 0x80u)
        return LINE_EDIT_MORE; /* not ASCII: never stored, never echoed (see line_edit.h) */
    if (e->len + 1u >= e->size) {
        e->overflow = 1;
        return LINE_EDIT_MORE;
    }
    e->buf[e->len++] = (char)c;
    echo[0] = (char)c;
    *echo_len = 1;
    return LINE_EDIT_MORE;
}
