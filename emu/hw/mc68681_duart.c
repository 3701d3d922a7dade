/*
 * Motorola MC68681 DUART on the RoboCube board (0xFFE400, IRQ level 5,
 * vectored through IVR).  Channel A = radio link, channel B = console.
 *
 * Modelled: MR1/MR2 with the MR pointer, SR, CSR (stored; baud rates are not
 * timed: characters go out at once), CR commands (receiver/transmitter
 * enable/disable and reset, reset MR pointer, reset error status), the
 * 3-deep receive FIFO with overrun, local-loopback and auto-echo channel
 * modes, ISR/IMR, IVR, the input port (IP0 = radio carrier detect, IP1..IP5 =
 * binary inputs; IPCR change detection with the ACR enables), OPCR/OPR
 * set/reset, and the counter/timer (counter and timer modes from the X1
 * crystal or X1/16, ISR counter-ready, start/stop commands) in virtual time.
 * Host interface (QOM): "input-port" (read/write), "opr", "output-pins" and
 * "received-a"/"received-b" (characters taken from each chardev; read-only).
 *
 * Radio mode (property "radio-medium", off by default): channel A is the
 * BiM-433 module on a shared medium (emu/python/robocube_emu/radio_medium.py).  Its chardev then
 * carries 2-byte messages instead of raw characters (protocol in
 * emu/README.md, "Radio medium"), characters take their real duration at the
 * programmed baud rate in virtual time (transmit holding + shift register,
 * received characters paced one per character time), OP0/OP1 gate reception
 * and transmission (both = the module's loop-back test mode) and IP0 follows
 * the medium's carrier.
 */
#include "qemu/osdep.h"
#include "qemu/log.h"
#include "qemu/timer.h"
#include "qapi/error.h"
#include "qapi/visitor.h"
#include "hw/sysbus.h"
#include "hw/qdev-properties.h"
#include "hw/qdev-properties-system.h"
#include "chardev/char-fe.h"
#include "qom/object.h"
#include "robocube_board.h"
#include "robocube_io.h"

OBJECT_DECLARE_SIMPLE_TYPE(MC68681DuartState, MC68681_DUART)

#define DUART_LEVEL 5
#define RX_FIFO_DEPTH 3

/* SR bits */
#define SR_RXRDY 0x01
#define SR_FFULL 0x02
#define SR_TXRDY 0x04
#define SR_TXEMT 0x08
#define SR_OE    0x10

/* ISR bits (channel A; channel B = << 4 for TxRDY/RxRDY) */
#define ISR_TXRDYA  0x01
#define ISR_RXRDYA  0x02
#define ISR_CTR     0x08
#define ISR_TXRDYB  0x10
#define ISR_RXRDYB  0x20
#define ISR_IPCHG   0x80

/* Radio mode: messages on channel A's chardev (emu/README.md). */
#define RADIO_MSG_DATA    0x00  /* both ways: one character */
#define RADIO_MSG_CONTROL 0x01  /* board -> medium: bit 0 RX select, bit 1 TX select */
#define RADIO_MSG_CARRIER 0x01  /* medium -> board: 1 = someone transmits */
#define RADIO_MSG_HELLO   0x02  /* board -> medium: station number (radio-station) */
#define RADIO_MSG_SYNC    0x03  /* board -> medium: end of my time quantum; medium -> board: go on */
#define RADIO_OP_RX 0x01        /* OP0: receive select */
#define RADIO_OP_TX 0x02        /* OP1: transmit select */
#define RADIO_RXQ 1024          /* characters in flight towards the FIFO */
#define HOST_RXQ 1024           /* characters from the host waiting for the FIFO */

typedef struct RadioState {
    bool enabled;               /* property radio-medium */
    uint8_t station;            /* property radio-station, sent in HELLO */
    bool carrier;               /* the medium's carrier */
    uint8_t msg_type;           /* first byte of a message being received */
    bool msg_half;              /* msg_type holds a first byte */
    uint8_t rxq[RADIO_RXQ];     /* characters on their way to the FIFO */
    unsigned rxq_head, rxq_count;
    QEMUTimer *rx_timer;        /* next character reaches the FIFO */
    QEMUTimer *tx_timer;        /* the shift register finishes a character */
    bool tx_shifting;           /* a character is in the shift register */
    bool tx_holding;            /* and one waits in the holding register */
    uint8_t tx_hold;
    uint8_t tx_shift;           /* the character in the shift register */
    uint8_t last_control;       /* last CONTROL sent (0xFF: none yet) */
    uint64_t rx_dropped;        /* characters heard while RX select was off */
    uint32_t sync_ns;           /* property radio-sync-ns: lock-step quantum, 0 = off */
    QEMUTimer *sync_timer;
    bool sync_go;               /* the medium's go-on arrived */
    uint64_t sync_rounds;
} RadioState;

