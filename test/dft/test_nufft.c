/* The type-1 NUFFT (nufft.h) against a direct sum in long double:
 * c_k = sum_j e^{-2 pi i k . x_j} at |k_d| <= F, with
 * max |c - c_direct| <= tol K over random, clustered and edge point sets;
 * the work-memory sizes, the grid sizes KissFFT can take without
 * allocating, and the error contract (bad input changes no byte). */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "mcspec.h"
#include "unity.h"

#if MCS_CONFIG_NUFFT
void setUp(void) {}
#else
/* Built without the NUFFT (config.h, make test-nonufft): every test of it
 * is skipped with this reason, and only the refusals are tested. */
static int testing_the_refusals;
void setUp(void)
{
    if (!testing_the_refusals)
        TEST_IGNORE_MESSAGE("library built with MCS_CONFIG_NUFFT 0: no NUFFT to test");
}
#endif
void tearDown(void) {}

#define MAX_F1 100 /* largest F of the 1D cases */
#define MAX_F2 40  /* largest F of the 2D cases */
#define MAX_K 5000
#define SIDE2 (2 * MAX_F2 + 1)
#define MAX_MODES (SIDE2 * SIDE2 > 2 * MAX_F1 + 1 ? SIDE2 * SIDE2 : 2 * MAX_F1 + 1)
/* The size macro is a constant expression: a firmware-style static buffer. */
#define WORK_BYTES \
    (MCS_NUFFT_SIZE(2, MAX_F2) > MCS_NUFFT_SIZE(1, MAX_F1) ? MCS_NUFFT_SIZE(2, MAX_F2) \
                                                          : MCS_NUFFT_SIZE(1, MAX_F1))

static unsigned char work[WORK_BYTES + 64];
static unsigned char work_copy[WORK_BYTES + 64];
static double points[2 * MAX_K];
static float points_f[2 * MAX_K];
static double out[2 * MAX_MODES], out2[2 * MAX_MODES], out_copy[2 * MAX_MODES];
static long double ref_re[MAX_MODES], ref_im[MAX_MODES];
static long double phase[2][2][2 * MAX_F1 + 1]; /* [axis][re, im][k + F] */

static const double below_one = 0x1.fffffffffffffp-1; /* 1 - 2^-53 */

/* ---- the direct sum, in long double ---- */

/* The phase e^{-2 pi i q x} as cosl and sinl of 2 pi r, r = q x - round(q x)
 * taken exactly (q x = hi + lo by fma, hi - round(hi) exact): accurate to
 * the last bits of the long double format, and still to about 1e-16 where
 * long double is double (valgrind runs x87 code at double precision, so
 * make memcheck sees a reference good to a few 1e-16 per point). */
static void phase_of(double x, size_t q, long double *re, long double *im)
{
    const double qd = (double)q, hi = qd * x, lo = fma(qd, x, -hi);
    const long double r = (long double)(hi - nearbyint(hi)) + (long double)lo;
    const long double arg = 6.283185307179586476925286766559L * r;
    *re = cosl(arg);
    *im = -sinl(arg);
}

/* c_k for the k points, in long double; negative k are the conjugates. In 2D
 * only the rows k_y >= 0 are summed and the others are their mirror
 * (c_{-k} = conj c_k for real points). */
