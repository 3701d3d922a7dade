/*
 * Board I/O bring-up and the boot report (see board_io.h).
 */
#include "drivers/board_io.h"

#include "drivers/analog.h"
#include "drivers/bio.h"
#include "drivers/binin.h"
#include "drivers/drv_err.h"
#include "drivers/fastout.h"
#include "drivers/i2c.h"
#include "kernel.h"

#define BOARD_IO_SCAN_MAX 16u

/* "i2c A: 6 devices: 0x38 0x39 ..." (or the error). */
static int report_bus(unsigned bus)
{
    uint8_t found[BOARD_IO_SCAN_MAX];
    int n = i2c_scan(bus, found, BOARD_IO_SCAN_MAX);
    char name = (char)('A' + bus);
    if (n < 0) {
        k_printf("i2c %c: scan failed: %s\n", name, drv_strerror(n));
        return n;
    }
    k_printf("i2c %c: %d device%s", name, n, n == 1 ? "" : "s");
    for (int i = 0; i < n && (unsigned)i < BOARD_IO_SCAN_MAX; i++)
        k_printf(" 0x%02x", found[i]);
    k_printf("\n");
    return DRV_OK;
}

int board_io_init(void)
{
    int first_err = DRV_OK, n;

    (void)fastout_write_all(0);
    (void)binin_init();
    for (unsigned bus = 0; bus < I2C_BUS_COUNT; bus++) {
        int rc = i2c_init(bus);
        if (rc == DRV_OK)
            rc = report_bus(bus);
        else
            k_printf("i2c %c: controller: %s\n", (char)('A' + bus), drv_strerror(rc));
        if (rc != DRV_OK && first_err == DRV_OK)
            first_err = rc;
    }
    n = analog_init();
    if (n < 0) {
        k_printf("analog: %s\n", drv_strerror(n));
    } else {
        k_printf("analog: %d PCF8591 (%d inputs, %d outputs)\n", n, 4 * n, n);
    }
    n = bio_init();
    if (n < 0) {
        k_printf("bio: %s\n", drv_strerror(n));
    } else {
        k_printf("bio: %d PCF8574A (%d lines)\n", n, 8 * n);
    }
    return first_err;
}
