/* Is the scrambling's randomness sound? Statistics over many seeds of the
 * Owen scramble (mcs_sampler_owen_scramble), of the Sobol kinds' first
 * points, and of the Halton kinds' digit permutations, each against what an
 * ideal (nested uniform) scrambling gives, in standard units:
 *  - chi-square of a uniform law over C cells, as a normal z by Wilson and
 *    Hilferty's cube root (good to the tails for few cells too): |z| < 5
 *    (the defects found gave z from 9 to thousands; main's before the fix);
 *  - counts of rare coincidences (two seeds, two axes or two related seeds
 *    giving the same top digits) against their expectation E: within
 *    5 sqrt(E) + 3 (Poisson).
 * Seeds are those a user passes: consecutive 1..N, and, for the samplers, the
 * command's PCG32 seeding (mcs_rng_seed(S, 0)). */
#include "mcspec/rng.h"
#include "mcspec/sampler.h"
#include "unity.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define NSEED 4096u
#define MAXK 256u
#define MAXD 8u
static unsigned counts[1u << 15];
static uint32_t vals[MAXD][NSEED];
static double pts[MAXD * MAXK], pts2[MAXD * MAXK];

static double chi2_z(const unsigned *c, unsigned cells, double n)
{
    double e = n / (double)cells, x2 = 0.0, df = (double)(cells - 1u);
    for (unsigned i = 0; i < cells; ++i)
        x2 += ((double)c[i] - e) * ((double)c[i] - e) / e;
    double v = 2.0 / (9.0 * df);
    return (cbrt(x2 / df) - (1.0 - v)) / sqrt(v);
}

static void assert_uniform(const unsigned *c, unsigned cells, double n, const char *what)
{
    double z = chi2_z(c, cells, n);
    if (fabs(z) >= 5.0) {
        char msg[160];
        snprintf(msg, sizeof msg, "%s: chi-square z = %.1f over %u cells", what, z, cells);
        TEST_FAIL_MESSAGE(msg);
    }
}

/* A count of rare events against its (Poisson) expectation. */
static void assert_rare_count(double count, double expect, const char *what)
{
    if (fabs(count - expect) > 5.0 * sqrt(expect) + 3.0) {
        char msg[160];
        snprintf(msg, sizeof msg, "%s: %.0f, expected %.2f", what, count, expect);
        TEST_FAIL_MESSAGE(msg);
    }
}

static int cmp_u32(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return (x > y) - (x < y);
}

/* Pairs among v[0..n) (sorted here) with equal top `bits` bits. */
static double equal_prefix_pairs(uint32_t *v, unsigned n, unsigned bits)
{
    qsort(v, n, sizeof *v, cmp_u32);
    double pairs = 0.0, run = 1.0;
    for (unsigned i = 1; i <= n; ++i) {
        if (i < n && (v[i] >> (32u - bits)) == (v[i - 1] >> (32u - bits))) {
            run += 1.0;
        } else {
            pairs += run * (run - 1.0) / 2.0;
            run = 1.0;
        }
    }
    return pairs;
}

/* Top b digits uniform for b = 1..12 (chi-square), and at 16, 20, 24 digits
 * as many coinciding pairs of seeds as n independent uniform values give:
 * a prefix that depends on few seed bits fails one or the other. */
static void assert_uniform_at_every_level(uint32_t *v, unsigned n, const char *what)
{
    char msg[120];
    for (unsigned b = 1; b <= 12u; ++b) {
        memset(counts, 0, sizeof(unsigned) << b);
        for (unsigned i = 0; i < n; ++i)
            counts[v[i] >> (32u - b)]++;
        snprintf(msg, sizeof msg, "%s, top %u digits", what, b);
        assert_uniform(counts, 1u << b, (double)n, msg);
    }
    for (unsigned bits = 16u; bits <= 24u; bits += 4u) {
        snprintf(msg, sizeof msg, "%s, pairs of seeds sharing the top %u digits", what, bits);
        assert_rare_count(equal_prefix_pairs(v, n, bits),
                          (double)n * (double)(n - 1u) / 2.0 / ldexp(1.0, (int)bits), msg);
    }
}

static uint32_t bits32(double x) { return (uint32_t)ldexp(x, 32); }