typedef struct DuartChannel {
    CharBackend chr;
    uint8_t mr1, mr2;
    bool mr_ptr_mr2;        /* false: next MR access hits MR1 */
    uint8_t csr;
    bool rx_enabled, tx_enabled;
    bool overrun;
    uint8_t rx_fifo[RX_FIFO_DEPTH];
    unsigned rx_count;
    /* Characters taken from the chardev that wait for room in the FIFO. Taking
     * a whole burst at once makes the guest see it at the same virtual times
     * however busy the host is (tests stop the VM, write, wait for
     * host_rx_taken, go on); from the chardev it comes in whenever the I/O
     * thread gets to it. */
    uint8_t hostq[HOST_RXQ];
    unsigned hostq_head, hostq_count;
    uint32_t host_rx_taken;     /* properties received-a, received-b (in radio
                                 * mode, received-a counts the medium's bytes) */
} DuartChannel;

struct MC68681DuartState {
    SysBusDevice parent_obj;

    MemoryRegion iomem;
    RoboCubeIntc *intc;
    DuartChannel ch[2];     /* 0 = A (radio), 1 = B (console) */

    uint8_t acr, imr, ivr, opcr, opr;
    uint8_t isr_latched;    /* counter-ready and input-port-change bits */
    uint8_t ip;             /* pin levels IP0..IP5 (bits 6,7 read as 1) */
    uint8_t ipcr_delta;     /* IPCR bits 7..4: change of IP3..IP0 since read */
    uint16_t ct_preload;    /* CTUR:CTLR */

    /* Counter/timer: runs from the X1 crystal (or X1/16), see ct_* below. */
    QEMUTimer *ct_timer;
    bool ct_running;        /* counter mode: between start and stop */
    bool ct_ready_latched;  /* ISR[3] known to be set */
    int64_t ct_origin_ns;   /* events are counted from here ... */
    uint32_t ct_origin_value;   /* ... where the count was this */
    int64_t ct_cleared_ns;  /* events up to here are consumed (ISR[3] cleared) */

    RadioState radio;       /* channel A in radio mode */
};

static MC68681DuartState *the_duart;

uint8_t robocube_duart_opr(void)
{
    return the_duart ? the_duart->opr : 0;
}

/* ---- interrupts ---------------------------------------------------------- */

static bool radio_channel(DuartChannel *c)
{
    return the_duart && the_duart->radio.enabled && c == &the_duart->ch[0];
}

static uint8_t channel_sr(DuartChannel *c)
{
    uint8_t sr = 0;

    if (c->rx_count) {
        sr |= SR_RXRDY;
    }
    if (c->rx_count == RX_FIFO_DEPTH) {
        sr |= SR_FFULL;
    }
    if (c->tx_enabled && radio_channel(c)) {
        /* Radio: characters take their time (holding + shift register). */
        RadioState *r = &the_duart->radio;
        if (!r->tx_holding) {
            sr |= SR_TXRDY;
        }
        if (!r->tx_shifting) {
            sr |= SR_TXEMT;
        }
    } else if (c->tx_enabled) {
        /* Transmission is instantaneous: holding and shift register empty. */
        sr |= SR_TXRDY | SR_TXEMT;
    }
    if (c->overrun) {
        sr |= SR_OE;
    }
    return sr;
}

static bool ct_ready(MC68681DuartState *s);
static uint32_t ct_clock_hz(MC68681DuartState *s);
static uint64_t ct_preload_cycles(MC68681DuartState *s);

static uint8_t duart_isr(MC68681DuartState *s)
{
    uint8_t isr = s->isr_latched;

    if (ct_ready(s)) {
        isr |= ISR_CTR;
    }
    int i;

    for (i = 0; i < 2; i++) {
        DuartChannel *c = &s->ch[i];
        uint8_t sr = channel_sr(c);
        /* MR1 bit 6 (RxIRQ select): 0 = RxRDY, 1 = FIFO full. */
        bool rx = (c->mr1 & 0x40) ? (sr & SR_FFULL) : (sr & SR_RXRDY);

        if (sr & SR_TXRDY) {
            isr |= i ? ISR_TXRDYB : ISR_TXRDYA;
        }
        if (rx) {
            isr |= i ? ISR_RXRDYB : ISR_RXRDYA;
        }
    }
    return isr;
}

static void duart_update_irq(MC68681DuartState *s)
{
    bool active = duart_isr(s) & s->imr;

    robocube_intc_request(s->intc, RC_IRQ_DUART, active ? DUART_LEVEL : 0, s->ivr);
}

/* ---- receive / transmit ------------------------------------------------ */

static void channel_push_rx(MC68681DuartState *s, DuartChannel *c, uint8_t byte)
{
    if (c->rx_count < RX_FIFO_DEPTH) {
        c->rx_fifo[c->rx_count++] = byte;
    } else {
        /* The shift register's character overwrites the last FIFO entry. */
        c->overrun = true;
        c->rx_fifo[RX_FIFO_DEPTH - 1] = byte;
    }
}

/* ---- radio mode (channel A on the shared medium) -------------------------- */

static void duart_set_ip(MC68681DuartState *s, uint8_t pins);

/* Baud rate of channel A's transmitter from CSRA and ACR bit 7 (baud-rate
 * set); 10 bits per character (start, 8 data, stop). Settings the model
 * cannot time (IP3/TxC clocks) count as 19200, the radio's usual rate. */
