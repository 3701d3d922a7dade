// expect: incompatible pointer type
/* A process is an argumentless C function returning nothing. */
#include "pdl/pdl.h"

static void turn(int angle) { (void)angle; }

int setup(void) { return add_process(turn); }
