#include "theory_ref.h"
#include "unity.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

void theory_assert_close(double expected, double actual, double rel, const char *what)
{
    double tol = rel * fmax(1.0, fabs(expected));
    if (!(fabs(expected - actual) <= tol)) {
        char msg[160];
        (void)snprintf(msg, sizeof msg, "%s: expected %.17g, got %.17g", what, expected, actual);
        TEST_FAIL_MESSAGE(msg);
    }
}

void theory_init(mcs_theory *t, mcs_pattern_kind kind, size_t n, size_t k,
                 const mcs_importance *im)
{
    mcs_pattern pat;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, kind, n, k, im));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_init(t, &pat));
}

void theory_make_f(size_t n, double *f, double phase)
{
    for (size_t b = 0; b < n; ++b)
        f[b] = 1.0 + sin(2.3 * (double)b + phase) + 0.5 * cos(0.7 * (double)(b * b)) +
               (double)b / (double)n;
}

void theory_ref_dft(size_t n, const double *x, double *re, double *im)
{
    for (size_t k = 0; k < n; ++k) {
        double r = 0.0, i = 0.0;
        for (size_t t = 0; t < n; ++t) {
            double a = 2.0 * THEORY_PI * (double)((k * t) % n) / (double)n;
            r += cos(a) * x[t];
            i -= sin(a) * x[t];
        }
        re[k] = r / sqrt((double)n);
        im[k] = i / sqrt((double)n);
    }
}

void theory_lumpy_importance(mcs_importance *imp, size_t n)
{
    static double w[MCS_MAX_N];
    for (size_t b = 0; b < n; ++b)
        w[b] = 0.3 + (double)((b * 7u) % 5u) + 0.1 * (double)b;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(imp, n, w));
}

/* ---- brute force ------------------------------------------------------------ */

static size_t bf_bin(const mcs_importance *im, size_t n, double u, double *w)
{
    if (im != NULL) {
        size_t b = 0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_warp(im, u, NULL, &b));
        *w = 1.0 / im->p[b];
        return b;
    }
    size_t b = (size_t)(u * (double)n);
    *w = 1.0;
    return b < n ? b : n - 1u;
}

/* Adds one equally likely outcome; the caller divides by their number at the
 * end (without importance every sum is then an exact integer). */
static void bf_add(size_t n, size_t k, const size_t *bins, const double *w, size_t shift,
                   double *mean, double *second)
{
    double s[MCS_MAX_COV_N] = {0.0};
    for (size_t j = 0; j < k; ++j)
        s[(bins[j] + shift) % n] += w[j];
    for (size_t m = 0; m < n; ++m) {
        mean[m] += s[m];
        for (size_t b = 0; b < n; ++b)
            second[m * n + b] += s[m] * s[b];
    }
}

static void bf_normalise(size_t n, double outcomes, double *mean, double *second)
{
    for (size_t m = 0; m < n; ++m) {
        mean[m] /= outcomes;
        for (size_t b = 0; b < n; ++b)
            second[m * n + b] /= outcomes;
    }
}

/* Odometer over k digits in [0, base): returns 0 when it wraps. */
static int odometer_next(size_t *digit, size_t k, size_t base)
{
    for (size_t j = 0; j < k; ++j) {
        if (++digit[j] < base)
            return 1;
        digit[j] = 0;
    }
    return 0;
}

static void bf_random(size_t n, size_t k, const mcs_importance *im, size_t grid, double *mean,
                      double *second)
{
    size_t bins[THEORY_BF_KMAX] = {0}, digit[THEORY_BF_KMAX] = {0};
    double w[THEORY_BF_KMAX] = {0.0};
    const double gd = (double)grid;
    do {
        for (size_t j = 0; j < k; ++j)
            bins[j] = bf_bin(im, n, ((double)digit[j] + 0.5) / gd, &w[j]);
        bf_add(n, k, bins, w, 0u, mean, second);
    } while (odometer_next(digit, k, grid));
    bf_normalise(n, pow(gd, (double)k), mean, second);
}

static void bf_stratified(mcs_pattern_kind kind, size_t n, size_t k, const mcs_importance *im,
                          size_t grid, double *mean, double *second)
{
    size_t bins[THEORY_BF_KMAX] = {0}, digit[THEORY_BF_KMAX] = {0};
    double w[THEORY_BF_KMAX] = {0.0};
    TEST_ASSERT_EQUAL_UINT(0u, grid % k);
    const size_t cells = grid / k;
    const size_t shifts = kind == MCS_PATTERN_HOMOGENIZED ? n : 1u;
    do {
        for (size_t j = 0; j < k; ++j)
            bins[j] = bf_bin(im, n, ((double)(j * cells + digit[j]) + 0.5) / (double)grid, &w[j]);
        for (size_t d = 0; d < shifts; ++d)
            bf_add(n, k, bins, w, d, mean, second);
    } while (odometer_next(digit, k, cells));
    bf_normalise(n, pow((double)cells, (double)k) * (double)shifts, mean, second);
}