static uint32_t radio_baud(MC68681DuartState *s)
{
    static const uint32_t set1[13] = { 50, 110, 134, 200, 300, 600, 1200, 1050,
                                       2400, 4800, 7200, 9600, 38400 };
    static const uint32_t set2[13] = { 75, 110, 134, 150, 300, 600, 1200, 2000,
                                       2400, 4800, 1800, 9600, 19200 };
    unsigned code = s->ch[0].csr & 0x0F;

    if (code < 13) {
        return (s->acr & 0x80) ? set2[code] : set1[code];
    }
    if (code == 13 && ct_clock_hz(s)) {
        /* Counter/timer: square wave X1 / (2 preload), 16 clocks per bit. */
        uint64_t baud = ct_clock_hz(s) / (2 * ct_preload_cycles(s) * 16);
        return baud ? baud : 1;
    }
    return 19200;
}

static int64_t radio_char_ns(MC68681DuartState *s)
{
    return (int64_t)muldiv64(10, NANOSECONDS_PER_SECOND, radio_baud(s));
}

static void radio_send(MC68681DuartState *s, uint8_t type, uint8_t value)
{
    uint8_t msg[2] = { type, value };

    /* Never blocks: a stalled or dead medium loses the characters (as the
     * air would) instead of stopping the board. */
    if (qemu_chr_fe_backend_connected(&s->ch[0].chr)) {
        qemu_chr_fe_write(&s->ch[0].chr, msg, 2);
    }
}

static uint8_t radio_selects(MC68681DuartState *s)
{
    return s->opr & (RADIO_OP_RX | RADIO_OP_TX);
}

static bool radio_loopback(MC68681DuartState *s)
{
    return radio_selects(s) == (RADIO_OP_RX | RADIO_OP_TX);
}

/* IP0 (carrier detect, low = carrier) follows the medium's carrier and stays
 * low while received characters are still arriving. */
static void radio_update_carrier(MC68681DuartState *s)
{
    RadioState *r = &s->radio;
    bool carrier = r->carrier || r->rxq_count;
    uint8_t pins = carrier ? (s->ip & ~1) : (s->ip | 1);

    if (pins != s->ip) {
        duart_set_ip(s, pins);
    }
}

static void radio_send_control(MC68681DuartState *s)
{
    uint8_t ctl = radio_selects(s);

    if (s->radio.enabled && ctl != s->radio.last_control) {
        s->radio.last_control = ctl;
        radio_send(s, RADIO_MSG_CONTROL, ctl);
    }
}

static void radio_rx_enqueue(MC68681DuartState *s, uint8_t byte)
{
    RadioState *r = &s->radio;

    if (r->rxq_count == RADIO_RXQ) {
        r->rx_dropped++;
        return;
    }
    r->rxq[(r->rxq_head + r->rxq_count++) % RADIO_RXQ] = byte;
    if (!timer_pending(r->rx_timer)) {
        /* The character needs one character time to arrive. */
        timer_mod(r->rx_timer, qemu_clock_get_ns(QEMU_CLOCK_VIRTUAL) +
                  radio_char_ns(s));
    }
    radio_update_carrier(s);
}

static void radio_rx_tick(void *opaque)
{
    MC68681DuartState *s = opaque;
    RadioState *r = &s->radio;
    DuartChannel *c = &s->ch[0];

    if (r->rxq_count) {
        uint8_t byte = r->rxq[r->rxq_head];

        r->rxq_head = (r->rxq_head + 1) % RADIO_RXQ;
        r->rxq_count--;
        /* The module hears only with RX select on; the DUART only with its
         * receiver enabled (a full FIFO overruns, as on the chip). */
        if ((s->opr & RADIO_OP_RX) && c->rx_enabled) {
            channel_push_rx(s, c, byte);
        } else {
            r->rx_dropped++;
        }
    }
    if (r->rxq_count) {
        timer_mod(r->rx_timer, qemu_clock_get_ns(QEMU_CLOCK_VIRTUAL) +
                  radio_char_ns(s));
    }
    radio_update_carrier(s);
    duart_update_irq(s);
    qemu_chr_fe_accept_input(&c->chr);
}

/* A character enters the shift register; it reaches the air (or the own
 * receiver in loop-back) when its last bit has gone, one character time later,
 * provided the module is still keyed then. */
static void radio_shift_out(MC68681DuartState *s, uint8_t byte)
{
    RadioState *r = &s->radio;

    r->tx_shifting = true;
    r->tx_shift = byte;
    timer_mod(r->tx_timer, qemu_clock_get_ns(QEMU_CLOCK_VIRTUAL) + radio_char_ns(s));
}

static void radio_tx_tick(void *opaque)
{
    MC68681DuartState *s = opaque;
    RadioState *r = &s->radio;

    r->tx_shifting = false;
    if (radio_loopback(s)) {
        radio_rx_enqueue(s, r->tx_shift);   /* the module's test mode */
    } else if (s->opr & RADIO_OP_TX) {
        radio_send(s, RADIO_MSG_DATA, r->tx_shift);
    }
    /* TX select off: the module is not keyed, the character is lost. */
    if (r->tx_holding) {
        r->tx_holding = false;
        radio_shift_out(s, r->tx_hold);
    }
    duart_update_irq(s);
}

