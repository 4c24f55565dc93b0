/* Tests of the discrepancies (discrepancy.h): the closed forms against a
 * direct O(d K^2) sum in long double over all K^2 pairs, against the
 * definitions (the L2 star discrepancy as the integral of the squared local
 * discrepancy, cell by cell, in 1D and 2D; the centred one in 1D; the
 * generalized one as the sum of the L2 star discrepancies of every
 * projection), exact values of hand-made sets, the symmetries each measure
 * has (the wrap-around one under toroidal shifts, the centred, symmetric and
 * unanchored ones under reflections); the exact random expectations by exact
 * quadrature (K = 1, 2) and by Monte Carlo with fixed seeds within 5
 * standard errors, a bound that the plausible wrong formulas fail; the exact
 * 2D star discrepancy against a brute force over every box anchored at 0;
 * the accumulator against mcs_welford, its merge and bad input. */
#include "mcspec.h"
#include "points_ref.h"
#include "unity.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

enum { L2N = MCS_DISCREPANCY_L2_COUNT };

static void uniform(mcs_rng *rng, size_t n, double *out)
{
    for (size_t i = 0; i < n; ++i)
        mcs_rng_double(rng, &out[i]);
}

/* ---- independent references -------------------------------------------------- */

/* The six squared discrepancies by their kernels, summed over all K^2 pairs
 * (no symmetry used) in long double. scale[m] gets C0 + 2 |mean g| + mean h,
 * the size of the terms whose difference D^2 is. */
static void ref_l2(size_t k, size_t dim, const double *x, long double *d2, long double *scale)
{
    long double c0[L2N] = {1, 1, 1, 1, 1, 1};
    for (size_t a = 0; a < dim; ++a) {
        c0[0] *= 1.0L / 3.0L;
        c0[1] *= 13.0L / 12.0L;
        c0[2] *= 4.0L / 3.0L;
        c0[3] *= 4.0L / 3.0L;
        c0[4] *= 4.0L / 3.0L;
        c0[5] *= 1.0L / 12.0L;
    }
    long double single[L2N] = {0}, pair[L2N] = {0};
    for (size_t i = 0; i < k; ++i) {
        long double g[L2N] = {1, 1, 1, 1, 1, 1};
        for (size_t a = 0; a < dim; ++a) {
            long double u = x[i * dim + a], c = fabsl(u - 0.5L);
            g[0] *= (1 - u * u) / 2;
            g[1] *= 1 + (c - c * c) / 2;
            g[2] *= 4.0L / 3.0L;
            g[3] *= 1 + 2 * u - 2 * u * u;
            g[4] *= (3 - u * u) / 2;
            g[5] *= u * (1 - u) / 2;
        }
        for (int m = 0; m < L2N; ++m)
            single[m] += g[m];
        for (size_t j = 0; j < k; ++j) {
            long double h[L2N] = {1, 1, 1, 1, 1, 1};
            for (size_t a = 0; a < dim; ++a) {
                long double u = x[i * dim + a], v = x[j * dim + a];
                long double mx = u > v ? u : v, mn = u < v ? u : v, t = fabsl(u - v);
                h[0] *= 1 - mx;
                h[1] *= 1 + (fabsl(u - 0.5L) + fabsl(v - 0.5L) - t) / 2;
                h[2] *= 1.5L - t * (1 - t);
                h[3] *= 2 * (1 - t);
                h[4] *= 2 - mx;
                h[5] *= mn * (1 - mx);
            }
            for (int m = 0; m < L2N; ++m)
                pair[m] += h[m];
        }
    }
    const long double kk = (long double)k;
    for (int m = 0; m < L2N; ++m) {
        d2[m] = c0[m] - 2 * single[m] / kk + pair[m] / (kk * kk);
        if (scale != NULL)
            scale[m] = c0[m] + 2 * single[m] / kk + pair[m] / (kk * kk);
    }
}

/* The L2 star discrepancy by its definition in 1D: the integral of
 * (#{x_i < t}/K - t)^2 over [0,1], exactly, piece by piece between the
 * sorted points. */
static double def_star_1d(size_t k, const double *x)
{
    double s[64];
    TEST_ASSERT_TRUE(k <= 64u);
    memcpy(s, x, k * sizeof *s);
    for (size_t i = 1; i < k; ++i) /* insertion sort */
        for (size_t j = i; j > 0 && s[j - 1] > s[j]; --j) {
            double t = s[j];
            s[j] = s[j - 1];
            s[j - 1] = t;
        }
    long double total = 0, t0 = 0;
    for (size_t i = 0; i <= k; ++i) {
        long double t1 = i < k ? s[i] : 1.0L, c = (long double)i / (long double)k;
        total += (powl(c - t0, 3) - powl(c - t1, 3)) / 3;
        t0 = t1;
    }
    return (double)total;
}

/* The centred L2 discrepancy by its definition in 1D: the box from t to the
 * nearer end of [0,1], so the integral over [0, 1/2] of
 * (#{x_i < t}/K - t)^2 plus that over [1/2, 1] of (#{x_i >= t}/K - (1 - t))^2,
 * exactly on the pieces between the breakpoints (count at the midpoint). */
