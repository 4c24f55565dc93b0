/* Lloyd's relaxation on the torus (bluenoise.h): each step lowers the
 * quantisation energy toward Fejes Toth's hexagonal bound, the centroid
 * estimate converges as its lattice is refined, and the relaxed sets are
 * blue noise (low-frequency power far below 1, points far apart). */
#include "mcspec/bluenoise.h"
#include "mcspec/pointset2d.h"
#include "mcspec/rng.h"
#include "mcspec/spacing.h"
#include "unity.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define MAXK 256
static double pts[2u * MAXK], other[2u * MAXK];
static unsigned char work[MCS_BLUENOISE_WORK_SIZE(2, MAXK)];

static void lloyd(size_t k, uint32_t iterations, uint32_t resolution, uint64_t seed, double *out)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, seed, 3u);
    const mcs_bluenoise_params p = {0.0, 0u, iterations, resolution, 0u};
    size_t bytes = 0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_bluenoise_work_size(MCS_BLUENOISE_LLOYD, 2u, k, &bytes));
    TEST_ASSERT_TRUE(bytes <= sizeof work);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_bluenoise_draw(MCS_BLUENOISE_LLOYD, 2u, k, &p, &rng, work, bytes, out));
    for (size_t j = 0; j < 2u * k; ++j)
        TEST_ASSERT_TRUE(out[j] >= 0.0 && out[j] < 1.0);
}

/* K times the mean squared toroidal distance from the torus to the nearest
 * point, by brute force at the midpoints of a 256 x 256 lattice. */
static double energy(const double *p, size_t k)
{
    const int g = 256;
    double e = 0.0;
    for (int a = 0; a < g; ++a)
        for (int b = 0; b < g; ++b) {
            const double q[2] = {(a + 0.5) / g, (b + 0.5) / g};
            double best = 1.0;
            for (size_t i = 0; i < k; ++i) {
                double s = 0.0;
                for (int c = 0; c < 2; ++c) {
                    double d = fabs(q[c] - p[2u * i + c]);
                    d = d > 0.5 ? 1.0 - d : d;
                    s += d * d;
                }
                best = s < best ? s : best;
            }
            e += best;
        }
    return e * (double)k / (g * g);
}

/* A Lloyd step with exact centroids never raises the energy; with the
 * lattice estimate it still falls at every step here (measured K E: 0.2219
 * after one step, 0.1691 after twelve), and stays above the hexagonal
 * bound 5 / (18 sqrt 3) = 0.16038 that no K points beat (Fejes Toth). The
 * draw of i steps is the first i steps of a longer one (same seed). */
static void test_each_lloyd_step_lowers_the_energy_toward_the_hexagonal_bound(void)
{
    const double hexagonal = 5.0 / (18.0 * sqrt(3.0));
    double last = HUGE_VAL;
    for (uint32_t it = 1; it <= 12u; ++it) {
        lloyd(64u, it, 0u, 5u, pts);
        const double e = energy(pts, 64u);
        TEST_ASSERT_TRUE_MESSAGE(e < last, "a Lloyd step raised the energy");
        TEST_ASSERT_TRUE(e > hexagonal * 0.995);
        last = e;
    }
    TEST_ASSERT_TRUE(last < 0.175);
}

/* After one step from the same points, the positions at resolutions 4, 16
 * and 64 approach those at 1024 (measured rms gaps 1.1e-2, 3.9e-3, 1.5e-3:
 * about a tenth of the lattice spacing at the default 64). */
static void test_the_centroid_estimate_converges_as_its_lattice_is_refined(void)
{
    static double fine[2u * 64u];
    lloyd(64u, 1u, 1024u, 5u, fine);
    const uint32_t res[3] = {4u, 16u, 64u};
    double last = HUGE_VAL;
    for (int i = 0; i < 3; ++i) {
        lloyd(64u, 1u, res[i], 5u, pts);
        double s = 0.0;
        for (size_t j = 0; j < 128u; ++j) {
            double d = fabs(pts[j] - fine[j]);
            d = d > 0.5 ? 1.0 - d : d;
            s += d * d;
        }
        const double rms = sqrt(s / 128.0), spacing = 1.0 / ceil(sqrt(64.0 * res[i]));
        TEST_ASSERT_TRUE(rms < last);
        TEST_ASSERT_TRUE(rms < 0.25 * spacing);
        last = rms;
    }
}

/* Step 2 against an independent step from the points after step 1: each
 * Voronoi centroid by brute force over the midpoints of a 512 x 512 lattice
 * (nearest point by a full scan, toroidal displacement). The library's step
 * at resolution 1024 (its lattice 256 x 256) agrees to a fraction of its
 * lattice spacing (measured rms gap 1.6e-4 against an rms step of 8.5e-3). */
