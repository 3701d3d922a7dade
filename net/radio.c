/* BiM-433 radio driver on DUART channel A; see radio.h. */
#include "radio.h"
#include "boards/robocube/duart.h"
#include "boards/robocube/duart_console.h"
#include "boards/robocube/mc68681.h"

#define RADIO_OP_RX 0x01u     /* OP0 */
#define RADIO_OP_TX 0x02u     /* OP1 */
#define RADIO_IP_CD 0x01u     /* IP0, low while a carrier is heard */
#define RADIO_PAD   0x55u
#define RADIO_CT_PRELOAD 6u   /* counter/timer: 3.6864 MHz / (2 x 6) = 16 x 19200 */

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
static uint32_t radio_baud_rate;

int radio_carrier(void)
{
    return (DUART_REG(DUART_IP) & RADIO_IP_CD) == 0u;
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

static void radio_rx_chars(void)
{
    uint8_t sr;
    while (((sr = DUART_REG(DUART_SRA)) & DUART_SR_RXRDY) != 0u) {
        uint8_t b = DUART_REG(DUART_RBA);
        if ((sr & DUART_SR_OVERRUN) != 0u) {
            radio_stats.rx_overruns++;
            DUART_REG(DUART_CRA) = DUART_CR_RESET_ERROR;
        }
        if (radio_rx_complete(b)) {
            if (radio_ring_count >= RADIO_RX_FRAMES) {
                radio_stats.rx_ring_full++;
            } else {
                radio_ring_count++;
                (void)k_event_set(radio_ev, radio_rx_bit);
            }
        }
    }
}

static void radio_tx_chars(void)
{
    while ((DUART_REG(DUART_SRA) & DUART_SR_TXRDY) != 0u) {
        if (radio_carrier())
            radio_tx_heard_carrier = 1;
        if (radio_tx_pos < radio_tx_len) {
            DUART_REG(DUART_TBA) = radio_tx_buf[radio_tx_pos++];
            continue;
        }
        /* The pad is in the shift register: the frame is out. Back to receive. */
        duart_imr_update(0, DUART_INT_TXRDYA);
        duart_op_negate(RADIO_OP_TX);
        duart_op_assert(RADIO_OP_RX);
        if (radio_tx_heard_carrier)
            radio_stats.collisions++;
        radio_tx_on = 0;
        (void)k_event_set(radio_ev, radio_tx_bit);
        break;
    }
}

static void radio_isr(uint8_t pending, void *arg)
{
    (void)arg;
    if ((pending & DUART_INT_RXRDYA) != 0u)
        radio_rx_chars();
    if ((pending & DUART_INT_TXRDYA) != 0u)
        radio_tx_chars();
}

/* 19200 baud (the radio's default, net/README.md) for channel A: baud-rate set 2 has it
 * (code 0xC) when the console chose set 2; set 1 has not, so then the
 * counter/timer clocks channel A (CSR code 0xD, preload 6: X1 / 12 =
 * 16 x 19200). Only if the counter/timer is taken as well, 9600 from set 1. */
static uint8_t radio_csr(void)
{
    radio_baud_rate = 19200u;
    if ((console_acr() & 0x80u) != 0u)
        return 0xCCu;
    if (duart_ct_baud_clock(RADIO_CT_PRELOAD) == 0)
        return 0xDDu;
    radio_baud_rate = 9600u;
    return 0xBBu;
}

uint32_t radio_baud(void)
{
    return radio_baud_rate;
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
    DUART_REG(DUART_CRA) = DUART_CR_RESET_RX | DUART_CR_RX_DISABLE | DUART_CR_TX_DISABLE;
    DUART_REG(DUART_CRA) = DUART_CR_RESET_TX | DUART_CR_RX_DISABLE | DUART_CR_TX_DISABLE;
    DUART_REG(DUART_CRA) = DUART_CR_RESET_ERROR;
    DUART_REG(DUART_CRA) = DUART_CR_RESET_MR;
    DUART_REG(DUART_MRA) = 0x13u;       /* 8 data bits, no parity, RxRDY interrupt */
    DUART_REG(DUART_MRA) = 0x07u;       /* normal mode, 1 stop bit */
    DUART_REG(DUART_CSRA) = radio_csr();
    DUART_REG(DUART_CRA) = DUART_CR_RX_ENABLE | DUART_CR_TX_ENABLE;
    duart_op_negate(RADIO_OP_TX);
    duart_op_assert(RADIO_OP_RX);
    if (duart_irq_attach(DUART_INT_RXRDYA | DUART_INT_TXRDYA, radio_isr, NULL) != 0)
        return K_EINVAL;
    duart_imr_update(DUART_INT_RXRDYA, 0);
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
    /* Half duplex: the receiver is off while we transmit. */
    duart_op_negate(RADIO_OP_RX);
    duart_op_assert(RADIO_OP_TX);
    duart_imr_update(DUART_INT_TXRDYA, 0);
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
