/* The exact theory of Owen-scrambled sets (owen.h), by identities: phi_b
 * against a numerical integration of its definition; the 1D identity (an
 * Owen-scrambled van der Corput set of b^m points has the stratified
 * pattern's spectrum, mcs_pointset_exact_power) to rounding by both routes;
 * the pair counts of the unscrambled Sobol (dims 0, 1) and base-3
 * Hammersley sets equal to those the (0,m,2)-net property gives, the counts
 * against a brute-force count of shared digits, and the general route
 * against the fast one; bad calls change nothing. The Monte Carlo checks
 * are in test_owen_mc.c. */
#include <math.h>
#include <string.h>

#include "mcspec.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

#define KMAX 4096u
static double pts[2u * KMAX];
static uint64_t work[MCS_OWEN_LEN_MAX];
static mcs_owen ow;

/* ---- phi against its definition ----
 * x - y = (p - q + u - v) / b^(l+1), (p, q) a uniform pair of distinct
 * digits, u, v uniform: E e^{-i t (x - y)} = (|sum_p I_p|^2 - sum_p |I_p|^2)
 * / (b (b - 1)), I_p = int_0^1 e^{-i t (p + u)} du, by composite Simpson
 * (20000 panels: error below 1e-12 for t up to 63). */
static double phi_integrated(unsigned b, size_t l, long f)
{
    const double t = 2.0 * 3.14159265358979323846 * (double)f / pow((double)b, (double)l + 1.0);
    const int n = 20000;
    double sre = 0.0, sim = 0.0, s2 = 0.0;
    for (unsigned p = 0; p < b; ++p) {
        double re = 0.0, im = 0.0;
        for (int i = 0; i <= n; ++i) {
            const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
            const double a = t * ((double)p + (double)i / n);
            re += w * cos(a);
            im -= w * sin(a);
        }
        re /= 3.0 * n;
        im /= 3.0 * n;
        sre += re;
        sim += im;
        s2 += re * re + im * im;
    }
    return (sre * sre + sim * sim - s2) / ((double)b * ((double)b - 1.0));
}

static void test_phi_matches_the_integral_of_its_definition(void)
{
    const unsigned bases[3] = {2u, 3u, 5u};
    for (int bi = 0; bi < 3; ++bi)
        for (size_t l = 0; l < 4u; ++l)
            for (long f = -9; f <= 19; f += 7) {
                double v = 0.0;
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_owen_phi(bases[bi], l, f, &v));
                TEST_ASSERT_DOUBLE_WITHIN(1e-11, phi_integrated(bases[bi], l, f), v);
            }
}

static void test_phi_is_one_at_frequency_zero_and_even_in_frequency(void)
{
    for (size_t l = 0; l < 10u; ++l) {
        double a = 0.0, b = 0.0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_owen_phi(3u, l, 0, &a));
        TEST_ASSERT_DOUBLE_WITHIN(1e-15, 1.0, a);
        mcs_owen_phi(2u, l, 123457, &a);
        mcs_owen_phi(2u, l, -123457, &b);
        TEST_ASSERT_EQUAL_DOUBLE(a, b);
    }
}

/* ---- sets ---- */

static uint64_t ipow(unsigned b, unsigned e)
{
    uint64_t p = 1u;
    while (e-- > 0u)
        p *= b;
    return p;
}

/* Radical inverse of j in base b over D digits, one rounding: r / b^D. */
static double radical(uint64_t j, unsigned b, unsigned digits)
{
    uint64_t r = 0u;
    for (unsigned i = 0; i < digits; ++i, j /= b)
        r = r * b + j % b;
    return (double)r / (double)ipow(b, digits);
}

/* Unscrambled Sobol dims 0 and 1 (main's 2D sampler's base points). */
static void sobol01(size_t k)
{
    mcs_sampler s;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_init(&s, MCS_SAMPLER_SOBOL, 2u, k));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_base_points(&s, k, pts));
}

/* Hammersley in base b: (j / b^m, phi_b(j)), a (0,m,2)-net in base b. */
static void hammersley(unsigned b, unsigned m)
{
    const uint64_t k = ipow(b, m);
    for (uint64_t j = 0; j < k; ++j) {
        pts[2u * j] = (double)j / (double)k;
        pts[2u * j + 1u] = radical(j, b, m);
    }
}

