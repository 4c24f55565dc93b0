/* The 1D identities between low-discrepancy sets and the note's patterns,
 * shown by measurement: K = 2^m points of
 *  - van der Corput under a Cranley-Patterson rotation are {(i + beta)/K}
 *    (the first 2^m radical inverses are the multiples of 1/K), i.e. uniform
 *    jitter;
 *  - Sobol (dimension 1) under Owen scrambling have one point per stratum
 *    [j/K, (j+1)/K), uniform inside it and independent across strata, i.e.
 *    stratified sampling.
 * Binned on N = 36 bins (a multiple of K = 4, not of K = 8, whose strata
 * edges then fall inside bins), their measured spectra match the exact theory of
 * jitter and stratified within 5 standard errors, and each is refuted by the
 * other kind's theory (the comparison discriminates). Unbinned, their point-set
 * periodograms match the exact point-set spectra. */
#include "mcspec/pattern.h"
#include "mcspec/pointset.h"
#include "mcspec/rng.h"
#include "mcspec/sampler.h"
#include "mcspec/spectrum.h"
#include "mcspec/theory.h"
#include "unity.h"

#include <math.h>

void setUp(void) {}
void tearDown(void) {}

#define N_BINS 36u
#define TRIALS 20000

static mcs_spectrum spec;
static mcs_theory th_jitter, th_strat;
static mcs_pointset ps;
/* Its buffer, for the largest cutoff measured (3 K, K <= 64). */
static unsigned char ps_mem[MCS_POINTSET_SIZE(192u)];
static double pts[1024];

static void theory_for(mcs_theory *th, mcs_pattern_kind kind, size_t k)
{
    mcs_pattern pat;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, kind, N_BINS, k, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_init(th, &pat));
}

/* Draws TRIALS sets into the binned spectrum and the point-set periodogram. */
static void measure(mcs_sampler_kind kind, size_t k, uint64_t seed)
{
    mcs_sampler s;
    mcs_rng rng;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_init(&s, kind, 1u, k));
    mcs_rng_seed(&rng, seed, 15u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&spec, N_BINS));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(&ps, 3u * k, 0u, ps_mem, sizeof ps_mem));
    for (int t = 0; t < TRIALS; ++t) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_draw(&s, &rng, k, pts));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_points(&spec, k, pts, NULL));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add(&ps, k, pts));
    }
}

/* Largest |measured - exact| / stderr over the frequencies 1..N/2 (a
 * deterministic agreement, stderr 0, counts as z = 0). */
static double worst_z(const mcs_theory *th)
{
    double worst = 0.0;
    for (size_t q = 1; q <= N_BINS / 2u; ++q) {
        double p = 0.0, se = 0.0, ex = 0.0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(&spec, q, &p));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power_stderr(&spec, q, &se));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_power(th, q, &ex));
        double d = fabs(p - ex);
        double z = d <= 1e-9 * fabs(ex) + 1e-12 ? 0.0 : d / fmax(se, 1e-300);
        worst = fmax(worst, z);
    }
    return worst;
}

static void assert_pointset_matches(mcs_pattern_kind kind, size_t k)
{
    for (long f = 1; f <= (long)(3u * k); ++f) {
        double p = 0.0, se = 0.0, ex = 0.0;
        mcs_pointset_power(&ps, f, &p);
        mcs_pointset_power_stderr(&ps, f, &se);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_exact_power(kind, k, f, &ex));
        TEST_ASSERT_DOUBLE_WITHIN(5.0 * se + 1e-9 * k, ex, p);
    }
}

/* For K = 4 and 8: the sampler's binned spectrum matches kind `is` within
 * 5 standard errors and is told apart from the other of jitter and
 * stratified, and its point-set spectrum matches `is` unbinned. */
static void assert_sampler_is(mcs_sampler_kind sampler, mcs_pattern_kind is, uint64_t seed)
{
    const size_t ks[2] = {4u, 8u};
    for (int c = 0; c < 2; ++c) {
        theory_for(&th_jitter, MCS_PATTERN_JITTER, ks[c]);
        theory_for(&th_strat, MCS_PATTERN_STRATIFIED, ks[c]);
        measure(sampler, ks[c], seed + (uint64_t)c);
        const int jitter = is == MCS_PATTERN_JITTER;
        TEST_ASSERT_TRUE(worst_z(jitter ? &th_jitter : &th_strat) <= 5.0);
        TEST_ASSERT_TRUE(worst_z(jitter ? &th_strat : &th_jitter) > 5.0);
        assert_pointset_matches(is, ks[c]);
    }
}

static void test_rotated_van_der_corput_of_2_to_the_m_points_is_uniform_jitter(void)
{
    assert_sampler_is(MCS_SAMPLER_VAN_DER_CORPUT, MCS_PATTERN_JITTER, 100u);
}

static void test_owen_scrambled_sobol_of_2_to_the_m_points_is_stratified(void)
{
    assert_sampler_is(MCS_SAMPLER_SOBOL, MCS_PATTERN_STRATIFIED, 200u);
}

/* The identities need K = 2^m: 6 rotated radical inverses are not equally
 * spaced, so their spectrum is not jitter's. */
static void test_rotated_van_der_corput_of_6_points_is_not_uniform_jitter(void)
{
    theory_for(&th_jitter, MCS_PATTERN_JITTER, 6u);
    measure(MCS_SAMPLER_VAN_DER_CORPUT, 6u, 300u);
    TEST_ASSERT_TRUE(worst_z(&th_jitter) > 5.0);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_rotated_van_der_corput_of_2_to_the_m_points_is_uniform_jitter);
    RUN_TEST(test_owen_scrambled_sobol_of_2_to_the_m_points_is_stratified);
    RUN_TEST(test_rotated_van_der_corput_of_6_points_is_not_uniform_jitter);
    return UNITY_END();
}