/* ---- the scramble itself ---------------------------------------------------- */

static void test_scrambles_of_consecutive_seeds_are_uniform_at_every_level(void)
{
    const uint32_t xs[3] = {0u, 0x80000000u, 0x9e3779b9u};
    for (int c = 0; c < 3; ++c) {
        for (uint32_t s = 1u; s <= NSEED; ++s)
            vals[0][s - 1u] = mcs_sampler_owen_scramble(xs[c], s);
        assert_uniform_at_every_level(vals[0], NSEED, "scramble over seeds 1..4096");
    }
}

static void test_seeds_one_bit_apart_give_unrelated_scrambles(void)
{
    uint64_t state = 0x2545f4914f6cdd1du;
    double total = 0.0;
    for (unsigned bit = 0; bit < 32u; ++bit) {
        double same = 0.0;
        for (unsigned i = 0; i < NSEED; ++i) {
            state = state * 6364136223846793005u + 1442695040888963407u;
            uint32_t seed = (uint32_t)(state >> 32), x = (uint32_t)state;
            uint32_t a = mcs_sampler_owen_scramble(x, seed);
            uint32_t b = mcs_sampler_owen_scramble(x, seed ^ (1u << bit));
            same += (a >> 16) == (b >> 16);
        }
        char msg[80];
        snprintf(msg, sizeof msg, "seed bit %u flipped: top 16 digits unchanged", bit);
        assert_rare_count(same, NSEED / 65536.0, msg);
        total += same;
    }
    assert_rare_count(total, 32.0 * NSEED / 65536.0, "any seed bit flipped: top 16 unchanged");
}

/* The flips of digits 1..L of every prefix (2^L - 1 coins: digit l of the
 * image of the prefix with digit l = 0) as one code. */
static unsigned coin_code(uint32_t seed, unsigned levels)
{
    unsigned code = 0u, pos = 0u;
    for (unsigned l = 1; l <= levels; ++l)
        for (uint32_t p = 0; p < (1u << (l - 1u)); ++p, ++pos) {
            uint32_t x = l == 1u ? 0u : p << (33u - l);
            code |= ((mcs_sampler_owen_scramble(x, seed) >> (32u - l)) & 1u) << pos;
        }
    return code;
}

/* Owen's definition: every digit's flip is an independent fair coin per
 * prefix. So the 2^L - 1 coins of digits 1..L take all 2^(2^L - 1) values
 * equally often: for L = 3 (128 codes) and L = 4 (32768), over consecutive
 * seeds and over seeds that differ only above bit 14. */
static void test_digit_flips_are_independent_fair_coins_per_prefix(void)
{
    const unsigned n3 = 128u * 128u, n4 = 8u * 32768u;
    memset(counts, 0, sizeof(unsigned) << 7);
    for (uint32_t s = 1u; s <= n3; ++s)
        counts[coin_code(s, 3u)]++;
    assert_uniform(counts, 128u, n3, "coins of digits 1..3, seeds 1..16384");
    for (uint32_t shift = 0u; shift <= 14u; shift += 14u) {
        memset(counts, 0, sizeof(unsigned) << 15);
        for (uint32_t s = 1u; s <= n4; ++s)
            counts[coin_code(s << shift, 4u)]++;
        assert_uniform(counts, 32768u, n4,
                       shift ? "coins of digits 1..4, seeds (1..2^18) 2^14"
                             : "coins of digits 1..4, seeds 1..2^18");
    }
}

/* ---- Sobol samplers, seeded as the command seeds them ----------------------- */

static mcs_sampler make(mcs_sampler_kind kind, size_t dim, size_t k)
{
    mcs_sampler s;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_init(&s, kind, dim, k));
    return s;
}

static void draw_with_user_seed(const mcs_sampler *s, uint64_t seed, size_t k, double *p)
{
    mcs_rng rng;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, seed, 0u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_sampler_draw(s, &rng, k, p));
}