static const size_t ax01[2] = {0u, 1u};

static void init2(size_t k, unsigned bx, unsigned by)
{
    const unsigned bases[2] = {bx, by};
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_owen_init(&ow, k, 2u, pts, 2u, ax01, bases, work,
                                                MCS_OWEN_LEN_MAX));
}

/* Every N(a, c) of the set in ow equal to the (0,m,2)-net's. */
static void assert_net_counts(unsigned b, unsigned m)
{
    for (size_t a = 0; a <= ow.digits[0]; ++a)
        for (size_t c = 0; c <= ow.digits[1]; ++c) {
            uint64_t got = 0, net = 0;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_owen_pair_count(&ow, a, c, &got));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_owen_net_pairs(b, m, a, c, &net));
            TEST_ASSERT_EQUAL_UINT64(net, got);
        }
}

static void test_sobol_dims_0_and_1_have_the_pair_counts_of_a_0_m_2_net(void)
{
    for (unsigned m = 0; m <= 11u; ++m) {
        sobol01((size_t)1u << m);
        init2((size_t)1u << m, 2u, 2u);
        assert_net_counts(2u, m);
    }
}

static void test_base_3_hammersley_has_the_pair_counts_of_a_0_m_2_net(void)
{
    for (unsigned m = 0; m <= 6u; ++m) {
        hammersley(3u, m);
        init2((size_t)ipow(3u, m), 3u, 3u);
        assert_net_counts(3u, m);
    }
}

/* Shared leading digits of x and y in base b by brute force (digit by digit
 * on exact integers r / b^D). */
static size_t shared_brute(uint64_t rx, uint64_t ry, unsigned b, unsigned digits)
{
    size_t l = 0;
    for (uint64_t p = ipow(b, digits - 1u); l < digits && rx / p == ry / p; p /= b, ++l) {
        rx %= p;
        ry %= p;
    }
    return l;
}

static void test_counts_of_a_mixed_base_halton_set_match_brute_force(void)
{
    /* Halton (phi_2, phi_3) over D digits, K = 300: not a net. */
    const size_t k = 300u;
    static uint64_t brute[45u * 28u];
    memset(brute, 0, sizeof brute);
    for (size_t j = 0; j < k; ++j) {
        pts[2u * j] = radical(j, 2u, 44u);
        pts[2u * j + 1u] = radical(j, 3u, 27u);
    }
    init2(k, 2u, 3u);
    TEST_ASSERT_EQUAL_UINT(44u, ow.digits[0]);
    TEST_ASSERT_EQUAL_UINT(27u, ow.digits[1]);
    for (size_t i = 0; i < k; ++i)
        for (size_t j = i + 1u; j < k; ++j) {
            const size_t a = shared_brute((uint64_t)llround(pts[2u * i] * 0x1p44),
                                          (uint64_t)llround(pts[2u * j] * 0x1p44), 2u, 44u);
            const double p3 = (double)ipow(3u, 27u);
            const size_t c = shared_brute((uint64_t)llround(pts[2u * i + 1u] * p3),
                                          (uint64_t)llround(pts[2u * j + 1u] * p3), 3u, 27u);
            ++brute[a * 28u + c];
        }
    for (size_t a = 0; a <= 44u; ++a)
        for (size_t c = 0; c <= 27u; ++c) {
            uint64_t got = 0;
            mcs_owen_pair_count(&ow, a, c, &got);
            TEST_ASSERT_EQUAL_UINT64(brute[a * 28u + c], got);
        }
}

static void test_equal_coordinates_count_at_the_top_level(void)
{
    const double x[4] = {0.25, 0.25, 0.25, 0.75};
    const size_t ax = 0u;
    const unsigned b = 2u;
    uint64_t n = 0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_owen_init(&ow, 4u, 1u, x, 1u, &ax, &b, work, MCS_OWEN_LEN_MAX));
    mcs_owen_pair_count(&ow, 44u, 0u, &n);
    TEST_ASSERT_EQUAL_UINT64(3u, n);
    mcs_owen_pair_count(&ow, 0u, 0u, &n);
    TEST_ASSERT_EQUAL_UINT64(3u, n);
    /* Three coinciding points add their pairs at every frequency: E P(f) =
     * 1 + (2/4)(3 + 3 phi_2(0, f)), phi_2(0, f) = -sinc^2(pi f / 2). */
    double p = 0.0, phi0 = 0.0;
    mcs_owen_power(&ow, 3, 0, &p);
    mcs_owen_phi(2u, 0u, 3, &phi0);
    TEST_ASSERT_DOUBLE_WITHIN(1e-14, 1.0 + 0.5 * (3.0 + 3.0 * phi0), p);
}