static double def_centered_1d(size_t k, const double *x)
{
    double br[64 + 3];
    size_t nb = 0;
    TEST_ASSERT_TRUE(k <= 64u);
    br[nb++] = 0.0;
    br[nb++] = 0.5;
    br[nb++] = 1.0;
    for (size_t i = 0; i < k; ++i)
        br[nb++] = x[i];
    for (size_t i = 1; i < nb; ++i)
        for (size_t j = i; j > 0 && br[j - 1] > br[j]; --j) {
            double t = br[j];
            br[j] = br[j - 1];
            br[j - 1] = t;
        }
    long double total = 0;
    for (size_t p = 0; p + 1 < nb; ++p) {
        long double t0 = br[p], t1 = br[p + 1], mid = (t0 + t1) / 2;
        if (t1 == t0)
            continue;
        size_t n = 0;
        for (size_t i = 0; i < k; ++i)
            n += mid < 0.5L ? (x[i] < mid) : (x[i] >= mid);
        long double c = (long double)n / (long double)k;
        if (mid < 0.5L) /* (c - t)^2 */
            total += (powl(c - t0, 3) - powl(c - t1, 3)) / 3;
        else /* (c - 1 + t)^2 */
            total += (powl(c - 1 + t1, 3) - powl(c - 1 + t0, 3)) / 3;
    }
    return (double)total;
}

/* The L2 star discrepancy by its definition in 2D: the integral over (a, b)
 * of (#{x < a, y < b}/K - a b)^2, exactly on every cell of the grid of the
 * coordinates (the count is constant on a cell: taken at its centre). */
static double def_star_2d(size_t k, const double *p)
{
    double xs[34], ys[34];
    size_t n = 0;
    TEST_ASSERT_TRUE(k <= 32u);
    xs[n] = 0.0;
    ys[n++] = 0.0;
    for (size_t i = 0; i < k; ++i) {
        xs[n] = p[2 * i];
        ys[n++] = p[2 * i + 1];
    }
    xs[n] = 1.0;
    ys[n++] = 1.0;
    for (size_t i = 1; i < n; ++i)
        for (size_t j = i; j > 0; --j) {
            if (xs[j - 1] > xs[j]) {
                double t = xs[j];
                xs[j] = xs[j - 1];
                xs[j - 1] = t;
            }
            if (ys[j - 1] > ys[j]) {
                double t = ys[j];
                ys[j] = ys[j - 1];
                ys[j - 1] = t;
            }
        }
    long double total = 0;
    for (size_t i = 0; i + 1 < n; ++i)
        for (size_t j = 0; j + 1 < n; ++j) {
            long double a0 = xs[i], a1 = xs[i + 1], b0 = ys[j], b1 = ys[j + 1];
            if (a1 == a0 || b1 == b0)
                continue;
            long double am = (a0 + a1) / 2, bm = (b0 + b1) / 2, c = 0;
            for (size_t q = 0; q < k; ++q)
                c += p[2 * q] < am && p[2 * q + 1] < bm;
            c /= (long double)k;
            total += c * c * (a1 - a0) * (b1 - b0) -
                     2 * c * ((a1 * a1 - a0 * a0) / 2) * ((b1 * b1 - b0 * b0) / 2) +
                     ((a1 * a1 * a1 - a0 * a0 * a0) / 3) * ((b1 * b1 * b1 - b0 * b0 * b0) / 3);
        }
    return (double)total;
}

/* The exact star discrepancy by brute force: every box anchored at 0 with
 * its corner at a point's coordinates or 1, open and closed, O(K^3). */
static double brute_star(size_t k, const double *p)
{
    double best = 0.0;
    for (size_t i = 0; i <= k; ++i)
        for (size_t j = 0; j <= k; ++j) {
            const double a = i < k ? p[2 * i] : 1.0, b = j < k ? p[2 * j + 1] : 1.0;
            size_t open = 0, closed = 0;
            for (size_t q = 0; q < k; ++q) {
                open += p[2 * q] < a && p[2 * q + 1] < b;
                closed += p[2 * q] <= a && p[2 * q + 1] <= b;
            }
            const double lo = a * b - (double)open / (double)k;
            const double hi = (double)closed / (double)k - a * b;
            best = lo > best ? lo : best;
            best = hi > best ? hi : best;
        }
    return best;
}

static void l2_ok(size_t k, size_t dim, const double *x, double *d2)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_discrepancy_l2(k, dim, x, d2));
}

/* The rounding the header allows D^2 of measure m of this set: (d + 70) u
 * of the terms it is the difference of, with room 4. */
static double rounding(size_t k, size_t dim, const double *x, int m)
{
    long double d2[L2N], scale[L2N];
    ref_l2(k, dim, x, d2, scale);
    return 4.0 * (double)(dim + 70u) * (DBL_EPSILON / 2) * (double)scale[m];
}

/* ---- the closed forms ---------------------------------------------------------- */

static void test_l2_matches_a_direct_long_double_sum_in_every_dimension(void)
{
    static const size_t dims[] = {1, 2, 3, 5, 16, 64};
    static const size_t ks[] = {1, 2, 7, 100};
    static double x[100 * 64];
    mcs_rng rng;
    mcs_rng_seed(&rng, 2025u, 1u);
    for (size_t a = 0; a < sizeof dims / sizeof dims[0]; ++a)
        for (size_t b = 0; b < sizeof ks / sizeof ks[0]; ++b) {
            const size_t d = dims[a], k = ks[b];
            uniform(&rng, k * d, x);
            double got[L2N];
            long double want[L2N], scale[L2N];
            l2_ok(k, d, x, got);
            ref_l2(k, d, x, want, scale);
            for (int m = 0; m < L2N; ++m) {
                /* the header's bound, (d + 70) u of the terms, with room 4 */
                const double tol = 4.0 * (double)(d + 70u) * DBL_EPSILON / 2 * (double)scale[m];
                char msg[96];
                snprintf(msg, sizeof msg, "%s d=%zu K=%zu", mcs_discrepancy_measure_str(m), d, k);
                TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(tol, (double)want[m], got[m], msg);
            }
        }
}

