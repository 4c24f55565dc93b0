#include "mcspec/rng.h"
#include "mcspec/sampler.h"
#include "points_ref.h"
#include "unity.h"

#include <math.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define MAXK 1024
#define GUARD (-777.0)

static double pts[2 * MAXK + 2];
static double base[2 * MAXK + 2];

static const mcs_sampler_kind all_kinds[MCS_SAMPLER_KIND_COUNT] = {
    MCS_SAMPLER_VAN_DER_CORPUT, MCS_SAMPLER_HALTON, MCS_SAMPLER_HAMMERSLEY, MCS_SAMPLER_SOBOL,
    MCS_SAMPLER_KRONECKER};

static mcs_sampler make(mcs_sampler_kind kind, size_t dim, size_t k)
{
    mcs_sampler s;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_init(&s, kind, dim, k));
    return s;
}

/* Independent references: digit loops in long double. */
static double ref_radical_inverse(unsigned base_b, unsigned long j)
{
    long double inv = 1.0L / (long double)base_b, f = inv, r = 0.0L;
    while (j > 0) {
        r += (long double)(j % base_b) * f;
        j /= base_b;
        f *= inv;
    }
    return (double)r;
}

static double ref_frac(unsigned long j, long double alpha)
{
    long double x = (long double)j * alpha;
    return (double)(x - floorl(x));
}

static void test_base_points_are_the_published_sequences(void)
{
    /* Index order (x_j = xor of the direction numbers of j's set bits), not
     * Gray-code order: the first 2^m points are the same set either way. */
    const double sobol2[8] = {0.0, 0.5, 0.75, 0.25, 0.625, 0.125, 0.375, 0.875};
    mcs_sampler s = make(MCS_SAMPLER_SOBOL, 2u, 8u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_base_points(&s, 8u, pts));
    for (size_t j = 0; j < 8u; ++j) {
        TEST_ASSERT_EQUAL_DOUBLE(ref_radical_inverse(2u, j), pts[2 * j]);
        TEST_ASSERT_EQUAL_DOUBLE(sobol2[j], pts[2 * j + 1]);
    }
    s = make(MCS_SAMPLER_HALTON, 2u, 500u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_base_points(&s, 500u, pts));
    for (size_t j = 0; j < 500u; ++j) {
        TEST_ASSERT_EQUAL_DOUBLE(ref_radical_inverse(2u, j), pts[2 * j]);
        TEST_ASSERT_DOUBLE_WITHIN(1e-15, ref_radical_inverse(3u, j), pts[2 * j + 1]);
    }
    s = make(MCS_SAMPLER_HAMMERSLEY, 2u, 37u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_base_points(&s, 37u, pts));
    for (size_t j = 0; j < 37u; ++j) {
        TEST_ASSERT_EQUAL_DOUBLE((double)j / 37.0, pts[2 * j]);
        TEST_ASSERT_EQUAL_DOUBLE(ref_radical_inverse(2u, j), pts[2 * j + 1]);
    }
    const long double golden = 0.618033988749894848204586834365638118L;
    const long double r2x = 0.754877666246692760049508896358528692L;
    const long double r2y = 0.569840290998053265911399958119568649L;
    s = make(MCS_SAMPLER_KRONECKER, 1u, 1000u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_base_points(&s, 1000u, pts));
    for (size_t j = 0; j < 1000u; ++j)
        TEST_ASSERT_DOUBLE_WITHIN(1e-14, ref_frac(j, golden), pts[j]);
    s = make(MCS_SAMPLER_KRONECKER, 2u, 1000u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_base_points(&s, 1000u, pts));
    for (size_t j = 0; j < 1000u; ++j) {
        TEST_ASSERT_DOUBLE_WITHIN(1e-14, ref_frac(j, r2x), pts[2 * j]);
        TEST_ASSERT_DOUBLE_WITHIN(1e-14, ref_frac(j, r2y), pts[2 * j + 1]);
    }
}

/* x - y mod 1, in [0, 1). */
static double diff_mod1(double x, double y)
{
    double d = x - y;
    return d < 0.0 ? d + 1.0 : d;
}

static void test_rotated_and_shifted_draws_are_the_base_set_under_one_shift_per_axis(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 3u, 5u);
    const mcs_sampler_kind kinds[4] = {MCS_SAMPLER_VAN_DER_CORPUT, MCS_SAMPLER_HALTON,
                                       MCS_SAMPLER_HAMMERSLEY, MCS_SAMPLER_KRONECKER};
    for (int c = 0; c < 4; ++c) {
        size_t dim = kinds[c] == MCS_SAMPLER_VAN_DER_CORPUT ? 1u : 2u;
        mcs_sampler s = make(kinds[c], dim, 100u);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_base_points(&s, 100u, base));
        for (int t = 0; t < 20; ++t) {
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_draw(&s, &rng, 100u, pts));
            for (size_t a = 0; a < dim; ++a) {
                double shift = diff_mod1(pts[a], base[a]);
                for (size_t j = 0; j < 100u; ++j) {
                    double x = pts[dim * j + a];
                    TEST_ASSERT_TRUE(x >= 0.0 && x < 1.0);
                    double d = diff_mod1(x, base[dim * j + a]);
                    TEST_ASSERT_TRUE(fabs(d - shift) < 1e-15 || fabs(fabs(d - shift) - 1.0) < 1e-15);
                }
            }
        }
    }
}

