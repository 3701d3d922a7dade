/*
 * netnode: one station of the radio network, for the soak test, the target
 * tests and the figures.
 *
 * The configuration block below is patched in the ELF by the host
 * (tools/netpeer/netnode.py finds it by its magic), so one image serves
 * every station. Modes:
 *   SOAK   sends `messages` numbered reliable messages (port 2) to every peer
 *          in `peers`, round robin, and checks what arrives from each peer:
 *          in order, duplicates, gaps. Prints one line per peer and a summary.
 *   ECHO   only answers: every message on port 1 goes back to its sender
 *          (reliable), for the host peer's interoperation tests.
 *   BENCH  sends `messages` reliable messages of `size` bytes to the first
 *          peer and reports goodput and the mean time per message in virtual
 *          milliseconds.
 * Every mode runs the echo service and prints the statistics at the end.
 */
#include "kernel.h"
#include "boards/include/board.h"
#include "net/net.h"
#include "net/xdr.h"

#define PORT_ECHO 1u
#define PORT_SOAK 2u
#define MODE_SOAK 1u
#define MODE_ECHO 2u
#define MODE_BENCH 3u
#define PORT_SINK 3u
#define SOAK_LEN 16u

struct netnode_config {
    char magic[8];
    uint8_t station;
    uint8_t mode;
    uint16_t peers;          /* bit n: station n takes part */
    uint16_t messages;
    uint16_t size;
    uint32_t seed;
    uint32_t linger_ms;      /* SOAK: keep receiving this long after sending */
    uint8_t flags;           /* NETNODE_FEC: forward error correction on air */
    uint8_t reserved;
    uint16_t boot;           /* the host's count of this station's launches */
};
#define NETNODE_FEC 0x1u

/* Patched by the host: keep the layout in step with tools/netpeer/netnode.py. */
volatile const struct netnode_config netnode_config __attribute__((used, aligned(4))) = {
    { 'N', 'E', 'T', 'N', 'O', 'D', 'E', '\0' }, 1, MODE_ECHO, 0x0003, 10, 32, 1, 3000, 0, 0, 0
};

/* The network key and this boot's epoch (net_auth_setup), patched by the
 * host like the block above (netnode.py: the key it is given, the epoch its
 * count of the station's launches); flags NETAUTH_OFF: no authentication
 * (only to measure its cost, tools/netpeer/bench.py). The image's own value
 * is the public development key (net.h). */
struct netnode_auth {
    char magic[8];
    uint8_t key[NET_AUTH_KEY_LEN];
    uint32_t epoch;
    uint8_t flags;
    uint8_t reserved[3];
};
#define NETAUTH_OFF 0x1u
volatile const struct netnode_auth netnode_auth __attribute__((used, aligned(4))) = {
    { 'N', 'E', 'T', 'A', 'U', 'T', 'H', '\0' },
    { 'b', 's', 'c', 'h', 'e', 'd', '-', 'd', 'e', 'v', '-', 'k', 'e', 'y', '!', '!' },
    0, 0, { 0, 0, 0 }
};

static struct netnode_config cfg;
static struct netnode_auth auth_cfg;
static struct k_thread echo_thread, soak_rx_thread, sink_thread;
K_STACK_DEFINE(sink_stack, 1536);   /* 480 B own + 2 nested interrupts of 504 B (make stack) */
K_STACK_DEFINE(echo_stack, 2048);
K_STACK_DEFINE(soak_rx_stack, 2048);
K_STACK_DEFINE(main_stack, 2048);
static struct k_thread main_thread;

static uint32_t rx_next[LINK_MAX_STATIONS];   /* next expected number per peer */
static uint32_t rx_inorder[LINK_MAX_STATIONS], rx_dup[LINK_MAX_STATIONS],
                rx_gap[LINK_MAX_STATIONS];

static void *echo_main(void *arg)
{
    static uint8_t buf[NET_MSG_MAX];
    (void)arg;
    for (;;) {
        uint8_t src;
        int n = net_recv(PORT_ECHO, buf, sizeof buf, &src, 1000);
        if (n >= 0) {
            int rc = net_send(src, PORT_ECHO, buf, (size_t)n, NET_RELIABLE);
            if (rc != K_OK)
                k_printf("netnode: echo to %u failed (%d)\n", (unsigned)src, rc);
        }
    }
    return NULL;
}