static void test_hand_made_sets_have_their_exact_values(void)
{
    /* One point at 1/2 in 1D: star and centred 1/12 (1/24 from each side),
     * wrap-around 1/6 and unanchored 1/12 for any point, symmetric
     * 4/3 - 4x + 4x^2 = 1/3, generalized 1/3 - x + x^2 = 1/12. */
    double half = 0.5, d2[L2N];
    l2_ok(1, 1, &half, d2);
    const double one[L2N] = {1.0 / 12, 1.0 / 12, 1.0 / 6, 1.0 / 3, 1.0 / 12, 1.0 / 12};
    for (int m = 0; m < L2N; ++m)
        TEST_ASSERT_DOUBLE_WITHIN(1e-15, one[m], d2[m]);
    /* Any single point of [0,1)^d: WD^2 = (3/2)^d - (4/3)^d. */
    const double p3[3] = {0.1, 0.7, 0.95};
    l2_ok(1, 3, p3, d2);
    TEST_ASSERT_DOUBLE_WITHIN(1e-14, pow(1.5, 3) - pow(4.0 / 3, 3), d2[MCS_DISCREPANCY_L2_WRAPAROUND]);
    /* {1/4, 3/4}: star 1/192 + 2/192 + 1/192 = 1/48 (piece by piece). */
    const double two[2] = {0.25, 0.75};
    l2_ok(2, 1, two, d2);
    TEST_ASSERT_DOUBLE_WITHIN(1e-16, 1.0 / 48, d2[MCS_DISCREPANCY_L2_STAR]);
    /* 2D, one point at the centre: star 1/9 - (2)(3/8)^2 + 1/4 = 1/9 - 9/32 + 1/4. */
    const double c2[2] = {0.5, 0.5};
    l2_ok(1, 2, c2, d2);
    TEST_ASSERT_DOUBLE_WITHIN(1e-16, 1.0 / 9 - 9.0 / 32 + 0.25, d2[MCS_DISCREPANCY_L2_STAR]);
}

static void test_star_and_centred_match_their_definitions(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 7u, 7u);
    double x[64], d2[L2N];
    for (size_t k = 1; k <= 64u; k += 9u) {
        uniform(&rng, k, x);
        l2_ok(k, 1, x, d2);
        TEST_ASSERT_DOUBLE_WITHIN(1e-15, def_star_1d(k, x), d2[MCS_DISCREPANCY_L2_STAR]);
        TEST_ASSERT_DOUBLE_WITHIN(1e-15, def_centered_1d(k, x), d2[MCS_DISCREPANCY_L2_CENTERED]);
    }
    for (size_t k = 1; k <= 32u; k += 5u) {
        uniform(&rng, 2 * k, x);
        l2_ok(k, 2, x, d2);
        TEST_ASSERT_DOUBLE_WITHIN(1e-15, def_star_2d(k, x), d2[MCS_DISCREPANCY_L2_STAR]);
    }
    /* A point on a cell edge (ties in both coordinates) changes nothing. */
    const double tie[6] = {0.25, 0.5, 0.25, 0.75, 0.5, 0.5};
    l2_ok(3, 2, tie, d2);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, def_star_2d(3, tie), d2[MCS_DISCREPANCY_L2_STAR]);
}

/* Hickernell's generalized L2 discrepancy (beta = 1) expands as the sum over
 * the non-empty subsets u of the coordinates of the L2 star discrepancy of
 * the projection onto u: prod (1 + (1 - max)) = sum_u prod_{k in u} (1 - max). */
static void test_generalized_is_the_sum_of_the_star_discrepancies_of_every_projection(void)
{
    enum { K = 40, D = 3 };
    double x[K * D], proj[K * D], d2[L2N], full[L2N];
    mcs_rng rng;
    mcs_rng_seed(&rng, 5u, 3u);
    uniform(&rng, K * D, x);
    l2_ok(K, D, x, full);
    double sum = 0.0;
    for (unsigned u = 1; u < (1u << D); ++u) {
        size_t du = 0; /* the projection's points, du coordinates each */
        for (size_t i = 0; i < K; ++i)
            for (size_t a = 0; a < D; ++a)
                if (u & (1u << a))
                    proj[du++] = x[i * D + a];
        l2_ok(K, du / K, proj, d2);
        sum += d2[MCS_DISCREPANCY_L2_STAR];
    }
    /* eight closed forms, each within its rounding */
    TEST_ASSERT_DOUBLE_WITHIN(8.0 * rounding(K, D, x, MCS_DISCREPANCY_L2_GENERALIZED), sum,
                              full[MCS_DISCREPANCY_L2_GENERALIZED]);
}