static void test_owen_scramble_is_nested_and_permutes_every_prefix_level(void)
{
    uint64_t state = 0x1234567u;
    for (int t = 0; t < 2000; ++t) {
        state = state * 6364136223846793005u + 1442695040888963407u;
        uint32_t seed = (uint32_t)(state >> 32), x = (uint32_t)state;
        unsigned m = (unsigned)(t % 31) + 1u;
        uint32_t keep = ~0u << (32u - m); /* the top m bits */
        uint32_t y = (x & keep) | (~x & ~keep);
        TEST_ASSERT_EQUAL_HEX32(mcs_sampler_owen_scramble(x, seed) & keep,
                                mcs_sampler_owen_scramble(y, seed) & keep);
    }
    static unsigned char seen[256];
    for (uint32_t seed = 1u; seed < 4000000000u; seed += 397000001u) {
        memset(seen, 0, sizeof seen);
        for (uint32_t p = 0; p < 256u; ++p)
            seen[mcs_sampler_owen_scramble(p << 24, seed) >> 24] = 1u;
        for (int p = 0; p < 256; ++p)
            TEST_ASSERT_EQUAL_UINT8(1u, seen[p]);
    }
    /* It does scramble: not the identity, and the seed matters. */
    TEST_ASSERT_NOT_EQUAL(mcs_sampler_owen_scramble(0x80000000u, 1u),
                          mcs_sampler_owen_scramble(0x80000000u, 2u));
    TEST_ASSERT_NOT_EQUAL(0x80000000u, mcs_sampler_owen_scramble(0x80000000u, 1u));
}

/* Every elementary interval [a 2^-i, (a+1) 2^-i) x [b 2^-(m-i), ...) holds exactly
 * one of the K = 2^m points: a (0, m, 2)-net. */
static void assert_is_a_zero_m_two_net(const double *p, unsigned m)
{
    static unsigned char count[MAXK];
    size_t k = (size_t)1u << m;
    for (unsigned i = 0; i <= m; ++i) {
        memset(count, 0, sizeof count);
        double nx = (double)((size_t)1u << i), ny = (double)((size_t)1u << (m - i));
        for (size_t j = 0; j < k; ++j) {
            size_t cx = (size_t)(p[2 * j] * nx), cy = (size_t)(p[2 * j + 1] * ny);
            count[cy * ((size_t)1u << i) + cx]++;
        }
        for (size_t c = 0; c < k; ++c)
            TEST_ASSERT_EQUAL_UINT8(1u, count[c]);
    }
}

static void test_owen_scrambled_sobol_points_form_a_zero_m_two_net_every_trial(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 11u, 2u);
    for (unsigned m = 0; m <= 10u; ++m) {
        size_t k = (size_t)1u << m;
        mcs_sampler s = make(MCS_SAMPLER_SOBOL, 2u, k);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_base_points(&s, k, pts));
        assert_is_a_zero_m_two_net(pts, m);
        for (int t = 0; t < 10; ++t) {
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_draw(&s, &rng, k, pts));
            assert_is_a_zero_m_two_net(pts, m);
        }
    }
}

/* Randomised QMC is unbiased: each point is uniform on [0,1) by itself. With
 * T trials, the mean of x_j is 1/2 +- sqrt(1/12/T) and its mean square 1/3. */
static void test_every_point_of_every_kind_is_marginally_uniform(void)
{
    enum { T = 4000, K = 8 };
    mcs_rng rng;
    mcs_rng_seed(&rng, 21u, 4u);
    for (int c = 0; c < MCS_SAMPLER_KIND_COUNT; ++c) {
        for (size_t dim = 1; dim <= 2u; ++dim) {
            if (!mcs_sampler_has_dim(all_kinds[c], dim))
                continue;
            mcs_sampler s = make(all_kinds[c], dim, K);
            double sum[2 * K] = {0}, sum2[2 * K] = {0};
            for (int t = 0; t < T; ++t) {
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_draw(&s, &rng, K, pts));
                for (size_t i = 0; i < dim * K; ++i) {
                    sum[i] += pts[i];
                    sum2[i] += pts[i] * pts[i];
                }
            }
            for (size_t i = 0; i < dim * K; ++i) {
                TEST_ASSERT_DOUBLE_WITHIN(5.0 * sqrt(1.0 / 12.0 / T), 0.5, sum[i] / T);
                TEST_ASSERT_DOUBLE_WITHIN(5.0 * sqrt(4.0 / 45.0 / T), 1.0 / 3.0, sum2[i] / T);
            }
        }
    }
}

