/*
 * Binding table: which quantity is which port of the board. A program binds
 * a quantity to a port in one line (pdl_bind_sensor / pdl_bind_actuator, or
 * a whole pdl_binding table); every cycle the runtime copies the board's
 * inputs into the sensor quantities (from one snapshot, so all sensors of a
 * cycle are from the same instant) and writes each actuator quantity whose
 * value changed to its driver (writes over I2C cost ~0.3 ms each, so
 * unchanged values are not rewritten). An input the drivers failed to read
 * (the snapshot's valid bits) leaves its sensor quantities unchanged.
 *
 * The ports themselves are the platform's (pdl_board.c with pdl/ports/: the
 * board's drivers or its own port access; host/pdl_host.c: arrays a test or
 * a simulator fills and reads).
 */
#include "pdl/pdl_internal.h"
#include "boards/include/board_ports.h"

/* Every PDL port is a kind of the board's port table
 * (boards/include/board_ports.h) in one direction: its numbers and value
 * range are that kind's on the board the runtime is built for. */
struct pdl_port_info {
    uint8_t kind;       /* enum board_port_kind */
    uint8_t output;
};

static const struct pdl_port_info pdl_port_table[PDL_PORT_END] = {
    [PDL_ANALOG_IN]  = {BOARD_PORT_ANALOG_IN, 0},
    [PDL_BINARY_IN]  = {BOARD_PORT_BINARY_IN, 0},
    [PDL_BIO_IN]     = {BOARD_PORT_BINARY_IO, 0},
    [PDL_MOTOR]      = {BOARD_PORT_MOTOR, 1},
    [PDL_ANALOG_OUT] = {BOARD_PORT_ANALOG_OUT, 1},
    [PDL_BIO_OUT]    = {BOARD_PORT_BINARY_IO, 1},
    [PDL_FAST_OUT]   = {BOARD_PORT_FAST_OUT, 1},
    [PDL_PWM]        = {BOARD_PORT_PWM, 1},
    [PDL_LED]        = {BOARD_PORT_LED, 1},
};

int pdl_port_kind(enum pdl_port port)
{
    return (int)port > 0 && port < PDL_PORT_END ? pdl_port_table[port].kind : -1;
}

struct pdl_bound {
    struct pdl_head *q;
    uint8_t port;       /* enum pdl_port */
    uint8_t index;
    uint8_t written_valid;
    uint8_t failed;     /* a driver refused a write (reported once) */
    int32_t written;    /* last value written (actuators) */
};

static struct pdl_bound pdl_bindings[PDL_MAX_BINDINGS];
static unsigned pdl_nbindings;
static unsigned pdl_nsensor_bindings;

int pdl_port_check(enum pdl_port port, unsigned index, int output)
{
    const struct board_port_range *range;
    if ((int)port <= 0 || port >= PDL_PORT_END)
        return PDL_ERR_PORT;
    range = &board_ports[pdl_port_table[port].kind];
    if (index < range->first || index > range->last || (int)pdl_port_table[port].output != (output != 0))
        return PDL_ERR_PORT;
    return PDL_OK;
}

void pdl_bind_reset(void)
{
    pdl_nbindings = 0;
    pdl_nsensor_bindings = 0;
}

static int pdl_is_declared(const struct pdl_head *h, enum pdl_kind kind)
{
    return h->id != 0u && h->kind == (uint8_t)kind;
}

/* Whether h may be bound to port/index: PDL_OK or the refusal's code (not
 * yet counted). `pending` lines of a table being checked count as bound. */
static int pdl_bind_check(const struct pdl_head *h, enum pdl_port port, unsigned index,
                          int output, const struct pdl_binding *pending, size_t npending)
{
    unsigned i;
    size_t k;
    if (h == NULL)
        return PDL_ERR_NULL;
    if (pdl_core_started())
        return PDL_ERR_RUNNING;
    if (!pdl_is_declared(h, output ? PDL_KIND_INT : PDL_KIND_SENSOR))
        return PDL_ERR_UNDECLARED;
    if (pdl_port_check(port, index, output) != PDL_OK)
        return PDL_ERR_PORT;
    for (i = 0; i < pdl_nbindings; i++) {
        const struct pdl_bound *b = &pdl_bindings[i];
        if (!output && b->q == h)
            return PDL_ERR_TWICE;   /* a sensor has one source */
        if (output && b->port == (uint8_t)port && b->index == index)
            return PDL_ERR_PORT_TAKEN;
    }
    /* input and output ports are disjoint, so an earlier line on the same
     * port and index is an output as well */
    for (k = 0; k < npending; k++) {
        if (!output && pending[k].q == h)
            return PDL_ERR_TWICE;
        if (output && pending[k].port == port && pending[k].index == index)
            return PDL_ERR_PORT_TAKEN;
    }
    return PDL_OK;
}

/* Binds a line pdl_bind_check accepted, with room in the table. */
static void pdl_bind_add(struct pdl_head *h, enum pdl_port port, unsigned index, int output)
{
    unsigned i;
    /* sensors first, so the refresh walks a prefix of the table */
    if (!output) {
        pdl_bindings[pdl_nbindings] = pdl_bindings[pdl_nsensor_bindings];
        i = pdl_nsensor_bindings++;
    } else {
        i = pdl_nbindings;
    }
    pdl_nbindings++;
    pdl_bindings[i] = (struct pdl_bound){.q = h, .port = (uint8_t)port, .index = (uint8_t)index};
}

