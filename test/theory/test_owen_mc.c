/* The exact Owen theory (owen.h) against Monte Carlo: the mean point-set
 * periodogram over T scrambled sets (mcs_pointset2d, mcs_pointset) within
 * 5 standard errors of E P(k) at every wave vector tested, for
 *  - main's 2D Owen-scrambled Sobol sampler (dims 0 and 1, K = 2^m), the
 *    (0,m,2)-net route;
 *  - Sobol dims 4 and 5 (Joe and Kuo's new-joe-kuo-6.21201 lines d = 5 and
 *    6, t = 2 at K = 2^7), scrambled here with mcs_sampler_owen_scramble
 *    and an independent seed per dimension, the general route;
 *  - Halton (phi_2, phi_3), K = 100, base 2 scrambled as above and base 3
 *    by a nested scrambling of this file (a random permutation of the three
 *    digits per node of the digit tree, from a hash of the digits above);
 *  - a base-3 scrambled van der Corput set of 27 points in 1D (stratified).
 * Each check also shows that a wrong phi fails at the same trials: 0.99 phi
 * (a 1% error) departs by more than 5 standard errors somewhere. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mcspec.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

#define F2 8u
#define F1 60u
#define KMAX 256u
static _Alignas(64) unsigned char mem2[MCS_POINTSET2D_SIZE_DIRECT(F2)];
static _Alignas(64) unsigned char mem1[MCS_POINTSET_SIZE_DIRECT(F1)];
static mcs_pointset2d acc2;
static mcs_pointset acc1;
static double base_pts[2u * KMAX], pts[2u * KMAX];
static uint64_t work[MCS_OWEN_LEN_MAX];
static mcs_owen ow;
static mcs_rng rng;

static uint32_t u32(void)
{
    uint32_t v = 0;
    mcs_rng_u32(&rng, &v);
    return v;
}

/* 20 random low bits below a 32-bit (base 2) or 20-digit (base 3) prefix:
 * the prefix plus them stays exact and below 1. */
static double tail(void) { return (double)(u32() >> 12) * 0x1p-20; }

static double owen2(uint32_t bits, uint32_t seed)
{
    return ((double)mcs_sampler_owen_scramble(bits, seed) + tail()) * 0x1p-32;
}

/* ---- a base-3 nested uniform scrambling ---- */

static uint64_t mix(uint64_t z)
{
    z += 0x9E3779B97F4A7C15u;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
}

static const unsigned char perm3[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                          {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};

#define D3 20u
#define P3 3486784401.0 /* 3^20 */

/* phi_3(j) over D3 digits, digit i mapped by the permutation of its node
 * (i and the digits above it, coded as 3^i + prefix), then a random tail. */
static double owen3(uint64_t j, uint64_t seed)
{
    uint64_t node = 1u, r = 0u;
    for (unsigned i = 0; i < D3; ++i, j /= 3u) {
        const unsigned d = (unsigned)(j % 3u);
        r = 3u * r + perm3[mix(seed ^ mix(node)) % 6u][d];
        node = 3u * node + d;
    }
    const double y = ((double)r + tail()) / P3;
    return y < 1.0 ? y : nextafter(1.0, 0.0);
}

static double radical3(uint64_t j)
{
    uint64_t r = 0u;
    for (unsigned i = 0; i < D3; ++i, j /= 3u)
        r = 3u * r + j % 3u;
    return (double)r / P3;
}

static uint32_t reverse32(uint32_t x)
{
    uint32_t r = 0;
    for (int i = 0; i < 32; ++i, x >>= 1)
        r = (r << 1) | (x & 1u);
    return r;
}

/* ---- Sobol dimensions from Joe-Kuo direction numbers ---- */

typedef struct {
    unsigned s, a;
    unsigned m[4];
} jk_line;

/* new-joe-kuo-6.21201, d = 5: s 3, a 2, m 1 1 1; d = 6: s 4, a 1, m 1 1 3 3. */
static const jk_line jk5 = {3u, 2u, {1u, 1u, 1u, 0u}}, jk6 = {4u, 1u, {1u, 1u, 3u, 3u}};

static void directions(const jk_line *jk, uint32_t *v)
{
    for (unsigned i = 1; i <= jk->s && i <= 4u; ++i)
        v[i - 1u] = (uint32_t)jk->m[i - 1u] << (32u - i);
    for (unsigned i = jk->s + 1u; i <= 32u; ++i) {
        uint32_t x = v[i - jk->s - 1u] ^ (v[i - jk->s - 1u] >> jk->s);
        for (unsigned q = 1; q < jk->s; ++q)
            if ((jk->a >> (jk->s - 1u - q)) & 1u)
                x ^= v[i - q - 1u];
        v[i - 1u] = x;
    }
}

static uint32_t sobol_bits(uint32_t j, const uint32_t *v)
{
    uint32_t x = 0;
    for (unsigned b = 0; j != 0u; ++b, j >>= 1)
        if (j & 1u)
            x ^= v[b];
    return x;
}

/* ---- the comparison ---- */

/* The counts of ow, read once (each read checks all of them). */
static uint64_t counts[(MCS_OWEN_MAX_DIGITS + 1u) * (MCS_OWEN_MAX_DIGITS + 1u)];

static void read_counts(void)
{
    for (size_t a = 0; a <= ow.digits[0]; ++a)
        for (size_t c = 0; c <= ow.digits[1]; ++c)
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_owen_pair_count(&ow, a, c,
                                                              &counts[a * (ow.digits[1] + 1u) + c]));
}

