/* The host's results for rt_vectors.c: one line per vector, as the board prints them. */
#include <inttypes.h>
#include <stdio.h>

#include "rt_libc.h"
#include "rt_vectors.h"

static void emit(const char *name, unsigned index, uint64_t bits)
{
    printf("RT %s %u %08" PRIx32 "%08" PRIx32 "\n", name, index, (uint32_t)(bits >> 32),
           (uint32_t)bits);
}

int main(void)
{
    printf("RT done %u\n", rt_vectors_run(emit));
    printf("RT libc %d\n", rt_libc_run());
    return 0;
}
