/*
 * Line assembly for a console: bytes in, complete lines out. Pure logic (no
 * hardware, no kernel), so the console reader and the host tests share it.
 *
 *   CR, LF or CR LF      end the line (the LF of a CR LF pair is swallowed)
 *   BS (0x08), DEL 0x7F  delete the last character (echo "\b \b")
 *   Ctrl-C, Ctrl-U       discard the line typed so far (echo "^C" / "^U" and a newline)
 *   TAB                  a space
 *   other control bytes  ignored
 *   bytes 0x80..0xFF     ignored: not stored, not echoed. Commands are ASCII;
 *                        0x80..0x9F are the C1 controls (0x9B is CSI, 0x90 DCS,
 *                        0x9D OSC), which a terminal would obey if echoed raw,
 *                        and 0xA0..0xFF only ever start or continue a UTF-8
 *                        sequence that could encode one (C2 9B), so none of
 *                        them is echoed.
 *
 * A line longer than the buffer is refused whole: once it overflows, the
 * rest of it up to its end is swallowed (not echoed) and the line ends with
 * LINE_EDIT_TOO_LONG instead of being cut into a command.
 */
#ifndef DRIVERS_LINE_EDIT_H
#define DRIVERS_LINE_EDIT_H

#include <stddef.h>

struct line_edit {
    char *buf;        /* holds the line, NUL-terminated when it is complete */
    size_t size;      /* capacity including the NUL */
    size_t len;       /* characters so far */
    int overflow;     /* the current line is longer than size - 1 */
    int after_cr;     /* the previous byte was CR (swallow one LF) */
    int complete;     /* buf holds a finished line: the next byte starts anew */
};

/* What line_edit_feed made of one byte. */
enum line_edit_result {
    LINE_EDIT_MORE = 0,      /* keep feeding */
    LINE_EDIT_DONE = 1,      /* buf holds a complete line of len characters */
    LINE_EDIT_TOO_LONG = 2,  /* a line ended that did not fit; it was discarded */
    LINE_EDIT_CANCELLED = 3  /* Ctrl-C / Ctrl-U discarded the line */
};

/* size >= 1. */
void line_edit_init(struct line_edit *e, char *buf, size_t size);
/* Starts a new line (after DONE / TOO_LONG / CANCELLED: feed does it itself). */
void line_edit_reset(struct line_edit *e);
/*
 * Feeds one received byte. The characters to echo back to the terminal go
 * to echo[] (at most LINE_EDIT_ECHO_MAX, not NUL-terminated), their count to
 * *echo_len. The next byte after a finished line starts a new one.
 */
#define LINE_EDIT_ECHO_MAX 4u
enum line_edit_result line_edit_feed(struct line_edit *e, unsigned char c, char *echo,
                                     size_t *echo_len);

#endif /* DRIVERS_LINE_EDIT_H */
