/*
 * MC68332 Queued Serial Module (QSM) on the RoboCube board: the SCI UART on
 * a chardev (third serial port, header H9), with its interrupt.
 *
 * Modelled: QSMCR, QILR/QIVR (the SCI requests at ILSCI with vector
 * QIVR & 0xFE: the QSM forces bit 0 to 0 for the SCI and to 1 for the QSPI),
 * SCCR0 (baud divisor, stored; characters are not timed), SCCR1 (TE, RE,
 * TIE, TCIE, RIE, ILIE, LOOPS), SCSR (TDRE, TC, RDRF, OR; RDRF/OR are
 * cleared by reading SCSR and then SCDR), SCDR, and the port/QSPI registers
 * and QSPI RAM as plain storage (the QSPI does not transfer).
 */
#include "qemu/osdep.h"
#include "qemu/log.h"
#include "qapi/error.h"
#include "hw/sysbus.h"
#include "hw/qdev-properties.h"
#include "hw/qdev-properties-system.h"
#include "chardev/char-fe.h"
#include "qom/object.h"
#include "robocube_board.h"

OBJECT_DECLARE_SIMPLE_TYPE(MC68332QsmState, MC68332_QSM)

#define QSM_SIZE 0x200          /* registers 0xFFFC00.., QSPI RAM 0xFFFD00.. */

enum {
    QSM_QSMCR = 0x00, QSM_QTEST = 0x02, QSM_QILR = 0x04, QSM_QIVR = 0x05,
    QSM_SCCR0 = 0x08, QSM_SCCR1 = 0x0A, QSM_SCSR = 0x0C, QSM_SCDR = 0x0E,
};

/* SCCR1 bits */
#define SCCR1_LOOPS 0x4000
#define SCCR1_TIE   0x0080
#define SCCR1_TCIE  0x0040
#define SCCR1_RIE   0x0020
#define SCCR1_ILIE  0x0010
#define SCCR1_TE    0x0008
#define SCCR1_RE    0x0004

/* SCSR bits */
#define SCSR_TDRE 0x0100
#define SCSR_TC   0x0080
#define SCSR_RDRF 0x0040
#define SCSR_IDLE 0x0010
#define SCSR_OR   0x0008

struct MC68332QsmState {
    SysBusDevice parent_obj;

    MemoryRegion iomem;
    CharBackend chr;
    RoboCubeIntc *intc;

    uint8_t regs[QSM_SIZE];     /* storage for the registers without side effects */
    uint16_t qsmcr, sccr0, sccr1;
    uint8_t qilr, qivr;
    uint16_t scsr;
    uint8_t rdr;
    bool scsr_read_with_rdrf;   /* first half of the RDRF/OR clearing sequence */
};

static void qsm_update_irq(MC68332QsmState *s)
{
    bool active = ((s->sccr1 & SCCR1_TIE) && (s->scsr & SCSR_TDRE)) ||
                  ((s->sccr1 & SCCR1_TCIE) && (s->scsr & SCSR_TC)) ||
                  ((s->sccr1 & SCCR1_RIE) && (s->scsr & (SCSR_RDRF | SCSR_OR))) ||
                  ((s->sccr1 & SCCR1_ILIE) && (s->scsr & SCSR_IDLE));
    unsigned level = s->qilr & 7;

    robocube_intc_request(s->intc, RC_IRQ_SCI, active ? level : 0, s->qivr & 0xFE);
}

static void qsm_receive_byte(MC68332QsmState *s, uint8_t byte)
{
    if (s->scsr & SCSR_RDRF) {
        /* The new character is lost; RDR keeps the unread one. */
        s->scsr |= SCSR_OR;
    } else {
        s->rdr = byte;
        s->scsr |= SCSR_RDRF;
    }
}

static int qsm_can_receive(void *opaque)
{
    MC68332QsmState *s = opaque;

    /* The host-side chardev holds characters until RDR is free. */
    if (!(s->sccr1 & SCCR1_RE) || (s->sccr1 & SCCR1_LOOPS)) {
        return 0;
    }
    return (s->scsr & SCSR_RDRF) ? 0 : 1;
}

static void qsm_receive(void *opaque, const uint8_t *buf, int size)
{
    MC68332QsmState *s = opaque;
    int i;

    for (i = 0; i < size; i++) {
        qsm_receive_byte(s, buf[i]);
    }
    qsm_update_irq(s);
}

static void qsm_transmit(MC68332QsmState *s, uint8_t byte)
{
    if (!(s->sccr1 & SCCR1_TE)) {
        qemu_log_mask(LOG_GUEST_ERROR, "mc68332-qsm: SCDR write with TE=0\n");
        return;
    }
    if (s->sccr1 & SCCR1_LOOPS) {
        /* Loop mode: transmitter output feeds the receiver. */
        if (s->sccr1 & SCCR1_RE) {
            qsm_receive_byte(s, byte);
        }
    } else {
        qemu_chr_fe_write_all(&s->chr, &byte, 1);
    }
    /* Transmission is instantaneous: data register and shifter empty again. */
    s->scsr |= SCSR_TDRE | SCSR_TC;
}