static void direct_sum(size_t dim, size_t f, size_t k)
{
    const size_t side = 2u * f + 1u, modes = dim == 1u ? side : side * side;
    const size_t first = dim == 1u ? 0u : f * side; /* the rows k_y >= 0 */
    for (size_t m = 0; m < modes; ++m)
        ref_re[m] = ref_im[m] = 0.0L;
    for (size_t j = 0; j < k; ++j) {
        for (size_t a = 0; a < dim; ++a) {
            /* Exact seeds every 4 modes, multiplied on by e^{-2 pi i x} in
             * between: 3 roundings at most, 7e-16 where long double is double. */
            long double c1, s1, c = 1.0L, s = 0.0L;
            phase_of(points[j * dim + a], 1u, &c1, &s1);
            for (size_t q = 0; q <= f; ++q) {
                if (q % 4u == 0u)
                    phase_of(points[j * dim + a], q, &c, &s);
                phase[a][0][f + q] = c;
                phase[a][1][f + q] = s;
                phase[a][0][f - q] = c;
                phase[a][1][f - q] = -s;
                const long double c2 = c * c1 - s * s1;
                s = c * s1 + s * c1;
                c = c2;
            }
        }
        if (dim == 1u) {
            for (size_t q = 0; q < side; ++q) {
                ref_re[q] += phase[0][0][q];
                ref_im[q] += phase[0][1][q];
            }
            continue;
        }
        for (size_t qy = f; qy < side; ++qy) {
            const long double yr = phase[1][0][qy], yi = phase[1][1][qy];
            long double *rr = ref_re + qy * side, *ri = ref_im + qy * side;
            for (size_t qx = 0; qx < side; ++qx) {
                const long double xr = phase[0][0][qx], xi = phase[0][1][qx];
                rr[qx] += xr * yr - xi * yi;
                ri[qx] += xr * yi + xi * yr;
            }
        }
    }
    for (size_t m = 0; m < first; ++m) {
        ref_re[m] = ref_re[modes - 1u - m];
        ref_im[m] = -ref_im[modes - 1u - m];
    }
}

/* max |out - direct| over the modes. */
static double max_error(size_t dim, size_t f)
{
    const size_t side = 2u * f + 1u, modes = dim == 1u ? side : side * side;
    long double worst = 0.0L;
    for (size_t m = 0; m < modes; ++m) {
        const long double dr = (long double)out[2u * m] - ref_re[m];
        const long double di = (long double)out[2u * m + 1u] - ref_im[m];
        const long double e = sqrtl(dr * dr + di * di);
        if (e > worst)
            worst = e;
    }
    return (double)worst;
}

/* ---- point sets ---- */

enum { SET_RANDOM, SET_CLUSTERED, SET_EDGE, SET_COUNT };
static const char *const set_name[SET_COUNT] = {"random", "clustered", "edge"};

static double uniform(mcs_rng *rng)
{
    double u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_double(rng, &u));
    return u;
}

/* c + d wrapped into [0, 1). */
static double wrap(double c, double d)
{
    double x = c + d;
    if (x < 0.0)
        x += 1.0;
    if (x >= 1.0)
        x -= 1.0;
    return x < 1.0 ? x : below_one;
}

/* random: i.i.d. uniform. clustered: three clusters of side 1e-3 (one of
 * them across the wrap at 0), points drawn round-robin. edge: the first 64
 * points at the corners of the cube (coordinates 0 and 1 - 2^-53, point j at
 * corner j mod 2^d), the rest uniform: at most 32 points coincide, so the
 * rounding of coincident sums (test_coincident_points_...) stays out. */
static void make_points(int set, size_t dim, size_t k, uint64_t seed)
{
    mcs_rng rng;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, seed, 54u));
    double centre[3][2];
    for (size_t c = 0; c < 3; ++c)
        for (size_t a = 0; a < 2; ++a)
            centre[c][a] = c == 0 ? 0.0002 : uniform(&rng);
    for (size_t j = 0; j < k; ++j)
        for (size_t a = 0; a < dim; ++a) {
            double x = uniform(&rng);
            if (set == SET_CLUSTERED)
                x = wrap(centre[j % 3u][a], 1e-3 * (x - 0.5));
            else if (set == SET_EDGE && j < 64u)
                x = ((j >> a) & 1u) ? below_one : 0.0;
            points[j * dim + a] = x;
        }
}

static mcs_nufft plan;

static void init_plan(size_t dim, size_t f, double tol)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_nufft_init(&plan, dim, f, tol, work, sizeof work));
}

/* ---- accuracy ---- */

static const double tols[] = {1e-6, 1e-9, 1e-12, 1e-14};
static const size_t ks[] = {1, 2, 100, 5000};