static void radio_transmit(MC68681DuartState *s, uint8_t byte)
{
    RadioState *r = &s->radio;

    if (!r->tx_shifting) {
        radio_shift_out(s, byte);
    } else if (!r->tx_holding) {
        r->tx_holding = true;
        r->tx_hold = byte;
    } else {
        /* Writing TB while TxRDY is off overwrites the holding register. */
        r->tx_hold = byte;
    }
}

static int radio_can_receive(MC68681DuartState *s)
{
    /* Messages are taken as long as the paced queue has room for them. */
    return 2 * (RADIO_RXQ - s->radio.rxq_count);
}

static void radio_receive(MC68681DuartState *s, const uint8_t *buf, int size)
{
    RadioState *r = &s->radio;
    int i;

    s->ch[0].host_rx_taken += (uint32_t)size;
    for (i = 0; i < size; i++) {
        if (!r->msg_half) {
            r->msg_type = buf[i];
            r->msg_half = true;
            continue;
        }
        r->msg_half = false;
        if (r->msg_type == RADIO_MSG_DATA) {
            /* Heard only with RX select on and not in loop-back mode. */
            if (radio_selects(s) == RADIO_OP_RX) {
                radio_rx_enqueue(s, buf[i]);
            } else {
                r->rx_dropped++;
            }
        } else if (r->msg_type == RADIO_MSG_CARRIER) {
            r->carrier = buf[i] != 0;
            radio_update_carrier(s);
        } else if (r->msg_type == RADIO_MSG_SYNC) {
            r->sync_go = true;
        } else {
            qemu_log_mask(LOG_GUEST_ERROR, "mc68681: radio medium sent message %u\n",
                          r->msg_type);
        }
    }
}

/*
 * Lock step (radio-sync-ns > 0, with -icount sleep=off): at the end of every
 * quantum of virtual time the board tells the medium and waits, reading the
 * socket synchronously, until the medium says go on, which it does once every
 * synchronised station has finished the same quantum. Characters sent in a
 * quantum reach the other boards before their next one, so all clocks advance
 * together whatever the host's load (emu/README.md, "Radio medium").
 */
static void radio_sync_tick(void *opaque)
{
    MC68681DuartState *s = opaque;
    RadioState *r = &s->radio;
    CharBackend *chr = &s->ch[0].chr;
    uint8_t byte;

    if (!qemu_chr_fe_backend_connected(chr)) {
        return;                             /* no medium: run free */
    }
    {
        uint8_t msg[2] = { RADIO_MSG_SYNC, 0 };
        if (qemu_chr_fe_write_all(chr, msg, 2) != 2) {
            return;                         /* the medium is gone: run free */
        }
    }
    r->sync_go = false;
    while (!r->sync_go) {
        if (qemu_chr_fe_read_all(chr, &byte, 1) != 1) {
            return;                         /* gone while we waited: run free */
        }
        radio_receive(s, &byte, 1);
    }
    r->sync_rounds++;
    duart_update_irq(s);
    timer_mod(r->sync_timer, qemu_clock_get_ns(QEMU_CLOCK_VIRTUAL) + r->sync_ns);
}

static void radio_event(void *opaque, QEMUChrEvent event)
{
    MC68681DuartState *s = opaque;

    if (event == CHR_EVENT_OPENED) {
        s->radio.msg_half = false;
        radio_send(s, RADIO_MSG_HELLO, s->radio.station);
        s->radio.last_control = 0xFF;
        radio_send_control(s);
        if (s->radio.sync_ns && !timer_pending(s->radio.sync_timer)) {
            timer_mod(s->radio.sync_timer,
                      qemu_clock_get_ns(QEMU_CLOCK_VIRTUAL) + s->radio.sync_ns);
        }
    } else if (event == CHR_EVENT_CLOSED) {
        /* The medium left: no carrier from it any more. */
        s->radio.carrier = false;
        radio_update_carrier(s);
    }
}

static void channel_transmit(MC68681DuartState *s, DuartChannel *c, uint8_t byte)
{
    if (!c->tx_enabled) {
        qemu_log_mask(LOG_GUEST_ERROR, "mc68681: write to TB with transmitter off\n");
        return;
    }
    if (radio_channel(c) && (c->mr2 >> 6) != 2) {
        radio_transmit(s, byte);
        return;
    }
    switch (c->mr2 >> 6) {
    case 2:         /* local loopback: back into our own receiver */
        if (c->rx_enabled) {
            channel_push_rx(s, c, byte);
        }
        break;
    case 1:         /* auto echo: the CPU transmitter is disconnected */
        break;
    default:
        /* Blocking write: a console must not lose characters. */
        qemu_chr_fe_write_all(&c->chr, &byte, 1);
        break;
    }
}