/* E P of a wrong phi, 0.99 phi at every level below L (1 at L), from the
 * set's counts in ow (read_counts): a 1% error in phi must fail. */
static double wrong_power(long fx, long fy)
{
    double px[MCS_OWEN_MAX_DIGITS + 1u], py[MCS_OWEN_MAX_DIGITS + 1u], sum = 0.0;
    const long f[2] = {fx, fy};
    double *row[2] = {px, py};
    for (size_t d = 0; d < 2u; ++d) {
        const size_t top = d < ow.dims ? ow.digits[d] : 0u;
        for (size_t l = 0; l < top; ++l) {
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_owen_phi(ow.base[d], l, f[d], &row[d][l]));
            row[d][l] *= 0.99;
        }
        row[d][top] = 1.0;
    }
    for (size_t a = 0; a <= ow.digits[0]; ++a)
        for (size_t c = 0; c <= ow.digits[1]; ++c)
            sum += (double)counts[a * (ow.digits[1] + 1u) + c] * px[a] * py[c];
    return 1.0 + 2.0 * sum / (double)ow.k;
}

typedef double (*exact_fn)(long fx, long fy);

/* Max |z| over the stored half plane of acc2 (f != 0) of the mean
 * periodogram against exact, and the same against the wrong phi. */
static void compare2(const char *what, exact_fn exact, double *zmax, double *zwrong)
{
    *zmax = 0.0;
    *zwrong = 0.0;
    for (long fy = 0; fy <= (long)F2; ++fy)
        for (long fx = fy == 0 ? 1 : -(long)F2; fx <= (long)F2; ++fx) {
            double mean = 0.0, se = 0.0;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_power(&acc2, fx, fy, &mean));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_power_stderr(&acc2, fx, fy, &se));
            const double e = exact(fx, fy), z = fabs(mean - e) / se;
            const double zw = fabs(mean - wrong_power(fx, fy)) / se;
            if (z > *zmax)
                *zmax = z;
            if (zw > *zwrong)
                *zwrong = zw;
            if (z >= 5.0)
                printf("%s: f = (%ld, %ld) mean %.5f exact %.5f se %.5f\n", what, fx, fy, mean, e,
                       se);
        }
    printf("%s: max |z| %.2f over %u wave vectors; 0.99 phi max |z| %.1f\n", what, *zmax,
           (2u * F2 + 1u) * F2 + F2, *zwrong);
    TEST_ASSERT_TRUE(*zmax < 5.0);
    TEST_ASSERT_TRUE(*zwrong > 5.0);
}

static void begin2(uint64_t seed)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_init(&acc2, F2, MCS_POINTSET_DIRECT_ONLY, mem2,
                                                      sizeof mem2));
    mcs_rng_seed(&rng, seed, 26u);
}

static const size_t ax01[2] = {0u, 1u};

static void owen_init2(size_t k, unsigned bx, unsigned by)
{
    const unsigned bases[2] = {bx, by};
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_owen_init(&ow, k, 2u, base_pts, 2u, ax01, bases, work,
                                                MCS_OWEN_LEN_MAX));
    read_counts();
}

static double general_power(long fx, long fy)
{
    double p = 0.0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_owen_power(&ow, fx, fy, &p));
    return p;
}

static double sobol01_power(long fx, long fy)
{
    double p = 0.0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_owen_net_power(2u, 6u, fx, fy, &p));
    return p;
}

#define TRIALS 3000u

static void test_owen_sobol_sampler_follows_the_net_theory_within_5_se(void)
{
    const size_t k = 64u;
    mcs_sampler s;
    double z, zw;
    begin2(0x50b01u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_init(&s, MCS_SAMPLER_SOBOL, 2u, k));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_base_points(&s, k, base_pts));
    owen_init2(k, 2u, 2u); /* for the wrong phi's counts */
    for (unsigned t = 0; t < TRIALS; ++t) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_draw(&s, &rng, k, pts));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add(&acc2, k, pts));
    }
    compare2("sobol-owen dims 0,1 K=64", sobol01_power, &z, &zw);
}