#define NTOL (sizeof tols / sizeof tols[0])

/* Every (F, K, set, tol) of one dimension: the worst ratio
 * max |c - c_direct| / (tol K) per tol into worst[NTOL]; fails on any ratio
 * above 1. */
static void worst_ratio_over(size_t dim, const size_t *fs, size_t nf, double *worst)
{
    char msg[160];
    for (size_t fi = 0; fi < nf; ++fi)
        for (size_t ki = 0; ki < sizeof ks / sizeof ks[0]; ++ki)
            for (int set = 0; set < SET_COUNT; ++set) {
                const size_t f = fs[fi], k = ks[ki];
                make_points(set, dim, k, 1000u * fi + 10u * ki + (uint64_t)set);
                direct_sum(dim, f, k);
                for (size_t ti = 0; ti < sizeof tols / sizeof tols[0]; ++ti) {
                    init_plan(dim, f, tols[ti]);
                    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_nufft_type1(&plan, points, k, out));
                    const double ratio = max_error(dim, f) / (tols[ti] * (double)k);
                    if (ratio > worst[ti])
                        worst[ti] = ratio;
                    if (!(ratio <= 1.0)) {
                        (void)snprintf(msg, sizeof msg,
                                       "%zuD F = %zu K = %zu %s tol = %g: error / (tol K) = %.3g",
                                       dim, f, k, set_name[set], tols[ti], ratio);
                        TEST_FAIL_MESSAGE(msg);
                    }
                }
            }
}

static void print_ratios(size_t dim, const double *worst)
{
    printf("%zuD: worst max|c - c_direct| / (tol K):", dim);
    for (size_t ti = 0; ti < NTOL; ++ti)
        printf(" %.3f at %g%s", worst[ti], tols[ti], ti + 1u < NTOL ? "," : "\n");
}

static void test_1d_agrees_with_the_direct_sum_to_tol_k(void)
{
    static const size_t fs[] = {1, 2, 7, 32, 100};
    double worst[NTOL] = {0};
    worst_ratio_over(1u, fs, sizeof fs / sizeof fs[0], worst);
    print_ratios(1u, worst);
}

static void test_2d_agrees_with_the_direct_sum_to_tol_k(void)
{
    static const size_t fs[] = {1, 5, 16, 40};
    double worst[NTOL] = {0};
    worst_ratio_over(2u, fs, sizeof fs / sizeof fs[0], worst);
    print_ratios(2u, worst);
}

/* One point alone at each corner and at a scan of positions within a grid
 * cell: c_k = e^{-2 pi i k x} to tol at every mode. This is where a wrong
 * kernel correction shows first (the modes near F, where 1/Psi is ~10). */
static void test_a_single_point_gives_its_plane_wave_at_every_mode(void)
{
    const double tol = 1e-12;
    for (size_t dim = 1; dim <= 2; ++dim) {
        const size_t f = dim == 1u ? MAX_F1 : MAX_F2;
        init_plan(dim, f, tol);
        for (size_t s = 0; s < 20u; ++s) {
            for (size_t a = 0; a < dim; ++a)
                points[a] = s < 4u ? (((s >> a) & 1u) ? below_one : 0.0)
                                   : (37.0 + (double)(s - 4u + a) / 16.0) / (double)plan.n;
            direct_sum(dim, f, 1u);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_nufft_type1(&plan, points, 1u, out));
            TEST_ASSERT_TRUE_MESSAGE(max_error(dim, f) <= tol, "single point");
        }
    }
}

/* m points at one place add the same kernel values m times, one rounding per
 * add: up to about m eps of their share (nufft.h; a direct sum in double
 * rounds the same way). 2500 points at 0.3 and 2500 at 1 - 2^-53. */
