/* Listen-before-talk arbitration; see mac.h. */
#include "mac.h"

void mac_init(struct mac *m, uint32_t seed)
{
    m->rng = seed != 0u ? seed : 0x9E3779B9u;
    m->attempt = 0;
    m->waited = 0;
    m->burst = 0;
    m->deferrals = 0;
    m->drops = 0;
}

uint32_t mac_random(struct mac *m)
{
    uint32_t x = m->rng;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    m->rng = x;
    return x;
}

void mac_begin(struct mac *m)
{
    m->attempt = 0;
    m->waited = 0;
    m->burst = 0;
}

void mac_begin_burst(struct mac *m)
{
    m->attempt = 0;
    m->waited = 1;
    m->burst = 1;
}

static uint32_t mac_window(unsigned attempt)
{
    uint32_t cw = MAC_CW_MIN;
    while (attempt-- > 0u && cw < MAC_CW_MAX)
        cw <<= 1;
    return cw;
}

int mac_decide(struct mac *m, int carrier, int is_ack, uint32_t *wait_ms)
{
    if (!is_ack && !m->waited) {
        m->waited = 1;
        *wait_ms = (mac_random(m) % (MAC_CW_MIN + 1u)) * MAC_SLOT_MS;
        if (*wait_ms > 0u)
            return MAC_WAIT;
    }
    if (!carrier)
        return MAC_SEND;
    m->deferrals++;
    if (++m->attempt > MAC_MAX_ATTEMPTS) {
        m->drops++;
        return MAC_DROP;
    }
    *wait_ms = is_ack || (m->burst && m->attempt <= MAC_BURST_RETRIES)
                   ? MAC_ACK_RETRY_MS
                   : (1u + mac_random(m) % mac_window(m->attempt)) * MAC_SLOT_MS;
    return MAC_WAIT;
}
