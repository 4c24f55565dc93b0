/* The library's nested-scrambled samplers against the exact Owen theory
 * (owen.h) on projections other than dimensions 0 and 1: the mean
 * periodogram of 3000 trials within 5 standard errors of E P at every wave
 * vector |kx|, |ky| <= 8 of the half plane, for
 *  - halton-owen, axes 2 and 3 (bases 5 and 7), K = 100: the theory needs
 *    each node's permutation to send two distinct digits to a uniform pair of
 *    distinct digits (docs/owen.md, section 2);
 *  - sobol-owen-nd, axes 4 and 5 (t = 2 at K = 2^7), K = 128.
 * Each also shows that a 1% error in the theory (0.99 E P - 1) fails. */
#include <math.h>
#include <stdio.h>

#include "mcspec.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

#define F2 8u
#define KMAX 128u
#define DIM 6u
#define TRIALS 3000u
static _Alignas(64) unsigned char mem2[MCS_POINTSET2D_SIZE_DIRECT(F2)];
static mcs_pointset2d acc2;
static double base_pts[DIM * KMAX], pts[DIM * KMAX], pair[2u * KMAX];
static uint64_t work[MCS_OWEN_LEN_MAX];
static mcs_owen ow;

static void check_projection(mcs_sampler_kind kind, size_t k, size_t ax, size_t ay, uint64_t seed,
                             const char *what)
{
    mcs_sampler s;
    mcs_rng rng;
    const size_t axes[2] = {ax, ay};
    const unsigned primes[DIM] = {2u, 3u, 5u, 7u, 11u, 13u};
    const unsigned bases[2] = {kind == MCS_SAMPLER_SOBOL_ND ? 2u : primes[ax],
                               kind == MCS_SAMPLER_SOBOL_ND ? 2u : primes[ay]};
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_init(&s, kind, DIM, k));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_base_points(&s, k, base_pts));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_owen_init(&ow, k, DIM, base_pts, 2u, axes, bases, work,
                                                MCS_OWEN_LEN_MAX));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_init(&acc2, F2, MCS_POINTSET_DIRECT_ONLY, mem2,
                                                      sizeof mem2));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, seed, 0u));
    for (unsigned t = 0; t < TRIALS; ++t) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_draw(&s, &rng, k, pts));
        for (size_t j = 0; j < k; ++j) {
            pair[2u * j] = pts[DIM * j + ax];
            pair[2u * j + 1u] = pts[DIM * j + ay];
        }
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add(&acc2, k, pair));
    }
    double zmax = 0.0, zwrong = 0.0;
    for (long fy = 0; fy <= (long)F2; ++fy)
        for (long fx = fy == 0 ? 1 : -(long)F2; fx <= (long)F2; ++fx) {
            double mean = 0.0, se = 0.0, exact = 0.0;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_power(&acc2, fx, fy, &mean));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_power_stderr(&acc2, fx, fy, &se));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_owen_power(&ow, fx, fy, &exact));
            zmax = fmax(zmax, fabs(mean - exact) / se);
            zwrong = fmax(zwrong, fabs(mean - (1.0 + 0.99 * (exact - 1.0))) / se);
        }
    printf("%s: max |z| %.2f over %u wave vectors; 1%% off the theory: max |z| %.1f\n", what,
           zmax, (2u * F2 + 1u) * F2 + F2, zwrong);
    TEST_ASSERT_TRUE_MESSAGE(zmax < 5.0, what);
    TEST_ASSERT_TRUE(zwrong > 5.0);
}

static void test_halton_owen_axes_of_bases_5_and_7_follow_the_owen_theory(void)
{
    check_projection(MCS_SAMPLER_HALTON_OWEN, 100u, 2u, 3u, 0x57u, "halton-owen axes 2,3 K=100");
}

static void test_sobol_owen_nd_axes_4_and_5_follow_the_owen_theory(void)
{
    check_projection(MCS_SAMPLER_SOBOL_ND, 128u, 4u, 5u, 0x45u, "sobol-owen-nd axes 4,5 K=128");
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_halton_owen_axes_of_bases_5_and_7_follow_the_owen_theory);
    RUN_TEST(test_sobol_owen_nd_axes_4_and_5_follow_the_owen_theory);
    return UNITY_END();
}