static void test_a_sobol_pair_with_t_2_follows_the_general_theory_within_5_se(void)
{
    const size_t k = 128u;
    uint32_t v5[32], v6[32];
    double z, zw;
    directions(&jk5, v5);
    directions(&jk6, v6);
    for (uint32_t j = 0; j < k; ++j) {
        base_pts[2u * j] = (double)sobol_bits(j, v5) * 0x1p-32;
        base_pts[2u * j + 1u] = (double)sobol_bits(j, v6) * 0x1p-32;
    }
    owen_init2(k, 2u, 2u);
    /* Not a (0,7,2)-net: the counts differ from the net's (t = 2). */
    int differ = 0;
    for (size_t a = 0; a <= 7u; ++a)
        for (size_t c = 0; c <= 7u; ++c) {
            uint64_t got = 0, net = 0;
            mcs_owen_pair_count(&ow, a, c, &got);
            mcs_owen_net_pairs(2u, 7u, a, c, &net);
            differ += got != net;
        }
    TEST_ASSERT_TRUE(differ > 0);
    begin2(0x50b02u);
    for (unsigned t = 0; t < TRIALS; ++t) {
        const uint32_t sx = u32(), sy = u32();
        for (uint32_t j = 0; j < k; ++j) {
            pts[2u * j] = owen2(sobol_bits(j, v5), sx);
            pts[2u * j + 1u] = owen2(sobol_bits(j, v6), sy);
        }
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add(&acc2, k, pts));
    }
    compare2("sobol dims 4,5 (t=2) K=128", general_power, &z, &zw);
}

static void test_owen_scrambled_halton_2_3_follows_the_general_theory_within_5_se(void)
{
    const size_t k = 100u;
    double z, zw;
    for (uint32_t j = 0; j < k; ++j) {
        base_pts[2u * j] = (double)reverse32(j) * 0x1p-32;
        base_pts[2u * j + 1u] = radical3(j);
    }
    owen_init2(k, 2u, 3u);
    begin2(0x4a170u);
    for (unsigned t = 0; t < TRIALS; ++t) {
        const uint32_t sx = u32();
        const uint64_t sy = ((uint64_t)u32() << 32) | u32();
        for (uint32_t j = 0; j < k; ++j) {
            pts[2u * j] = owen2(reverse32(j), sx);
            pts[2u * j + 1u] = owen3(j, sy);
        }
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add(&acc2, k, pts));
    }
    compare2("halton-owen bases 2,3 K=100", general_power, &z, &zw);
}

static void test_base_3_scrambled_van_der_corput_is_stratified_within_5_se(void)
{
    const size_t k = 27u, ax = 0u;
    const unsigned b = 3u;
    for (uint32_t j = 0; j < k; ++j)
        base_pts[j] = radical3(j);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_owen_init(&ow, k, 1u, base_pts, 1u, &ax, &b, work,
                                                MCS_OWEN_LEN_MAX));
    read_counts();
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(&acc1, F1, MCS_POINTSET_DIRECT_ONLY, mem1,
                                                    sizeof mem1));
    mcs_rng_seed(&rng, 0x3dc3u, 26u);
    for (unsigned t = 0; t < TRIALS; ++t) {
        const uint64_t seed = ((uint64_t)u32() << 32) | u32();
        for (uint32_t j = 0; j < k; ++j)
            pts[j] = owen3(j, seed);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add(&acc1, k, pts));
    }
    double zmax = 0.0, zwrong = 0.0;
    for (long f = 1; f <= (long)F1; ++f) {
        double mean = 0.0, se = 0.0, strat = 0.0, own = 0.0;
        mcs_pointset_power(&acc1, f, &mean);
        mcs_pointset_power_stderr(&acc1, f, &se);
        mcs_pointset_exact_power(MCS_PATTERN_STRATIFIED, k, f, &strat);
        mcs_owen_power(&ow, f, 0, &own);
        TEST_ASSERT_DOUBLE_WITHIN(1e-12, strat, own);
        zmax = fmax(zmax, fabs(mean - own) / se);
        zwrong = fmax(zwrong, fabs(mean - wrong_power(f, 0)) / se);
    }
    printf("van der corput base 3 K=27 1D: max |z| %.2f over %u frequencies; 0.99 phi %.1f\n",
           zmax, F1, zwrong);
    TEST_ASSERT_TRUE(zmax < 5.0);
    TEST_ASSERT_TRUE(zwrong > 5.0);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_owen_sobol_sampler_follows_the_net_theory_within_5_se);
    RUN_TEST(test_a_sobol_pair_with_t_2_follows_the_general_theory_within_5_se);
    RUN_TEST(test_owen_scrambled_halton_2_3_follows_the_general_theory_within_5_se);
    RUN_TEST(test_base_3_scrambled_van_der_corput_is_stratified_within_5_se);
    return UNITY_END();
}
