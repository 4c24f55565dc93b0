#include "importance.h"
#include "exact.h"
#include "readout.h"

#include <math.h>

/* The parameters the weights and ex_g_inverse_integral share. */
static const double mismatch_c = 0.2;               /* g2 = c + (1 - x)^2 */
static const double smooth_a = 0.45, smooth_b = 0.3; /* a + b sin(2 pi x) */

static double g_weight(int g, double x)
{
    const double pi = 3.14159265358979323846;
    switch (g) {
    case EX_G_FOLLOW:
    case EX_G_BALANCED:
        return 0.45 + 0.3 * sin(2.0 * pi * x) + (x >= 0.35 ? 0.3 : 0.0);
    case EX_G_MISMATCH:
        return mismatch_c + (1.0 - x) * (1.0 - x);
    case EX_G_UNRELATED:
        return 1.0 + 0.6 * sin(10.0 * pi * x + 1.0);
    case EX_G_PROPORTIONAL:
        return ex_integrand(x);
    case EX_G_SMOOTH:
        return smooth_a + smooth_b * sin(2.0 * pi * x);
    default:
        return 1.0;
    }
}

double ex_g_inverse_integral(int g)
{
    if (g == EX_G_MISMATCH) {
        /* mean of g: c + 1/3; integral of 1/(c + u^2) over [0, 1): atan(1/sqrt c)/sqrt c */
        const double r = sqrt(mismatch_c);
        return (mismatch_c + 1.0 / 3.0) * atan(1.0 / r) / r;
    }
    if (g == EX_G_SMOOTH) /* mean a; integral of 1/(a + b sin) over a period: 1/sqrt(a^2 - b^2) */
        return smooth_a / sqrt(smooth_a * smooth_a - smooth_b * smooth_b);
    return EX_NA;
}

mcs_status ex_importance_for(int g, size_t m, size_t k, mcs_importance *imp)
{
    static double w[MCS_MAX_N];
    for (size_t b = 0; b < m; ++b)
        w[b] = g_weight(g, ((double)b + 0.5) / (double)m);
    if (g == EX_G_BALANCED && m % k == 0u) {
        size_t block = m / k;
        for (size_t s0 = 0; s0 < m; s0 += block) {
            double mass = 0.0;
            for (size_t b = s0; b < s0 + block; ++b)
                mass += w[b];
            for (size_t b = s0; b < s0 + block; ++b)
                w[b] /= mass;
        }
    }
    return mcs_importance_init(imp, m, w);
}

double ex_closed_power_at(mcs_pattern_kind kind, const mcs_importance *imp, size_t m, size_t k,
                          size_t q)
{
    double v = 0.0;
    mcs_status st;
    if (kind == MCS_PATTERN_RANDOM)
        st = imp == NULL ? mcs_eq23_random_power(m, k, q, &v)
                         : mcs_eq45_importance_power(imp, k, q, &v);
    else if (imp == NULL)
        st = mcs_eq33_stratified_power_limit(m, k, ex_fold(m, q), &v);
    else
        st = mcs_eq50_importance_stratified_power(imp, k, ex_fold(m, q), &v);
    return ex_or_na(st, &v);
}

double ex_whole_bin_power_at(size_t m, size_t k, double h, size_t q)
{
    double v = 0.0;
    if (mcs_eq33_stratified_power_exact(m, k, q, &v) != MCS_OK)
        return EX_NA;
    return v + (double)k / (double)m * (1.0 / h - 1.0);
}

double ex_strata_misalignment(const mcs_importance *imp, size_t k)
{
    double sum = 0.0;
    for (size_t j = 1; j < k; ++j) {
        const double u = (double)j / (double)k;
        size_t b = 0;
        (void)mcs_importance_warp(imp, u, NULL, &b);
        const double lo = u - imp->cdf[b], hi = imp->cdf[b + 1u] - u;
        sum += fmin(lo, hi) / (imp->cdf[b + 1u] - imp->cdf[b]);
    }
    return k > 1u ? sum / (double)(k - 1u) : 0.0;
}

/* Importance functions over m bins, one kept for the tables' N and one for
 * the larger N, each rebuilt only when (g, m, K) changes: the limit checks
 * ask for them once per frequency. */
typedef struct {
    int g;
    size_t m, k;
    mcs_importance imp;
} imp_slot;

static imp_slot slots[2]; /* m = 0: empty */

/* Run r's g over m bins; NULL without importance or on failure. */
static const mcs_importance *importance_at(const ex_imp_run *r, size_t m)
{
    if (r->g == EX_G_NONE)
        return NULL;
    imp_slot *s = &slots[m == r->n ? 0 : 1];
    if (s->g != r->g || s->m != m || s->k != r->k) {
        s->m = 0u;
        if (ex_importance_for(r->g, m, r->k, &s->imp) != MCS_OK)
            return NULL;
        s->g = r->g;
        s->m = m;
        s->k = r->k;
    }
    return &s->imp;
}

/* H of run r's g over m bins (1 without importance; the flat g's at N). */
static double h_at(const ex_imp_run *r, size_t m)
{
    if (r->g == EX_G_NONE)
        return 1.0;
    const mcs_importance *imp = importance_at(r, r->g == EX_G_FLAT ? r->n : m);
    return imp != NULL ? imp->harmonic_mean : EX_NA;
}

double ex_imp_closed_power(const ex_imp_run *r, size_t m, size_t q)
{
    return ex_closed_power_at(r->kind, importance_at(r, m), m, r->k, q);
}

double ex_imp_exact_power(const ex_imp_run *r, size_t m, size_t q)
{
    const int g = r->g;
    const double h = h_at(r, m);
    if (r->kind != MCS_PATTERN_STRATIFIED ||
        (g != EX_G_NONE && g != EX_G_FLAT && !(g == EX_G_BALANCED && m % r->k == 0u)))
        return EX_NA;
    return ex_whole_bin_power_at(m, r->k, h, q);
}

double ex_imp_mean_power(const ex_imp_run *r, size_t m, int exact)
{
    double sum = 0.0;
    for (size_t q = 1; q < m; ++q)
        sum += exact ? ex_imp_exact_power(r, m, q) : ex_imp_closed_power(r, m, q);
    return sum / (double)(m - 1u);
}

double ex_imp_limit_gap(const ex_imp_run *r, size_t q, double floor_)
{
    const size_t big = ex_large_n(r->n);
    if (big == 0u)
        return EX_NA;
    double c = q == 0u ? ex_imp_mean_power(r, big, 0) : ex_imp_closed_power(r, big, q);
    double e = q == 0u ? ex_imp_mean_power(r, big, 1) : ex_imp_exact_power(r, big, q);
    if (isnan(c) || isnan(e))
        return EX_NA;
    return ex_rel_gap(c, e, floor_ / (double)(big / r->n));
}
