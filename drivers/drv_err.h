/*
 * Result codes shared by every driver and by the uniform access layer above
 * them: 0 or a positive value is success (a reading), each failure has its own
 * negative code, so a caller (the shell, PDL) can tell a typo from a dead chip.
 */
#ifndef DRIVERS_DRV_ERR_H
#define DRIVERS_DRV_ERR_H

#define DRV_OK            0
#define DRV_ERR_CHANNEL (-1)   /* no such channel / port / line number */
#define DRV_ERR_RANGE   (-2)   /* value out of the channel's range */
#define DRV_ERR_ABSENT  (-3)   /* device did not acknowledge (absent or dead) */
#define DRV_ERR_TIMEOUT (-4)   /* bus stuck or transaction timed out (controller reset) */
#define DRV_ERR_ARB     (-5)   /* I2C arbitration lost */
#define DRV_ERR_BUSY    (-6)   /* queue full / resource in use, try again */
#define DRV_ERR_PARAM   (-7)   /* bad argument (NULL, length, mode) */
#define DRV_ERR_STATE   (-8)   /* not initialised, or not allowed in this state */

/* A short name for a code ("absent", "timeout", ...), for messages. */
const char *drv_strerror(int code);

#endif /* DRIVERS_DRV_ERR_H */
