/* Host unit tests of the console line assembly (drivers/line_edit.c). */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "drivers/line_edit.h"

static char buf[8];              /* up to 7 characters */
static struct line_edit ed;
static char echoed[256];
static size_t echoed_len;

static int setup(void **state)
{
    (void)state;
    memset(buf, 'X', sizeof buf);
    line_edit_init(&ed, buf, sizeof buf);
    echoed_len = 0;
    echoed[0] = '\0';
    return 0;
}

/* Feeds s; returns the results of each byte as letters (. more, D done,
 * L too long, C cancelled), so a test sees where each line ended. */
static const char *feed(const char *s, size_t n)
{
    static char results[256];
    size_t i;
    for (i = 0; i < n; i++) {
        char echo[LINE_EDIT_ECHO_MAX];
        size_t len = 99;
        enum line_edit_result r = line_edit_feed(&ed, (unsigned char)s[i], echo, &len);
        assert_true(len <= LINE_EDIT_ECHO_MAX);
        memcpy(echoed + echoed_len, echo, len);
        echoed_len += len;
        echoed[echoed_len] = '\0';
        results[i] = ".DLC"[r];
    }
    results[n] = '\0';
    return results;
}
#define FEED(s) feed(s, sizeof(s) - 1u)

static void test_cr_lf_and_crlf_end_lines(void **state)
{
    (void)state;
    assert_string_equal(FEED("help\r"), "....D");
    assert_string_equal(buf, "help");
    assert_int_equal(ed.len, 4);
    assert_string_equal(FEED("ad 5\n"), "....D");
    assert_string_equal(buf, "ad 5");
    /* CR LF is one end of line, not an extra empty line */
    assert_string_equal(FEED("ps\r\nup\r\n"), "..D...D.");
    assert_string_equal(buf, "up");
    /* LF LF is two lines, the second empty */
    assert_string_equal(FEED("a\n\n"), ".DD");
    assert_string_equal(buf, "");
    assert_string_equal(echoed, "help\nad 5\nps\nup\na\n\n");
}

static void test_backspace_and_delete(void **state)
{
    (void)state;
    assert_string_equal(FEED("lex\bd o\x7f\x7f\n"), ".........D");
    assert_string_equal(buf, "led");
    /* backspace on an empty line does nothing, echoes nothing */
    echoed_len = 0;
    assert_string_equal(FEED("\b\bx\n"), "...D");
    assert_string_equal(buf, "x");
    assert_string_equal(echoed, "x\n");
}

static void test_overlong_line_is_refused_whole(void **state)
{
    (void)state;
    /* 7 characters fit, the 8th overflows: the line is discarded at its end */
    assert_string_equal(FEED("1234567\n"), ".......D");
    assert_string_equal(buf, "1234567");
    assert_string_equal(FEED("ad 5 and more\n"), ".............L");
    assert_int_equal(ed.len, 0);
    /* the tail was not treated as a command, the next line is clean */
    assert_string_equal(FEED("led on\r\n"), "......D.");
    assert_string_equal(buf, "led on");
    /* a backspace after the overflow does not make the line acceptable */
    assert_string_equal(FEED("12345678\b\n"), ".........L");
    /* the echo stops at the overflow */
    echoed_len = 0;
    assert_string_equal(FEED("abcdefghij\n"), "..........L");
    assert_string_equal(echoed, "abcdefg\n");
}

static void test_cancel_and_control_characters(void **state)
{
    (void)state;
    assert_string_equal(FEED("motor 1\x03"), ".......C");
    assert_int_equal(ed.len, 0);
    assert_string_equal(FEED("ab\x15" "cd\n"), "..C..D");
    assert_string_equal(buf, "cd");
    /* escape, bell, NUL are ignored; TAB is a blank */
    assert_string_equal(FEED("a\x1b\x07\tb\n"), ".....D");
    assert_string_equal(buf, "a b");
    /* Ctrl-C also ends an overlong line without an error */
    assert_string_equal(FEED("0123456789\x03"), "..........C");
    assert_string_equal(FEED("ok\n"), "..D");
    assert_string_equal(buf, "ok");
}

/* Bytes 0x80..0xFF are neither stored nor echoed: echoed raw, the C1 controls
 * (0x9B CSI, 0x90 DCS, 0x9D OSC, ...) would be obeyed by the terminal. */
static void test_bytes_above_ascii_are_ignored_and_never_echoed(void **state)
{
    char line[16];
    unsigned c;
    (void)state;
    for (c = 0x80u; c <= 0xFFu; c++) {
        line[0] = 'a';
        line[1] = (char)c;
        line[2] = 'b';
        line[3] = '\n';
        echoed_len = 0;
        echoed[0] = '\0';
        assert_string_equal(feed(line, 4), "...D");
        assert_string_equal(buf, "ab");
        assert_int_equal(echoed_len, 3);
        assert_memory_equal(echoed, "ab\n", 3);
    }
    /* a CSI sequence that would clear the screen, and its UTF-8 form */
    echoed_len = 0;
    assert_string_equal(FEED("\x9b" "2J\xc2\x9b" "2J\n"), ".......D");
    assert_string_equal(buf, "2J2J");
    assert_memory_equal(echoed, "2J2J\n", 5);
    assert_int_equal(echoed_len, 5);
}

static void test_tiny_buffer(void **state)
{
    char one[1];
    (void)state;
    line_edit_init(&ed, one, sizeof one); /* room for the empty line only */
    assert_string_equal(FEED("\n"), "D");
    assert_string_equal(one, "");
    assert_string_equal(FEED("x\n"), ".L");
}

int main(void)
{
#define T(name) cmocka_unit_test_setup(name, setup)
    const struct CMUnitTest tests[] = {
        T(test_cr_lf_and_crlf_end_lines),
        T(test_backspace_and_delete),
        T(test_overlong_line_is_refused_whole),
        T(test_cancel_and_control_characters),
        T(test_bytes_above_ascii_are_ignored_and_never_echoed),
        T(test_tiny_buffer),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