static void test_first_sobol_point_over_user_seeds_is_uniform_on_every_axis(void)
{
    const mcs_sampler_kind kinds[2] = {MCS_SAMPLER_SOBOL, MCS_SAMPLER_SOBOL_ND};
    const size_t dims[2] = {2u, MAXD};
    for (int c = 0; c < 2; ++c) {
        mcs_sampler s = make(kinds[c], dims[c], 2u);
        for (uint64_t seed = 1u; seed <= NSEED; ++seed) {
            draw_with_user_seed(&s, seed, 2u, pts);
            for (size_t a = 0; a < dims[c]; ++a)
                vals[a][seed - 1u] = bits32(pts[a]);
        }
        for (size_t a = 0; a < dims[c]; ++a)
            assert_uniform_at_every_level(vals[a], NSEED, "first point over --seed 1..4096");
    }
}

/* Points whose coordinates on two axes share their top `bits` digits, over
 * all pairs of axes, K points and user seeds 1..4096: for independent
 * scrambles each is a 2^-bits event. A seed shared by two axes makes point 0
 * agree on all 32. */
static void test_axes_of_one_seed_do_not_agree(void)
{
    const mcs_sampler_kind kinds[2] = {MCS_SAMPLER_SOBOL, MCS_SAMPLER_SOBOL_ND};
    const size_t dims[2] = {2u, MAXD}, k = 64u;
    for (int c = 0; c < 2; ++c) {
        const size_t d = dims[c];
        mcs_sampler s = make(kinds[c], d, k);
        double agree12 = 0.0, agree20 = 0.0;
        for (uint64_t seed = 1u; seed <= NSEED; ++seed) {
            draw_with_user_seed(&s, seed, k, pts);
            for (size_t j = 0; j < k; ++j)
                for (size_t a = 0; a < d; ++a)
                    for (size_t b = a + 1u; b < d; ++b) {
                        uint32_t x = bits32(pts[d * j + a]) ^ bits32(pts[d * j + b]);
                        agree12 += x >> 20 == 0u;
                        agree20 += x >> 12 == 0u;
                    }
        }
        const double n = (double)NSEED * (double)k * (double)(d * (d - 1u) / 2u);
        assert_rare_count(agree12, n / 4096.0, "coordinates of two axes sharing 12 digits");
        assert_rare_count(agree20, n / 1048576.0, "coordinates of two axes sharing 20 digits");
    }
}

/* --seed S and --seed S + 2^63 (or 2^32) start PCG32 from related states;
 * the sets must still be unrelated: coordinates sharing 16 digits as
 * independent uniform ones do. */
static void test_user_seeds_one_high_bit_apart_give_unrelated_sets(void)
{
    const mcs_sampler_kind kinds[2] = {MCS_SAMPLER_SOBOL, MCS_SAMPLER_SOBOL_ND};
    const size_t dims[2] = {2u, MAXD}, k = 16u;
    const uint64_t flips[2] = {UINT64_C(1) << 63, UINT64_C(1) << 32};
    for (int c = 0; c < 2; ++c)
        for (int f = 0; f < 2; ++f) {
            mcs_sampler s = make(kinds[c], dims[c], k);
            double same = 0.0;
            for (uint64_t seed = 1u; seed <= NSEED; ++seed) {
                draw_with_user_seed(&s, seed, k, pts);
                draw_with_user_seed(&s, seed ^ flips[f], k, pts2);
                for (size_t i = 0; i < k * dims[c]; ++i)
                    same += (bits32(pts[i]) ^ bits32(pts2[i])) >> 16 == 0u;
            }
            assert_rare_count(same, (double)NSEED * (double)(k * dims[c]) / 65536.0,
                              f ? "--seed S and S ^ 2^32: coordinates sharing 16 digits"
                                : "--seed S and S ^ 2^63: coordinates sharing 16 digits");
        }
}

/* ---- Halton digit permutations ---------------------------------------------- */

static const unsigned halton_bases[5] = {2u, 3u, 5u, 7u, 11u};

/* Digit i (0 = the 1/b digit) of x in base b. */
static unsigned digit(double x, unsigned b, unsigned i)
{
    for (unsigned r = 0; r < i; ++r)
        x = x * b - floor(x * b);
    return (unsigned)(x * b);
}

#define NPAIR (4u * NSEED)
static unsigned tally[5][121];

/* Over user seeds 1..NPAIR, on each axis a (base b), the pair (digit i of
 * point 0, digit i of point j2[a]) tallied in tally[a][u * b + v]. */
