#include "spectra_ref.h"
#include "unity.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

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

void spectra_make_importance(mcs_importance *imp, size_t n, double base, size_t mult,
                             size_t bump_bin, double bump)
{
    static double g[MCS_MAX_N];
    for (size_t b = 0; b < n; ++b)
        g[b] = base + (double)((b * mult) % n) / (double)n + (b == bump_bin ? bump : 0.0);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(imp, n, g));
}

void spectra_run(mcs_spectrum *a, mcs_pattern_kind kind, size_t n, size_t k,
                 const mcs_importance *importance, uint64_t seed, uint64_t seq, size_t trials,
                 size_t *bins, double *weights)
{
    spectra_stream st;
    spectra_stream_init(&st, kind, n, k, importance, seed, seq);
    for (size_t t = 0; t < trials; ++t) {
        spectra_stream_draw(&st, bins, weights, NULL);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(a, k, bins, weights));
    }
}

/* The object a bad trial is offered to, its size, a scratch copy and its add. */
typedef struct {
    void *obj, *scratch;
    size_t size;
    spectra_add_bins_fn add;
} bad_trial;

/* add(obj, ...) (add(NULL, ...) when no_object) returns status and leaves
 * obj as it was. */
static void refused(const bad_trial *t, mcs_status status, int no_object, size_t k,
                    const size_t *bins, const double *weights, const char *what)
{
    memcpy(t->scratch, t->obj, t->size);
    TEST_ASSERT_EQUAL_INT_MESSAGE(status, t->add(no_object ? NULL : t->obj, k, bins, weights),
                                  what);
    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(t->scratch, t->obj, t->size, what);
}

void spectra_refuses_bad_trials(void *obj, void *scratch, size_t size, size_t n,
                                spectra_add_bins_fn add, size_t *bins, double *weights,
                                size_t bin_at, size_t weight_at)
{
    const bad_trial t = {obj, scratch, size, add};
    const size_t bin = bins[bin_at];
    const double weight = weights[weight_at];
    refused(&t, MCS_ERR_NULL, 1, 3u, bins, weights, "NULL object");
    refused(&t, MCS_ERR_NULL, 0, 3u, NULL, weights, "NULL bins");
    refused(&t, MCS_ERR_NULL, 0, 3u, bins, NULL, "NULL weights");
    refused(&t, MCS_ERR_K_RANGE, 0, 0u, bins, weights, "K = 0");
    bins[bin_at] = n;
    refused(&t, MCS_ERR_BIN_RANGE, 0, 3u, bins, weights, "bin N");
    bins[bin_at] = bin;
    weights[weight_at] = NAN;
    refused(&t, MCS_ERR_NOT_FINITE, 0, 3u, bins, weights, "NaN weight");
    weights[weight_at] = -weight;
    refused(&t, MCS_ERR_NEGATIVE, 0, 3u, bins, weights, "negative weight");
    weights[weight_at] = weight;
}

void spectra_assert_close(double expected, double actual, double tol, double scale,
                          const char *what, size_t a, size_t b)
{
    if (!(fabs(actual - expected) <= tol * (fabs(expected) + scale))) {
        char msg[160];
        (void)snprintf(msg, sizeof msg, "%s (%zu, %zu): expected %.17g, got %.17g", what, a, b,
                       expected, actual);
        TEST_FAIL_MESSAGE(msg);
    }
}

double spectra_mean_power(const mcs_spectrum *acc)
{
    double sum = 0.0;
    for (size_t f = 0; f < acc->n; ++f) {
        double p;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(acc, f, &p));
        sum += p;
    }
    return sum / (double)acc->n;
}

/* A value no read-out computes: a huge negative with a ragged mantissa. */
static const double guard_word = -7.0312500000000011e300;

void spectra_guard_set(double *buf, size_t len)
{
    buf[len] = guard_word;
}

void spectra_guard_check(const double *buf, size_t len, const char *what)
{
    if (memcmp(&buf[len], &guard_word, sizeof guard_word) != 0) {
        char msg[160];
        (void)snprintf(msg, sizeof msg, "%s wrote past its %zu outputs (guard word now %.17g)",
                       what, len, buf[len]);
        TEST_FAIL_MESSAGE(msg);
    }
}
