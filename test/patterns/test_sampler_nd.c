/* The any-dimension samplers: Owen-scrambled Sobol on Joe and Kuo's
 * direction numbers (t-values of the first dimensions by counting points in
 * elementary intervals), Halton with permuted digits and Owen scrambling. */
#include "mcspec/rng.h"
#include "mcspec/sampler.h"
#include "unity.h"

#include <math.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define MAXK 1024
#define MAXD 8
static double pts[MCS_SAMPLER_MAX_DIM * MAXK];
static double ref[MCS_SAMPLER_MAX_DIM * MAXK];
static unsigned counts[1u << 12];

static mcs_sampler make(mcs_sampler_kind kind, size_t dim, size_t k)
{
    mcs_sampler s;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_init(&s, kind, dim, k));
    return s;
}

static mcs_rng seeded(uint64_t seed)
{
    mcs_rng r;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&r, seed, 7u));
    return r;
}

/* Top d binary digits of x in [0,1). */
static unsigned top_bits(double x, unsigned d)
{
    return (unsigned)ldexp(x, (int)d);
}

/* 1 if points [first, first + 2^m) of a dim-wide set, on the axes ax[0..s-1],
 * form a (t, m, s)-net in base 2: every elementary box of volume 2^(t-m)
 * (sides 2^-d_i, sum d_i = m - t) holds exactly 2^t points. */
static int is_net(const double *p, size_t dim, size_t first, unsigned m, unsigned t,
                  const size_t *ax, unsigned s)
{
    unsigned d[MAXD] = {0};
    const unsigned q = m - t;
    for (;;) {
        unsigned sum = 0;
        for (unsigned i = 0; i < s; ++i)
            sum += d[i];
        if (sum == q) {
            memset(counts, 0, sizeof(unsigned) << q);
            for (size_t j = first; j < first + ((size_t)1 << m); ++j) {
                unsigned cell = 0;
                for (unsigned i = 0; i < s; ++i)
                    cell = (cell << d[i]) | top_bits(p[dim * j + ax[i]], d[i]);
                counts[cell]++;
            }
            for (unsigned c = 0; c < (1u << q); ++c)
                if (counts[c] != (1u << t))
                    return 0;
        }
        /* next d with every d_i <= q (odometer) */
        unsigned i = 0;
        while (i < s && d[i] == q)
            d[i++] = 0;
        if (i == s)
            return 1;
        d[i]++;
    }
}

/* Sobol's t-value bound of the first s dimensions, sum of (degree - 1) of
 * their polynomials (x, x + 1, x^2 + x + 1, x^3 + x + 1, x^3 + x^2 + 1, and
 * degree 4 for dimensions 6 and 7): 0, 0, 1, 3, 5, 8, 11. */
static const unsigned sobol_t[8] = {0, 0, 0, 1, 3, 5, 8, 11};

/* The smallest t for which every block of 2^m points (indices k 2^m ..) of
 * the first 512 is a (t, m, s)-net, for m = 1..8, then the largest over m:
 * the t-value of the sequence's first 512 points. */
static unsigned measured_t(const double *p, size_t dim, unsigned sd)
{
    size_t ax[MAXD];
    for (unsigned i = 0; i < sd; ++i)
        ax[i] = i;
    unsigned worst = 0;
    for (unsigned m = 1; m <= 8u; ++m) {
        unsigned t = 0;
        for (;; ++t) {
            int all = 1;
            for (size_t first = 0; all && first + ((size_t)1 << m) <= 512u; first += (size_t)1 << m)
                all = is_net(p, dim, first, m, t, ax, sd);
            if (all)
                break;
        }
        worst = t > worst ? t : worst;
    }
    return worst;
}

