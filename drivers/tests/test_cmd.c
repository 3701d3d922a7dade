/*
 * Host unit tests of the console command tables (drivers/cmd.c), the parser
 * of the shell and the test images: word splitting, whole-word lookup,
 * argument counts, decimal numbers at the int32 limits.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include <cmocka.h>

#include "drivers/cmd.h"

static int ran;
static void run_a(int argc, char **argv, const char *line) { (void)argv; (void)line; ran = argc; }

static const struct cmd table[] = {
    {"led", "on|off", "the LED", 0, 1, run_a},
    {"ledx", "", "a longer name with the same start", 0, 0, run_a},
    {"da", "N V", "analog out", 2, 2, run_a},
};

static void test_split_blanks_and_tabs(void **state)
{
    char line[] = "  da\t 3   200 \t";
    char *argv[4];
    (void)state;
    assert_int_equal(cmd_split(line, argv, 4), 3);
    assert_string_equal(argv[0], "da");
    assert_string_equal(argv[1], "3");
    assert_string_equal(argv[2], "200");
}

static void test_split_blank_line_and_too_many(void **state)
{
    char blank[] = " \t ";
    char many[] = "a b c d";
    char exact[] = "a b c";
    char *argv[3];
    (void)state;
    assert_int_equal(cmd_split(blank, argv, 3), 0);
    assert_int_equal(cmd_split(many, argv, 3), -1);
    assert_int_equal(cmd_split(exact, argv, 3), 3);
    assert_string_equal(argv[2], "c");
}

static void test_same_is_whole_word(void **state)
{
    (void)state;
    assert_true(cmd_same("led", "led"));
    assert_false(cmd_same("le", "led"));
    assert_false(cmd_same("ledx", "led"));
    assert_true(cmd_same("", ""));
}

static void test_parse_int_limits(void **state)
{
    int32_t v = 7;
    (void)state;
    assert_true(cmd_parse_int("2147483647", &v));
    assert_int_equal(v, INT32_MAX);
    assert_true(cmd_parse_int("-2147483648", &v));
    assert_int_equal(v, INT32_MIN);
    assert_true(cmd_parse_int("+5", &v));
    assert_int_equal(v, 5);
    v = 7;
    assert_false(cmd_parse_int("2147483648", &v));
    assert_false(cmd_parse_int("-2147483649", &v));
    assert_false(cmd_parse_int("-", &v));
    assert_false(cmd_parse_int("", &v));
    assert_false(cmd_parse_int("12a", &v));
    assert_false(cmd_parse_int("0x10", &v));
    assert_int_equal(v, 7); /* untouched when refused */
}

static void test_find_counts_and_unknown(void **state)
{
    const struct cmd *c = NULL;
    char *one[] = {"led"}, *two[] = {"led", "on"}, *three[] = {"led", "on", "x"};
    char *da_short[] = {"da", "1"}, *unknown[] = {"le"}, *longer[] = {"ledx"};
    (void)state;
    assert_int_equal(cmd_find(table, 3, 1, one, &c), CMD_FOUND);
    assert_ptr_equal(c, &table[0]);
    assert_int_equal(cmd_find(table, 3, 2, two, &c), CMD_FOUND);
    assert_int_equal(cmd_find(table, 3, 3, three, &c), CMD_USAGE);
    assert_ptr_equal(c, &table[0]);
    assert_int_equal(cmd_find(table, 3, 2, da_short, &c), CMD_USAGE);
    assert_ptr_equal(c, &table[2]);
    assert_int_equal(cmd_find(table, 3, 1, longer, &c), CMD_FOUND);
    assert_ptr_equal(c, &table[1]);
    assert_int_equal(cmd_find(table, 3, 1, unknown, &c), CMD_UNKNOWN);
    assert_null(c);
    ran = 0;
    assert_int_equal(cmd_find(table, 3, 2, two, &c), CMD_FOUND);
    c->run(2, two, "led on");
    assert_int_equal(ran, 2);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_split_blanks_and_tabs),
        cmocka_unit_test(test_split_blank_line_and_too_many),
        cmocka_unit_test(test_same_is_whole_word),
        cmocka_unit_test(test_parse_int_limits),
        cmocka_unit_test(test_find_counts_and_unknown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