static void test_each_measure_has_the_symmetries_of_its_boxes(void)
{
    enum { K = 50, D = 3 };
    double x[K * D], y[K * D], a[L2N], b[L2N];
    mcs_rng rng;
    mcs_rng_seed(&rng, 11u, 4u);
    uniform(&rng, K * D, x);
    l2_ok(K, D, x, a);
    /* A toroidal shift: only the wrap-around discrepancy stays. */
    const double shift[D] = {0.3, 0.55, 0.91};
    for (size_t i = 0; i < K * D; ++i) {
        double v = x[i] + shift[i % D];
        y[i] = v >= 1.0 ? v - 1.0 : v;
    }
    l2_ok(K, D, y, b);
    double tol[L2N];
    for (int m = 0; m < L2N; ++m)
        tol[m] = 2.0 * rounding(K, D, x, m);
    TEST_ASSERT_DOUBLE_WITHIN(tol[MCS_DISCREPANCY_L2_WRAPAROUND], a[MCS_DISCREPANCY_L2_WRAPAROUND],
                              b[MCS_DISCREPANCY_L2_WRAPAROUND]);
    TEST_ASSERT_TRUE(fabs(a[MCS_DISCREPANCY_L2_STAR] - b[MCS_DISCREPANCY_L2_STAR]) > 1e-6);
    /* A reflection x -> 1 - x of the second coordinate: centred, symmetric,
     * unanchored and wrap-around stay; star and generalized do not. */
    memcpy(y, x, sizeof y);
    for (size_t i = 0; i < K; ++i)
        y[i * D + 1] = 1.0 - x[i * D + 1];
    l2_ok(K, D, y, b);
    const int kept[] = {MCS_DISCREPANCY_L2_CENTERED, MCS_DISCREPANCY_L2_SYMMETRIC,
                        MCS_DISCREPANCY_L2_UNANCHORED, MCS_DISCREPANCY_L2_WRAPAROUND};
    for (size_t m = 0; m < 4; ++m)
        TEST_ASSERT_DOUBLE_WITHIN(tol[kept[m]], a[kept[m]], b[kept[m]]);
    TEST_ASSERT_TRUE(fabs(a[MCS_DISCREPANCY_L2_STAR] - b[MCS_DISCREPANCY_L2_STAR]) > 1e-6);
    TEST_ASSERT_TRUE(fabs(a[MCS_DISCREPANCY_L2_GENERALIZED] - b[MCS_DISCREPANCY_L2_GENERALIZED]) > 1e-6);
    /* Swapping coordinates and reordering points change nothing at all. */
    for (size_t i = 0; i < K; ++i)
        for (size_t c = 0; c < D; ++c)
            y[(K - 1 - i) * D + c] = x[i * D + (D - 1 - c)];
    l2_ok(K, D, y, b);
    for (int m = 0; m < L2N; ++m)
        TEST_ASSERT_DOUBLE_WITHIN(tol[m], a[m], b[m]);
}

static void test_float_points_give_the_bits_of_their_widened_doubles(void)
{
    enum { K = 33, D = 4 };
    float xf[K * D];
    double xd[K * D], a[L2N], b[L2N];
    mcs_rng rng;
    mcs_rng_seed(&rng, 3u, 9u);
    for (size_t i = 0; i < K * D; ++i) {
        double u;
        mcs_rng_double(&rng, &u);
        xf[i] = (float)u < 1.0f ? (float)u : 0.0f;
        xd[i] = xf[i];
    }
    l2_ok(K, D, xd, a);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_discrepancy_l2_f(K, D, xf, b));
    TEST_ASSERT_EQUAL_MEMORY(a, b, sizeof a);
}

static void test_bad_input_is_refused_and_writes_nothing(void)
{
    double x[4] = {0.1, 0.2, 0.3, 0.4}, d2[L2N];
    points_guard_fill(d2, L2N, -7.0);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_discrepancy_l2(2, 2, NULL, d2));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_discrepancy_l2(2, 2, x, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_discrepancy_l2(2, 0, x, d2));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_discrepancy_l2(1, MCS_DISCREPANCY_MAX_DIM + 1, x, d2));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_discrepancy_l2(0, 2, x, d2));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_discrepancy_l2(SIZE_MAX / 2, 4, x, d2));
    const double bad[] = {1.0, -1e-300, NAN, INFINITY, -INFINITY};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
        x[3] = bad[i];
        TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_discrepancy_l2(2, 2, x, d2));
    }
    const float badf[2] = {0.5f, 1.0f};
    TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_discrepancy_l2_f(1, 2, badf, d2));
    points_guard_check(d2, L2N, -7.0);
    double e = -7.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_discrepancy_l2_exact_random(MCS_DISCREPANCY_L2_STAR, 1, 1, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_discrepancy_l2_exact_random(MCS_DISCREPANCY_STAR, 1, 2, &e));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_discrepancy_l2_exact_random(MCS_DISCREPANCY_MEASURES, 1, 2, &e));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_discrepancy_l2_exact_random((mcs_discrepancy_measure)-1, 1, 2, &e));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_discrepancy_l2_exact_random(MCS_DISCREPANCY_L2_STAR, 1, 0, &e));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_discrepancy_l2_exact_random(MCS_DISCREPANCY_L2_STAR, 1, 65, &e));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_discrepancy_l2_exact_random(MCS_DISCREPANCY_L2_STAR, 0, 2, &e));
    TEST_ASSERT_EQUAL_DOUBLE(-7.0, e);
    TEST_ASSERT_EQUAL_STRING("l2_star", mcs_discrepancy_measure_str(MCS_DISCREPANCY_L2_STAR));
    TEST_ASSERT_EQUAL_STRING("l2_wraparound", mcs_discrepancy_measure_str(MCS_DISCREPANCY_L2_WRAPAROUND));
    TEST_ASSERT_EQUAL_STRING("star", mcs_discrepancy_measure_str(MCS_DISCREPANCY_STAR));
    TEST_ASSERT_EQUAL_STRING("unknown", mcs_discrepancy_measure_str(MCS_DISCREPANCY_MEASURES));
}

/* ---- the exact random expectations -------------------------------------------- */

static double exact_random(int m, size_t k, size_t d)
{
    double e = 0.0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_discrepancy_l2_exact_random((mcs_discrepancy_measure)m, k, d, &e));
    return e;
}

static void test_exact_random_values_are_the_table_of_the_header(void)
{
    for (size_t d = 1; d <= 64u; d += 9u)
        for (size_t k = 1; k <= 1000u; k *= 10u) {
            const double kk = (double)k, dd = (double)d;
            const double want[L2N] = {
                (pow(0.5, dd) - pow(1.0 / 3, dd)) / kk, (pow(1.25, dd) - pow(13.0 / 12, dd)) / kk,
                (pow(1.5, dd) - pow(4.0 / 3, dd)) / kk, (pow(2.0, dd) - pow(4.0 / 3, dd)) / kk,
                (pow(1.5, dd) - pow(4.0 / 3, dd)) / kk, (pow(1.0 / 6, dd) - pow(1.0 / 12, dd)) / kk};
            for (int m = 0; m < L2N; ++m)
                TEST_ASSERT_DOUBLE_WITHIN(1e-13 * fabs(want[m]), want[m], exact_random(m, k, d));
        }
}