static void test_sobol_nd_first_dimensions_are_t_s_sequences_with_the_known_t(void)
{
    /* Sobol's bound sum (e_i - 1) is 0, 1, 3, 5 for s = 2..5, and it is the
     * exact t for s = 2, 3, 4 (the first three dimensions form a
     * (1,3)-sequence; no (0,3)-sequence exists in base 2); Joe and Kuo's
     * numbers do better than the bound for s = 5 over 512 points (t = 3,
     * counted here and by an independent Python count). */
    mcs_sampler s = make(MCS_SAMPLER_SOBOL_ND, 6u, MAXK);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_base_points(&s, MAXK, pts));
    TEST_ASSERT_EQUAL_UINT(0u, measured_t(pts, 6u, 2u));
    TEST_ASSERT_EQUAL_UINT(1u, measured_t(pts, 6u, 3u));
    TEST_ASSERT_EQUAL_UINT(3u, measured_t(pts, 6u, 4u));
    TEST_ASSERT_EQUAL_UINT(3u, measured_t(pts, 6u, 5u));
    /* the bound itself for every block of 2^10 points at m = 10 */
    const size_t ax[5] = {0, 1, 2, 3, 4};
    for (unsigned sd = 2; sd <= 5u; ++sd)
        TEST_ASSERT_TRUE(is_net(pts, 6u, 0u, 10u, sobol_t[sd], ax, sd));
}

static void test_owen_scrambled_sobol_nd_keeps_the_net_property_every_trial(void)
{
    mcs_sampler s = make(MCS_SAMPLER_SOBOL_ND, 5u, 256u);
    mcs_rng r = seeded(11u);
    const size_t ax[5] = {0, 1, 2, 3, 4};
    for (int trial = 0; trial < 5; ++trial) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_draw(&s, &r, 256u, pts));
        for (unsigned sd = 2; sd <= 5u; ++sd)
            TEST_ASSERT_TRUE(is_net(pts, 5u, 0u, 8u, sobol_t[sd], ax, sd));
    }
}

static void test_every_sobol_dimension_up_to_64_is_stratified_alone(void)
{
    /* m_i odd for every row: each dimension alone is a (0,1)-sequence, so
     * the first 2^10 points of every one of the 64 fall one per 2^-10 cell. */
    mcs_sampler s = make(MCS_SAMPLER_SOBOL_ND, MCS_SAMPLER_MAX_DIM, MAXK);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_base_points(&s, MAXK, pts));
    for (size_t a = 0; a < MCS_SAMPLER_MAX_DIM; ++a) {
        size_t ax[1] = {a};
        TEST_ASSERT_TRUE(is_net(pts, MCS_SAMPLER_MAX_DIM, 0u, 10u, 0u, ax, 1u));
    }
    /* dimension 64 (Joe and Kuo's row 64): point 1 is v_0 = 1/2, point 2 is
     * v_1 = m_2 / 4 = 1/4, point 3 is v_0 ^ v_1 = 3/4; row 41's point 2 is
     * m_2 / 4 = 3/4 (pbrt's SobolMatrices32 give the same). */
    TEST_ASSERT_EQUAL_DOUBLE(0.5, pts[MCS_SAMPLER_MAX_DIM * 1 + 63]);
    TEST_ASSERT_EQUAL_DOUBLE(0.25, pts[MCS_SAMPLER_MAX_DIM * 2 + 63]);
    TEST_ASSERT_EQUAL_DOUBLE(0.75, pts[MCS_SAMPLER_MAX_DIM * 3 + 63]);
    TEST_ASSERT_EQUAL_DOUBLE(0.75, pts[MCS_SAMPLER_MAX_DIM * 2 + 40]);
}

static void test_sobol_nd_in_one_and_two_dimensions_is_sobol_owen_bit_for_bit(void)
{
    for (size_t dim = 1; dim <= 2u; ++dim) {
        mcs_sampler a = make(MCS_SAMPLER_SOBOL, dim, 300u), b = make(MCS_SAMPLER_SOBOL_ND, dim, 300u);
        mcs_rng ra = seeded(5u), rb = seeded(5u);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_draw(&a, &ra, 300u, pts));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_draw(&b, &rb, 300u, ref));
        TEST_ASSERT_EQUAL_MEMORY(pts, ref, dim * 300u * sizeof(double));
        TEST_ASSERT_EQUAL_MEMORY(&ra, &rb, sizeof ra);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_base_points(&a, 300u, pts));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_base_points(&b, 300u, ref));
        TEST_ASSERT_EQUAL_MEMORY(pts, ref, dim * 300u * sizeof(double));
    }
}

