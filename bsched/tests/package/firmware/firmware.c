/* A freestanding image for the cross builds of the bsched-package suite: no C
 * library, no start files, no compiler runtime (linked -nostdlib), so the
 * link shows that libbsched.a needs none of them on the target. It plans
 * Table 1's set and steps it for ever; nothing runs it. */
#include "bsched.h"

static struct bsched sched;
static const uint8_t pv[] = {1, 1, 1, 2, 2, 3, 4, 4, 4};
/* Kept so the compiler cannot drop the steps. */
volatile uint32_t firmware_runs;

void _start(void);

void _start(void)
{
    if (bsched_init(&sched, pv, sizeof pv) == BSCHED_OK) {
        for (;;) {
            firmware_runs += (uint32_t)bsched_step(&sched);
        }
    }
    for (;;) {
    }
}
