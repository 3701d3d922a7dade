/*
 * The RoboCube v2.0 controller board (VUB AI Lab, 1999): MC68332 (CPU32 core,
 * SIM, QSM, TPU, 2 KiB TPURAM), 1 MiB flash on CSBOOT, 1 MiB SRAM on
 * CS0/CS1, MC68681 DUART, two PCF8584 I2C controllers with the I/O board.
 *
 * The CPU32 has a 24-bit address bus: the board occupies the first 16 MiB of
 * the CPU's address space, and the same 16 MiB also appear at 0xFF000000 so
 * that sign-extended short absolute addresses ($FA00.W = 0xFFFFFA00) reach
 * the on-chip modules as on the real chip.  Anything not decoded raises a
 * bus error (CPU32 format $C frame), as does any write to flash.
 *
 * Serial ports: -serial #0 = DUART channel B (console), #1 = DUART channel A
 * (radio link), #2 = QSM SCI.  Memory and register maps: emu/README.md.
 */
#include "qemu/osdep.h"
#include "qemu/units.h"
#include "qemu/error-report.h"
#include "qemu/log.h"
#include "qapi/error.h"
#include "cpu.h"
#include "hw/boards.h"
#include "hw/loader.h"
#include "hw/qdev-core.h"
#include "elf.h"
#include "exec/address-spaces.h"
#include "sysemu/qtest.h"
#include "sysemu/reset.h"
#include "sysemu/sysemu.h"
#include "robocube_board.h"
#include "robocube_intc.h"
#include "robocube_io.h"

#define RC_FLASH_LINK_BASE 0xE00000     /* where firmware is linked (CSBARBT=0xE007) */
#define RC_BUS_SIZE        (16 * MiB)
#define RC_BUS_MIRROR      0xFF000000   /* A24..A31 are not decoded */

typedef struct RoboCubeMachine {
    M68kCPU *cpu;
    MemoryRegion bus;
    MemoryRegion bus_mirror;
    MemoryRegion flash;
    /* Loader view: the flash at its link address only, so that -kernel
     * places the image into the flash whatever the chip selects say. */
    MemoryRegion loader_root;
    MemoryRegion loader_flash;
    AddressSpace loader_as;
} RoboCubeMachine;

static RoboCubeMachine board;

/* Flash is read directly (ROM device in romd mode); any CPU write is a bus
 * error (the AMD command interface of the Am29F800B is not modelled). */
static MemTxResult flash_read(void *opaque, hwaddr addr, uint64_t *data,
                              unsigned size, MemTxAttrs attrs)
{
    *data = 0;
    return MEMTX_ERROR;
}

static MemTxResult flash_write(void *opaque, hwaddr addr, uint64_t data,
                               unsigned size, MemTxAttrs attrs)
{
    qemu_log_mask(LOG_GUEST_ERROR,
                  "robocube: write to flash offset 0x%" HWADDR_PRIx " -> bus error\n",
                  addr);
    return MEMTX_ERROR;
}

static const MemoryRegionOps flash_ops = {
    .read_with_attrs = flash_read,
    .write_with_attrs = flash_write,
    .endianness = DEVICE_BIG_ENDIAN,
    .valid = { .min_access_size = 1, .max_access_size = 4 },
};

/* Reset: the SIM has mapped the flash at 0 (CSBOOT reset value); the CPU
 * fetches SSP and PC from flash offsets 0 and 4. */
static void robocube_cpu_reset(void *opaque)
{
    RoboCubeMachine *b = opaque;
    CPUM68KState *env = &b->cpu->env;
    const uint8_t *vectors;

    cpu_reset(CPU(b->cpu));
    vectors = rom_ptr_for_as(&b->loader_as, RC_FLASH_LINK_BASE, 8);
    if (!vectors) {
        vectors = memory_region_get_ram_ptr(&b->flash);
    }
    env->aregs[7] = ldl_be_p(vectors);
    env->pc = ldl_be_p(vectors + 4);
}

/* ELF segments may be linked at the flash address (0xE00000..) or at flash
 * offsets (0..1 MiB, the boot alias): both land in the flash. */
static uint64_t robocube_translate_load(void *opaque, uint64_t addr)
{
    return addr < RC_FLASH_SIZE ? addr + RC_FLASH_LINK_BASE : addr;
}