static double radical_inverse(unsigned b, unsigned long j)
{
    long double inv = 1.0L / (long double)b, f = inv, r = 0.0L;
    for (; j > 0; j /= b, f *= inv)
        r += (long double)(j % b) * f;
    return (double)r;
}

static const unsigned first_primes[8] = {2, 3, 5, 7, 11, 13, 17, 19};

static void test_unpermuted_halton_base_points_are_the_radical_inverses(void)
{
    mcs_sampler s = make(MCS_SAMPLER_HALTON_PERMUTED, 8u, 500u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_base_points(&s, 500u, pts));
    for (size_t j = 0; j < 500u; ++j)
        for (size_t a = 0; a < 8u; ++a)
            TEST_ASSERT_DOUBLE_WITHIN(1e-15, radical_inverse(first_primes[a], j), pts[8u * j + a]);
}

/* Base-b stratification: b^m points of axis a fall one per b^-m cell. */
static int stratified(const double *p, size_t dim, size_t a, size_t n)
{
    memset(counts, 0, sizeof counts);
    for (size_t j = 0; j < n; ++j) {
        size_t c = (size_t)(p[dim * j + a] * (double)n);
        if (c >= n || counts[c]++ != 0u)
            return 0;
    }
    return 1;
}

static void test_permuted_and_owen_halton_keep_the_stratification_of_each_base(void)
{
    const mcs_sampler_kind kinds[2] = {MCS_SAMPLER_HALTON_PERMUTED, MCS_SAMPLER_HALTON_OWEN};
    const size_t sizes[4] = {1024u, 729u, 625u, 343u}; /* 2^10, 3^6, 5^4, 7^3 */
    for (int c = 0; c < 2; ++c)
        for (size_t a = 0; a < 4u; ++a) {
            mcs_sampler s = make(kinds[c], 4u, sizes[a]);
            mcs_rng r = seeded(3u + a);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_draw(&s, &r, sizes[a], pts));
            TEST_ASSERT_TRUE(stratified(pts, 4u, a, sizes[a]));
        }
    /* 2D: K = 2^3 3^2 points put one point in each 2^-3 x 3^-2 box */
    for (int c = 0; c < 2; ++c) {
        mcs_sampler s = make(kinds[c], 2u, 72u);
        mcs_rng r = seeded(9u);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_draw(&s, &r, 72u, pts));
        memset(counts, 0, sizeof counts);
        for (size_t j = 0; j < 72u; ++j)
            counts[(size_t)(pts[2 * j] * 8.0) * 9u + (size_t)(pts[2 * j + 1] * 9.0)]++;
        for (size_t b = 0; b < 72u; ++b)
            TEST_ASSERT_EQUAL_UINT(1u, counts[b]);
    }
}

/* Over trials each point of a scrambled or permuted Halton set is uniform:
 * mean 1/2 and variance 1/12 within 5 standard errors, for point 0 (all of
 * its digits 0 before permutation) and point 5, on axes of bases 2, 3, 311. */