static void test_same_seed_same_points_and_kinds_have_names(void)
{
    mcs_rng a, b;
    mcs_rng_seed(&a, 9u, 9u);
    mcs_rng_seed(&b, 9u, 9u);
    mcs_sampler s = make(MCS_SAMPLER_SOBOL, 2u, 64u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_draw(&s, &a, 64u, pts));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_draw(&s, &b, 64u, base));
    TEST_ASSERT_EQUAL_MEMORY(pts, base, 128u * sizeof(double));
    TEST_ASSERT_EQUAL_STRING("sobol-owen", mcs_sampler_kind_str(MCS_SAMPLER_SOBOL));
    TEST_ASSERT_EQUAL_STRING("halton", mcs_sampler_kind_str(MCS_SAMPLER_HALTON));
    TEST_ASSERT_EQUAL_STRING("unknown", mcs_sampler_kind_str((mcs_sampler_kind)99));
}

static void test_bad_configuration_returns_an_error_and_changes_nothing(void)
{
    mcs_sampler s, before;
    memset(&s, 0x5a, sizeof s);
    before = s;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_sampler_init(NULL, MCS_SAMPLER_SOBOL, 1u, 4u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_sampler_init(&s, MCS_SAMPLER_HALTON, 1u, 4u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_sampler_init(&s, MCS_SAMPLER_VAN_DER_CORPUT, 2u, 4u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_sampler_init(&s, MCS_SAMPLER_SOBOL, 3u, 4u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_sampler_init(&s, (mcs_sampler_kind)7, 1u, 4u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_sampler_init(&s, MCS_SAMPLER_SOBOL, 1u, 0u));
#if SIZE_MAX > UINT32_MAX
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE,
                          mcs_sampler_init(&s, MCS_SAMPLER_SOBOL, 1u, (size_t)UINT32_MAX + 2u));
#endif
    TEST_ASSERT_EQUAL_MEMORY(&before, &s, sizeof s);
}

static void test_bad_draw_writes_nothing_and_does_not_advance_the_rng(void)
{
    mcs_rng rng, rng0;
    mcs_rng_seed(&rng, 1u, 1u);
    rng0 = rng;
    mcs_sampler s = make(MCS_SAMPLER_HALTON, 2u, 4u), bad;
    memset(&bad, 0, sizeof bad);
    bad.kind = MCS_SAMPLER_HALTON;
    bad.dim = 1u; /* not a valid combination: not from init */
    bad.k = 4u;
    points_guard_fill(pts, 10u, GUARD);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_sampler_draw(NULL, &rng, 4u, pts));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_sampler_draw(&s, NULL, 4u, pts));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_sampler_draw(&s, &rng, 4u, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, mcs_sampler_draw(&s, &rng, 5u, pts));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_sampler_draw(&bad, &rng, 4u, pts));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_sampler_base_points(&bad, 4u, pts));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, mcs_sampler_base_points(&s, 3u, pts));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_sampler_base_points(&s, 4u, NULL));
    points_guard_check(pts, 10u, GUARD);
    TEST_ASSERT_EQUAL_MEMORY(&rng0, &rng, sizeof rng);
    /* A good draw writes exactly k * dim values. */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_draw(&s, &rng, 4u, pts));
    TEST_ASSERT_EQUAL_DOUBLE(GUARD, pts[8]);
}

/* A never-seeded (zeroed) generator outputs only zeros, so every trial
 * would be the same set as if randomised. Every kind refuses it, as
 * mcs_pattern_draw does, and writes nothing. */
static void test_draw_with_a_never_seeded_rng_is_refused_and_writes_nothing(void)
{
    mcs_rng rng, rng0;
    memset(&rng, 0, sizeof rng);
    rng0 = rng;
    for (int c = 0; c < MCS_SAMPLER_KIND_COUNT; ++c)
        for (size_t dim = 1u; dim <= 2u; ++dim) {
            if (!mcs_sampler_has_dim(all_kinds[c], dim))
                continue;
            mcs_sampler s = make(all_kinds[c], dim, 8u);
            points_guard_fill(pts, 18u, GUARD);
            TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_sampler_draw(&s, &rng, 8u, pts));
            TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_sampler_draw(&s, &rng, 7u, pts));
            points_guard_check(pts, 18u, GUARD);
            TEST_ASSERT_EQUAL_MEMORY(&rng0, &rng, sizeof rng);
        }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_base_points_are_the_published_sequences);
    RUN_TEST(test_rotated_and_shifted_draws_are_the_base_set_under_one_shift_per_axis);
    RUN_TEST(test_owen_scramble_is_nested_and_permutes_every_prefix_level);
    RUN_TEST(test_owen_scrambled_sobol_points_form_a_zero_m_two_net_every_trial);
    RUN_TEST(test_every_point_of_every_kind_is_marginally_uniform);
    RUN_TEST(test_same_seed_same_points_and_kinds_have_names);
    RUN_TEST(test_bad_configuration_returns_an_error_and_changes_nothing);
    RUN_TEST(test_bad_draw_writes_nothing_and_does_not_advance_the_rng);
    RUN_TEST(test_draw_with_a_never_seeded_rng_is_refused_and_writes_nothing);
    return UNITY_END();
}