/* Gauss-Legendre on [0, 1], 4 nodes (exact to degree 7). */
static const double gl_x[4] = {0.0694318442029737124, 0.3300094782075718676,
                               0.6699905217924281324, 0.9305681557970262876};
static const double gl_w[4] = {0.1739274225687269287, 0.3260725774312730713,
                               0.3260725774312730713, 0.1739274225687269287};

/* K = 1: D^2 of one point is a polynomial on each quadrant split at 1/2
 * (the centred kernel's |x - 1/2|), so Gauss-Legendre on the four squares is
 * exact: its mean over the point is E[D^2]. */
static void test_exact_random_of_one_point_is_the_exact_mean_over_the_square(void)
{
    long double mean[L2N] = {0};
    for (int qx = 0; qx < 2; ++qx)
        for (int qy = 0; qy < 2; ++qy)
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j) {
                    double p[2] = {0.5 * (qx + gl_x[i]), 0.5 * (qy + gl_x[j])}, d2[L2N];
                    l2_ok(1, 2, p, d2);
                    for (int m = 0; m < L2N; ++m)
                        mean[m] += 0.25L * gl_w[i] * gl_w[j] * d2[m];
                }
    for (int m = 0; m < L2N; ++m)
        TEST_ASSERT_DOUBLE_WITHIN(1e-14, exact_random(m, 1, 2), (double)mean[m]);
}

/* K = 2 in 1D: D^2(x1, x2) is a polynomial on each piece of the unit square
 * cut at x = 1/2 in both coordinates and along the diagonal (max, min, |x1 -
 * x2|): Gauss-Legendre on the off-diagonal squares, and on each half of a
 * diagonal square through x2 = a + h u, x1 = a + h u v (Jacobian h^2 u),
 * symmetry giving the other half. */
static void test_exact_random_of_two_points_is_the_exact_mean_over_the_pairs(void)
{
    long double mean[L2N] = {0};
    for (int s = 0; s < 2; ++s)
        for (int t = 0; t < 2; ++t)
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j) {
                    double p[2], d2[L2N], w;
                    if (s != t) {
                        p[0] = 0.5 * (s + gl_x[i]);
                        p[1] = 0.5 * (t + gl_x[j]);
                        w = 0.25 * gl_w[i] * gl_w[j];
                    } else {
                        const double u = gl_x[i], v = gl_x[j], a = 0.5 * s;
                        p[1] = a + 0.5 * u;
                        p[0] = a + 0.5 * u * v;
                        w = 2.0 * 0.25 * u * gl_w[i] * gl_w[j];
                    }
                    l2_ok(2, 1, p, d2);
                    for (int m = 0; m < L2N; ++m)
                        mean[m] += (long double)w * d2[m];
                }
    for (int m = 0; m < L2N; ++m)
        TEST_ASSERT_DOUBLE_WITHIN(1e-14, exact_random(m, 2, 1), (double)mean[m]);
}

/* Monte Carlo over sets of independent uniform points: the mean of each D^2
 * within 5 standard errors of its exact expectation; and two wrong formulas
 * a bound this loose could hide (the diagonal left out, E h(x, x) / K; the
 * K - 1 of a pair count, (E h(x, x) - C0) / (K - 1)) are each more than 5
 * standard errors away for some measure and dimension. */
static void test_monte_carlo_means_are_within_5_stderr_of_the_exact_expectation(void)
{
    static const size_t dims[] = {1, 2, 4};
    static const size_t ks[] = {4, 64};
    enum { SETS = 3000 };
    static double x[64 * 4];
    int tried = 0, caught = 0;
    for (size_t a = 0; a < 3; ++a)
        for (size_t b = 0; b < 2; ++b) {
            const size_t d = dims[a], k = ks[b];
            mcs_rng rng;
            mcs_rng_seed(&rng, 100u + d, 7u * k);
            mcs_welford w[L2N];
            for (int m = 0; m < L2N; ++m)
                mcs_welford_init(&w[m]);
            for (int t = 0; t < SETS; ++t) {
                double d2[L2N];
                uniform(&rng, k * d, x);
                l2_ok(k, d, x, d2);
                for (int m = 0; m < L2N; ++m)
                    mcs_welford_add(&w[m], d2[m]);
            }
            for (int m = 0; m < L2N; ++m) {
                double mean, se;
                mcs_welford_mean(&w[m], &mean);
                mcs_welford_stderr(&w[m], &se);
                const double e = exact_random(m, k, d);
                char msg[128];
                snprintf(msg, sizeof msg, "%s d=%zu K=%zu: mean %.6g exact %.6g z %.2f",
                         mcs_discrepancy_measure_str(m), d, k, mean, e, (mean - e) / se);
                TEST_ASSERT_TRUE_MESSAGE(fabs(mean - e) < 5.0 * se, msg);
                /* the wrong forms, C0 from the same table: each that is more
                 * than 15% off must be caught */
                const double c0[L2N] = {pow(1.0 / 3, (double)d), pow(13.0 / 12, (double)d),
                                        pow(4.0 / 3, (double)d), pow(4.0 / 3, (double)d),
                                        pow(4.0 / 3, (double)d), pow(1.0 / 12, (double)d)};
                const double wrong[2] = {e + c0[m] / (double)k, e * (double)k / (double)(k - 1u)};
                for (int w2 = 0; w2 < 2; ++w2) {
                    if (fabs(wrong[w2] - e) <= 0.15 * e)
                        continue;
                    ++tried;
                    caught += fabs(mean - wrong[w2]) > 5.0 * se;
                }
            }
        }
    TEST_ASSERT_EQUAL_INT(tried, caught);
    TEST_ASSERT_TRUE(tried >= 2 * L2N);
}