static int duart_can_receive(DuartChannel *c)
{
    /* Characters wait on the host side while the receiver is off, and in the
     * host queue while the FIFO is full (no loss from the host's point of view). */
    if (!c->rx_enabled || (c->mr2 >> 6) == 2) {
        return 0;
    }
    return HOST_RXQ - c->hostq_count;
}

/* Moves host characters into the FIFO while it has room (auto-echo mode
 * echoes each as it arrives). */
static void channel_fill_fifo(MC68681DuartState *s, DuartChannel *c)
{
    while (c->rx_enabled && c->hostq_count && c->rx_count < RX_FIFO_DEPTH) {
        uint8_t byte = c->hostq[c->hostq_head];

        c->hostq_head = (c->hostq_head + 1) % HOST_RXQ;
        c->hostq_count--;
        channel_push_rx(s, c, byte);
        if ((c->mr2 >> 6) == 1) {
            qemu_chr_fe_write_all(&c->chr, &byte, 1);
        }
    }
}

static void duart_receive(MC68681DuartState *s, DuartChannel *c,
                          const uint8_t *buf, int size)
{
    int i;

    for (i = 0; i < size && c->hostq_count < HOST_RXQ; i++) {
        c->hostq[(c->hostq_head + c->hostq_count++) % HOST_RXQ] = buf[i];
        c->host_rx_taken++;
    }
    channel_fill_fifo(s, c);
    duart_update_irq(s);
}

static int duart_can_receive_a(void *opaque)
{
    MC68681DuartState *s = opaque;
    if (s->radio.enabled) {
        return radio_can_receive(s);
    }
    return duart_can_receive(&s->ch[0]);
}

static int duart_can_receive_b(void *opaque)
{
    MC68681DuartState *s = opaque;
    return duart_can_receive(&s->ch[1]);
}

static void duart_receive_a(void *opaque, const uint8_t *buf, int size)
{
    MC68681DuartState *s = opaque;
    if (s->radio.enabled) {
        radio_receive(s, buf, size);
        duart_update_irq(s);
        return;
    }
    duart_receive(s, &s->ch[0], buf, size);
}

static void duart_receive_b(void *opaque, const uint8_t *buf, int size)
{
    MC68681DuartState *s = opaque;
    duart_receive(s, &s->ch[1], buf, size);
}

static uint8_t channel_read_rb(MC68681DuartState *s, DuartChannel *c)
{
    uint8_t byte = c->rx_fifo[0];

    if (c->rx_count) {
        memmove(c->rx_fifo, c->rx_fifo + 1, RX_FIFO_DEPTH - 1);
        c->rx_count--;
        channel_fill_fifo(s, c);
        qemu_chr_fe_accept_input(&c->chr);
    }
    return byte;
}

static void channel_command(MC68681DuartState *s, DuartChannel *c, uint8_t cr)
{
    switch ((cr >> 4) & 7) {
    case 1:
        c->mr_ptr_mr2 = false;
        break;
    case 2:
        c->rx_enabled = false;
        c->rx_count = 0;
        c->overrun = false;
        break;
    case 3:
        c->tx_enabled = false;
        break;
    case 4:
        c->overrun = false;
        break;
    default:
        /* Break commands: no break is ever received or sent. */
        break;
    }
    if ((cr & 3) == 1) {
        c->rx_enabled = true;
    } else if ((cr & 3) == 2) {
        c->rx_enabled = false;
    }
    if (((cr >> 2) & 3) == 1) {
        c->tx_enabled = true;
    } else if (((cr >> 2) & 3) == 2) {
        c->tx_enabled = false;
    }
    if (c->rx_enabled) {
        channel_fill_fifo(s, c);
        qemu_chr_fe_accept_input(&c->chr);
    }
}

/* ---- counter/timer -------------------------------------------------------
 *
 * Evaluated lazily from the virtual clock: counter-ready events happen at
 * fixed cycle counts after an origin (ct_origin_ns, where the count was
 * ct_origin_value), so ISR[3] and CUR:CLR are computed when read.  A QEMU
 * timer is armed only when the event must raise an interrupt (IMR bit 3 set
 * and ISR[3] not yet set): the console's 57600 baud setting runs the
 * timer at 1.085 us per period, far too often for a callback per event. */

/* Clock of the counter/timer in Hz, or 0 for sources not modelled
 * (IP2 pin, TxCA/TxCB). */
static uint32_t ct_clock_hz(MC68681DuartState *s)
{
    switch ((s->acr >> 4) & 7) {
    case 3: case 7: return RC_DUART_XTAL_HZ / 16;
    case 6: return RC_DUART_XTAL_HZ;
    default: return 0;
    }
}

static bool ct_timer_mode(MC68681DuartState *s)
{
    return s->acr & 0x40;
}

static bool ct_active(MC68681DuartState *s)
{
    return ct_clock_hz(s) && (ct_timer_mode(s) || s->ct_running);
}

static uint64_t ct_preload_cycles(MC68681DuartState *s)
{
    return s->ct_preload ? s->ct_preload : 0x10000;
}

