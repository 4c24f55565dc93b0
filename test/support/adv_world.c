/* The world of one adversarial row: every pointer argument gets its own
 * region of a static arena, with 64 guard bytes on each side, so a call can
 * be checked byte for byte against a snapshot taken before it. */
#include "adv_world.h"

#include <float.h>
#include <math.h>
#include <string.h>

_Alignas(64) unsigned char adv_arena[ADV_ARENA_BYTES];
_Alignas(64) unsigned char adv_snap[ADV_ARENA_BYTES];
size_t adv_used;
adv_region adv_regs[ADV_MAX_REGIONS];
int adv_nregs;
int adv_overflow;

static void *region(size_t bytes, int slot, int kind)
{
    size_t off = adv_used + ADV_GUARD;
    if (adv_nregs >= ADV_MAX_REGIONS || off + bytes + ADV_GUARD > ADV_ARENA_BYTES) {
        adv_overflow = 1;
        return NULL;
    }
    adv_region *g = &adv_regs[adv_nregs++];
    g->off = off;
    g->bytes = bytes;
    g->slot = slot;
    g->kind = kind;
    memset(adv_arena + adv_used, ADV_GUARD_BYTE, ADV_GUARD);
    memset(adv_arena + off + bytes, ADV_GUARD_BYTE, ADV_GUARD);
    adv_used = (off + bytes + ADV_GUARD + 63u) / 64u * 64u;
    return adv_arena + off;
}

void *adv_dep_alloc(size_t bytes)
{
    static _Alignas(64) unsigned char spare[1u << 17];
    void *p = region(bytes, -1, K_OBJ_IN);
    return p != NULL ? p : spare; /* the overflow flag fails the row */
}

/* ---- contents of input arrays ---- */

static double frac(double x) { return x - floor(x); }

static double fill_value(int role, size_t j)
{
    switch (role) {
    case R_WEIGHT: return 0.5 + 0.25 * (double)(j % 5u);
    case R_IMPW: return 1.0 + (double)(j % 4u);
    case R_POINT: return frac(0.6180339887 * (double)j + 0.05);
    default: return cos(1.3 * (double)j) + 0.25 * (double)(j % 3u);
    }
}

static double mutated_value(int mv)
{
    switch (mv) {
    case MV_NAN: return NAN;
    case MV_PINF: return INFINITY;
    case MV_NINF: return -INFINITY;
    case MV_NEG: return -1.0;
    case MV_SUB: return 4.9406564584124654e-324;
    case MV_HUGE: return 1e300;
    case MV_ZERO: return 0.0;
    case MV_ONE: return 1.0;
    case MV_NZERO: return -0.0;
    case MV_BELOW1: return nextafter(1.0, 0.0);
    case MV_SQRTMAX: return 1.5e154; /* finite, but its square is not */
    default: return DBL_MAX;
    }
}

double adv_scalar_double(const adv_row *r, int i)
{
    const adv_slot *s = &r->fn->slot[i];
    return r->slot == i && r->mk == MK_DBL ? mutated_value(r->mv) : s->dbase;
}

void adv_fill_array(const adv_row *r, int i, void *p, size_t len, size_t n_bins)
{
    const adv_slot *s = &r->fn->slot[i];
    const int mutated = r->slot == i;
    if (s->role == R_RECORD) {
        unsigned char *b = p;
        adv_record(s->len.a, b);
        if (mutated && r->mk == MK_BINS && len > 0u) /* a flipped bit: header, middle, CRC */
            b[r->mv == 0 ? 0u : r->mv == 1 ? len / 2u : len - 1u] ^= 0x10u;
        return;
    }
    if (s->role == R_BINS) {
        size_t *b = p;
        for (size_t j = 0; j < len; ++j)
            b[j] = (j * 5u + 1u) % n_bins;
        if (len > 1u)
            b[1] = b[0]; /* a repeated bin: sums of weights, not single weights */
        if (mutated && r->mk == MK_BINS && len > 0u) {
            if (r->mv == 2)
                for (size_t j = 0; j < len; ++j)
                    b[j] = n_bins - 1u;
            else
                b[len - 1u] = r->mv == 0 ? n_bins : SIZE_MAX;
        }
        return;
    }
    double *d = p;
    for (size_t j = 0; j < len; ++j)
        d[j] = fill_value(s->role, j);
    if (mutated && r->mk == MK_DBL && len > 0u) {
        if (r->mv == MV_ALLMAX)
            for (size_t j = 0; j < len; ++j)
                d[j] = DBL_MAX;
        else
            d[len - 1u] = mutated_value(r->mv);
    }
}

void *adv_region_for(size_t bytes, int slot, int kind) { return region(bytes, slot, kind); }

void adv_world_reset(void)
{
    adv_used = 0;
    adv_nregs = 0;
    adv_overflow = 0;
}