static void robocube_load_firmware(MachineState *machine, RoboCubeMachine *b)
{
    uint64_t entry, low, high;
    ssize_t size;

    if (machine->firmware) {
        size = load_image_targphys_as(machine->firmware, RC_FLASH_LINK_BASE,
                                      RC_FLASH_SIZE, &b->loader_as);
        if (size < 8) {
            error_report("robocube: cannot load flash image '%s' "
                         "(raw binary of at most 1 MiB)", machine->firmware);
            exit(1);
        }
    }
    if (machine->kernel_filename) {
        size = load_elf_as(machine->kernel_filename, NULL, robocube_translate_load,
                           NULL, &entry, &low, &high, NULL, 1, EM_68K, 0, 0,
                           &b->loader_as);
        if (size < 0) {
            error_report("robocube: '%s' is not a big-endian m68k ELF file",
                         machine->kernel_filename);
            exit(1);
        }
        if (low < RC_FLASH_LINK_BASE || high > RC_FLASH_LINK_BASE + RC_FLASH_SIZE) {
            error_report("robocube: '%s' has segments at 0x%" PRIx64 "..0x%" PRIx64
                         "; -kernel loads into the 1 MiB flash at 0x%x "
                         "(link the image there; RAM contents are copied by "
                         "the firmware)", machine->kernel_filename, low, high,
                         RC_FLASH_LINK_BASE);
            exit(1);
        }
    } else if (!machine->firmware && !qtest_enabled()) {
        warn_report("robocube: no -kernel or -bios given: the flash is blank "
                    "and the CPU will fault at reset");
    }
}

static void robocube_init(MachineState *machine)
{
    RoboCubeMachine *b = &board;
    MemoryRegion *sysmem = get_system_memory();
    RoboCubeIntc *intc;

    if (machine->ram_size != RC_SRAM_SIZE) {
        error_report("robocube: the board has exactly 1 MiB of SRAM (-m 1M)");
        exit(1);
    }

    b->cpu = M68K_CPU(cpu_create(machine->cpu_type));

    memory_region_init(&b->bus, NULL, "robocube.bus", RC_BUS_SIZE);
    memory_region_add_subregion(sysmem, 0, &b->bus);
    memory_region_init_alias(&b->bus_mirror, NULL, "robocube.bus-mirror",
                             &b->bus, 0, RC_BUS_SIZE);
    memory_region_add_subregion(sysmem, RC_BUS_MIRROR, &b->bus_mirror);

    memory_region_init_rom_device(&b->flash, NULL, &flash_ops, b, "robocube.flash",
                                  RC_FLASH_SIZE, &error_fatal);
    memset(memory_region_get_ram_ptr(&b->flash), 0xFF, RC_FLASH_SIZE);

    memory_region_init(&b->loader_root, NULL, "robocube.loader", RC_BUS_SIZE);
    memory_region_init_alias(&b->loader_flash, NULL, "robocube.loader-flash",
                             &b->flash, 0, RC_FLASH_SIZE);
    memory_region_add_subregion(&b->loader_root, RC_FLASH_LINK_BASE, &b->loader_flash);
    address_space_init(&b->loader_as, &b->loader_root, "robocube-loader");

    intc = robocube_intc_create(b->cpu);

    /* QOM paths /machine/sim, /machine/qsm, /machine/duart (emu/README.md). */
    mc68332_sim_create(&b->bus, &b->flash, machine->ram, intc);
    mc68332_qsm_create(&b->bus, intc, serial_hd(2));
    mc68681_duart_create(&b->bus, RC_DUART_BASE, intc, serial_hd(1), serial_hd(0));

    robocube_io_init(&b->bus, intc);
    robocube_lockstep_create();

    robocube_load_firmware(machine, b);
    qemu_register_reset(robocube_cpu_reset, b);
}

static void robocube_machine_init(MachineClass *mc)
{
    mc->desc = "RoboCube v2.0 controller (MC68332, MC68681, 2x PCF8584)";
    mc->init = robocube_init;
    mc->default_cpu_type = M68K_CPU_TYPE_NAME("cpu32");
    mc->default_ram_size = RC_SRAM_SIZE;
    mc->default_ram_id = "robocube.sram";
    mc->no_parallel = 1;
    mc->no_floppy = 1;
    mc->no_cdrom = 1;
}

DEFINE_MACHINE("robocube", robocube_machine_init)
