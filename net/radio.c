/* The radio driver on the board's radio channel; see radio.h. */
#include "radio.h"
#include "boards/include/board_radio.h"

#define RADIO_PAD   0x55u

static struct k_event *radio_ev;
static uint32_t radio_rx_bit, radio_tx_bit;
static struct frame_rx radio_rx;
static struct frame radio_ring[RADIO_RX_FRAMES];
static volatile uint8_t radio_ring_head, radio_ring_count;
static struct frame radio_scratch;
static uint8_t radio_tx_buf[RADIO_TX_MAX];
static volatile size_t radio_tx_len, radio_tx_pos;
static volatile uint8_t radio_tx_on;
static uint8_t radio_tx_heard_carrier;
static struct radio_stats radio_stats;
/* With FEC the ring holds undecoded codewords (fec.h). */
static uint8_t radio_fec_on;
static struct fec_rx radio_fec_rx;
static struct fec_raw radio_raw_ring[RADIO_RX_FRAMES];
static struct fec_raw radio_raw_scratch;
static struct fec_raw radio_raw_taken;

int radio_carrier(void)
{
    return board_radio_carrier();
}

/* The next free ring slot, or the scratch slot when the ring is full. */
static int radio_rx_complete(uint8_t b)
{
    int full = radio_ring_count >= RADIO_RX_FRAMES;
    unsigned at = (radio_ring_head + radio_ring_count) % RADIO_RX_FRAMES;
    if (radio_fec_on)
        return fec_rx_byte(&radio_fec_rx, b, full ? &radio_raw_scratch : &radio_raw_ring[at]);
    return frame_rx_byte(&radio_rx, b, full ? &radio_scratch : &radio_ring[at]);
}

/* In the channel's receive interrupt: one character. */
static void radio_rx_char(uint8_t b, int overrun)
{
    if (overrun)
        radio_stats.rx_overruns++;
    if (radio_rx_complete(b)) {
        if (radio_ring_count >= RADIO_RX_FRAMES) {
            radio_stats.rx_ring_full++;
        } else {
            radio_ring_count++;
            (void)k_event_set(radio_ev, radio_rx_bit);
        }
    }
}

/* In the channel's transmit interrupt: the next character, or -1 once the
 * pad is in the shift register (the closing flag has left: the frame is out). */
static int radio_tx_char(void)
{
    if (radio_carrier())
        radio_tx_heard_carrier = 1;
    if (radio_tx_pos < radio_tx_len)
        return radio_tx_buf[radio_tx_pos++];
    if (radio_tx_heard_carrier)
        radio_stats.collisions++;
    radio_tx_on = 0;
    (void)k_event_set(radio_ev, radio_tx_bit);
    return -1;
}

uint32_t radio_baud(void)
{
    return board_radio_baud();
}

int radio_init(struct k_event *ev, uint32_t rx_bit, uint32_t tx_bit, int fec)
{
    radio_ev = ev;
    radio_fec_on = fec != 0;
    fec_rx_init(&radio_fec_rx);
    radio_rx_bit = rx_bit;
    radio_tx_bit = tx_bit;
    frame_rx_init(&radio_rx);
    radio_ring_head = radio_ring_count = 0;
    radio_tx_on = 0;
    if (board_radio_start(radio_rx_char, radio_tx_char) != 0)
        return K_EINVAL;
    return K_OK;
}

int radio_tx_busy(void)
{
    return radio_tx_on;
}

int radio_transmit(const uint8_t *bytes, size_t len)
{
    size_t i;
    if (len == 0u || len + 1u > RADIO_TX_MAX)
        return K_EINVAL;
    if (radio_tx_on)
        return K_EBUSY;
    for (i = 0; i < len; i++)
        radio_tx_buf[i] = bytes[i];
    radio_tx_buf[len] = RADIO_PAD;
    radio_tx_len = len + 1u;
    radio_tx_pos = 0;
    radio_tx_heard_carrier = 0;
    radio_tx_on = 1;
    board_radio_transmit();     /* half duplex: the receiver is off meanwhile */
    return K_OK;
}

int radio_receive(struct frame *out)
{
    uint32_t irq;
    for (;;) {
        if (radio_ring_count == 0u)
            return 0;
        if (radio_fec_on)
            radio_raw_taken = radio_raw_ring[radio_ring_head];
        else
            *out = radio_ring[radio_ring_head];
        irq = k_arch_irq_save();
        radio_ring_head = (uint8_t)((radio_ring_head + 1u) % RADIO_RX_FRAMES);
        radio_ring_count--;
        k_arch_irq_restore(irq);
        /* Correction takes far longer than a character: here, not in the ISR. */
        if (!radio_fec_on || fec_frame_decode(&radio_raw_taken, out, &radio_stats.fec))
            return 1;
    }
}

void radio_stats_get(struct radio_stats *out, struct frame_rx_stats *framing)
{
    uint32_t irq = k_arch_irq_save();
    *out = radio_stats;
    out->fec_bad_count = radio_fec_rx.stats.bad_count;
    *framing = radio_rx.stats;
    if (radio_fec_on) {
        framing->bytes = radio_fec_rx.stats.bytes;
        framing->frames = radio_stats.fec.frames;
        framing->crc_errors = radio_stats.fec.bad_frames;
    }
    k_arch_irq_restore(irq);
}
