/* Host port of the kernel for the unit tests: threads are ucontexts. */
#ifndef K_ARCH_CTX_H
#define K_ARCH_CTX_H

#include <ucontext.h>

struct k_arch_context {
    ucontext_t uc;
};

#endif