/* A soak message: XDR (sender, number, fill) so both ends agree byte for byte. */
static int soak_encode(uint8_t *buf, size_t size, uint32_t from, uint32_t number)
{
    struct nxdr x;
    uint8_t fill[SOAK_LEN - 8u];
    unsigned i;
    for (i = 0; i < sizeof fill; i++)
        fill[i] = (uint8_t)(number + i);
    nxdr_init_encode(&x, buf, size);
    if (!nxdr_u_int(&x, &from) || !nxdr_u_int(&x, &number) || !nxdr_opaque(&x, fill, sizeof fill))
        return -1;
    return (int)nxdr_getpos(&x);
}

/* Port 3 swallows the bench's messages, so the sender's are never refused. */
static void *sink_main(void *arg)
{
    static uint8_t buf[NET_MSG_MAX];
    (void)arg;
    for (;;)
        (void)net_recv(PORT_SINK, buf, sizeof buf, NULL, 1000);
    return NULL;
}

static void *soak_rx_main(void *arg)
{
    uint8_t buf[64];
    (void)arg;
    for (;;) {
        uint8_t src;
        uint32_t from, number;
        struct nxdr x;
        int n = net_recv(PORT_SOAK, buf, sizeof buf, &src, 1000);
        if (n < 0)
            continue;
        nxdr_init_decode(&x, buf, (size_t)n);
        if (!nxdr_u_int(&x, &from) || !nxdr_u_int(&x, &number) || from != src ||
            src >= LINK_MAX_STATIONS) {
            k_printf("netnode: bad soak message from %u\n", (unsigned)src);
            continue;
        }
        if (number == rx_next[src]) {
            rx_inorder[src]++;
            rx_next[src]++;
        } else if (number < rx_next[src]) {
            rx_dup[src]++;
        } else {
            rx_gap[src] += number - rx_next[src];
            rx_next[src] = number + 1u;
        }
    }
    return NULL;
}

static void run_soak(void)
{
    uint8_t buf[SOAK_LEN];
    uint32_t sent = 0, failed = 0, i;
    unsigned p;
    uint32_t start = k_uptime_ms();
    for (i = 0; i < cfg.messages; i++) {
        for (p = 0; p < LINK_MAX_STATIONS; p++) {
            int n, rc;
            if (p == cfg.station || (cfg.peers & (1u << p)) == 0u)
                continue;
            n = soak_encode(buf, sizeof buf, cfg.station, i);
            rc = net_send((uint8_t)p, PORT_SOAK, buf, (size_t)n, NET_RELIABLE);
            if (rc == K_OK) {
                sent++;
            } else {
                failed++;
                k_printf("netnode: send %lu to %u failed (%d)\n", (unsigned long)i, p, rc);
            }
        }
    }
    k_printf("netnode: station %u sent %lu acknowledged, %lu failed in %lu ms\n",
             (unsigned)cfg.station, (unsigned long)sent, (unsigned long)failed,
             (unsigned long)(k_uptime_ms() - start));
    /* Keep receiving until every peer's messages are in, or linger_ms. */
    start = k_uptime_ms();
    while (k_uptime_ms() - start < cfg.linger_ms) {
        int all = 1;
        for (p = 0; p < LINK_MAX_STATIONS; p++)
            if (p != cfg.station && (cfg.peers & (1u << p)) != 0u && rx_next[p] < cfg.messages)
                all = 0;
        if (all)
            break;
        (void)k_sleep_ticks(k_ms_to_ticks(100));
    }
    for (p = 0; p < LINK_MAX_STATIONS; p++) {
        if (p == cfg.station || (cfg.peers & (1u << p)) == 0u)
            continue;
        k_printf("netnode: from %u: %lu in order, %lu duplicates, %lu lost\n", p,
                 (unsigned long)rx_inorder[p], (unsigned long)rx_dup[p],
                 (unsigned long)(rx_gap[p] + (cfg.messages - rx_next[p] < cfg.messages
                                              ? cfg.messages - rx_next[p] : 0u)));
    }
}

