/*
 * The PDL runtime's ports through the drivers, on a board whose ports are
 * its drivers' (the RoboCube: boards/robocube/board.mk links this file).
 * Sensors come from the sampler's latest snapshot (no bus access in the
 * cycle), actuators are written by the uniform access layer's driver calls
 * (drivers/sai.h), and pdl_platform_start_ports brings up the drivers the
 * bindings use.
 */
#include "pdl/pdl_internal.h"

#include "drivers/sai.h"
#include "drivers/sampler.h"
#include "drivers/board_io.h"
#include "drivers/motor.h"
#include "drivers/tpu.h"

/* Sampler period when run_pdl starts it (ms): a full sweep of the I/O board
 * takes 6 ms (drivers/README.md), so sensors are at most ~16 ms old. */
#ifndef PDL_SAMPLER_MS
#define PDL_SAMPLER_MS 10u
#endif

void pdl_platform_read_inputs(struct pdl_inputs *in)
{
    struct sensor_snapshot snap;
    unsigned i;
    sampler_read(&snap);
    for (i = 0; i < 24u; i++)
        in->analog[i] = snap.analog[i];
    in->bio = snap.bio;
    in->binin = (uint8_t)(snap.binin << 1);     /* the sampler has IP1 in bit 0 */
    in->valid = snap.seq == 0u ? 0u : snap.valid;
}

/* Through the uniform access layer's dispatch (drivers/sai.h): the driver's
 * result. Index and value are in the port's range (pdl_bind.c checked and
 * clipped). */
int pdl_platform_write(enum pdl_port port, unsigned index, int32_t v)
{
    const struct sai_kind_info *k = sai_kind_info((unsigned)pdl_port_kind(port));
    if (k == NULL || k->write == NULL)
        return PDL_ERR_DRIVER;
    return k->write(index, v);
}

static int pdl_driver_failed(int code, const char *what)
{
    pdl_stats.last_driver_code = code;
    return pdl_refuse(PDL_ERR_DRIVER, what);
}

/* Brings up the drivers the bindings use, each once per boot: the I/O board
 * (board_io_init) for analog/binary ports, the sampler for inputs, the
 * motors, the TPU for PWM. */
int pdl_platform_start_ports(void)
{
    static int io_up, sampler_up, motors_up, tpu_up;
    int r;
    if (!io_up && (pdl_bind_uses(PDL_ANALOG_IN) || pdl_bind_uses(PDL_BINARY_IN) ||
                   pdl_bind_uses(PDL_BIO_IN) || pdl_bind_uses(PDL_ANALOG_OUT) ||
                   pdl_bind_uses(PDL_BIO_OUT) || pdl_bind_uses(PDL_FAST_OUT))) {
        r = board_io_init();
        if (r < 0)
            return pdl_driver_failed(r, "run_pdl: board_io_init");
        io_up = 1;
    }
    if (!sampler_up && (pdl_bind_uses(PDL_ANALOG_IN) || pdl_bind_uses(PDL_BINARY_IN) ||
                        pdl_bind_uses(PDL_BIO_IN))) {
        r = sampler_start(PDL_SAMPLER_MS);
        if (r < 0)
            return pdl_driver_failed(r, "run_pdl: sampler_start");
        sampler_up = 1;
    }
    if (!motors_up && pdl_bind_uses(PDL_MOTOR)) {
        r = motor_init();
        if (r < 0)
            return pdl_driver_failed(r, "run_pdl: motor_init");
        motors_up = 1;
    }
    if (!tpu_up && pdl_bind_uses(PDL_PWM)) {
        r = tpu_init();
        if (r < 0)
            return pdl_driver_failed(r, "run_pdl: tpu_init");
        tpu_up = 1;
    }
    return PDL_OK;
}
