/* Runs the complete example of pdl/README.md ("A complete program";
 * extracted by pdl/pdl.mk into build/pdl/readme_example.c) on the host:
 * it must start, and turn toward a light on the left. Exit status 0 = pass. */
#include <stdio.h>

#include "pdl/host/pdl_host.h"

int start(void);

int main(void)
{
    int r = start();
    int32_t left, right;
    if (r != PDL_OK) {
        printf("README example: start() = %d (%s)\n", r, pdl_strerror(r));
        return 1;
    }
    pdl_host_set_input(PDL_ANALOG_IN, 0, 200);    /* light on the left */
    pdl_host_set_input(PDL_ANALOG_IN, 1, 40);
    pdl_run_cycles(100);
    left = pdl_host_output(PDL_MOTOR, 0);
    right = pdl_host_output(PDL_MOTOR, 1);
    printf("README example: motors %ld, %ld after 100 cycles\n", (long)left, (long)right);
    return right > left + 100 ? 0 : 1;
}