static void test_coincident_points_add_only_their_summation_rounding(void)
{
    const size_t k = 5000u, f = 32u, m = k / 2u;
    for (size_t j = 0; j < k; ++j)
        points[j] = j % 2u ? below_one : 0.3;
    direct_sum(1u, f, k);
    for (size_t ti = 0; ti < sizeof tols / sizeof tols[0]; ++ti) {
        init_plan(1u, f, tols[ti]);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_nufft_type1(&plan, points, k, out));
        const double bound = (tols[ti] + 2.0 * (double)m * DBL_EPSILON) * (double)k;
        TEST_ASSERT_TRUE_MESSAGE(max_error(1u, f) <= bound, "coincident points");
    }
}

/* ---- the output's shape ---- */

static void test_the_modes_are_hermitian_and_c0_is_k(void)
{
    for (size_t dim = 1; dim <= 2; ++dim) {
        const size_t f = 16u, side = 2u * f + 1u, modes = dim == 1u ? side : side * side;
        const size_t k = 777u;
        make_points(SET_RANDOM, dim, k, 99u);
        init_plan(dim, f, 1e-9);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_nufft_type1(&plan, points, k, out));
        for (size_t m = 0; m < modes; ++m) {
            TEST_ASSERT_TRUE(out[2u * m] == out[2u * (modes - 1u - m)]);
            TEST_ASSERT_TRUE(out[2u * m + 1u] == -out[2u * (modes - 1u - m) + 1u]);
        }
        const size_t centre = (modes - 1u) / 2u;
        TEST_ASSERT_TRUE(out[2u * centre + 1u] == 0.0);
        TEST_ASSERT_DOUBLE_WITHIN(1e-9 * (double)k, (double)k, out[2u * centre]);
    }
}

/* Row-major with k_y slowest: one point at (0, y) has c = e^{-2 pi i k_y y},
 * the same along each row. */
static void test_2d_layout_is_row_major_with_ky_slowest(void)
{
    const size_t f = 5u, side = 2u * f + 1u;
    points[0] = 0.0;
    points[1] = 0.125;
    init_plan(2u, f, 1e-12);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_nufft_type1(&plan, points, 1u, out));
    for (size_t qy = 0; qy < side; ++qy)
        for (size_t qx = 0; qx < side; ++qx) {
            const double a = -6.283185307179586 * ((double)qy - (double)f) * 0.125;
            TEST_ASSERT_DOUBLE_WITHIN(1e-11, cos(a), out[2u * (qy * side + qx)]);
            TEST_ASSERT_DOUBLE_WITHIN(1e-11, sin(a), out[2u * (qy * side + qx) + 1u]);
        }
}

static void test_float_points_give_the_bits_of_their_widened_doubles(void)
{
    for (size_t dim = 1; dim <= 2; ++dim) {
        const size_t k = 300u, f = 20u, count = k * dim;
        make_points(SET_RANDOM, dim, k, 5u);
        for (size_t j = 0; j < count; ++j) {
            points_f[j] = (float)points[j];
            if (points_f[j] >= 1.0f)
                points_f[j] = 0x1.fffffep-1f;
            points[j] = (double)points_f[j];
        }
        points_f[0] = 0x1.fffffep-1f; /* the largest float below 1 */
        points[0] = (double)points_f[0];
        init_plan(dim, f, 1e-10);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_nufft_type1(&plan, points, k, out));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_nufft_type1_f(&plan, points_f, k, out2));
        const size_t side = 2u * f + 1u, modes = dim == 1u ? side : side * side;
        TEST_ASSERT_EQUAL_MEMORY(out, out2, 2u * modes * sizeof(double));
    }
}

/* The plan places its arrays at the first 64-byte boundary of any buffer,
 * and a copy of the header works as the original. */
static void test_any_buffer_alignment_and_a_copied_plan_give_the_same_bits(void)
{
    const size_t k = 200u, f = 12u, modes = (2u * f + 1u) * (2u * f + 1u);
    make_points(SET_RANDOM, 2u, k, 8u);
    init_plan(2u, f, 1e-8);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_nufft_type1(&plan, points, k, out));
    size_t need = 0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_nufft_size(2u, f, 1e-8, &need));
    for (size_t off = 1; off < 64u; off += 7u) {
        mcs_nufft shifted;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_nufft_init(&shifted, 2u, f, 1e-8, work + off, need));
        mcs_nufft copy = shifted;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_nufft_type1(&copy, points, k, out2));
        TEST_ASSERT_EQUAL_MEMORY(out, out2, 2u * modes * sizeof(double));
    }
}

