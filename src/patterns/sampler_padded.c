/* Padded samplers (sampler.h): independent 2D sets of the pad kind for each
 * pair of axes (2p, 2p + 1), each pair's points in the order of its own
 * random permutation of [0, K), as pbrt pads dimensions: so two pairs are
 * independent, point by point. */
#include "sampler_internal.h"
#include "mcspec/pattern2d.h"
#include "random/rng_inline.h"

#include <stddef.h>
#include <stdint.h>

/* One pair's randomisation, drawn in the order the pad kind's own 2D draw
 * uses (two Owen keys, two shifts, or two 64-bit shifts), then the permutation
 * key. */
typedef struct {
    uint64_t key[2]; /* the Owen keys drawn */
    double shift[2];
    uint64_t shift64[2];
    uint32_t perm;
} pair_rand;

static void draw_pair(uint32_t pad, mcs_rng *rng, pair_rand *r)
{
    for (int c = 0; c < 2; ++c) {
        r->key[c] = 0u;
        r->shift[c] = 0.0;
        r->shift64[c] = 0u;
        if (pad == (uint32_t)MCS_SAMPLER_SOBOL) {
            r->key[c] = mcs_smp_draw_key_(rng);
        } else if (pad == (uint32_t)MCS_SAMPLER_KRONECKER) {
            uint64_t hi = mcs_rng_next_(rng);
            r->shift64[c] = hi << 32 | mcs_rng_next_(rng);
        } else {
            r->shift[c] = mcs_rng_double_(rng);
        }
    }
    r->perm = mcs_rng_next_(rng);
}

/* Coordinate c of point idx of the pad kind's 2D set of k points, randomised
 * by r (or not, r NULL). */
static double pair_coordinate(uint32_t pad, uint64_t k, uint32_t idx, int c, const pair_rand *r)
{
    switch (pad) {
    case MCS_SAMPLER_SOBOL: {
        uint32_t bits = mcs_smp_sobol_bits_(idx, (size_t)c);
        return r != NULL ? mcs_smp_owen_to_double_(bits, r->key[c])
                         : (double)bits * MCS_SMP_TWO_M32;
    }
    case MCS_SAMPLER_KRONECKER: {
        uint64_t step = c == 0 ? MCS_SMP_KRONECKER_R2_X : MCS_SMP_KRONECKER_R2_Y;
        return mcs_smp_fraction64_((uint64_t)idx * step + (r != NULL ? r->shift64[c] : 0u));
    }
    default: {
        double u;
        if (pad == (uint32_t)MCS_SAMPLER_HALTON)
            u = c == 0 ? (double)mcs_smp_reverse_bits_(idx) * MCS_SMP_TWO_M32
                       : mcs_smp_radical_inverse3_(idx);
        else /* hammersley */
            u = c == 0 ? (double)idx / (double)k
                       : (double)mcs_smp_reverse_bits_(idx) * MCS_SMP_TWO_M32;
        return r != NULL ? mcs_smp_rotate_(u, r->shift[c]) : u;
    }
    }
}

static void fill_pair(const mcs_sampler *s, size_t p, const pair_rand *r, double *points)
{
    const size_t dim = s->dim, k = s->k;
    for (size_t j = 0; j < k; ++j) {
        uint32_t idx = r != NULL ? mcs_pattern2d_permute((uint32_t)j, (uint32_t)k, r->perm)
                                 : (uint32_t)j;
        for (int c = 0; c < 2 && 2u * p + (size_t)c < dim; ++c)
            points[dim * j + 2u * p + (size_t)c] = pair_coordinate(s->pad, k, idx, c, r);
    }
}

void mcs_sampler_draw_padded_(const mcs_sampler *s, mcs_rng *rng, double *points)
{
    for (size_t p = 0; 2u * p < s->dim; ++p) {
        pair_rand r;
        draw_pair(s->pad, rng, &r);
        fill_pair(s, p, &r, points);
    }
}

void mcs_sampler_base_padded_(const mcs_sampler *s, double *points)
{
    for (size_t p = 0; 2u * p < s->dim; ++p)
        fill_pair(s, p, NULL, points);
}
