/* Names of the shared driver result codes (drv_err.h). */
#include "drivers/drv_err.h"

const char *drv_strerror(int code)
{
    switch (code) {
    case DRV_OK:          return "ok";
    case DRV_ERR_CHANNEL: return "no such channel";
    case DRV_ERR_RANGE:   return "value out of range";
    case DRV_ERR_ABSENT:  return "device absent";
    case DRV_ERR_TIMEOUT: return "timeout (bus stuck)";
    case DRV_ERR_ARB:     return "arbitration lost";
    case DRV_ERR_BUSY:    return "busy";
    case DRV_ERR_PARAM:   return "bad argument";
    case DRV_ERR_STATE:   return "not ready";
    default:              return code >= 0 ? "ok" : "unknown error";
    }
}