/* ---- sizes ---- */

/* 1 when n has no prime factor above 5. */
static int smooth(size_t n)
{
    for (size_t p = 2; p <= 5u; ++p)
        while (n % p == 0u)
            n /= p;
    return n == 1u;
}

static void test_the_grid_is_even_smooth_and_at_least_twice_the_modes(void)
{
    static const double ts[] = {1e-1, 1e-4, 1e-9, 1e-13, 9e-14, 1e-15};
    for (size_t dim = 1; dim <= 2; ++dim)
        for (size_t f = 1; f <= (dim == 1u ? (size_t)MAX_F1 : (size_t)MAX_F2); ++f)
            for (size_t ti = 0; ti < sizeof ts / sizeof ts[0]; ++ti) {
                init_plan(dim, f, ts[ti]);
                TEST_ASSERT_TRUE(plan.n % 2u == 0u && smooth(plan.n));
                TEST_ASSERT_TRUE(plan.n >= 2u * (2u * f + 1u) && plan.n >= 2u * plan.width);
                TEST_ASSERT_TRUE(plan.n <= MCS_NUFFT_GRID_BOUND(dim, f));
                TEST_ASSERT_TRUE(plan.width >= 2u && plan.width <= MCS_NUFFT_MAX_WIDTH);
            }
}

static void test_the_size_macro_bounds_the_size_query(void)
{
    static const double ts[] = {1e-1, 3e-2, 1e-3, 1e-6, 1e-9, 1e-12, 1e-13, 9.9e-14, 1e-14, 1e-15};
    static const size_t big[] = {500, 1000, 4095, 4096, 65535, 65536, 1u << 20, 1u << 24};
    for (size_t dim = 1; dim <= 2; ++dim)
        for (size_t i = 0; i < 200u + sizeof big / sizeof big[0]; ++i) {
            const size_t f = i < 200u ? i + 1u : big[i - 200u];
            if (f > (dim == 1u ? (size_t)MCS_NUFFT_MAX_FREQ_1D : (size_t)MCS_NUFFT_MAX_FREQ_2D))
                continue;
            for (size_t ti = 0; ti < sizeof ts / sizeof ts[0]; ++ti) {
                size_t bytes = 0;
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_nufft_size(dim, f, ts[ti], &bytes));
                TEST_ASSERT_TRUE(bytes > 0u && bytes <= MCS_NUFFT_SIZE(dim, f));
            }
        }
}

/* Every m below 4e9 has an even 2^a 3^b 5^c in [m, 15 m / 14 + 32]: the
 * grid bound of nufft.h. Checked at m = s + 1 for consecutive such numbers
 * s < s' (the bound grows with m, so that is the worst m of each gap). */
static void test_the_grid_bound_holds_for_every_m_below_4e9(void)
{
    static uint64_t s[4096];
    size_t count = 0;
    const uint64_t limit = 4000000000u;
    for (uint64_t a = 2; a <= limit; a *= 2u)
        for (uint64_t b = a; b <= limit; b *= 3u)
            for (uint64_t c = b; c <= limit; c *= 5u) {
                TEST_ASSERT_TRUE(count < sizeof s / sizeof s[0]);
                s[count++] = c;
            }
    for (size_t i = 1; i < count; ++i) /* insertion sort: ~1700 values */
        for (size_t j = i; j > 0u && s[j - 1u] > s[j]; --j) {
            const uint64_t t = s[j];
            s[j] = s[j - 1u];
            s[j - 1u] = t;
        }
    for (size_t i = 0; i + 1u < count; ++i) {
        const uint64_t m = s[i] + 1u;
        TEST_ASSERT_TRUE(s[i + 1u] <= (m > 36u ? m : 36u) * 15u / 14u + 32u);
    }
}