/* ---- the exact star discrepancy ------------------------------------------------ */

static double star_ok(size_t k, const double *p)
{
    static unsigned char work[MCS_DISCREPANCY_STAR_WORK_SIZE(MCS_DISCREPANCY_STAR_MAX_K)];
    double out = -1.0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_discrepancy_star(k, p, work, sizeof work, &out));
    return out;
}

static void test_star_matches_a_brute_force_over_every_anchored_box(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 77u, 1u);
    double p[2 * 40];
    for (size_t k = 1; k <= 40u; ++k)
        for (int rep = 0; rep < 5; ++rep) {
            uniform(&rng, 2 * k, p);
            if (rep == 1) /* coordinates on a coarse grid: ties in x and in y */
                for (size_t i = 0; i < 2 * k; ++i)
                    p[i] = floor(p[i] * 4.0) / 4.0;
            if (rep == 2 && k > 1u) { /* a duplicate point and one at the origin */
                p[2] = p[0];
                p[3] = p[1];
                p[2 * k - 2] = 0.0;
                p[2 * k - 1] = 0.0;
            }
            TEST_ASSERT_DOUBLE_WITHIN(4 * DBL_EPSILON, brute_star(k, p), star_ok(k, p));
        }
}

static void test_star_of_known_sets(void)
{
    const double centre[2] = {0.5, 0.5};
    TEST_ASSERT_DOUBLE_WITHIN(1e-16, 0.75, star_ok(1, centre)); /* the closed box [0,1/2]^2 */
    const double origin[2] = {0.0, 0.0};
    TEST_ASSERT_DOUBLE_WITHIN(1e-16, 1.0, star_ok(1, origin));
    /* The 4 x 4 grid of cell centres (ties everywhere). */
    double grid[32];
    for (int i = 0; i < 16; ++i) {
        grid[2 * i] = (i % 4 + 0.5) / 4;
        grid[2 * i + 1] = (i / 4 + 0.5) / 4;
    }
    TEST_ASSERT_DOUBLE_WITHIN(1e-16, brute_star(16, grid), star_ok(16, grid));
}

static void test_star_bounds_the_l2_star_discrepancy(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 8u, 8u);
    static double p[2 * 512];
    for (size_t k = 1; k <= 512u; k *= 2u) {
        double d2[L2N];
        uniform(&rng, 2 * k, p);
        l2_ok(k, 2, p, d2);
        const double s = star_ok(k, p);
        TEST_ASSERT_TRUE(sqrt(d2[MCS_DISCREPANCY_L2_STAR]) <= s);
        TEST_ASSERT_TRUE(s <= 1.0);
    }
    /* at the largest K, against the brute force once */
    uniform(&rng, 2 * 300, p);
    TEST_ASSERT_DOUBLE_WITHIN(4 * DBL_EPSILON, brute_star(300, p), star_ok(300, p));
}

static void test_star_float_points_and_bad_input(void)
{
    enum { K = 20 };
    static unsigned char work[MCS_DISCREPANCY_STAR_WORK_SIZE(K) + 16];
    float pf[2 * K];
    double pd[2 * K];
    mcs_rng rng;
    mcs_rng_seed(&rng, 1u, 2u);
    for (size_t i = 0; i < 2 * K; ++i) {
        double u;
        mcs_rng_double(&rng, &u);
        pf[i] = (float)u < 1.0f ? (float)u : 0.0f;
        pd[i] = pf[i];
    }
    double a = -1.0, b = -1.0;
    size_t bytes = 0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_discrepancy_star_work_size(K, &bytes));
    TEST_ASSERT_EQUAL_UINT64(MCS_DISCREPANCY_STAR_WORK_SIZE(K), bytes);
    /* any alignment of the caller's buffer */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_discrepancy_star(K, pd, work + 3, bytes, &a));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_discrepancy_star_f(K, pf, work + 1, bytes, &b));
    TEST_ASSERT_EQUAL_MEMORY(&a, &b, sizeof a);
    TEST_ASSERT_DOUBLE_WITHIN(4 * DBL_EPSILON, brute_star(K, pd), a);

    memset(work, 0xA5, sizeof work);
    double out = -3.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_discrepancy_star(K, NULL, work, bytes, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_discrepancy_star(K, pd, NULL, bytes, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_discrepancy_star(K, pd, work, bytes, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_discrepancy_star(0, pd, work, bytes, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE,
                          mcs_discrepancy_star(MCS_DISCREPANCY_STAR_MAX_K + 1, pd, work, bytes, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_SPACE, mcs_discrepancy_star(K, pd, work, bytes - 1, &out));
    pd[5] = 1.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_discrepancy_star(K, pd, work, bytes, &out));
    pd[5] = 0.5;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_discrepancy_star(K, (const double *)(void *)(work + 8), work, bytes, &out));
    TEST_ASSERT_EQUAL_DOUBLE(-3.0, out);
    for (size_t i = 0; i < sizeof work; ++i)
        TEST_ASSERT_EQUAL_HEX8(0xA5, work[i]);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_discrepancy_star_work_size(0, &bytes));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_discrepancy_star_work_size(MCS_DISCREPANCY_STAR_MAX_K + 1, &bytes));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_discrepancy_star_work_size(1, NULL));
    TEST_ASSERT_EQUAL_UINT64(MCS_DISCREPANCY_STAR_WORK_SIZE(K), bytes);
}

/* ---- the accumulator ------------------------------------------------------------- */

