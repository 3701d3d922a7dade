// expect: 'struct pdl_sensor' has no member named 'sum'
/* A sensor quantity is read-only: add_value on it must not compile. */
#include "pdl/pdl.h"

struct pdl_sensor light;

void push_light(void) { add_value(light, 1); }