/* ---- the error contract ---- */

#define SENTINEL 0xA5

static void fill_sentinels(void)
{
    memset(&plan, SENTINEL, sizeof plan);
    memset(work, SENTINEL, sizeof work);
}

/* init and size with bad arguments: the status, and no byte of the plan,
 * the buffer or *bytes changed. */
static void expect_init_error(mcs_status want, mcs_nufft *p, size_t dim, size_t f, double tol,
                              void *mem, size_t bytes)
{
    fill_sentinels();
    mcs_nufft plan_before;
    memcpy(&plan_before, &plan, sizeof plan);
    memcpy(work_copy, work, sizeof work);
    TEST_ASSERT_EQUAL_INT(want, mcs_nufft_init(p, dim, f, tol, mem, bytes));
    TEST_ASSERT_EQUAL_MEMORY(&plan_before, &plan, sizeof plan);
    TEST_ASSERT_EQUAL_MEMORY(work_copy, work, sizeof work);
    if (p != NULL && mem != NULL && want != MCS_ERR_SPACE && want != MCS_ERR_ALIAS) {
        size_t got = 12345u;
        TEST_ASSERT_EQUAL_INT(want, mcs_nufft_size(dim, f, tol, &got));
        TEST_ASSERT_TRUE(got == 12345u);
    }
}

static void test_bad_init_arguments_return_an_error_and_change_nothing(void)
{
    const double nan = (double)NAN, inf = (double)INFINITY;
    size_t need = 0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_nufft_size(2u, 7u, 1e-9, &need));
    expect_init_error(MCS_ERR_NULL, NULL, 2u, 7u, 1e-9, work, sizeof work);
    expect_init_error(MCS_ERR_NULL, &plan, 2u, 7u, 1e-9, NULL, sizeof work);
    expect_init_error(MCS_ERR_DOMAIN, &plan, 0u, 7u, 1e-9, work, sizeof work);
    expect_init_error(MCS_ERR_DOMAIN, &plan, 3u, 7u, 1e-9, work, sizeof work);
    expect_init_error(MCS_ERR_DOMAIN, &plan, SIZE_MAX, 7u, 1e-9, work, sizeof work);
    expect_init_error(MCS_ERR_FREQ_RANGE, &plan, 2u, 0u, 1e-9, work, sizeof work);
    expect_init_error(MCS_ERR_FREQ_RANGE, &plan, 1u, (size_t)MCS_NUFFT_MAX_FREQ_1D + 1u, 1e-9,
                      work, sizeof work);
    expect_init_error(MCS_ERR_FREQ_RANGE, &plan, 2u, (size_t)MCS_NUFFT_MAX_FREQ_2D + 1u, 1e-9,
                      work, sizeof work);
    expect_init_error(MCS_ERR_FREQ_RANGE, &plan, 2u, SIZE_MAX, 1e-9, work, sizeof work);
    expect_init_error(MCS_ERR_DOMAIN, &plan, 2u, 7u, 0.99e-15, work, sizeof work);
    expect_init_error(MCS_ERR_DOMAIN, &plan, 2u, 7u, 0.1000001, work, sizeof work);
    expect_init_error(MCS_ERR_DOMAIN, &plan, 2u, 7u, 0.0, work, sizeof work);
    expect_init_error(MCS_ERR_DOMAIN, &plan, 2u, 7u, -1e-9, work, sizeof work);
    expect_init_error(MCS_ERR_NOT_FINITE, &plan, 2u, 7u, nan, work, sizeof work);
    expect_init_error(MCS_ERR_NOT_FINITE, &plan, 2u, 7u, inf, work, sizeof work);
    expect_init_error(MCS_ERR_SPACE, &plan, 2u, 7u, 1e-9, work, need - 1u);
    expect_init_error(MCS_ERR_SPACE, &plan, 2u, 7u, 1e-9, work, 0u);
    /* The plan inside the buffer it is given. */
    expect_init_error(MCS_ERR_ALIAS, (mcs_nufft *)(void *)(work + 128), 2u, 7u, 1e-9, work, need);
    /* The bounds themselves are accepted, and exactly need bytes suffice. */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_nufft_init(&plan, 2u, 7u, 1e-9, work, need));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_nufft_init(&plan, 1u, 7u, MCS_NUFFT_TOL_MIN, work, sizeof work));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_nufft_init(&plan, 1u, 7u, MCS_NUFFT_TOL_MAX, work, sizeof work));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_nufft_size(1u, 7u, 1e-9, NULL));
}

