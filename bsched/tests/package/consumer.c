/* The host consumer of the bsched package, built three ways by the
 * bsched-package suite (add_subdirectory, find_package, pkg-config): it plans
 * the paper's Table 1 set, runs two major cycles and compares every minor
 * cycle with Table 2, and checks that the capacity it was compiled with is
 * the library's. Exit status 0 only if every check holds. */
#include <stdio.h>
#include <string.h>

#include "bsched.h"
#include "../table2.h"

/* The capacity the build asked for. If the package's BSCHED_MAX_PROCS did not
 * reach this file, bsched.h's default (256) would stand here instead, and the
 * struct this file allocates would not be the one the library fills. */
#ifndef BSCHED_EXPECT_MAX_PROCS
#error "build with -DBSCHED_EXPECT_MAX_PROCS=N, the capacity the package was configured with"
#endif

static struct bsched sched;
static uint8_t all_zero[BSCHED_MAX_PROCS + 1];

static int failures;

static void check(int ok, const char *what)
{
    if (!ok) {
        printf("consumer: FAILED: %s\n", what);
        failures++;
    }
}

int main(void)
{
    check(BSCHED_MAX_PROCS == BSCHED_EXPECT_MAX_PROCS, "BSCHED_MAX_PROCS is the configured capacity");
    check(bsched_init(&sched, table1_pv, sizeof table1_pv) == BSCHED_OK, "Table 1's set is planned");
    check(sched.perfect == 3, "perfect = ceil(U) = 3 for Table 1");
    for (uint32_t t = 0; t < 32; t++) {
        const int *row = table2[t % 16];
        int32_t n = bsched_step(&sched);
        int32_t want = 0;
        while (want < 4 && row[want] >= 0) {
            want++;
        }
        int same = n == want;
        for (int32_t k = 0; same && k < n; k++) {
            same = sched.ran[k] == row[k];
        }
        if (!same) {
            printf("consumer: minor cycle %u differs from Table 2\n", (unsigned)t);
        }
        check(same, "every minor cycle of two major cycles is Table 2's");
    }
    /* The library's own limit is the capacity this file sees. */
    memset(all_zero, 0, sizeof all_zero);
    check(bsched_init(&sched, all_zero, BSCHED_MAX_PROCS) == BSCHED_OK, "a full set is planned");
    check(bsched_init(&sched, all_zero, BSCHED_MAX_PROCS + 1) == BSCHED_ERR_TOO_MANY,
          "one process more is BSCHED_ERR_TOO_MANY");
    if (failures == 0) {
        printf("consumer: Table 2 over two major cycles, capacity %u: ok\n", (unsigned)BSCHED_MAX_PROCS);
    }
    return failures == 0 ? 0 : 1;
}
