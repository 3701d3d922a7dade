/*
 * bsched_fast.c: Fig. 7's minor cycle from the closed form (see bsched_fast.h).
 *
 * Class k (pv == k) holds c_k members at slots first_k .. first_k + c_k - 1 of
 * s->order[]; member j has the offset rev_k((s_k + j) mod 2^k) (bsched_init's
 * closed form, proven by WP). It runs in cycle t iff t mod 2^k equals that
 * offset, iff (rev_k is an involution) j = Y_k - s_k (mod 2^k) with
 * Y_k = rev_k(t mod 2^k) = R >> (maxpv - k), R = rev_maxpv(t mod 2^maxpv).
 * Visiting the classes upwards and each class's due members upwards visits the
 * slots of order[] upwards: Fig. 7's execution order.
 */
#include "bsched_fast.h"

/* The low `bits` bits of x in reverse order. */
static uint32_t reverse_low_bits(uint32_t x, uint32_t bits)
{
    uint32_t reversed = 0u;
    uint32_t b;

    for (b = 0u; b < bits; b++) {
        reversed = (reversed << 1) | ((x >> b) & 1u);
    }
    return reversed;
}

/* The cheap check of bsched.c's plausible_state, and cycle < 2^maxpv. */
static int plausible(const struct bsched *s)
{
    return s->count != 0u && (uint32_t)s->count - 1u < (uint32_t)BSCHED_MAX_PROCS &&
           s->maxpv <= BSCHED_MAX_PV && s->perfect >= 1u && s->cycle >> s->maxpv == 0u;
}

/* O(1): the table was built (and checked) for a state of this shape, so the
 * state passes plausible() too; and its cycle is within the major cycle. */
static int table_matches(const struct bsched_fast *f, const struct bsched *s)
{
    return f->maxpv == s->maxpv && f->count == s->count && s->perfect != 0u &&
           s->cycle <= f->cycles && f->used != 0u && f->used <= (uint32_t)BSCHED_FAST_CLASSES &&
           f->cycles == ((uint32_t)1u << f->maxpv) - 1u;
}

/* The processes due in the cycle whose bit-reversed number is `reversed`, in
 * execution order, into out[]. With a table from bsched_fast_init each slot of
 * order[] is visited at most once, so at most count entries are written; on a
 * state from bsched_init at most `perfect` (the balance theorem), so Fig. 7's
 * cap at `perfect` never bites and is not repeated here. */
static uint32_t collect_classes(const struct bsched *s, const struct bsched_fast *f,
                                uint32_t reversed, uint16_t *out)
{
    uint32_t done = 0u;
    uint32_t u;

    for (u = 0u; u < f->used; u++) {
        /* Y_k - s_k mod 2^k: the first due member (no wrap: both terms <= 2^k). */
        uint32_t mask = ((uint32_t)1u << f->classes[u].pv) - 1u;
        uint32_t j0 = ((reversed >> f->classes[u].shift) + f->classes[u].lead) & mask;
        uint32_t size = f->classes[u].size;
        uint32_t slot;
        uint32_t stop;

        if (j0 >= size) {
            continue;
        }
        slot = f->classes[u].first + j0;
        stop = done + ((size - 1u - j0) >> f->classes[u].pv) + 1u;
        for (; done != stop; done++) {
            out[done] = s->order[slot];
            slot += mask + 1u;
        }
    }
    return done;
}

/* The same list from the laps: class by class, the laps x = reversed + m 2^maxpv
 * below the total area fall in the classes' intervals [base, end) in ascending
 * order; lap x in class k is its member (x - base) >> (maxpv - k), and the next
 * lap in the same class is member + 2^k. Classes without a lap cost one
 * comparison. Needs area + 2^maxpv < 2^32 (f->laps). */
static uint32_t collect_laps(const struct bsched *s, const struct bsched_fast *f,
                             uint32_t reversed, uint16_t *out)
{
    uint32_t area = f->end[f->used - 1u];
    uint32_t x = reversed;
    uint32_t done = 0u;
    uint32_t u = 0u;

    while (x < area) {
        uint32_t runs;
        uint32_t slot;
        uint32_t stop;
        uint32_t stride;

        while (x >= f->end[u]) {
            u++; /* stops at the last class at the latest: x < area */
        }
        /* (Fields read through the array, not a pointer to the element: the same
         * code for a compiler, far smaller formulas for CBMC.) */
        runs = ((f->end[u] - 1u - x) >> f->maxpv) + 1u;
        slot = f->classes[u].first + ((x - f->classes[u].base) >> f->classes[u].shift);
        stride = (uint32_t)1u << f->classes[u].pv;
        stop = done + runs;
        x += runs << f->maxpv; /* <= end - 1 + 2^maxpv: no wrap when f->laps */
        for (; done != stop; done++) {
            out[done] = s->order[slot];
            slot += stride;
        }
        u++;
    }
    return done;
}

static uint32_t collect_due(const struct bsched *s, const struct bsched_fast *f,
                            uint32_t reversed, uint16_t *out)
{
    return f->laps != 0u ? collect_laps(s, f, reversed, out) : collect_classes(s, f, reversed, out);
}