static void test_a_step_moves_each_point_to_the_centroid_of_its_voronoi_cell(void)
{
    static double sx[64], sy[64], n[64], before[128];
    const size_t k = 64u;
    const int g = 512;
    lloyd(k, 1u, 1024u, 7u, before);
    lloyd(k, 2u, 1024u, 7u, pts);
    memset(sx, 0, sizeof sx);
    memset(sy, 0, sizeof sy);
    memset(n, 0, sizeof n);
    for (int a = 0; a < g; ++a)
        for (int b = 0; b < g; ++b) {
            const double q[2] = {(a + 0.5) / g, (b + 0.5) / g};
            double best = 1.0, dx = 0.0, dy = 0.0;
            size_t near = 0;
            for (size_t i = 0; i < k; ++i) {
                double d[2];
                for (int c = 0; c < 2; ++c) {
                    d[c] = q[c] - before[2u * i + c];
                    d[c] -= floor(d[c] + 0.5); /* toroidal, in [-1/2, 1/2) */
                }
                const double s2 = d[0] * d[0] + d[1] * d[1];
                if (s2 < best) {
                    best = s2;
                    near = i;
                    dx = d[0];
                    dy = d[1];
                }
            }
            sx[near] += dx;
            sy[near] += dy;
            n[near] += 1.0;
        }
    double gap = 0.0, step = 0.0;
    for (size_t i = 0; i < k; ++i) {
        const double want[2] = {before[2u * i] + sx[i] / n[i], before[2u * i + 1u] + sy[i] / n[i]};
        for (int c = 0; c < 2; ++c) {
            double d = pts[2u * i + c] - want[c];
            d -= floor(d + 0.5);
            gap += d * d;
            double m = pts[2u * i + c] - before[2u * i + c];
            m -= floor(m + 0.5);
            step += m * m;
        }
    }
    gap = sqrt(gap / (2.0 * k));
    step = sqrt(step / (2.0 * k));
    TEST_ASSERT_TRUE_MESSAGE(gap < 0.1 * step && gap < 0.25 / 256.0, "not the Voronoi centroid");
}

/* Low-frequency power below 1 in the annuli 1..5 by more than 10 standard
 * errors (10 sets of 128 points), and every set's points at least half d_max
 * apart (random points: about 0.03 d_max at this K). */
static void test_lloyd_sets_are_blue_noise(void)
{
    static unsigned char mem[MCS_POINTSET2D_SIZE_DIRECT(6)];
    static unsigned char swork[MCS_SPACING_WORK_SIZE(128)];
    mcs_pointset2d acc;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_init(&acc, 6u, MCS_POINTSET_DIRECT_ONLY, mem, sizeof mem));
    for (uint64_t s = 0; s < 10u; ++s) {
        lloyd(128u, 0u, 0u, 40u + s, pts);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add(&acc, 128u, pts));
        double d[MCS_SPACING_STATISTICS];
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spacing_distances(128u, 2u, pts, swork, sizeof swork, d));
        TEST_ASSERT_TRUE(d[MCS_SPACING_MIN_DISTANCE] > 0.5);
    }
    for (size_t r = 1; r <= 5u; ++r) {
        double mean = 0.0, se = 0.0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_radial(&acc, r, &mean));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_radial_stderr(&acc, r, &se));
        TEST_ASSERT_TRUE_MESSAGE(1.0 - mean > 10.0 * se, "low-frequency power not below 1");
    }
}

static void test_lloyd_draws_are_deterministic_for_a_seed(void)
{
    lloyd(100u, 3u, 0u, 9u, pts);
    lloyd(100u, 3u, 0u, 9u, other);
    TEST_ASSERT_EQUAL_MEMORY(pts, other, 200u * sizeof(double));
    lloyd(100u, 3u, 0u, 10u, other);
    TEST_ASSERT_TRUE(memcmp(pts, other, 200u * sizeof(double)) != 0);
    lloyd(1u, 2u, 0u, 9u, pts); /* one point: its cell is the torus */
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_each_lloyd_step_lowers_the_energy_toward_the_hexagonal_bound);
    RUN_TEST(test_the_centroid_estimate_converges_as_its_lattice_is_refined);
    RUN_TEST(test_a_step_moves_each_point_to_the_centroid_of_its_voronoi_cell);
    RUN_TEST(test_lloyd_sets_are_blue_noise);
    RUN_TEST(test_lloyd_draws_are_deterministic_for_a_seed);
    return UNITY_END();
}
