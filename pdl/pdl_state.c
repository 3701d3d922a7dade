/*
 * What the PDL core (pdl_core.c) and the binding table (pdl_bind.c) share,
 * below both: the statistics, whether run_pdl() has started the set, and the
 * refusal of misuse (counted, reported through the platform). The core calls
 * the binding table; the binding table never calls the core.
 */
#include "pdl/pdl_internal.h"

struct pdl_stats pdl_stats;
int pdl_started;

void pdl_count_refusal(int code, const char *what)
{
    pdl_stats.misuse++;
    pdl_stats.last_error = code;
    pdl_platform_report(code, what);
}

const char *pdl_strerror(int code)
{
    switch (code) {
    case PDL_OK: return "ok";
    case PDL_ERR_NULL: return "NULL quantity or process";
    case PDL_ERR_RUNNING: return "not allowed after run_pdl()";
    case PDL_ERR_TOO_MANY_PROCESSES: return "too many processes";
    case PDL_ERR_TOO_MANY_QUANTITIES: return "too many quantities";
    case PDL_ERR_PV_RANGE: return "priority value out of range";
    case PDL_ERR_BOUNDS: return "min > max, or initial value outside [min, max]";
    case PDL_ERR_TWICE: return "quantity declared or bound twice";
    case PDL_ERR_UNDECLARED: return "quantity not declared";
    case PDL_ERR_NO_PROCESSES: return "no process";
    case PDL_ERR_PORT: return "no such port for this direction";
    case PDL_ERR_PORT_TAKEN: return "output already bound";
    case PDL_ERR_FREQUENCY: return "cycle frequency out of range";
    case PDL_ERR_NOT_RUNNING: return "run_pdl() not called";
    case PDL_ERR_DRIVER: return "driver error";
    case PDL_ERR_KERNEL: return "kernel refused the cycle thread";
    case PDL_ERR_OUTSIDE_PROCESS: return "add_value outside a process";
    case PDL_ERR_TOO_MANY_BINDINGS: return "too many bindings";
    case PDL_ERR_NOT_FINITE: return "NaN or infinite value for an integer quantity";
    default: return "unknown error";
    }
}

void pdl_core_set_started(int started) { pdl_started = started; }
int pdl_core_started(void) { return pdl_started; }
