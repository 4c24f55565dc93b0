#include "importance.h"
#include "readout.h"

#include <math.h>

static double g_weight(int g, double x)
{
    const double pi = 3.14159265358979323846;
    switch (g) {
    case EX_G_FOLLOW:
    case EX_G_BALANCED:
        return 0.45 + 0.3 * sin(2.0 * pi * x) + (x >= 0.35 ? 0.3 : 0.0);
    case EX_G_MISMATCH:
        return 0.2 + (1.0 - x) * (1.0 - x);
    default:
        return 1.0;
    }
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
