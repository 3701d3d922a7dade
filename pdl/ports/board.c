/*
 * The PDL runtime's ports through the board's own port access
 * (boards/include/board_ports.h: board_port_start, _read, _write), on a board
 * whose ports are its registers with no driver between (the STM32F405:
 * boards/stm32f405/board.mk links this file). Every cycle reads each bound
 * kind of sensor port whole, in number order, from the board.
 */
#include "pdl/pdl_internal.h"

#include "boards/include/board_ports.h"

/* Each number of kind that reads, as bit n of *bits; 1 when every one did. */
static int pdl_read_bits(enum board_port_kind kind, uint32_t *bits)
{
    const struct board_port_range *r = &board_ports[kind];
    unsigned n;
    int32_t v;
    int all = 1;
    *bits = 0;
    for (n = r->first; n <= r->last && n < 32u; n++) {
        if (board_port_read(kind, n, &v) != 0)
            all = 0;
        else if (v != 0)
            *bits |= 1ul << n;
    }
    return all;
}

void pdl_platform_read_inputs(struct pdl_inputs *in)
{
    const struct board_port_range *analog = &board_ports[BOARD_PORT_ANALOG_IN];
    uint32_t bits;
    unsigned n;
    int32_t v;
    for (n = 0; n < sizeof in->analog; n++)
        in->analog[n] = 0;
    in->bio = 0;
    in->binin = 0;
    in->valid = 0;
    if (pdl_bind_uses(PDL_ANALOG_IN)) {
        for (n = analog->first; n <= analog->last && n < sizeof in->analog; n++) {
            if (board_port_read(BOARD_PORT_ANALOG_IN, n, &v) == 0) {
                in->analog[n] = (uint8_t)v;
                in->valid |= 1ul << n;
            }
        }
    }
    if (pdl_bind_uses(PDL_BIO_IN) && pdl_read_bits(BOARD_PORT_BINARY_IO, &bits)) {
        in->bio = (uint16_t)bits;
        in->valid |= PDL_VALID_BIO0 | PDL_VALID_BIO1;
    }
    if (pdl_bind_uses(PDL_BINARY_IN) && pdl_read_bits(BOARD_PORT_BINARY_IN, &bits)) {
        in->binin = (uint8_t)bits;
        in->valid |= PDL_VALID_BININ;
    }
}

/* Index and value are in the port's range (pdl_bind.c checked and clipped). */
int pdl_platform_write(enum pdl_port port, unsigned index, int32_t v)
{
    int kind = pdl_port_kind(port);
    if (kind < 0)
        return PDL_ERR_DRIVER;
    return board_port_write((enum board_port_kind)kind, index, v);
}

int pdl_platform_start_ports(void)
{
    int port, r;
    for (port = 1; port < (int)PDL_PORT_END; port++) {
        if (!pdl_bind_uses((enum pdl_port)port))
            continue;
        r = board_port_start((enum board_port_kind)pdl_port_kind((enum pdl_port)port));
        if (r < 0) {
            pdl_stats.last_driver_code = r;
            return pdl_refuse(PDL_ERR_DRIVER, "run_pdl: board_port_start");
        }
    }
    return PDL_OK;
}