static unsigned char star_work[MCS_DISCREPANCY_STAR_WORK_SIZE(MCS_DISCREPANCY_STAR_MAX_K)];

static void add_ok(mcs_discrepancy *acc, size_t k, const double *p, int with_star)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_discrepancy_add(acc, k, p, with_star ? star_work : NULL,
                                                      with_star ? sizeof star_work : 0u));
}

static double read_mean(const mcs_discrepancy *acc, int m)
{
    double v = NAN;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_discrepancy_mean(acc, (mcs_discrepancy_measure)m, &v));
    return v;
}

static double read_stderr(const mcs_discrepancy *acc, int m)
{
    double v = NAN;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_discrepancy_stderr(acc, (mcs_discrepancy_measure)m, &v));
    return v;
}

static void test_accumulator_gives_the_welford_mean_and_stderr_of_each_measure(void)
{
    enum { SETS = 40, D = 2 };
    static double p[2 * 200];
    mcs_discrepancy acc;
    mcs_welford ref[MCS_DISCREPANCY_MEASURES];
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_discrepancy_init(&acc, D));
    for (int m = 0; m < MCS_DISCREPANCY_MEASURES; ++m)
        mcs_welford_init(&ref[m]);
    mcs_rng rng;
    mcs_rng_seed(&rng, 4u, 4u);
    double inv_k = 0.0;
    size_t k_max = 0;
    for (int t = 0; t < SETS; ++t) {
        const size_t k = 10u + (size_t)(t * 37 % 190); /* mixed K */
        k_max = k > k_max ? k : k_max;
        uniform(&rng, 2 * k, p);
        add_ok(&acc, k, p, t % 4 != 3); /* every fourth set without the star */
        double d2[L2N];
        l2_ok(k, D, p, d2);
        for (int m = 0; m < L2N; ++m)
            mcs_welford_add(&ref[m], d2[m]);
        if (t % 4 != 3) {
            double s = star_ok(k, p);
            mcs_welford_add(&ref[MCS_DISCREPANCY_STAR], s * s);
        }
        inv_k += 1.0 / (double)k;
    }
    inv_k /= SETS;
    for (int m = 0; m < MCS_DISCREPANCY_MEASURES; ++m) {
        double mean, se;
        uint64_t count = 0;
        mcs_welford_mean(&ref[m], &mean);
        mcs_welford_stderr(&ref[m], &se);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_discrepancy_count(&acc, (mcs_discrepancy_measure)m, &count));
        TEST_ASSERT_EQUAL_UINT64(m == MCS_DISCREPANCY_STAR ? 30u : 40u, count);
        TEST_ASSERT_EQUAL_DOUBLE(mean, read_mean(&acc, m));
        TEST_ASSERT_EQUAL_DOUBLE(se, read_stderr(&acc, m));
    }
    /* exact random of mixed K: (E h - C0) times the mean of 1/K */
    for (int m = 0; m < L2N; ++m) {
        double e = NAN;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_discrepancy_exact_random(&acc, (mcs_discrepancy_measure)m, &e));
        TEST_ASSERT_DOUBLE_WITHIN(1e-14 * fabs(e), exact_random(m, 1, D) * inv_k, e);
    }
    double e = -2.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_discrepancy_exact_random(&acc, MCS_DISCREPANCY_STAR, &e));
    TEST_ASSERT_EQUAL_DOUBLE(-2.0, e);
    TEST_ASSERT_EQUAL_UINT64(10u, acc.k_min);
    TEST_ASSERT_EQUAL_UINT64(k_max, acc.k_max);
}

static void test_merge_of_halves_equals_one_pass(void)
{
    enum { SETS = 30, K = 64, D = 3 };
    static double p[K * D];
    mcs_discrepancy one, a, b;
    mcs_discrepancy_init(&one, D);
    mcs_discrepancy_init(&a, D);
    mcs_discrepancy_init(&b, D);
    mcs_rng rng;
    mcs_rng_seed(&rng, 6u, 5u);
    for (int t = 0; t < SETS; ++t) {
        uniform(&rng, K * D, p);
        add_ok(&one, K, p, 1); /* dim 3: the star is skipped, work or not */
        add_ok(t < 11 ? &a : &b, K, p, 0);
    }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_discrepancy_merge(&a, &b));
    for (int m = 0; m < L2N; ++m)
        points_assert_merged(read_mean(&one, m), read_stderr(&one, m), read_mean(&a, m),
                             read_stderr(&a, m));
    uint64_t count = 9;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_discrepancy_count(&a, MCS_DISCREPANCY_STAR, &count));
    TEST_ASSERT_EQUAL_UINT64(0u, count);
    double v = -1.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_EMPTY, mcs_discrepancy_mean(&a, MCS_DISCREPANCY_STAR, &v));
    TEST_ASSERT_EQUAL_DOUBLE(-1.0, v);
    /* self-merge doubles every count */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_discrepancy_merge(&a, &a));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_discrepancy_count(&a, MCS_DISCREPANCY_L2_STAR, &count));
    TEST_ASSERT_EQUAL_UINT64(2u * SETS, count);
    /* other dimension */
    mcs_discrepancy c, before;
    mcs_discrepancy_init(&c, 2);
    before = a;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, mcs_discrepancy_merge(&a, &c));
    TEST_ASSERT_EQUAL_MEMORY(&before, &a, sizeof a);
}