/* ---- the 1D identity ---- */

static void test_scrambled_van_der_corput_is_stratified_to_rounding(void)
{
    const unsigned bases[3] = {2u, 3u, 5u}, ms[3] = {10u, 6u, 4u};
    for (int bi = 0; bi < 3; ++bi) {
        const unsigned b = bases[bi];
        const size_t k = (size_t)ipow(b, ms[bi]), ax = 0u;
        for (size_t j = 0; j < k; ++j)
            pts[j] = radical(j, b, ms[bi]);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_owen_init(&ow, k, 1u, pts, 1u, &ax, &b, work,
                                                    MCS_OWEN_LEN_MAX));
        for (long f = -3 * (long)k; f <= 3 * (long)k; f += (long)k / 7 + 1) {
            double strat = 0.0, general = 0.0, net = 0.0;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_exact_power(MCS_PATTERN_STRATIFIED, k, f,
                                                                   &strat));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_owen_power(&ow, f, 0, &general));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_owen_net_power(b, ms[bi], f, 0, &net));
            TEST_ASSERT_DOUBLE_WITHIN(1e-12 * (double)k, strat, general);
            TEST_ASSERT_DOUBLE_WITHIN(1e-12 * (double)k, strat, net);
        }
    }
}

static void test_general_and_net_routes_agree_on_sobol_0_1(void)
{
    const unsigned m = 8u;
    sobol01((size_t)1u << m);
    init2((size_t)1u << m, 2u, 2u);
    for (long fx = -20; fx <= 20; fx += 3)
        for (long fy = 0; fy <= 300; fy += 23) {
            double g = 0.0, n = 0.0;
            mcs_owen_power(&ow, fx, fy, &g);
            mcs_owen_net_power(2u, m, fx, fy, &n);
            TEST_ASSERT_DOUBLE_WITHIN(1e-11, n, g);
            TEST_ASSERT_TRUE(g > -1e-11);
        }
}

static void test_a_projection_reads_only_its_axes(void)
{
    /* Sobol (0, 1) written as axes 2 and 0 of 3D points whose other axis is
     * out of range: the same counts as the 2D set. */
    static double p3[3u * 256u];
    const size_t axes[2] = {2u, 0u};
    const unsigned bases[2] = {2u, 2u};
    sobol01(256u);
    for (size_t j = 0; j < 256u; ++j) {
        p3[3u * j + 2u] = pts[2u * j];
        p3[3u * j] = pts[2u * j + 1u];
        p3[3u * j + 1u] = 7.0;
    }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_owen_init(&ow, 256u, 3u, p3, 2u, axes, bases, work,
                                                MCS_OWEN_LEN_MAX));
    assert_net_counts(2u, 8u);
}

/* ---- bad calls ---- */