/* type1 with bad arguments: the status, and no byte of out, the plan or its
 * buffer changed. */
static void expect_type1_error(mcs_status want, mcs_nufft *p, const double *pts, size_t k,
                               double *o)
{
    memset(out, SENTINEL, sizeof out);
    memcpy(out_copy, out, sizeof out);
    memcpy(work_copy, work, sizeof work);
    mcs_nufft plan_before;
    memcpy(&plan_before, &plan, sizeof plan);
    TEST_ASSERT_EQUAL_INT(want, mcs_nufft_type1(p, pts, k, o));
    TEST_ASSERT_EQUAL_MEMORY(out_copy, out, sizeof out);
    TEST_ASSERT_EQUAL_MEMORY(work_copy, work, sizeof work);
    TEST_ASSERT_EQUAL_MEMORY(&plan_before, &plan, sizeof plan);
}

static void test_bad_type1_arguments_return_an_error_and_change_nothing(void)
{
    const size_t k = 50u;
    make_points(SET_RANDOM, 2u, k, 3u);
    init_plan(2u, 6u, 1e-9);
    expect_type1_error(MCS_ERR_NULL, NULL, points, k, out);
    expect_type1_error(MCS_ERR_NULL, &plan, NULL, k, out);
    expect_type1_error(MCS_ERR_NULL, &plan, points, k, NULL);
    expect_type1_error(MCS_ERR_K_RANGE, &plan, points, 0u, out);
    expect_type1_error(MCS_ERR_K_RANGE, &plan, points, SIZE_MAX / 8u, out);
    const double bad[] = {1.0, (double)NAN, -0.5, -DBL_TRUE_MIN, (double)INFINITY, 1.5};
    for (size_t b = 0; b < sizeof bad / sizeof bad[0]; ++b)
        for (size_t where = 0; where < 2u; ++where) { /* the first and the last coordinate */
            const size_t at = where == 0u ? 0u : 2u * k - 1u;
            const double keep = points[at];
            points[at] = bad[b];
            expect_type1_error(MCS_ERR_POINT_RANGE, &plan, points, k, out);
            points[at] = keep;
        }
    /* out or the points inside the plan's buffer or header. */
    expect_type1_error(MCS_ERR_ALIAS, &plan, points, k, plan.grid);
    expect_type1_error(MCS_ERR_ALIAS, &plan, plan.corr, 1u, out);
    expect_type1_error(MCS_ERR_ALIAS, &plan, points, k, (double *)(void *)&plan);
    /* A header that init did not set: zeroed, filled, or with a field changed. */
    mcs_nufft good = plan;
    memset(&plan, 0, sizeof plan);
    expect_type1_error(MCS_ERR_UNINIT, &plan, points, k, out);
    memset(&plan, SENTINEL, sizeof plan);
    expect_type1_error(MCS_ERR_UNINIT, &plan, points, k, out);
    plan = good;
    plan.n += 2u;
    expect_type1_error(MCS_ERR_UNINIT, &plan, points, k, out);
    plan = good;
    plan.grid += 1;
    expect_type1_error(MCS_ERR_UNINIT, &plan, points, k, out);
    plan = good;
    plan.tol = 1e-3;
    expect_type1_error(MCS_ERR_UNINIT, &plan, points, k, out);
    plan = good;
    /* The float variant checks the same way. */
    for (size_t j = 0; j < 2u * k; ++j)
        points_f[j] = (float)points[j] < 1.0f ? (float)points[j] : 0.5f;
    points_f[2u * k - 1u] = 1.0f;
    memset(out, SENTINEL, sizeof out);
    memcpy(out_copy, out, sizeof out);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_nufft_type1_f(&plan, points_f, k, out));
    TEST_ASSERT_EQUAL_MEMORY(out_copy, out, sizeof out);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_nufft_type1_f(&plan, NULL, k, out));
    /* out may overlap the points: they are all read before out is written. */
    memcpy(out2, points, 2u * k * sizeof(double));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_nufft_type1(&plan, points, k, out));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_nufft_type1(&plan, out2, k, out2));
    TEST_ASSERT_EQUAL_MEMORY(out, out2, 2u * 13u * 13u * sizeof(double));
}

