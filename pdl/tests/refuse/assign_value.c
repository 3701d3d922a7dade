// expect: lvalue required as left operand of assignment
/* value(q) is the previous cycle's value, not a variable: it cannot be assigned. */
#include "pdl/pdl.h"

struct pdl_quantity speed;

void set_speed(void) { value(speed) = 3; }