/* Cycle count (after the origin) of counter-ready event k >= 1. */
static uint64_t ct_event_cycle(MC68681DuartState *s, uint64_t k)
{
    uint64_t first;

    if (ct_timer_mode(s)) {
        /* Square wave of period 2 x preload; ISR[3] once per period. */
        return k * 2 * ct_preload_cycles(s);
    }
    /* Counter: terminal count after the origin value, then every 0x10000. */
    first = s->ct_origin_value ? s->ct_origin_value : 0x10000;
    return first + (k - 1) * 0x10000;
}

static int64_t ct_cycle_ns(MC68681DuartState *s, uint64_t cycles)
{
    return s->ct_origin_ns +
           (int64_t)muldiv64(cycles, NANOSECONDS_PER_SECOND, ct_clock_hz(s));
}

static uint64_t ct_cycles_at(MC68681DuartState *s, int64_t ns)
{
    return ns <= s->ct_origin_ns ? 0 :
           muldiv64(ns - s->ct_origin_ns, ct_clock_hz(s), NANOSECONDS_PER_SECOND);
}

/* Time of the first event after the last clear of ISR[3]. */
static int64_t ct_next_event_ns(MC68681DuartState *s)
{
    uint64_t c = ct_cycles_at(s, s->ct_cleared_ns);
    uint64_t k;

    if (ct_timer_mode(s)) {
        k = c / (2 * ct_preload_cycles(s));
    } else {
        uint64_t first = s->ct_origin_value ? s->ct_origin_value : 0x10000;
        k = c < first ? 0 : (c - first) / 0x10000;
    }
    k = MAX(k, 1);
    while (ct_cycle_ns(s, ct_event_cycle(s, k)) <= s->ct_cleared_ns) {
        k++;
    }
    return ct_cycle_ns(s, ct_event_cycle(s, k));
}

static bool ct_ready(MC68681DuartState *s)
{
    return s->ct_ready_latched ||
           (ct_active(s) &&
            ct_next_event_ns(s) <= qemu_clock_get_ns(QEMU_CLOCK_VIRTUAL));
}

static void ct_schedule(MC68681DuartState *s)
{
    if (ct_active(s) && !s->ct_ready_latched && (s->imr & ISR_CTR)) {
        timer_mod(s->ct_timer, ct_next_event_ns(s));
    } else {
        timer_del(s->ct_timer);
    }
}

static void ct_expire(void *opaque)
{
    MC68681DuartState *s = opaque;

    s->ct_ready_latched = true;
    duart_update_irq(s);
}

/* Current counter value (CUR:CLR readback). */
static uint16_t ct_value(MC68681DuartState *s)
{
    uint64_t elapsed;

    if (!ct_active(s)) {
        return s->ct_origin_value;
    }
    elapsed = ct_cycles_at(s, qemu_clock_get_ns(QEMU_CLOCK_VIRTUAL));
    if (ct_timer_mode(s)) {
        return ct_preload_cycles(s) - (elapsed % ct_preload_cycles(s));
    }
    return (uint16_t)(s->ct_origin_value - elapsed);
}

/* Moves the origin to now with the given count, keeping ISR[3]. */
static void ct_rebase(MC68681DuartState *s, uint32_t value)
{
    int64_t now = qemu_clock_get_ns(QEMU_CLOCK_VIRTUAL);

    s->ct_ready_latched = ct_ready(s);
    s->ct_origin_ns = now;
    s->ct_origin_value = value;
    s->ct_cleared_ns = now;
}

static void ct_start_command(MC68681DuartState *s)
{
    ct_rebase(s, s->ct_preload);
    s->ct_running = true;
    ct_schedule(s);
}

static void ct_stop_command(MC68681DuartState *s)
{
    if (!ct_timer_mode(s) && s->ct_running) {
        ct_rebase(s, ct_value(s));
        s->ct_running = false;
    }
    s->ct_ready_latched = false;
    s->ct_cleared_ns = qemu_clock_get_ns(QEMU_CLOCK_VIRTUAL);
    ct_schedule(s);
}

static void ct_write_acr(MC68681DuartState *s, uint8_t acr)
{
    uint8_t old_mode = (s->acr >> 4) & 7;

    if (old_mode != ((acr >> 4) & 7)) {
        /* Keep ISR[3] and the count through a change of mode or clock. */
        uint32_t value = ct_value(s);

        ct_rebase(s, value);
        s->acr = acr;
        if (ct_timer_mode(s)) {
            s->ct_origin_value = s->ct_preload;     /* the timer reloads */
        }
    } else {
        s->acr = acr;
    }
    ct_schedule(s);
}

/* ---- input port ------------------------------------------------------------ */

static void duart_set_ip(MC68681DuartState *s, uint8_t pins)
{
    uint8_t changed = (s->ip ^ pins) & 0x0F;

    s->ip = pins & 0x3F;
    s->ipcr_delta |= changed;
    if (changed & s->acr & 0x0F) {
        s->isr_latched |= ISR_IPCHG;
    }
    duart_update_irq(s);
}

/* ---- register access ----------------------------------------------------- */

