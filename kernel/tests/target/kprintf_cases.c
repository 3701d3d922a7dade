/*
 * Host-side driver for kernel/lib/kprintf.c: prints each case as
 * "<format>|<ksnprintf result>|<return value>" for test_kprintf_host.py,
 * which compares each with the output printf would give. Also checks
 * truncation.
 */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "kernel/lib/kprintf.h"

#define CASE(fmt, ...)                                                 \
    do {                                                               \
        char buf[64];                                                  \
        int count = ksnprintf(buf, sizeof buf, fmt, __VA_ARGS__);      \
        printf("%s|%s|%d\n", fmt, buf, count);                         \
    } while (0)

int main(void)
{
    char small[5];
    int n;

    CASE("%d", 0);
    CASE("%d", -1);
    CASE("%d", 2147483647);
    CASE("%d", (int)INT32_MIN);
    CASE("%u", 4294967295u);
    CASE("%x", 0xdeadbeefu);
    CASE("%X", 0xdeadbeefu);
    CASE("%08x", 0x1234u);
    CASE("%08lx", 0xe00400ul);
    CASE("%04x", 0x2704u);
    CASE("%5d|", 42);
    CASE("%-5d|", 42);
    CASE("%05d", -42);
    CASE("%c%c", 'o', 'k');
    CASE("%s", "p1.1");
    CASE("%-6s|", "ab");
    CASE("%6s|", "ab");
    CASE("%*d", 4, 7);
    CASE("100%%", 0);
    CASE("%lu ticks", 16ul);
    CASE("cycle %lu: %s", 15ul, "p1.2 p2.2");

    n = ksnprintf(small, sizeof small, "%s", "truncated");
    printf("trunc|%s|%d\n", small, n);
    return 0;
}
