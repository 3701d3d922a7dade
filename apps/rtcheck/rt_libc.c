/* The cases of rt_libc.h. Inputs go through volatile objects so the compiler
 * cannot compute the results (or rewrite printf into puts) at build time. */
#include "rt_libc.h"

#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static volatile int vi[] = {0, 7, -1, 42, INT_MAX, INT_MIN};
/* long is 32 bits on the CPU32 and 64 on the host: values both print alike. */
static volatile long vl[] = {0L, -123456789L, 2147483647L, -2147483647L - 1L};
static volatile long long vll[] = {0LL, -1LL, 1234567890123456789LL, LLONG_MIN, LLONG_MAX};
static volatile unsigned vu[] = {0u, 1u, 3000000000u, UINT_MAX};
static volatile double vd[] = {0.0, -0.0, 1.0, -2.5, 3.14159265358979, 1e-7, 123456789.125,
                               1e300, 6.02214076e23};
static volatile float vf[] = {0.0f, 0.5f, -1.25f, 3.0f, 100.0f, 1e-3f, 2.71828f};
static const char *volatile vs[] = {"", "robot", "light seeking"};
static volatile size_t cut = 8;

static int compare_ints(const void *a, const void *b)
{
    int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

static void libm_line(const char *name, unsigned index, float r)
{
    union { float f; uint32_t u; } v;
    v.f = r;
    printf("RTM %s %u %08lx\n", name, index, (unsigned long)v.u);
}

int rt_libc_run(void)
{
    int lines = 0, n;
    unsigned i;
    char buf[64];
    int sorted[] = {5, -3, 9, 0, 9, -100, 42, 7};

    for (i = 0; i < sizeof vi / sizeof vi[0]; i++, lines++)
        printf("RTP d %u [%d] [%5d] [%-5d] [%05d] [%x] [%X] [%o] [%c]\n", i, vi[i], vi[i], vi[i],
               vi[i], (unsigned)vi[i], (unsigned)vi[i], (unsigned)vi[i], 'A' + (int)(i % 26u));
    for (i = 0; i < sizeof vu / sizeof vu[0]; i++, lines++)
        printf("RTP u %u [%u] [%#x] [%08x]\n", i, vu[i], vu[i], vu[i]);
    for (i = 0; i < sizeof vl / sizeof vl[0]; i++, lines++)
        printf("RTP ld %u [%ld] [%lx]\n", i, vl[i], (unsigned long)(vl[i] < 0 ? -(vl[i] + 1) : vl[i]));
    for (i = 0; i < sizeof vll / sizeof vll[0]; i++, lines++)
        printf("RTP lld %u [%lld] [%llx] [%llu]\n", i, vll[i], (unsigned long long)vll[i],
               (unsigned long long)vll[i]);
    for (i = 0; i < sizeof vd / sizeof vd[0]; i++, lines++)
        printf("RTP f %u [%f] [%.2f] [%10.3f] [%e] [%.3e] [%g]\n", i, vd[i], vd[i], vd[i], vd[i],
               vd[i], vd[i]);
    for (i = 0; i < sizeof vs / sizeof vs[0]; i++, lines++)
        printf("RTP s %u [%s] [%8s] [%-8s] [%.3s] [%zu]\n", i, vs[i], vs[i], vs[i], vs[i],
               strlen(vs[i]));
    /* snprintf: truncation and the length the whole output would have had. */
    n = snprintf(buf, cut, "%s-%d", vs[2], vi[3]);
    lines++;
    printf("RTP snprintf %d [%s]\n", n, buf);
    /* string.h */
    strcpy(buf, "wander");
    strcat(buf, "+avoid");
    lines++;
    printf("RTP string [%s] %d %d %d [%s]\n", buf, (int)strlen(buf), strcmp(buf, "wander") > 0,
           strncmp(buf, "wand", 4) == 0, strchr(buf, '+'));
    /* stdlib.h */
    lines++;
    printf("RTP stdlib %ld %ld %ld %d %d\n", strtol("-1234xyz", NULL, 10), strtol("0x7f", NULL, 16),
           strtol("777", NULL, 8), abs(vi[2] * 5), atoi("  42"));
    qsort(sorted, sizeof sorted / sizeof sorted[0], sizeof sorted[0], compare_ints);
    lines++;
    printf("RTP qsort");
    for (i = 0; i < sizeof sorted / sizeof sorted[0]; i++)
        printf(" %d", sorted[i]);
    printf("\n");
    puts("RTP puts done");
    lines++;
    /* float libm: what behaviours use. */
    for (i = 0; i < sizeof vf / sizeof vf[0]; i++, lines += 5) {
        libm_line("sinf", i, sinf(vf[i]));
        libm_line("cosf", i, cosf(vf[i]));
        libm_line("atan2f", i, atan2f(vf[i], 1.5f - vf[i]));
        libm_line("sqrtf", i, sqrtf(vf[i] < 0.0f ? -vf[i] : vf[i]));
        libm_line("fabsf", i, fabsf(vf[i]));
    }
    return lines;
}