static uint64_t duart_read(void *opaque, hwaddr addr, unsigned size)
{
    MC68681DuartState *s = opaque;
    DuartChannel *c = &s->ch[(addr >> 3) & 1];
    uint8_t v = 0;

    switch (addr & 0xF) {
    case 0x0: case 0x8:                 /* MR1x / MR2x */
        v = c->mr_ptr_mr2 ? c->mr2 : c->mr1;
        c->mr_ptr_mr2 = true;
        break;
    case 0x1: case 0x9:                 /* SRx */
        v = channel_sr(c);
        break;
    case 0x3: case 0xB:                 /* RBx */
        v = channel_read_rb(s, c);
        break;
    case 0x4:                           /* IPCR */
        v = (s->ipcr_delta << 4) | (s->ip & 0x0F);
        s->ipcr_delta = 0;
        s->isr_latched &= ~ISR_IPCHG;
        break;
    case 0x5:                           /* ISR */
        v = duart_isr(s);
        break;
    case 0x6:                           /* CUR */
        v = ct_value(s) >> 8;
        break;
    case 0x7:                           /* CLR */
        v = ct_value(s) & 0xFF;
        break;
    case 0xC:                           /* IVR */
        v = s->ivr;
        break;
    case 0xD:                           /* IP: IP0..IP5, bits 6-7 read 1 */
        v = s->ip | 0xC0;
        break;
    case 0xE:                           /* start counter command */
        ct_start_command(s);
        v = 0xFF;
        break;
    case 0xF:                           /* stop counter command */
        ct_stop_command(s);
        v = 0xFF;
        break;
    default:                            /* 0x2, 0xA: reserved/test */
        v = 0xFF;
        break;
    }
    duart_update_irq(s);
    return v;
}

static void duart_write(void *opaque, hwaddr addr, uint64_t value, unsigned size)
{
    MC68681DuartState *s = opaque;
    DuartChannel *c = &s->ch[(addr >> 3) & 1];
    uint8_t v = value;

    switch (addr & 0xF) {
    case 0x0: case 0x8:
        if (c->mr_ptr_mr2) {
            c->mr2 = v;
        } else {
            c->mr1 = v;
            c->mr_ptr_mr2 = true;
        }
        break;
    case 0x1: case 0x9:
        c->csr = v;
        break;
    case 0x2: case 0xA:
        channel_command(s, c, v);
        break;
    case 0x3: case 0xB:
        channel_transmit(s, c, v);
        break;
    case 0x4:
        ct_write_acr(s, v);
        break;
    case 0x5:
        s->imr = v;
        ct_schedule(s);
        break;
    case 0x6:
        s->ct_preload = (s->ct_preload & 0x00FF) | (v << 8);
        if (ct_timer_mode(s)) {
            ct_rebase(s, s->ct_preload);    /* the timer runs on the new value */
            ct_schedule(s);
        }
        break;
    case 0x7:
        s->ct_preload = (s->ct_preload & 0xFF00) | v;
        if (ct_timer_mode(s)) {
            ct_rebase(s, s->ct_preload);
            ct_schedule(s);
        }
        break;
    case 0xC:
        s->ivr = v;
        break;
    case 0xD:
        s->opcr = v;
        break;
    case 0xE:
        s->opr |= v;
        radio_send_control(s);
        break;
    case 0xF:
        s->opr &= ~v;
        radio_send_control(s);
        break;
    }
    duart_update_irq(s);
}

static const MemoryRegionOps duart_ops = {
    .read = duart_read,
    .write = duart_write,
    .endianness = DEVICE_BIG_ENDIAN,
    .impl = { .min_access_size = 1, .max_access_size = 1 },
    .valid = { .min_access_size = 1, .max_access_size = 4 },
};

/* ---- QOM ------------------------------------------------------------------ */

static void duart_reset(DeviceState *dev)
{
    MC68681DuartState *s = MC68681_DUART(dev);
    int i;

    for (i = 0; i < 2; i++) {
        DuartChannel *c = &s->ch[i];
        c->mr1 = c->mr2 = 0;
        c->mr_ptr_mr2 = false;
        c->csr = 0;
        c->rx_enabled = c->tx_enabled = false;
        c->overrun = false;
        c->rx_count = 0;
    }
    s->acr = 0;
    s->imr = 0;
    s->ivr = 0x0F;
    s->opcr = 0;
    s->opr = 0;
    s->isr_latched = 0;
    s->ipcr_delta = 0;
    s->ct_preload = 0;
    s->ct_running = false;
    s->ct_ready_latched = false;
    s->ct_origin_ns = s->ct_cleared_ns = qemu_clock_get_ns(QEMU_CLOCK_VIRTUAL);
    s->ct_origin_value = 0;
    timer_del(s->ct_timer);
    s->radio.rxq_head = s->radio.rxq_count = 0;
    s->radio.tx_shifting = s->radio.tx_holding = false;
    timer_del(s->radio.rx_timer);
    timer_del(s->radio.tx_timer);
    if (s->radio.enabled) {
        radio_send_control(s);
        radio_update_carrier(s);
    }
    duart_update_irq(s);
}