void theory_brute_force(mcs_pattern_kind kind, size_t n, size_t k, const mcs_importance *im,
                        size_t grid, double *mean, double *second)
{
    TEST_ASSERT_TRUE(n <= MCS_MAX_COV_N && k <= THEORY_BF_KMAX);
    memset(mean, 0, n * sizeof *mean);
    memset(second, 0, n * n * sizeof *second);
    size_t bins[THEORY_BF_KMAX] = {0};
    double w[THEORY_BF_KMAX] = {0.0};
    const double gd = (double)grid;
    if (kind == MCS_PATTERN_RANDOM) {
        bf_random(n, k, im, grid, mean, second);
    } else if (kind == MCS_PATTERN_STRATIFIED || kind == MCS_PATTERN_HOMOGENIZED) {
        bf_stratified(kind, n, k, im, grid, mean, second);
    } else if (kind == MCS_PATTERN_JITTER) {
        for (size_t c = 0; c < grid; ++c) {
            double beta = ((double)c + 0.5) / gd;
            for (size_t j = 0; j < k; ++j)
                bins[j] = bf_bin(im, n, ((double)j + beta) / (double)k, &w[j]);
            bf_add(n, k, bins, w, 0u, mean, second);
        }
        bf_normalise(n, gd, mean, second);
    } else { /* uniform, deterministic: the one outcome is the generator's */
        mcs_pattern pat;
        mcs_rng rng;
        mcs_rng_seed(&rng, 9u, 9u);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, kind, n, k, im));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_draw(&pat, &rng, k, bins, w, NULL));
        bf_add(n, k, bins, w, 0u, mean, second);
    }
}

static size_t gcd(size_t a, size_t b)
{
    while (b != 0u) {
        size_t t = a % b;
        a = b;
        b = t;
    }
    return a;
}

size_t theory_lcm(size_t a, size_t b)
{
    return a / gcd(a, b) * b;
}

/* ---- bad integrands ----------------------------------------------------------- */

static mcs_theory th_before;

/* fn(th, n, k, f, g) through whichever of one, two is given. */
static mcs_status call(theory_one_fn one, theory_two_fn two, const mcs_theory *th, size_t n,
                       size_t k, const double *f, const double *g, double *out)
{
    return one != NULL ? one(th, n, k, f, out) : two(th, n, k, f, g, out);
}

static void expect(mcs_status want, theory_one_fn one, theory_two_fn two, const mcs_theory *th,
                   size_t n, size_t k, const double *f, const double *g, double *out)
{
    const double sentinel = -7.25e300;
    double o = sentinel;
    if (th != NULL)
        memcpy(&th_before, th, sizeof th_before);
    TEST_ASSERT_EQUAL_INT(want, call(one, two, th, n, k, f, g, out != NULL ? &o : NULL));
    TEST_ASSERT_EQUAL_MEMORY(&sentinel, &o, sizeof o);
    if (th != NULL)
        TEST_ASSERT_EQUAL_MEMORY(&th_before, th, sizeof th_before);
}

void theory_check_bad_integrands(const mcs_theory *th, theory_one_fn one, theory_two_fn two)
{
    static mcs_theory zero; /* never initialised */
    double f[MCS_MAX_COV_N], bad_f[MCS_MAX_COV_N];
    const size_t n = th->n, k = th->k;
    double out = 0.0;
    theory_make_f(n, f, 0.0);
    memcpy(bad_f, f, sizeof f);
    bad_f[n / 2u] = NAN;
    expect(MCS_ERR_NULL, one, two, NULL, n, k, f, f, &out);
    expect(MCS_ERR_NULL, one, two, th, n, k, NULL, f, &out);
    if (two != NULL)
        expect(MCS_ERR_NULL, one, two, th, n, k, f, NULL, &out);
    expect(MCS_ERR_NULL, one, two, th, n, k, f, f, NULL);
    expect(MCS_ERR_UNINIT, one, two, &zero, n, k, f, f, &out);
    expect(MCS_ERR_MISMATCH, one, two, th, n - 1u, k, f, f, &out);
    expect(MCS_ERR_MISMATCH, one, two, th, n + 1u, k, f, f, &out);
    expect(MCS_ERR_K_RANGE, one, two, th, n, 0u, f, f, &out);
    expect(MCS_ERR_MISMATCH, one, two, th, n, k + 1u, f, f, &out); /* not the pattern's K */
    expect(MCS_ERR_NOT_FINITE, one, two, th, n, k, bad_f, f, &out);
    if (two != NULL)
        expect(MCS_ERR_NOT_FINITE, one, two, th, n, k, f, bad_f, &out);
}