static void test_bad_calls_change_nothing(void)
{
    sobol01(64u);
    init2(64u, 2u, 2u);
    mcs_owen before = ow;
    static uint64_t wbefore[MCS_OWEN_LEN_MAX];
    memcpy(wbefore, work, sizeof work);
    const unsigned bases[2] = {2u, 2u}, bad_b[2] = {2u, 1u};
    const size_t same[2] = {1u, 1u}, far[2] = {0u, 2u};
    size_t len = 0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_owen_len(2u, bases, &len));
    TEST_ASSERT_EQUAL_UINT64(45u * 45u + 90u, len);
    pts[5] = 1.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_owen_init(&ow, 64u, 2u, pts, 2u, ax01, bases, work, len));
    pts[5] = 0.5;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_SPACE, mcs_owen_init(&ow, 64u, 2u, pts, 2u, ax01, bases, work, len - 1u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_owen_init(&ow, 64u, 2u, pts, 2u, same, bases, work, len));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_owen_init(&ow, 64u, 2u, pts, 2u, far, bases, work, len));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_owen_init(&ow, 64u, 2u, pts, 2u, ax01, bad_b, work, len));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_owen_init(&ow, 0u, 2u, pts, 2u, ax01, bases, work, len));
    /* The adversarial table passes axes and bases as scalars: their NULLs here. */
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_owen_init(&ow, 64u, 2u, pts, 2u, NULL, bases, work, len));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_owen_init(&ow, 64u, 2u, pts, 2u, ax01, NULL, work, len));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_owen_len(2u, NULL, &len));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_owen_init(&ow, 64u, 2u, (const double *)(void *)work, 2u,
                                                       ax01, bases, work, len));
    TEST_ASSERT_EQUAL_MEMORY(&before, &ow, sizeof ow);
    TEST_ASSERT_EQUAL_MEMORY(wbefore, work, sizeof work);
    double p = 42.0;
    uint64_t n = 42u;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE, mcs_owen_power(&ow, MCS_OWEN_MAX_FREQ + 1L, 0, &p));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_owen_pair_count(&ow, 45u, 0u, &n));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_owen_net_power(2u, 33u, 1, 1, &p));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_owen_phi(2u, 44u, 1, &p));
    ++work[3]; /* the caller wrote the counts */
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_owen_power(&ow, 1, 1, &p));
    --work[3];
    mcs_owen zero;
    memset(&zero, 0, sizeof zero);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_owen_power(&zero, 1, 1, &p));
    TEST_ASSERT_EQUAL_DOUBLE(42.0, p);
    TEST_ASSERT_EQUAL_UINT64(42u, n);
}

static void test_every_sampler_kind_states_its_theory(void)
{
    mcs_owen_theory t = MCS_OWEN_THEORY_NONE;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_owen_theory_of(MCS_SAMPLER_SOBOL, 2u, &t));
    TEST_ASSERT_EQUAL_INT(MCS_OWEN_THEORY_NESTED, t);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_owen_theory_of(MCS_SAMPLER_HALTON, 2u, &t));
    TEST_ASSERT_EQUAL_INT(MCS_OWEN_THEORY_PHASE, t);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_owen_theory_of(MCS_SAMPLER_HALTON, 1u, &t));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_owen_theory_of((mcs_sampler_kind)99, 2u, &t));
    TEST_ASSERT_EQUAL_INT(MCS_OWEN_THEORY_PHASE, t);
    const struct {
        mcs_sampler_kind kind;
        mcs_owen_theory want;
    } kinds[] = {{MCS_SAMPLER_SOBOL_ND, MCS_OWEN_THEORY_NESTED},
                 {MCS_SAMPLER_HALTON_OWEN, MCS_OWEN_THEORY_NESTED},
                 {MCS_SAMPLER_LATTICE, MCS_OWEN_THEORY_PHASE},
                 {MCS_SAMPLER_HALTON_PERMUTED, MCS_OWEN_THEORY_NONE},
                 {MCS_SAMPLER_PADDED, MCS_OWEN_THEORY_NONE}};
    for (size_t i = 0; i < sizeof kinds / sizeof kinds[0]; ++i) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_owen_theory_of(kinds[i].kind, 2u, &t));
        TEST_ASSERT_EQUAL_INT(kinds[i].want, t);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_phi_matches_the_integral_of_its_definition);
    RUN_TEST(test_phi_is_one_at_frequency_zero_and_even_in_frequency);
    RUN_TEST(test_sobol_dims_0_and_1_have_the_pair_counts_of_a_0_m_2_net);
    RUN_TEST(test_base_3_hammersley_has_the_pair_counts_of_a_0_m_2_net);
    RUN_TEST(test_counts_of_a_mixed_base_halton_set_match_brute_force);
    RUN_TEST(test_equal_coordinates_count_at_the_top_level);
    RUN_TEST(test_scrambled_van_der_corput_is_stratified_to_rounding);
    RUN_TEST(test_general_and_net_routes_agree_on_sobol_0_1);
    RUN_TEST(test_a_projection_reads_only_its_axes);
    RUN_TEST(test_bad_calls_change_nothing);
    RUN_TEST(test_every_sampler_kind_states_its_theory);
    return UNITY_END();
}