static void tally_digit_pairs(mcs_sampler_kind kind, size_t k, const size_t *j2, unsigned i)
{
    mcs_sampler s = make(kind, 5u, k);
    memset(tally, 0, sizeof tally);
    for (uint64_t seed = 1u; seed <= NPAIR; ++seed) {
        draw_with_user_seed(&s, seed, k, pts);
        for (size_t a = 0; a < 5u; ++a) {
            const unsigned b = halton_bases[a];
            tally[a][digit(pts[a], b, i) * b + digit(pts[5u * j2[a] + a], b, i)]++;
        }
    }
}

/* Two different digits below the same node of the digit tree: an ideal
 * permutation sends them to a uniform pair of distinct digits, each of the
 * b (b - 1) pairs equally often, never to equal digits. */
static void assert_distinct_pair_law(mcs_sampler_kind kind, const char *what)
{
    for (size_t a = 0; a < 5u; ++a) {
        const unsigned b = halton_bases[a];
        unsigned off[121], n = 0u;
        for (unsigned u = 0; u < b; ++u)
            for (unsigned v = 0; v < b; ++v) {
                if (u == v)
                    TEST_ASSERT_EQUAL_UINT_MESSAGE(0u, tally[a][u * b + v], "two digits merged");
                else
                    off[n++] = tally[a][u * b + v];
            }
        char msg[120];
        snprintf(msg, sizeof msg, "%s: %s, base %u", mcs_sampler_kind_str(kind), what, b);
        assert_uniform(off, n, NPAIR, msg);
    }
}

static void test_halton_permutations_send_two_digits_to_a_uniform_pair(void)
{
    const size_t one[5] = {1u, 1u, 1u, 1u, 1u};
    tally_digit_pairs(MCS_SAMPLER_HALTON_PERMUTED, 2u, one, 0u);
    assert_distinct_pair_law(MCS_SAMPLER_HALTON_PERMUTED, "digit 0 of points 0, 1");
    tally_digit_pairs(MCS_SAMPLER_HALTON_OWEN, 2u, one, 0u);
    assert_distinct_pair_law(MCS_SAMPLER_HALTON_OWEN, "digit 0 of points 0, 1");
    /* Owen, one level down: on the axis of base b, points 0 and b share
     * digit 0 and differ in digit 1 (0 and 1), below the same node. */
    const size_t own_base[5] = {2u, 3u, 5u, 7u, 11u};
    tally_digit_pairs(MCS_SAMPLER_HALTON_OWEN, 12u, own_base, 1u);
    assert_distinct_pair_law(MCS_SAMPLER_HALTON_OWEN, "digit 1 of points 0, b");
}

/* Owen: points 0 and 1 differ in digit 0, so digit 1 (0 for both) is
 * permuted at two different nodes: independently, b^2 pairs equally often.
 * Permuted (one permutation per digit position): equal images, always. */
static void test_halton_owen_permutes_each_node_independently(void)
{
    const size_t one[5] = {1u, 1u, 1u, 1u, 1u};
    tally_digit_pairs(MCS_SAMPLER_HALTON_OWEN, 2u, one, 1u);
    for (size_t a = 0; a < 5u; ++a) {
        const unsigned b = halton_bases[a];
        char msg[120];
        snprintf(msg, sizeof msg, "halton-owen: digit 1 of points 0, 1, base %u", b);
        assert_uniform(tally[a], b * b, NPAIR, msg);
    }
    tally_digit_pairs(MCS_SAMPLER_HALTON_PERMUTED, 2u, one, 1u);
    for (size_t a = 0; a < 5u; ++a) {
        const unsigned b = halton_bases[a];
        unsigned same = 0u;
        for (unsigned u = 0; u < b; ++u)
            same += tally[a][u * b + u];
        TEST_ASSERT_EQUAL_UINT(NPAIR, same);
    }
}

/* Three points with distinct digits 0, 1, 2 at place 0 (points 0, 1, 2):
 * under uniform permutations their images are a uniform triple of distinct
 * digits, b (b - 1) (b - 2) triples equally often. Affine maps alone reach
 * only b (b - 1) of them (an arithmetic progression), which a spectrum does
 * not see but a set's largest periodogram peaks do. Bases 5 and 7 (60 and
 * 210 triples), both kinds; bound 5 standard units (the hashed permutations
 * are random functions of the key, not uniform permutations: this measures
 * how close). */