int32_t bsched_fast_init(struct bsched_fast *f, const struct bsched *s)
{
    struct bsched_fast t;
    uint64_t area;
    uint32_t d;

    if (f == NULL || s == NULL) {
        return BSCHED_ERR_NULL;
    }
    if (!plausible(s)) {
        return BSCHED_ERR_STATE;
    }
    t.maxpv = s->maxpv;
    t.count = s->count;
    t.used = 0u;
    area = 0u;
    /* order[] is sorted by pv: each class is one run of slots. */
    for (d = 0u; d < s->count; d++) {
        uint16_t p = s->order[d];
        uint8_t pv;
        if (p >= s->count || s->pv[p] > s->maxpv) {
            return BSCHED_ERR_STATE;
        }
        pv = s->pv[p];
        if (t.used == 0u || t.classes[t.used - 1u].pv != pv) {
            uint32_t u = t.used;
            if ((u > 0u && t.classes[u - 1u].pv > pv) || u >= (uint32_t)BSCHED_FAST_CLASSES) {
                return BSCHED_ERR_STATE; /* not sorted, or more classes than the table holds */
            }
            if (s->offset[p] >> pv != 0u) {
                return BSCHED_ERR_STATE;
            }
            t.classes[u].pv = pv;
            t.classes[u].shift = (uint8_t)(s->maxpv - pv);
            t.classes[u].first = (uint16_t)d;
            t.classes[u].size = 0u;
            t.classes[u].base = (uint32_t)area; /* only used when the whole area fits */
            t.classes[u].unused = 0u;
            /* Member 0's offset is rev_k(s_k), and rev_k is an involution. */
            t.classes[u].lead = ((uint32_t)1u << pv) - reverse_low_bits(s->offset[p], pv);
            t.used++;
        }
        t.classes[t.used - 1u].size++;
        area += (uint64_t)1u << (s->maxpv - pv);
        t.end[t.used - 1u] = (uint32_t)area;
    }
    t.laps = area + ((uint64_t)1u << s->maxpv) <= 0xFFFFFFFFu ? 1u : 0u;
    if (t.laps != 0u) {
        /* The interval picture and the offsets agree: s_k = B_k mod 2^k, B_k the
         * area below class k in units of 2^-k (Fig. 6; WP's lemma_start_is_area). */
        uint32_t u;
        for (u = 0u; u < t.used; u++) {
            if ((((t.classes[u].base >> t.classes[u].shift) + t.classes[u].lead) &
                 (((uint32_t)1u << t.classes[u].pv) - 1u)) != 0u) {
                return BSCHED_ERR_STATE;
            }
        }
    }
    t.cycle = s->cycle;
    t.cycles = ((uint32_t)1u << s->maxpv) - 1u;
    t.reversed = reverse_low_bits(s->cycle, s->maxpv);
    *f = t;
    return BSCHED_OK;
}

int32_t bsched_fast_step(struct bsched *s, struct bsched_fast *f)
{
    uint32_t reversed;
    uint32_t done;
    uint32_t bit;

    if (s == NULL || f == NULL) {
        return BSCHED_ERR_NULL;
    }
    if (!table_matches(f, s)) {
        return BSCHED_ERR_STATE;
    }
    reversed = f->cycle == s->cycle ? f->reversed : reverse_low_bits(s->cycle, s->maxpv);
    done = collect_due(s, f, reversed, s->ran);
    s->ran_count = (uint16_t)done;
    s->cycle = (s->cycle + 1u) & f->cycles;
    /* rev(t + 1): add 1 at the top bit of the reversed counter, carrying
     * downwards; bit becomes 0 (and ends the loop) only when t was 2^maxpv - 1. */
    bit = (f->cycles + 1u) / 2u;
    while ((reversed & bit) != 0u) {
        reversed &= ~bit;
        bit >>= 1;
    }
    f->reversed = reversed | bit;
    f->cycle = s->cycle;
    return (int32_t)done;
}

int32_t bsched_fast_run_cycle(struct bsched *s, struct bsched_fast *f,
                              bsched_process_fn run, void *context)
{
    int32_t ran;
    uint32_t k;

    if (run == NULL) {
        return BSCHED_ERR_NULL;
    }
    ran = bsched_fast_step(s, f);
    for (k = 0u; ran > 0 && k < (uint32_t)ran; k++) {
        run(context, s->ran[k]);
    }
    return ran;
}

int32_t bsched_fast_due(const struct bsched *s, const struct bsched_fast *f,
                        uint32_t ahead, uint16_t *due)
{
    uint32_t mask;
    uint32_t t;

    if (s == NULL || f == NULL || due == NULL) {
        return BSCHED_ERR_NULL;
    }
    if (!plausible(s) || !table_matches(f, s)) {
        return BSCHED_ERR_STATE;
    }
    mask = ((uint32_t)1u << s->maxpv) - 1u;
    t = (s->cycle + (ahead & mask)) & mask; /* both terms below 2^31: no wrap */
    return (int32_t)collect_due(s, f, reverse_low_bits(t, s->maxpv), due);
}

int32_t bsched_wait(const struct bsched *s, uint16_t i)
{
    uint32_t mask;

    if (s == NULL) {
        return BSCHED_ERR_NULL;
    }
    if (!plausible(s)) {
        return BSCHED_ERR_STATE;
    }
    if (i >= s->count) {
        return BSCHED_ERR_INDEX;
    }
    if (s->pv[i] > BSCHED_MAX_PV || s->offset[i] >> s->pv[i] != 0u) {
        return BSCHED_ERR_STATE;
    }
    mask = ((uint32_t)1u << s->pv[i]) - 1u;
    /* (offset - t) mod 2^pv, written without an unsigned wrap. */
    return (int32_t)((s->offset[i] + (mask + 1u) - (s->cycle & mask)) & mask);
}
