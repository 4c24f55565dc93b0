#include "spectra_ref.h"
#include "unity.h"

#include <math.h>

#define SPECTRA_REF_MAX 4096

void spectra_naive_dft(size_t n, const double *s, size_t nfreq, double *re, double *im)
{
    static long double c[SPECTRA_REF_MAX], sn[SPECTRA_REF_MAX];
    const long double two_pi = 6.283185307179586476925286766559L;
    for (size_t j = 0; j < n; ++j) {
        c[j] = cosl(two_pi * (long double)j / (long double)n);
        sn[j] = sinl(two_pi * (long double)j / (long double)n);
    }
    const long double scale = 1.0L / sqrtl((long double)n);
    for (size_t k = 0; k < nfreq; ++k) {
        long double ar = 0.0L, ai = 0.0L;
        size_t idx = 0;
        for (size_t m = 0; m < n; ++m) {
            ar += (long double)s[m] * c[idx];
            ai -= (long double)s[m] * sn[idx];
            idx += k;
            if (idx >= n)
                idx -= n;
        }
        re[k] = (double)(ar * scale);
        im[k] = (double)(ai * scale);
    }
}

double spectra_uniform(uint64_t *state, double lo, double hi)
{
    uint64_t x = *state;
    x ^= x << 13;
    x ^= x >> 7;
    x ^= x << 17;
    *state = x;
    return lo + (hi - lo) * ((double)(x >> 11) * (1.0 / 9007199254740992.0));
}

double spectra_max_rel_err(size_t n, const double *a, const double *b, double scale)
{
    double worst = 0.0;
    for (size_t k = 0; k < n; ++k) {
        double e = fabs(a[k] - b[k]) / (fabs(b[k]) + scale);
        if (e > worst)
            worst = e;
    }
    return worst;
}

void spectra_stream_init(spectra_stream *st, mcs_pattern_kind kind, size_t n, size_t k,
                         const mcs_importance *importance, uint64_t seed, uint64_t seq)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&st->pat, kind, n, k, importance));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&st->rng, seed, seq));
    st->k = k;
}

void spectra_stream_draw(spectra_stream *st, size_t *bins, double *weights, double *points)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK,
                          mcs_pattern_draw(&st->pat, &st->rng, st->k, bins, weights, points));
}
