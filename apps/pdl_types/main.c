/*
 * One quantity of each type (int8, int16, int32, uint8, uint16, float), fed
 * by processes with pseudo-random contributions, small and far past the
 * bounds, so that each cycle sums, clips and saturates. A recorder process
 * logs the values every process sees (the previous cycle's) for LOG_CYCLES
 * cycles; main then prints one line per cycle:
 *   TYPES cycle i8 i16 i32 u8 u16 float-bits
 * The same file runs on the board and on the host runtime; the two outputs
 * must be equal (pdl/tests/target/test_pdl_types.py): the runtimes have the
 * same semantics.
 */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "pdl/pdl.h"

#define LOG_CYCLES 1000u

static struct pdl_quantity_int8 q_i8;
static struct pdl_quantity_int16 q_i16;
static struct pdl_quantity q_i32;
static struct pdl_quantity_uint8 q_u8;
static struct pdl_quantity_uint16 q_u16;
static struct pdl_fquantity q_f;

static int8_t log_i8[LOG_CYCLES];
static int16_t log_i16[LOG_CYCLES];
static int32_t log_i32[LOG_CYCLES];
static uint8_t log_u8[LOG_CYCLES];
static uint16_t log_u16[LOG_CYCLES];
static float log_f[LOG_CYCLES];
static volatile uint32_t logged;

static uint32_t rng = 0x9E3779B9u;

/* xorshift32: the same sequence on both runtimes */
static int32_t next_random(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 17;
    rng ^= rng << 5;
    return (int32_t)(rng & 0xFFFFu) - 0x8000;       /* -32768..32767 */
}

static void recorder(void)
{
    uint32_t k = logged;
    if (k < LOG_CYCLES) {
        log_i8[k] = value(q_i8);
        log_i16[k] = value(q_i16);
        log_i32[k] = value(q_i32);
        log_u8[k] = value(q_u8);
        log_u16[k] = value(q_u16);
        log_f[k] = value(q_f);
        logged = k + 1u;
    }
}

/* Small steps, mostly: drifts to the bounds and back. */
static void drift(void)
{
    int32_t r = next_random();
    add_value(q_i8, r / 512);
    add_value(q_i16, r / 4);
    add_value(q_i32, r * 4096);
    add_value(q_u8, r / 256);
    add_value(q_u16, r);
    add_value(q_f, (float)r * 0.001f - value(q_f) * 0.125f);
}

/* Every fourth cycle a kick far past every bound, either way. */
static void kick(void)
{
    int64_t big = next_random() < 0 ? -(INT64_C(1) << 40) : (INT64_C(1) << 40);
    add_value(q_i8, big);
    add_value(q_i16, big);
    add_value(q_i32, big);
    add_value(q_u8, big);
    add_value(q_u16, big);
    add_value(q_f, (float)big);
}

/* A pull back toward the middle that the same cycle's kick may override. */
static void pull(void)
{
    add_value(q_i8, -value(q_i8) / 2);
    add_value(q_i16, -value(q_i16) / 2);
    add_value(q_i32, -value(q_i32) / 2);
    add_value(q_u8, (128 - value(q_u8)) / 2);
    add_value(q_u16, (32768 - value(q_u16)) / 2);
    add_value(q_f, -value(q_f) * 0.5f);
}

int main(void)
{
    uint32_t k, bits;
    int r;

    add_quantity_int8(&q_i8, INT8_MIN, INT8_MAX, 0);
    add_quantity_int16(&q_i16, -20000, 20000, 0);
    add_quantity(&q_i32, INT32_MIN, INT32_MAX, 0);
    add_quantity_uint8(&q_u8, 0, UINT8_MAX, 100);
    add_quantity_uint16(&q_u16, 1000, UINT16_MAX, 1000);
    add_fquantity(&q_f, -1000.0f, 1000.0f, 0.5f);
    add_process(recorder);
    add_process(drift);
    add_process_pv(kick, 2);
    add_process_pv(pull, 3);
    r = pdl_set_frequency(512);
    if (r == PDL_OK)
        r = run_pdl();
    if (r != PDL_OK) {
        printf("TYPES failed: %s (%d)\n", pdl_strerror(r), r);
        return 1;
    }
    while (logged < LOG_CYCLES)
        (void)pdl_sleep_ms(100);
    for (k = 0; k < LOG_CYCLES; k++) {
        memcpy(&bits, &log_f[k], sizeof bits);
        printf("TYPES %lu %d %d %ld %u %u %08lx\n", (unsigned long)k, log_i8[k], log_i16[k],
               (long)log_i32[k], log_u8[k], log_u16[k], (unsigned long)bits);
    }
    printf("TYPES done\n");
    return 0;
}
