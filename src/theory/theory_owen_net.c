/* The fast route of owen.h for (0,m,2)-nets in base b, whose pair counts
 * per level vector follow from the net property alone (docs/owen.md), and
 * which exact theory each sampler kind has. */
#include "core/internal.h"
#include "mcspec/owen.h"

#include <float.h>
#include <math.h>

/* b^e for b^e <= 2^32 (callers check m first). */
static uint64_t ipow(unsigned base, size_t e)
{
    uint64_t p = 1u;
    while (e-- > 0u)
        p *= base;
    return p;
}

/* b^m <= MCS_OWEN_MAX_K, without overflow. */
static int net_fits(unsigned base, size_t m)
{
    uint64_t p = 1u;
    for (size_t i = 0; i < m; ++i) {
        p *= base;
        if (p > (uint64_t)MCS_OWEN_MAX_K)
            return 0;
    }
    return 1;
}

static mcs_status check_net(unsigned base, size_t m, const void *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    if (base < 2u || base > MCS_OWEN_MAX_BASE)
        return MCS_ERR_DOMAIN;
    return net_fits(base, m) ? MCS_OK : MCS_ERR_K_RANGE;
}

/* Unordered pairs sharing at least a digits in x and c in y: the boxes
 * b^-a x b^-c with a + c <= m hold b^(m-a-c) points each (the net property),
 * b^(a+c) boxes; with a + c >= m a box lies in an elementary box of volume
 * b^-m, which holds one point. K (b^(m-a-c) - 1) / 2 is whole: b^e - 1 is
 * even for odd b, K even for even b and m >= 1. */
static uint64_t at_least(unsigned base, size_t m, size_t a, size_t c)
{
    if (a + c >= m || a >= m || c >= m)
        return 0u;
    return ipow(base, m) * (ipow(base, m - a - c) - 1u) / 2u;
}

/* Exactly (a, c): the second difference of at_least; the sum of the first
 * two terms is at most 3/2 of K^2 / 2 < 2^64, and the result is >= 0. */
static uint64_t exactly(unsigned base, size_t m, size_t a, size_t c)
{
    return at_least(base, m, a, c) + at_least(base, m, a + 1u, c + 1u) -
           at_least(base, m, a + 1u, c) - at_least(base, m, a, c + 1u);
}

/* As in theory_owen.c: a rounding negative of an exact zero reads 0. */
static double nonneg(double v, double k)
{
    return v < 0.0 && v > -64.0 * k * DBL_EPSILON ? 0.0 : v;
}

mcs_status mcs_owen_net_pairs(unsigned base, size_t m, size_t level_x, size_t level_y,
                              uint64_t *out)
{
    mcs_status st = check_net(base, m, out);
    if (st != MCS_OK)
        return st;
    *out = level_x >= m || level_y >= m ? 0u : exactly(base, m, level_x, level_y);
    return MCS_OK;
}

mcs_status mcs_owen_net_power(unsigned base, size_t m, long freq_x, long freq_y, double *out)
{
    mcs_status st = check_net(base, m, out);
    if (st == MCS_OK && (freq_x < -MCS_OWEN_MAX_FREQ || freq_x > MCS_OWEN_MAX_FREQ ||
                         freq_y < -MCS_OWEN_MAX_FREQ || freq_y > MCS_OWEN_MAX_FREQ))
        st = MCS_ERR_FREQ_RANGE;
    if (st != MCS_OK)
        return st;
    /* b^m <= 2^32: m <= 32 levels, each below L of the base (b^m < 2^44). */
    double px[32], py[32];
    for (size_t l = 0; l < m; ++l) {
        st = mcs_owen_phi(base, l, freq_x, &px[l]);
        if (st == MCS_OK)
            st = mcs_owen_phi(base, l, freq_y, &py[l]);
        if (st != MCS_OK)
            return st;
    }
    const double kd = (double)ipow(base, m);
    if (freq_x == 0 && freq_y == 0)
        return mcs_set_(out, kd);
    double sum = 0.0;
    for (size_t a = 0; a < m; ++a)
        for (size_t c = 0; a + c < m; ++c)
            sum += (double)exactly(base, m, a, c) * px[a] * py[c];
    return mcs_set_(out, nonneg(1.0 + 2.0 * sum / kd, kd));
}

mcs_status mcs_owen_theory_of(mcs_sampler_kind kind, size_t dim, mcs_owen_theory *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    if (!mcs_sampler_has_dim(kind, dim))
        return MCS_ERR_KIND;
    switch (kind) {
    case MCS_SAMPLER_SOBOL:
    case MCS_SAMPLER_SOBOL_ND:
    case MCS_SAMPLER_HALTON_OWEN: *out = MCS_OWEN_THEORY_NESTED; break;
    case MCS_SAMPLER_VAN_DER_CORPUT:
    case MCS_SAMPLER_HALTON:
    case MCS_SAMPLER_HAMMERSLEY:
    case MCS_SAMPLER_KRONECKER:
    case MCS_SAMPLER_LATTICE: *out = MCS_OWEN_THEORY_PHASE; break;
    /* permuted digits are not nested (docs/owen.md); padded pairs are
     * Sobol pairs only dimension by dimension */
    default: *out = MCS_OWEN_THEORY_NONE; break;
    }
    return MCS_OK;
}