static uint64_t qsm_read(void *opaque, hwaddr addr, unsigned size)
{
    MC68332QsmState *s = opaque;
    uint8_t v;

    switch (addr) {
    case QSM_QSMCR: v = s->qsmcr >> 8; break;
    case QSM_QSMCR + 1: v = s->qsmcr; break;
    case QSM_QILR: v = s->qilr; break;
    case QSM_QIVR: v = s->qivr; break;
    case QSM_SCCR0: v = s->sccr0 >> 8; break;
    case QSM_SCCR0 + 1: v = s->sccr0; break;
    case QSM_SCCR1: v = s->sccr1 >> 8; break;
    case QSM_SCCR1 + 1: v = s->sccr1; break;
    case QSM_SCSR:
        v = s->scsr >> 8;
        break;
    case QSM_SCSR + 1:
        v = s->scsr;
        s->scsr_read_with_rdrf = s->scsr & (SCSR_RDRF | SCSR_OR);
        break;
    case QSM_SCDR:
        v = 0;
        break;
    case QSM_SCDR + 1:
        v = s->rdr;
        if (s->scsr_read_with_rdrf) {
            s->scsr &= ~(SCSR_RDRF | SCSR_OR);
            s->scsr_read_with_rdrf = false;
            qsm_update_irq(s);
            qemu_chr_fe_accept_input(&s->chr);
        }
        break;
    default:
        v = s->regs[addr];
        break;
    }
    return v;
}

static void qsm_write(void *opaque, hwaddr addr, uint64_t value, unsigned size)
{
    MC68332QsmState *s = opaque;
    uint8_t v = value;

    switch (addr) {
    case QSM_QSMCR: s->qsmcr = (s->qsmcr & 0x00FF) | ((v & 0xE0) << 8); break;
    case QSM_QSMCR + 1: s->qsmcr = (s->qsmcr & 0xFF00) | (v & 0x8F); break;
    case QSM_QILR: s->qilr = v & 0x3F; break;
    case QSM_QIVR: s->qivr = v; break;
    case QSM_SCCR0: s->sccr0 = (s->sccr0 & 0x00FF) | ((v & 0x1F) << 8); break;
    case QSM_SCCR0 + 1: s->sccr0 = (s->sccr0 & 0xFF00) | v; break;
    case QSM_SCCR1: s->sccr1 = (s->sccr1 & 0x00FF) | ((v & 0x7F) << 8); break;
    case QSM_SCCR1 + 1:
        s->sccr1 = (s->sccr1 & 0xFF00) | v;
        if (s->sccr1 & SCCR1_RE) {
            qemu_chr_fe_accept_input(&s->chr);
        }
        break;
    case QSM_SCSR: case QSM_SCSR + 1:
        break;          /* status is read-only */
    case QSM_SCDR:
        break;          /* bit 8 (9-bit frames) is not modelled */
    case QSM_SCDR + 1:
        qsm_transmit(s, v);
        break;
    default:
        s->regs[addr] = v;
        break;
    }
    qsm_update_irq(s);
}

static const MemoryRegionOps qsm_ops = {
    .read = qsm_read,
    .write = qsm_write,
    .endianness = DEVICE_BIG_ENDIAN,
    .impl = { .min_access_size = 1, .max_access_size = 1 },
    .valid = { .min_access_size = 1, .max_access_size = 4 },
};

static void qsm_reset(DeviceState *dev)
{
    MC68332QsmState *s = MC68332_QSM(dev);

    memset(s->regs, 0, sizeof(s->regs));
    s->qsmcr = 0x0080;      /* SUPV */
    s->qilr = 0;
    s->qivr = 0x0F;
    s->sccr0 = 0x0004;
    s->sccr1 = 0;
    s->scsr = SCSR_TDRE | SCSR_TC;
    s->rdr = 0;
    s->scsr_read_with_rdrf = false;
    qsm_update_irq(s);
}

static void qsm_realize(DeviceState *dev, Error **errp)
{
    MC68332QsmState *s = MC68332_QSM(dev);

    qemu_chr_fe_set_handlers(&s->chr, qsm_can_receive, qsm_receive, NULL, NULL,
                             s, NULL, true);
}

static void qsm_init(Object *obj)
{
    MC68332QsmState *s = MC68332_QSM(obj);

    memory_region_init_io(&s->iomem, obj, &qsm_ops, s, "mc68332.qsm", QSM_SIZE);
    object_property_add_uint16_ptr(obj, "scsr", &s->scsr, OBJ_PROP_FLAG_READ);
}

static Property qsm_properties[] = {
    DEFINE_PROP_CHR("chardev", MC68332QsmState, chr),
    DEFINE_PROP_END_OF_LIST(),
};

static void qsm_class_init(ObjectClass *klass, void *data)
{
    DeviceClass *dc = DEVICE_CLASS(klass);

    dc->realize = qsm_realize;
    dc->reset = qsm_reset;
    dc->desc = "MC68332 queued serial module (SCI)";
    device_class_set_props(dc, qsm_properties);
}

static const TypeInfo qsm_info = {
    .name = TYPE_MC68332_QSM,
    .parent = TYPE_SYS_BUS_DEVICE,
    .instance_size = sizeof(MC68332QsmState),
    .instance_init = qsm_init,
    .class_init = qsm_class_init,
};

static void qsm_register_types(void)
{
    type_register_static(&qsm_info);
}

type_init(qsm_register_types)

DeviceState *mc68332_qsm_create(MemoryRegion *bus, RoboCubeIntc *intc,
                                Chardev *sci_chr)
{
    DeviceState *dev = qdev_new(TYPE_MC68332_QSM);
    MC68332QsmState *s = MC68332_QSM(dev);

    s->intc = intc;
    qdev_prop_set_chr(dev, "chardev", sci_chr);
    object_property_add_child(qdev_get_machine(), "qsm", OBJECT(dev));
    sysbus_realize_and_unref(SYS_BUS_DEVICE(dev), &error_fatal);
    memory_region_add_subregion_overlap(bus, RC_QSM_BASE, &s->iomem, 4);
    return dev;
}
