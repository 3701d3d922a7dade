/*
 * drivers/analog.c on the host against a fake I2C layer: CubeOS numbering of
 * the PCF8591 chips found (bus A 0x48..0x4F, then bus B), the chip read
 * (control byte, 5 bytes, the first dropped), output control byte, and the
 * channel and range checks (which must not touch the bus).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "drivers/analog.h"
#include "drivers/drv_err.h"
#include "drivers/i2c.h"

/* present[bus][addr7] */
static uint8_t present[I2C_BUS_COUNT][128];
static unsigned transfers;
static uint8_t last_wr[8];
static size_t last_wr_len, last_rd_len;
static unsigned last_bus;
static uint8_t last_addr;
static int fail_with;

int i2c_probe(unsigned bus, uint8_t addr7)
{
    return present[bus][addr7] ? DRV_OK : DRV_ERR_ABSENT;
}

int i2c_transfer(unsigned bus, uint8_t addr7, const uint8_t *wr, size_t wr_len,
                 uint8_t *rd, size_t rd_len)
{
    transfers++;
    last_bus = bus;
    last_addr = addr7;
    last_wr_len = wr_len;
    last_rd_len = rd_len;
    if (wr_len > 0)
        memcpy(last_wr, wr, wr_len);
    if (fail_with)
        return fail_with;
    if (!present[bus][addr7])
        return DRV_ERR_ABSENT;
    for (size_t i = 0; i < rd_len; i++)
        rd[i] = (uint8_t)(addr7 + 16u * i);   /* byte 0 = the stale conversion */
    return DRV_OK;
}

static int setup(void **state)
{
    (void)state;
    memset(present, 0, sizeof present);
    transfers = 0;
    fail_with = 0;
    return 0;
}

static void test_six_chips_on_bus_a(void **state)
{
    (void)state;
    for (uint8_t a = 0x48; a <= 0x4D; a++)
        present[I2C_BUS_A][a] = 1;
    assert_int_equal(analog_init(), 6);
    for (unsigned c = 0; c < 6; c++)
        assert_int_equal(analog_chip_present(c), 1);
    assert_int_equal(analog_read(0), 0x48 + 16);       /* chip 0, AIN0 = read byte 1 */
    assert_int_equal(last_addr, 0x48);
    assert_int_equal(last_wr_len, 1);
    assert_int_equal(last_wr[0], 0x04);                 /* auto-increment from AIN0, single-ended */
    assert_int_equal(last_rd_len, ANALOG_CHIP_READ_LEN);
    assert_int_equal(analog_read(23), 0x4D + 64);       /* chip 5, AIN3 = byte 4 */
}

static void test_numbering_skips_gaps_and_continues_on_bus_b(void **state)
{
    (void)state;
    present[I2C_BUS_A][0x49] = 1;
    present[I2C_BUS_A][0x4F] = 1;
    present[I2C_BUS_B][0x48] = 1;
    present[I2C_BUS_B][0x4F] = 1;                       /* bus B probes only up to 0x4E */
    assert_int_equal(analog_init(), 3);
    assert_int_equal(analog_read(0), 0x49 + 16);
    assert_int_equal(analog_read(5), 0x4F + 32);        /* chip 1 = 0x4F on bus A */
    assert_int_equal(analog_read(8), 0x48 + 16);        /* chip 2 = 0x48 on bus B */
    assert_int_equal(last_bus, I2C_BUS_B);
    assert_int_equal(analog_chip_present(3), 0);
    transfers = 0;
    assert_int_equal(analog_read(12), DRV_ERR_ABSENT);  /* chip 3 not found: no bus access */
    assert_int_equal(analog_write(3, 1), DRV_ERR_ABSENT);
    assert_int_equal(transfers, 0);
}

static void test_bad_channels_and_values_do_not_touch_the_bus(void **state)
{
    (void)state;
    for (uint8_t a = 0x48; a <= 0x4D; a++)
        present[I2C_BUS_A][a] = 1;
    assert_int_equal(analog_init(), 6);
    transfers = 0;
    assert_int_equal(analog_read(24), DRV_ERR_CHANNEL);
    assert_int_equal(analog_read(1000), DRV_ERR_CHANNEL);
    assert_int_equal(analog_write(6, 0), DRV_ERR_CHANNEL);
    assert_int_equal(analog_write(0, 256), DRV_ERR_RANGE);
    assert_int_equal(analog_write(0, -1), DRV_ERR_RANGE);
    assert_int_equal(analog_chip_present(6), DRV_ERR_CHANNEL);
    assert_int_equal(transfers, 0);
}

static void test_write_enables_the_output_and_later_reads_keep_it(void **state)
{
    (void)state;
    for (uint8_t a = 0x48; a <= 0x4D; a++)
        present[I2C_BUS_A][a] = 1;
    assert_int_equal(analog_init(), 6);
    assert_int_equal(analog_write(2, 200), DRV_OK);
    assert_int_equal(last_addr, 0x4A);
    assert_int_equal(last_wr_len, 2);
    assert_int_equal(last_wr[0], 0x44);                 /* output enable + auto-increment */
    assert_int_equal(last_wr[1], 200);
    assert_int_equal(analog_read(9), 0x4A + 32);
    assert_int_equal(last_wr[0], 0x44);                 /* a read must not switch the DAC off */
    assert_int_equal(analog_read(0), 0x48 + 16);
    assert_int_equal(last_wr[0], 0x04);                 /* other chips' outputs stay off */
}

static void test_bus_errors_are_passed_on(void **state)
{
    (void)state;
    present[I2C_BUS_A][0x48] = 1;
    assert_int_equal(analog_init(), 1);
    fail_with = DRV_ERR_TIMEOUT;
    assert_int_equal(analog_read(1), DRV_ERR_TIMEOUT);
    assert_int_equal(analog_write(0, 5), DRV_ERR_TIMEOUT);
    fail_with = DRV_ERR_ABSENT;
    assert_int_equal(analog_read(1), DRV_ERR_ABSENT);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup(test_six_chips_on_bus_a, setup),
        cmocka_unit_test_setup(test_numbering_skips_gaps_and_continues_on_bus_b, setup),
        cmocka_unit_test_setup(test_bad_channels_and_values_do_not_touch_the_bus, setup),
        cmocka_unit_test_setup(test_write_enables_the_output_and_later_reads_keep_it, setup),
        cmocka_unit_test_setup(test_bus_errors_are_passed_on, setup),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