static void test_accumulator_refuses_bad_input_and_changes_nothing(void)
{
    mcs_discrepancy acc, before;
    double p[8] = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8};
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_discrepancy_init(NULL, 2));
    memset(&acc, 0x5A, sizeof acc);
    before = acc;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_discrepancy_init(&acc, 0));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_discrepancy_init(&acc, 65));
    TEST_ASSERT_EQUAL_MEMORY(&before, &acc, sizeof acc);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_discrepancy_add(&acc, 4, p, NULL, 0));

    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_discrepancy_init(&acc, 2));
    add_ok(&acc, 4, p, 1);
    before = acc;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_discrepancy_add(NULL, 4, p, NULL, 0));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_discrepancy_add(&acc, 4, NULL, NULL, 0));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_discrepancy_add(&acc, 0, p, NULL, 0));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_SPACE, mcs_discrepancy_add(&acc, 4, p, star_work, 10));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_discrepancy_add(&acc, 4, p, (void *)p, 1000));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_discrepancy_add(&acc, 4, p, (void *)&acc, 1000));
    p[7] = 1.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_discrepancy_add(&acc, 4, p, NULL, 0));
    p[7] = 0.8;
    TEST_ASSERT_EQUAL_MEMORY(&before, &acc, sizeof acc);
    /* a set too large for the star skips it without needing the space */
    static double big[2 * (MCS_DISCREPANCY_STAR_MAX_K + 1)];
    for (size_t i = 0; i < sizeof big / sizeof big[0]; ++i)
        big[i] = (double)((i * 7919u) % 10007u) / 10007.0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_discrepancy_add(&acc, MCS_DISCREPANCY_STAR_MAX_K + 1, big,
                                                      star_work, 16));
    uint64_t n2 = 0, ns = 0;
    mcs_discrepancy_count(&acc, MCS_DISCREPANCY_L2_STAR, &n2);
    mcs_discrepancy_count(&acc, MCS_DISCREPANCY_STAR, &ns);
    TEST_ASSERT_EQUAL_UINT64(2u, n2);
    TEST_ASSERT_EQUAL_UINT64(1u, ns);
    /* corrupted states */
    before = acc;
    acc.d2[MCS_DISCREPANCY_L2_SYMMETRIC].count = 7;
    mcs_discrepancy copy = acc;
    double v = -1.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_discrepancy_mean(&acc, MCS_DISCREPANCY_L2_STAR, &v));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_discrepancy_add(&acc, 4, p, NULL, 0));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_discrepancy_merge(&acc, &before));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_discrepancy_merge(&before, &acc));
    TEST_ASSERT_EQUAL_MEMORY(&copy, &acc, sizeof acc);
    acc = before;
    acc.d2[MCS_DISCREPANCY_STAR].count = 3;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_discrepancy_count(&acc, MCS_DISCREPANCY_STAR, &ns));
    acc = before;
    acc.d2[MCS_DISCREPANCY_L2_CENTERED].m2 = -1.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_discrepancy_stderr(&acc, MCS_DISCREPANCY_L2_STAR, &v));
    acc = before;
    acc.k_min = acc.k_max + 1u;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_discrepancy_mean(&acc, MCS_DISCREPANCY_L2_STAR, &v));
    acc = before;
    acc.dim = 0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_discrepancy_mean(&acc, MCS_DISCREPANCY_L2_STAR, &v));
    TEST_ASSERT_EQUAL_DOUBLE(-1.0, v);
    acc = before;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_discrepancy_mean(&acc, MCS_DISCREPANCY_MEASURES, &v));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_discrepancy_mean(&acc, MCS_DISCREPANCY_L2_STAR, NULL));
    mcs_discrepancy one;
    mcs_discrepancy_init(&one, 2);
    add_ok(&one, 4, p, 0);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_EMPTY, mcs_discrepancy_stderr(&one, MCS_DISCREPANCY_L2_STAR, &v));
    TEST_ASSERT_EQUAL_DOUBLE(-1.0, v);
    /* float sets give the bits of their widened doubles */
    mcs_discrepancy fa, da;
    mcs_discrepancy_init(&fa, 2);
    mcs_discrepancy_init(&da, 2);
    const float pf[8] = {0.125f, 0.5f, 0.75f, 0.25f, 0.375f, 0.875f, 0.0f, 0.625f};
    double pd[8];
    for (int i = 0; i < 8; ++i)
        pd[i] = pf[i];
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_discrepancy_add_f(&fa, 4, pf, star_work, sizeof star_work));
    add_ok(&da, 4, pd, 1);
    TEST_ASSERT_EQUAL_MEMORY(&da, &fa, sizeof da);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_l2_matches_a_direct_long_double_sum_in_every_dimension);
    RUN_TEST(test_hand_made_sets_have_their_exact_values);
    RUN_TEST(test_star_and_centred_match_their_definitions);
    RUN_TEST(test_generalized_is_the_sum_of_the_star_discrepancies_of_every_projection);
    RUN_TEST(test_each_measure_has_the_symmetries_of_its_boxes);
    RUN_TEST(test_float_points_give_the_bits_of_their_widened_doubles);
    RUN_TEST(test_bad_input_is_refused_and_writes_nothing);
    RUN_TEST(test_exact_random_values_are_the_table_of_the_header);
    RUN_TEST(test_exact_random_of_one_point_is_the_exact_mean_over_the_square);
    RUN_TEST(test_exact_random_of_two_points_is_the_exact_mean_over_the_pairs);
    RUN_TEST(test_monte_carlo_means_are_within_5_stderr_of_the_exact_expectation);
    RUN_TEST(test_star_matches_a_brute_force_over_every_anchored_box);
    RUN_TEST(test_star_of_known_sets);
    RUN_TEST(test_star_bounds_the_l2_star_discrepancy);
    RUN_TEST(test_star_float_points_and_bad_input);
    RUN_TEST(test_accumulator_gives_the_welford_mean_and_stderr_of_each_measure);
    RUN_TEST(test_merge_of_halves_equals_one_pass);
    RUN_TEST(test_accumulator_refuses_bad_input_and_changes_nothing);
    return UNITY_END();
}