static int pdl_bind(struct pdl_head *h, enum pdl_port port, unsigned index, int output,
                    const char *fn)
{
    int r = pdl_bind_check(h, port, index, output, NULL, 0);
    if (r != PDL_OK)
        return pdl_refuse(r, fn);
    if (pdl_nbindings >= PDL_MAX_BINDINGS)
        return pdl_refuse(PDL_ERR_TOO_MANY_BINDINGS, fn);
    pdl_bind_add(h, port, index, output);
    return PDL_OK;
}

int pdl_bind_sensor(struct pdl_sensor *q, enum pdl_port port, unsigned index)
{
    return pdl_bind(q == NULL ? NULL : &q->head, port, index, 0, "pdl_bind_sensor");
}

int pdl_bind_actuator(struct pdl_quantity *q, enum pdl_port port, unsigned index)
{
    return pdl_bind(q == NULL ? NULL : &q->head, port, index, 1, "pdl_bind_actuator");
}

/* prefix, n in decimal, suffix into buf (the board has no snprintf here). */
static void pdl_line_message(char *buf, size_t size, const char *prefix, size_t n,
                             const char *suffix)
{
    char digits[20];
    size_t k = 0, len = 0;
    do {
        digits[k++] = (char)('0' + n % 10u);
        n /= 10u;
    } while (n != 0u && k < sizeof digits);
    while (*prefix != '\0' && len + 1u < size)
        buf[len++] = *prefix++;
    while (k > 0u && len + 1u < size)
        buf[len++] = digits[--k];
    while (*suffix != '\0' && len + 1u < size)
        buf[len++] = *suffix++;
    buf[len] = '\0';
}

/* A table's line direction: by what its quantity was declared as. */
static int pdl_line_output(const struct pdl_binding *line)
{
    return line->q != NULL && line->q->kind == PDL_KIND_INT;
}

/* All or nothing: every line is checked (against the bindings made before
 * and the table's earlier lines) before the first is bound, so a refused
 * table leaves no binding that would read a port or drive an actuator. */
int pdl_bind_table(const struct pdl_binding *table, size_t count)
{
    static char what[48];
    size_t i;
    int r = PDL_OK;
    if (table == NULL)
        return pdl_refuse(PDL_ERR_NULL, "pdl_bind_table");
    for (i = 0; i < count && r == PDL_OK; i++)
        r = pdl_bind_check(table[i].q, table[i].port, table[i].index,
                           pdl_line_output(&table[i]), table, i);
    if (r != PDL_OK) {      /* line i (from 1) was refused */
        pdl_line_message(what, sizeof what, "pdl_bind_table: line ", i, ", none bound");
        return pdl_refuse(r, what);
    }
    if (count > PDL_MAX_BINDINGS - pdl_nbindings)
        return pdl_refuse(PDL_ERR_TOO_MANY_BINDINGS, "pdl_bind_table (none bound)");
    for (i = 0; i < count; i++)
        pdl_bind_add(table[i].q, table[i].port, table[i].index, pdl_line_output(&table[i]));
    return PDL_OK;
}

int pdl_bind_uses(enum pdl_port port)
{
    unsigned i;
    for (i = 0; i < pdl_nbindings; i++)
        if (pdl_bindings[i].port == (uint8_t)port)
            return 1;
    return 0;
}

static int32_t pdl_clip(int32_t v, int32_t lo, int32_t hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

static uint32_t pdl_valid_bit(uint8_t port, uint8_t index)
{
    switch (port) {
    case PDL_ANALOG_IN: return 1ul << index;
    case PDL_BINARY_IN: return PDL_VALID_BININ;
    default:            return index < 8u ? PDL_VALID_BIO0 : PDL_VALID_BIO1;
    }
}

static int32_t pdl_input_of(const struct pdl_inputs *in, uint8_t port, uint8_t index)
{
    switch (port) {
    case PDL_ANALOG_IN: return in->analog[index];
    case PDL_BINARY_IN: return (in->binin >> index) & 1;
    default:            return (in->bio >> index) & 1;      /* PDL_BIO_IN */
    }
}

void pdl_bind_refresh_sensors(void)
{
    struct pdl_inputs in;
    unsigned i;
    if (pdl_nsensor_bindings == 0u)
        return;
    pdl_platform_read_inputs(&in);
    for (i = 0; i < pdl_nsensor_bindings; i++) {
        const struct pdl_bound *b = &pdl_bindings[i];
        struct pdl_sensor *s = (struct pdl_sensor *)(void *)b->q;
        /* a value the drivers could not read keeps the sensor's last value */
        if (in.valid & pdl_valid_bit(b->port, b->index))
            s->cur = pdl_clip(pdl_input_of(&in, b->port, b->index), s->min, s->max);
    }
}

void pdl_bind_write_actuators(int force)
{
    unsigned i;
    for (i = pdl_nsensor_bindings; i < pdl_nbindings; i++) {
        struct pdl_bound *b = &pdl_bindings[i];
        const struct board_port_range *range = &board_ports[pdl_port_table[b->port].kind];
        int32_t v = pdl_clip(((const struct pdl_quantity *)(void *)b->q)->cur, range->min, range->max);
        int r;
        if (!force && b->written_valid && v == b->written)
            continue;
        r = pdl_platform_write((enum pdl_port)b->port, b->index, v);
        if (r < 0) {
            pdl_stats.driver_errors++;
            if (!b->failed) {
                b->failed = 1;
                pdl_stats.last_error = PDL_ERR_DRIVER;
                pdl_stats.last_driver_code = r;
                pdl_platform_report(PDL_ERR_DRIVER, "actuator write (first failure of this output)");
            }
            b->written_valid = 0;   /* try again next cycle */
            continue;
        }
        b->written = v;
        b->written_valid = 1;
    }
}