static void test_every_point_of_permuted_and_owen_halton_is_uniform_over_trials(void)
{
    const mcs_sampler_kind kinds[2] = {MCS_SAMPLER_HALTON_PERMUTED, MCS_SAMPLER_HALTON_OWEN};
    const size_t axes[3] = {0u, 1u, 63u}, points_j[2] = {0u, 5u};
    const int trials = 4000;
    for (int c = 0; c < 2; ++c) {
        mcs_sampler s = make(kinds[c], MCS_SAMPLER_MAX_DIM, 8u);
        mcs_rng r = seeded(21u);
        double sum[3][2] = {{0}}, sq[3][2] = {{0}};
        for (int t = 0; t < trials; ++t) {
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_draw(&s, &r, 8u, pts));
            for (int a = 0; a < 3; ++a)
                for (int q = 0; q < 2; ++q) {
                    double x = pts[MCS_SAMPLER_MAX_DIM * points_j[q] + axes[a]];
                    TEST_ASSERT_TRUE(x >= 0.0 && x < 1.0);
                    sum[a][q] += x - 0.5;
                    sq[a][q] += (x - 0.5) * (x - 0.5);
                }
        }
        for (int a = 0; a < 3; ++a)
            for (int q = 0; q < 2; ++q) {
                /* mean: sd 1/sqrt(12 T); second moment 1/12: sd sqrt(1/80 - 1/144)/sqrt(T) */
                double mean = sum[a][q] / trials, m2 = sq[a][q] / trials;
                TEST_ASSERT_DOUBLE_WITHIN(5.0 / sqrt(12.0 * trials), 0.0, mean);
                TEST_ASSERT_DOUBLE_WITHIN(5.0 * sqrt(1.0 / 80 - 1.0 / 144) / sqrt(trials),
                                          1.0 / 12.0, m2);
            }
    }
}

static void test_bad_any_dimension_configurations_are_refused_and_change_nothing(void)
{
    mcs_sampler s, before;
    memset(&s, 0x5a, sizeof s);
    before = s;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_sampler_init(&s, MCS_SAMPLER_SOBOL_ND, 65u, 4u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_sampler_init(&s, MCS_SAMPLER_HALTON_OWEN, 0u, 4u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_sampler_init(&s, MCS_SAMPLER_PADDED, 1u, 4u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_sampler_init(&s, MCS_SAMPLER_PADDED, 4u, (size_t)1 << 32));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_sampler_init(&s, MCS_SAMPLER_LATTICE, 4u, 0u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_sampler_init_padded(&s, MCS_SAMPLER_LATTICE, 4u, 4u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_sampler_init_padded(&s, MCS_SAMPLER_PADDED, 4u, 4u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, mcs_sampler_init_lattice(&s, 3u, 16u, 16u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, mcs_sampler_init_lattice(&s, 3u, 16u, 0u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_sampler_init_lattice(NULL, 3u, 16u, 3u));
    TEST_ASSERT_EQUAL_MEMORY(&before, &s, sizeof s);
    TEST_ASSERT_EQUAL_STRING("sobol-owen-nd", mcs_sampler_kind_str(MCS_SAMPLER_SOBOL_ND));
    TEST_ASSERT_EQUAL_STRING("lattice", mcs_sampler_kind_str(MCS_SAMPLER_LATTICE));
    /* a hand-made lattice with g = 0 is not from init */
    mcs_sampler l = make(MCS_SAMPLER_LATTICE, 3u, 16u);
    l.generator = 0u;
    mcs_rng r = seeded(1u), r0 = r;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_sampler_draw(&l, &r, 16u, pts));
    TEST_ASSERT_EQUAL_MEMORY(&r0, &r, sizeof r);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_sobol_nd_first_dimensions_are_t_s_sequences_with_the_known_t);
    RUN_TEST(test_owen_scrambled_sobol_nd_keeps_the_net_property_every_trial);
    RUN_TEST(test_every_sobol_dimension_up_to_64_is_stratified_alone);
    RUN_TEST(test_sobol_nd_in_one_and_two_dimensions_is_sobol_owen_bit_for_bit);
    RUN_TEST(test_unpermuted_halton_base_points_are_the_radical_inverses);
    RUN_TEST(test_permuted_and_owen_halton_keep_the_stratification_of_each_base);
    RUN_TEST(test_every_point_of_permuted_and_owen_halton_is_uniform_over_trials);
    RUN_TEST(test_bad_any_dimension_configurations_are_refused_and_change_nothing);
    return UNITY_END();
}