#if !MCS_CONFIG_NUFFT
/* Without the NUFFT every call returns MCS_ERR_DOMAIN, valid arguments or
 * not, and writes nothing. */
static void test_a_build_without_the_nufft_refuses_every_call_and_writes_nothing(void)
{
    static mcs_nufft p, snap;
    static unsigned char mem[4096], mem_snap[4096];
    static double pts[8] = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8}, res[64], res_snap[64];
    static float ptsf[8] = {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f, 0.7f, 0.8f};
    memset(&p, 0x5a, sizeof p);
    memset(mem, 0xa5, sizeof mem);
    memset(res, 0x3c, sizeof res);
    memcpy(&snap, &p, sizeof p);
    memcpy(mem_snap, mem, sizeof mem);
    memcpy(res_snap, res, sizeof res);
    size_t bytes = 7u;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_nufft_size(1u, 4u, 1e-6, &bytes));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_nufft_size(2u, 4u, 1e-13, &bytes));
    TEST_ASSERT_EQUAL_UINT64(7u, (uint64_t)bytes);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_nufft_init(&p, 1u, 4u, 1e-6, mem, sizeof mem));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_nufft_type1(&p, pts, 4u, res));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_nufft_type1_f(&p, ptsf, 4u, res));
    TEST_ASSERT_EQUAL_MEMORY(&snap, &p, sizeof p);
    TEST_ASSERT_EQUAL_MEMORY(mem_snap, mem, sizeof mem);
    TEST_ASSERT_EQUAL_MEMORY(res_snap, res, sizeof res);
}
#endif

int main(void)
{
    UNITY_BEGIN();
#if !MCS_CONFIG_NUFFT
    testing_the_refusals = 1;
    RUN_TEST(test_a_build_without_the_nufft_refuses_every_call_and_writes_nothing);
    testing_the_refusals = 0;
#endif
    RUN_TEST(test_1d_agrees_with_the_direct_sum_to_tol_k);
    RUN_TEST(test_2d_agrees_with_the_direct_sum_to_tol_k);
    RUN_TEST(test_a_single_point_gives_its_plane_wave_at_every_mode);
    RUN_TEST(test_coincident_points_add_only_their_summation_rounding);
    RUN_TEST(test_the_modes_are_hermitian_and_c0_is_k);
    RUN_TEST(test_2d_layout_is_row_major_with_ky_slowest);
    RUN_TEST(test_float_points_give_the_bits_of_their_widened_doubles);
    RUN_TEST(test_any_buffer_alignment_and_a_copied_plan_give_the_same_bits);
    RUN_TEST(test_the_grid_is_even_smooth_and_at_least_twice_the_modes);
    RUN_TEST(test_the_size_macro_bounds_the_size_query);
    RUN_TEST(test_the_grid_bound_holds_for_every_m_below_4e9);
    RUN_TEST(test_bad_init_arguments_return_an_error_and_change_nothing);
    RUN_TEST(test_bad_type1_arguments_return_an_error_and_change_nothing);
    return UNITY_END();
}