static void duart_get_u8(Object *obj, Visitor *v, const char *name,
                         void *opaque, Error **errp)
{
    MC68681DuartState *s = MC68681_DUART(obj);
    uint8_t value;

    if (!strcmp(name, "input-port")) {
        value = s->ip;
    } else if (!strcmp(name, "opr")) {
        value = s->opr;
    } else {
        /* Pin levels: OPR bit 1 drives the pin low. */
        value = ~s->opr;
    }
    visit_type_uint8(v, name, &value, errp);
}

static void duart_set_input_port(Object *obj, Visitor *v, const char *name,
                                 void *opaque, Error **errp)
{
    MC68681DuartState *s = MC68681_DUART(obj);
    uint8_t value;

    if (!visit_type_uint8(v, name, &value, errp)) {
        return;
    }
    if (value > 0x3F) {
        error_setg(errp, "input-port has 6 pins (IP0..IP5): 0..63, got %u", value);
        return;
    }
    duart_set_ip(s, value);
}

static void duart_realize(DeviceState *dev, Error **errp)
{
    MC68681DuartState *s = MC68681_DUART(dev);

    qemu_chr_fe_set_handlers(&s->ch[0].chr, duart_can_receive_a, duart_receive_a,
                             s->radio.enabled ? radio_event : NULL, NULL, s, NULL, true);
    qemu_chr_fe_set_handlers(&s->ch[1].chr, duart_can_receive_b, duart_receive_b,
                             NULL, NULL, s, NULL, true);
}

static void duart_init(Object *obj)
{
    MC68681DuartState *s = MC68681_DUART(obj);

    memory_region_init_io(&s->iomem, obj, &duart_ops, s, "mc68681.duart", 0x10);
    s->ct_timer = timer_new_ns(QEMU_CLOCK_VIRTUAL, ct_expire, s);
    s->radio.rx_timer = timer_new_ns(QEMU_CLOCK_VIRTUAL, radio_rx_tick, s);
    s->radio.tx_timer = timer_new_ns(QEMU_CLOCK_VIRTUAL, radio_tx_tick, s);
    s->radio.sync_timer = timer_new_ns(QEMU_CLOCK_VIRTUAL, radio_sync_tick, s);
    s->radio.last_control = 0xFF;
    s->ip = 0x3F;   /* pull-ups: every input high until the host says otherwise */
    object_property_add(obj, "input-port", "uint8", duart_get_u8,
                        duart_set_input_port, NULL, NULL);
    object_property_add(obj, "opr", "uint8", duart_get_u8, NULL, NULL, NULL);
    object_property_add(obj, "output-pins", "uint8", duart_get_u8, NULL, NULL, NULL);
    object_property_add_uint32_ptr(obj, "received-a", &s->ch[0].host_rx_taken,
                                   OBJ_PROP_FLAG_READ);
    object_property_add_uint32_ptr(obj, "received-b", &s->ch[1].host_rx_taken,
                                   OBJ_PROP_FLAG_READ);
}

static Property duart_properties[] = {
    DEFINE_PROP_CHR("chardev-a", MC68681DuartState, ch[0].chr),
    DEFINE_PROP_CHR("chardev-b", MC68681DuartState, ch[1].chr),
    DEFINE_PROP_BOOL("radio-medium", MC68681DuartState, radio.enabled, false),
    DEFINE_PROP_UINT8("radio-station", MC68681DuartState, radio.station, 0),
    DEFINE_PROP_UINT32("radio-sync-ns", MC68681DuartState, radio.sync_ns, 0),
    DEFINE_PROP_END_OF_LIST(),
};

static void duart_class_init(ObjectClass *klass, void *data)
{
    DeviceClass *dc = DEVICE_CLASS(klass);

    dc->realize = duart_realize;
    dc->reset = duart_reset;
    dc->desc = "MC68681 DUART";
    device_class_set_props(dc, duart_properties);
}

static const TypeInfo duart_info = {
    .name = TYPE_MC68681_DUART,
    .parent = TYPE_SYS_BUS_DEVICE,
    .instance_size = sizeof(MC68681DuartState),
    .instance_init = duart_init,
    .class_init = duart_class_init,
};

static void duart_register_types(void)
{
    type_register_static(&duart_info);
}

type_init(duart_register_types)

DeviceState *mc68681_duart_create(MemoryRegion *bus, hwaddr base,
                                  RoboCubeIntc *intc, Chardev *chr_a,
                                  Chardev *chr_b)
{
    DeviceState *dev = qdev_new(TYPE_MC68681_DUART);
    MC68681DuartState *s = MC68681_DUART(dev);

    s->intc = intc;
    the_duart = s;
    qdev_prop_set_chr(dev, "chardev-a", chr_a);
    qdev_prop_set_chr(dev, "chardev-b", chr_b);
    object_property_add_child(qdev_get_machine(), "duart", OBJECT(dev));
    sysbus_realize_and_unref(SYS_BUS_DEVICE(dev), &error_fatal);
    memory_region_add_subregion(bus, base, &s->iomem);
    return dev;
}