static void run_bench(void)
{
    static uint8_t buf[NET_MSG_MAX];
    unsigned p, dst = LINK_MAX_STATIONS;
    uint32_t i, ok = 0, start, ms;
    uint32_t size = cfg.size <= NET_MSG_MAX ? cfg.size : NET_MSG_MAX;
    for (p = 0; p < LINK_MAX_STATIONS && dst == LINK_MAX_STATIONS; p++)
        if (p != cfg.station && (cfg.peers & (1u << p)) != 0u)
            dst = p;
    for (i = 0; i < size; i++)
        buf[i] = (uint8_t)(i * 7u);
    start = k_uptime_ms();
    for (i = 0; i < cfg.messages; i++)
        if (net_send((uint8_t)dst, PORT_SINK, buf, size, NET_RELIABLE) == K_OK)
            ok++;
    ms = k_uptime_ms() - start;
    k_printf("netnode: bench %lu of %lu messages of %lu bytes to %u in %lu ms: "
             "%lu bit/s, %lu us per message\n",
             (unsigned long)ok, (unsigned long)cfg.messages, (unsigned long)size, dst,
             (unsigned long)ms, (unsigned long)(ms ? ok * size * 8u * 1000u / ms : 0u),
             (unsigned long)(cfg.messages ? ms * 1000u / cfg.messages : 0u));
}

/* The service thread's stack high-water mark: measured, since the stack
 * analysis (make stack) has no call graph of Mbed TLS's functions and
 * assumes 32 bytes for each. */
static void print_net_stack(void)
{
    static struct k_thread_info info[12];
    int n = k_thread_list(info, sizeof info / sizeof info[0]);
    int i;
    for (i = 0; i < n && i < (int)(sizeof info / sizeof info[0]); i++)
        if (info[i].name != NULL && info[i].name[0] == 'n' && info[i].name[1] == 'e' &&
            info[i].name[2] == 't' && info[i].name[3] == '\0')
            k_printf("netnode: net thread stack used %lu of %lu bytes\n",
                     (unsigned long)info[i].stack_used, (unsigned long)info[i].stack_bytes);
}

static void *main_fn(void *arg)
{
    int rc;
    (void)arg;
    /* Nothing on the board differs between two boots in the deterministic
     * emulator (no clock, no non-volatile memory), so the host counts them:
     * the epoch it patched grows per boot, and with it the link's session
     * (net.h); seed + boot makes the backoffs differ too. */
    {
        unsigned i;
        auth_cfg.epoch = netnode_auth.epoch;
        auth_cfg.flags = netnode_auth.flags;
        for (i = 0; i < NET_AUTH_KEY_LEN; i++)
            auth_cfg.key[i] = netnode_auth.key[i];
    }
    rc = net_auth_setup((auth_cfg.flags & NETAUTH_OFF) != 0u ? NULL : auth_cfg.key,
                        auth_cfg.epoch);
    if (rc != K_OK) {
        k_printf("netnode: net_auth_setup failed (%d): epoch %lu\n", rc,
                 (unsigned long)auth_cfg.epoch);
        return NULL;
    }
    rc = net_init_flags(cfg.station, cfg.seed + cfg.boot,
                        (cfg.flags & NETNODE_FEC) != 0u ? NET_FEC : 0u);
    if (rc != K_OK) {
        k_printf("netnode: net_init failed (%d)\n", rc);
        return NULL;
    }
    k_printf("netnode: station %u up, mode %u%s%s, boot %u, epoch %lu\n", (unsigned)cfg.station,
             (unsigned)cfg.mode, (cfg.flags & NETNODE_FEC) != 0u ? ", fec" : "",
             (auth_cfg.flags & NETAUTH_OFF) != 0u ? ", auth off" : "",
             (unsigned)cfg.boot, (unsigned long)auth_cfg.epoch);
    (void)k_thread_create(&echo_thread, "echo", echo_main, NULL, echo_stack,
                          sizeof echo_stack, 10);
    (void)k_thread_create(&soak_rx_thread, "soakrx", soak_rx_main, NULL, soak_rx_stack,
                          sizeof soak_rx_stack, 11);
    (void)k_thread_create(&sink_thread, "sink", sink_main, NULL, sink_stack,
                          sizeof sink_stack, 11);
    if (cfg.mode == MODE_SOAK)
        run_soak();
    else if (cfg.mode == MODE_BENCH)
        run_bench();
    else
        (void)k_sleep_ticks(k_ms_to_ticks(cfg.linger_ms));
    (void)net_stats_print();
    print_net_stack();
    k_printf("netnode: done\n");
    for (;;)
        (void)k_sleep_ticks(k_ms_to_ticks(1000));
    return NULL;
}

int main(void)
{
    cfg = netnode_config;
    board_start("netnode");
    (void)board_spawn(&main_thread, "main", main_fn, NULL, main_stack, sizeof main_stack, 9);
    k_start();
    return 0;
}