static void test_halton_permutations_send_three_digits_to_a_uniform_triple(void)
{
    const mcs_sampler_kind kinds[2] = {MCS_SAMPLER_HALTON_PERMUTED, MCS_SAMPLER_HALTON_OWEN};
    static unsigned trip[2][343];
    for (int c = 0; c < 2; ++c) {
        mcs_sampler s = make(kinds[c], 4u, 3u);
        memset(trip, 0, sizeof trip);
        for (uint64_t seed = 1u; seed <= NPAIR; ++seed) {
            draw_with_user_seed(&s, seed, 3u, pts);
            for (size_t a = 2; a < 4u; ++a) {
                const unsigned b = halton_bases[a];
                const unsigned u = digit(pts[a], b, 0u), v = digit(pts[4u + a], b, 0u),
                               w = digit(pts[8u + a], b, 0u);
                trip[a - 2u][(u * b + v) * b + w]++;
            }
        }
        for (size_t a = 2; a < 4u; ++a) {
            const unsigned b = halton_bases[a];
            unsigned cells[210], n = 0u;
            for (unsigned u = 0; u < b; ++u)
                for (unsigned v = 0; v < b; ++v)
                    for (unsigned w = 0; w < b; ++w) {
                        const unsigned got = trip[a - 2u][(u * b + v) * b + w];
                        if (u != v && v != w && u != w)
                            cells[n++] = got;
                        else
                            TEST_ASSERT_EQUAL_UINT(0u, got);
                    }
            char msg[120];
            snprintf(msg, sizeof msg, "%s: digit 0 of points 0, 1, 2, base %u",
                     mcs_sampler_kind_str(kinds[c]), b);
            assert_uniform(cells, n, NPAIR, msg);
        }
    }
}

/* The first point over user seeds: uniform over the b^L cells of every
 * level L with b^L <= 4096, on every axis, for both kinds. */
static void test_first_halton_point_over_user_seeds_is_uniform_at_every_level(void)
{
    const mcs_sampler_kind kinds[2] = {MCS_SAMPLER_HALTON_PERMUTED, MCS_SAMPLER_HALTON_OWEN};
    for (int c = 0; c < 2; ++c) {
        mcs_sampler s = make(kinds[c], 5u, 1u);
        for (uint64_t seed = 1u; seed <= NSEED; ++seed) {
            draw_with_user_seed(&s, seed, 1u, pts);
            for (size_t a = 0; a < 5u; ++a)
                vals[a][seed - 1u] = bits32(pts[a]);
        }
        for (size_t a = 0; a < 5u; ++a) {
            const unsigned b = halton_bases[a];
            for (unsigned cells = b; cells <= 4096u; cells *= b) {
                memset(counts, 0, sizeof(unsigned) * cells);
                for (unsigned i = 0; i < NSEED; ++i)
                    counts[(unsigned)(ldexp((double)vals[a][i], -32) * cells)]++;
                char msg[120];
                snprintf(msg, sizeof msg, "%s: first point, base %u, %u cells",
                         mcs_sampler_kind_str(kinds[c]), b, cells);
                assert_uniform(counts, cells, NSEED, msg);
            }
        }
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_scrambles_of_consecutive_seeds_are_uniform_at_every_level);
    RUN_TEST(test_seeds_one_bit_apart_give_unrelated_scrambles);
    RUN_TEST(test_digit_flips_are_independent_fair_coins_per_prefix);
    RUN_TEST(test_first_sobol_point_over_user_seeds_is_uniform_on_every_axis);
    RUN_TEST(test_axes_of_one_seed_do_not_agree);
    RUN_TEST(test_user_seeds_one_high_bit_apart_give_unrelated_sets);
    RUN_TEST(test_halton_permutations_send_two_digits_to_a_uniform_pair);
    RUN_TEST(test_halton_permutations_send_three_digits_to_a_uniform_triple);
    RUN_TEST(test_halton_owen_permutes_each_node_independently);
    RUN_TEST(test_first_halton_point_over_user_seeds_is_uniform_at_every_level);
    return UNITY_END();
}
