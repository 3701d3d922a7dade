/*
 * bsched.c: the B-scheduler (Birk, Kenn, Steels 2002, section 4, Figs. 6, 7).
 * See bsched.h for the interface and bsched/spec/ for what is proven about it.
 *
 * Arithmetic is written with *2, /2, %2 and masks on unsigned values so that
 * the same text is efficient on a CPU32 and close to its arithmetic ACSL spec.
 */
#include "bsched.h"

/* The low `bits` bits of x in reverse order (Fig. 6's reverse()).
 * BSCHED_MUTANT_NO_REVERSE builds a deliberately wrong variant (identity
 * instead of reversal) for the negative checks of the proof jobs: the
 * schedule stays periodic per class but is no longer balanced. */
static uint32_t reverse_bits(uint32_t x, uint32_t bits)
{
#ifdef BSCHED_MUTANT_NO_REVERSE
    (void)bits;
    return x;
#else
    uint32_t reversed = 0u;
    uint32_t rest = x;
    uint32_t b;
    for (b = 0u; b < bits; b++) {
        reversed = reversed * 2u + rest % 2u;
        rest = rest / 2u;
    }
    return reversed;
#endif
}

/* 2^pv as the period of a class, pv <= BSCHED_MAX_PV. */
static uint32_t period_of(uint8_t pv)
{
    return (uint32_t)1u << pv;
}

/* A cheap check that *s came from bsched_init (a zeroed struct does not):
 * 1 <= count <= BSCHED_MAX_PROCS, maxpv <= BSCHED_MAX_PV, perfect >= 1. */
static int plausible_state(const struct bsched *s)
{
    /* count - 1 < MAX covers both bounds and stays meaningful when MAX is 65535. */
    return (uint32_t)s->count - 1u < (uint32_t)BSCHED_MAX_PROCS &&
           s->maxpv <= BSCHED_MAX_PV && s->perfect >= 1u;
}

int32_t bsched_init(struct bsched *s, const uint8_t *pv, size_t count)
{
    /* Per class: its size, then (after the prefix sum) its first slot in order[]. */
    uint32_t class_size[BSCHED_MAX_PV + 1];
    uint32_t class_next[BSCHED_MAX_PV + 1];
    uint32_t maxpv = 0u;
    uint32_t first = 0u;
    uint32_t carry = 0u;
    uint32_t start = 0u;
    uint32_t slots = 1u;
    uint32_t i;
    uint32_t k;

    if (s == NULL || pv == NULL) {
        return BSCHED_ERR_NULL;
    }
    if (count == 0u) {
        return BSCHED_ERR_NO_PROCS;
    }
    if (count > (size_t)BSCHED_MAX_PROCS) {
        return BSCHED_ERR_TOO_MANY;
    }
    /* Validate everything before writing anything: bad input leaves *s as it was. */
    for (i = 0u; i < (uint32_t)count; i++) {
        if (pv[i] > BSCHED_MAX_PV) {
            return BSCHED_ERR_PV_RANGE;
        }
    }

    for (k = 0u; k <= BSCHED_MAX_PV; k++) {
        class_size[k] = 0u;
    }
    for (i = 0u; i < (uint32_t)count; i++) {
        class_size[pv[i]]++;
        if (pv[i] > maxpv) {
            maxpv = pv[i];
        }
    }
    for (k = 0u; k <= BSCHED_MAX_PV; k++) {
        class_next[k] = first;
        first += class_size[k];
    }

    /* Stable counting sort: ties keep the caller's order. */
    for (i = 0u; i < (uint32_t)count; i++) {
        s->pv[i] = pv[i];
        s->order[class_next[pv[i]]] = (uint16_t)i;
        class_next[pv[i]]++;
    }

    /* perfect = ceil(sum_k c_k 2^-k), folded from the top class down:
     * ceil(c_(k-1) + x/2) = c_(k-1) + ceil(ceil(x)/2), so 32 bits suffice. */
    for (k = maxpv; k > 0u; k--) {
        carry = (class_size[k] + carry + 1u) / 2u;
    }
    s->perfect = (uint16_t)(class_size[0] + carry);

    /* Fig. 6. Class 0 runs every cycle. For class k >= 1, member j gets
     * reverse_k((start + j) mod 2^k); start and the slot count double per class. */
    first = class_size[0];
    for (i = 0u; i < class_size[0]; i++) {
        s->offset[s->order[i]] = 0u;
    }
    for (k = 1u; k <= maxpv; k++) {
        start = start * 2u;
        slots = slots * 2u;
        for (i = 0u; i < class_size[k]; i++) {
            s->offset[s->order[first + i]] = reverse_bits((start + i) % slots, k);
        }
        start = (start + class_size[k]) % slots;
        first += class_size[k];
    }

    for (i = 0u; i < (uint32_t)count; i++) {
        s->wait[i] = s->offset[i];
    }
    s->count = (uint16_t)count;
    s->maxpv = (uint8_t)maxpv;
    s->cycle = 0u;
    s->ran_count = 0u;
    return BSCHED_OK;
}

int32_t bsched_step(struct bsched *s)
{
    uint32_t done = 0u;
    uint32_t id;
    uint32_t i;

    if (s == NULL) {
        return BSCHED_ERR_NULL;
    }
    if (!plausible_state(s)) {
        return BSCHED_ERR_STATE;
    }

    /* Fig. 7, lines 5-12: run the due processes in order, at most `perfect`. */
    for (id = 0u; id < s->count && done < s->perfect; id++) {
        uint16_t p = s->order[id];
        if (s->wait[p] == 0u) {
            s->ran[done] = p;
            done++;
            s->wait[p] = period_of(s->pv[p]);
        }
    }
    /* Fig. 7, line 13: every positive wait counts down one cycle. */
    for (i = 0u; i < s->count; i++) {
        if (s->wait[i] > 0u) {
            s->wait[i]--;
        }
    }
    s->ran_count = (uint16_t)done;
    s->cycle = (s->cycle + 1u) % period_of(s->maxpv);
    return (int32_t)done;
}

int32_t bsched_run_cycle(struct bsched *s, bsched_process_fn run, void *context)
{
    int32_t ran;
    uint32_t k;

    if (run == NULL) {
        return BSCHED_ERR_NULL;
    }
    ran = bsched_step(s);
    for (k = 0u; ran > 0 && k < (uint32_t)ran; k++) {
        run(context, s->ran[k]);
    }
    return ran;
}

int32_t bsched_due(const struct bsched *s, uint32_t ahead, uint16_t *due)
{
    uint32_t done = 0u;
    uint32_t id;

    if (s == NULL || due == NULL) {
        return BSCHED_ERR_NULL;
    }
    if (!plausible_state(s)) {
        return BSCHED_ERR_STATE;
    }
    /* wait < 2^pv always, so p is due `ahead` cycles on iff wait == ahead mod 2^pv. */
    for (id = 0u; id < s->count && done < s->perfect; id++) {
        uint16_t p = s->order[id];
        if (s->wait[p] == ahead % period_of(s->pv[p])) {
            due[done] = p;
            done++;
        }
    }
    return (int32_t)done;
}
