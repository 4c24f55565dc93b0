/* mcs_pattern_draw against a one-sample-at-a-time reference written from
 * its documentation: the fast draw (PCG32 states formed by jumps of one, two
 * and four steps, division by a power-of-two K as a multiplication, the bin
 * clamp as a floating-point minimum) must give bit for bit the bins, weights
 * and points of the plain definition, with and without points, and leave the
 * generator where the plain definition leaves it. Its alias rule is checked
 * against byte intervals. */
#include "mcspec.h"
#include "unity.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define MAXK 300

static size_t bins[MAXK], ref_bins[MAXK];
static double weights[MAXK], ref_weights[MAXK], points[MAXK], ref_points[MAXK];

static double next_double(mcs_rng *rng)
{
    double v = 0.0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_double(rng, &v));
    return v;
}

/* (b + t)/N moved by ulps into bin b, as documented for points. */
static double point_in_bin(size_t n, size_t b, double t)
{
    double x = ((double)b + t) / (double)n;
    while (x >= 1.0 || floor(x * (double)n) > (double)b)
        x = nextafter(x, 0.0);
    while (floor(x * (double)n) < (double)b)
        x = nextafter(x, 1.0);
    return x;
}

/* The documented draw without importance: v per sample (random, stratified)
 * or beta per trial (uniform 1/2, jitter); u = v or (j + v)/K below 1; bin
 * floor(t) with t = u N (random) or (j + v) N / K; the point is u when u lies
 * in that bin, else the point of t's fraction in it. */
static void reference_draw(mcs_pattern_kind kind, size_t n, size_t k, mcs_rng *rng)
{
    double beta = kind == MCS_PATTERN_JITTER ? next_double(rng) : 0.5;
    for (size_t j = 0; j < k; ++j) {
        double v = kind == MCS_PATTERN_RANDOM || kind == MCS_PATTERN_STRATIFIED ? next_double(rng) : beta;
        double u = kind == MCS_PATTERN_RANDOM ? v : ((double)j + v) / (double)k;
        double t = kind == MCS_PATTERN_RANDOM ? u * (double)n : ((double)j + v) * (double)n / (double)k;
        u = u < 1.0 ? u : nextafter(1.0, 0.0);
        size_t b = (size_t)t < n ? (size_t)t : n - 1u;
        double frac = t - (double)b;
        ref_bins[j] = b;
        ref_weights[j] = 1.0;
        ref_points[j] = (size_t)(u * (double)n) == b
                            ? u
                            : point_in_bin(n, b, frac < 1.0 ? frac : nextafter(1.0, 0.0));
    }
}

/* Trials with points, then without (the draw has a copy of its loop for
 * each: the one without is the spectra's and the bench's). */
static void check_kind(mcs_pattern_kind kind, size_t n, size_t k)
{
    mcs_pattern pat;
    mcs_rng fast, slow;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, kind, n, k, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&fast, 1234u + k, 77u + n));
    slow = fast;
    for (int trial = 0; trial < 20; ++trial) {
        double *out = trial < 10 ? points : NULL;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_draw(&pat, &fast, k, bins, weights, out));
        reference_draw(kind, n, k, &slow);
        TEST_ASSERT_EQUAL_MEMORY(ref_bins, bins, k * sizeof bins[0]);
        TEST_ASSERT_EQUAL_MEMORY(ref_weights, weights, k * sizeof weights[0]);
        if (out != NULL)
            TEST_ASSERT_EQUAL_MEMORY(ref_points, points, k * sizeof points[0]);
        TEST_ASSERT_EQUAL_MEMORY(&slow, &fast, sizeof fast);
    }
}

static void test_every_kind_draws_bit_for_bit_the_documented_samples_and_leaves_the_rng_alike(void)
{
    static const mcs_pattern_kind kinds[] = {MCS_PATTERN_RANDOM, MCS_PATTERN_STRATIFIED,
                                             MCS_PATTERN_UNIFORM, MCS_PATTERN_JITTER};
    /* Powers of two (multiplication by 1/K), odd K (a lone last sample in
     * the generator's pairs), K above and below N, N/K even (edges). */
    static const size_t ns[] = {1u, 24u, 1000u, 4096u, 4093u};
    static const size_t ks[] = {1u, 2u, 5u, 6u, 7u, 8u, 16u, 64u, 255u, 256u};
    for (size_t a = 0; a < sizeof kinds / sizeof kinds[0]; ++a)
        for (size_t b = 0; b < sizeof ns / sizeof ns[0]; ++b)
            for (size_t c = 0; c < sizeof ks / sizeof ks[0]; ++c)
                check_kind(kinds[a], ns[b], ks[c]);
}

static void test_the_homogenized_draw_uses_as_many_generator_steps_as_the_stratified_one_plus_its_shift(void)
{
    mcs_pattern strat, homog;
    mcs_rng r1, r2;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&strat, MCS_PATTERN_STRATIFIED, 100u, 7u, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&homog, MCS_PATTERN_HOMOGENIZED, 100u, 7u, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&r1, 9u, 3u));
    r2 = r1;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_draw(&homog, &r1, 7u, bins, weights, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_draw(&strat, &r2, 7u, ref_bins, ref_weights, NULL));
    uint32_t shift = 0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_bounded(&r2, 100u, &shift));
    TEST_ASSERT_EQUAL_MEMORY(&r2, &r1, sizeof r1);
    for (size_t j = 0; j < 7u; ++j)
        TEST_ASSERT_EQUAL_UINT((ref_bins[j] + shift) % 100u, bins[j]);
}

/* The alias rule of mcs_pattern_draw, by byte intervals: an output (bins,
 * weights, points when given) may not share a byte with another output, the
 * pattern, the generator or the importance function. Every object lives in
 * one arena; each output in turn is moved to just before, into the first
 * and last 8 bytes of, and just after each other object, and the draw must
 * refuse exactly the overlapping placements, writing nothing (arena byte
 * for byte, the generator in it included). */
#define ALIAS_K 6u
#define ALIAS_GAP 256u
enum { R_PAT, R_RNG, R_IMP, R_BINS, R_W, R_PTS, R_COUNT };

static double arena[(sizeof(mcs_importance) + 8u * ALIAS_GAP) / sizeof(double)];
static double arena_copy[sizeof arena / sizeof arena[0]];

static int bytes_overlap(size_t a, size_t a_len, size_t b, size_t b_len)
{
    return a_len > 0u && b_len > 0u && a < b + b_len && b < a + a_len;
}

/* Whether a draw with the regions at off[] (lengths len[]) must be refused. */
static int draw_must_refuse(const size_t *off, const size_t *len)
{
    for (int o = R_BINS; o < R_COUNT; ++o)
        for (int r = R_PAT; r < R_COUNT; ++r)
            if (r != o && bytes_overlap(off[o], len[o], off[r], len[r]))
                return 1;
    return 0;
}

static void check_alias_layout(mcs_pattern_kind kind, int with_imp, int with_pts, const size_t *off,
                               const size_t *len)
{
    unsigned char *base = (unsigned char *)arena;
    const size_t pat_k = ALIAS_K;
    mcs_pattern pat;
    mcs_rng rng;
    mcs_importance *imp = (mcs_importance *)(void *)(base + off[R_IMP]);
    double wts[8] = {1, 2, 3, 1, 2, 3, 1, 2};
    memset(arena, 0x5a, sizeof arena);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(imp, 8u, wts));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, kind, 8u, pat_k, with_imp ? imp : NULL));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, 5u, 6u));
    memcpy(base + off[R_PAT], &pat, sizeof pat);
    memcpy(base + off[R_RNG], &rng, sizeof rng);
    memcpy(arena_copy, arena, sizeof arena);
    mcs_status st = mcs_pattern_draw((const mcs_pattern *)(void *)(base + off[R_PAT]),
                                     (mcs_rng *)(void *)(base + off[R_RNG]), pat_k,
                                     (size_t *)(void *)(base + off[R_BINS]),
                                     (double *)(void *)(base + off[R_W]),
                                     with_pts ? (double *)(void *)(base + off[R_PTS]) : NULL);
    if (draw_must_refuse(off, len)) {
        TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, st);
        TEST_ASSERT_EQUAL_MEMORY(arena_copy, arena, sizeof arena);
    } else {
        TEST_ASSERT_EQUAL_INT(MCS_OK, st);
    }
}

static void test_the_draw_refuses_exactly_the_outputs_that_share_a_byte_with_what_it_touches(void)
{
    static const mcs_pattern_kind kinds[] = {MCS_PATTERN_RANDOM, MCS_PATTERN_STRATIFIED,
                                             MCS_PATTERN_HOMOGENIZED, MCS_PATTERN_UNIFORM,
                                             MCS_PATTERN_JITTER};
    /* Homes in order, ALIAS_GAP apart (more than any output is long). */
    const size_t sizes[R_COUNT] = {sizeof(mcs_pattern), sizeof(mcs_rng), sizeof(mcs_importance),
                                   ALIAS_K * sizeof(size_t), ALIAS_K * sizeof(double),
                                   ALIAS_K * sizeof(double)};
    size_t home[R_COUNT], at = ALIAS_GAP;
    for (int r = 0; r < R_COUNT; ++r) {
        home[r] = at;
        at += (sizes[r] + ALIAS_GAP + 7u) / 8u * 8u;
    }
    TEST_ASSERT_TRUE(at <= sizeof arena);
    size_t refused = 0, accepted = 0;
    for (size_t a = 0; a < sizeof kinds / sizeof kinds[0]; ++a)
        for (int flags = 0; flags < 4; ++flags) {
            const int with_imp = flags & 1, with_pts = flags >> 1;
            if (with_imp && kinds[a] == MCS_PATTERN_HOMOGENIZED)
                continue;
            size_t len[R_COUNT];
            memcpy(len, sizes, sizeof len);
            len[R_IMP] = with_imp ? sizes[R_IMP] : 0u;
            len[R_PTS] = with_pts ? sizes[R_PTS] : 0u;
            for (int o = R_BINS; o < R_COUNT; ++o) {
                if (len[o] == 0u)
                    continue;
                for (int r = R_PAT; r < R_COUNT; ++r) {
                    const size_t r_end = home[r] + (sizes[r] + 7u) / 8u * 8u;
                    const size_t at_r[5] = {home[r] - len[o], home[r] - len[o] + 8u, home[r],
                                            r_end - 8u, r_end};
                    for (int d = 0; d < 5 && r != o; ++d) {
                        size_t off[R_COUNT];
                        memcpy(off, home, sizeof off);
                        off[o] = at_r[d];
                        check_alias_layout(kinds[a], with_imp, with_pts, off, len);
                        draw_must_refuse(off, len) ? ++refused : ++accepted;
                    }
                }
            }
        }
    TEST_ASSERT_TRUE(refused > 100u && accepted > 100u);
}

/* fuzz_api: an importance object with a valid n but p_n = 0 (zeroed) gave
 * weights of inf with MCS_OK; it is refused and nothing is written. */
static void test_bin_points_refuses_a_corrupted_importance_object_writing_nothing(void)
{
    static mcs_importance broken;
    memset(&broken, 0, sizeof broken);
    broken.n = 2u;
    const double x[2] = {0.25, 0.75};
    const float xf[2] = {0.25f, 0.75f};
    for (int f = 0; f < 2; ++f) {
        bins[0] = bins[1] = 7u;
        weights[0] = weights[1] = -1.0;
        mcs_status st = f ? mcs_pattern_bin_points_f(2u, 2u, &broken, xf, bins, weights)
                          : mcs_pattern_bin_points(2u, 2u, &broken, x, bins, weights);
        TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, st);
        TEST_ASSERT_EQUAL_UINT(7u, bins[0]);
        TEST_ASSERT_EQUAL_UINT(7u, bins[1]);
        TEST_ASSERT_EQUAL_DOUBLE(-1.0, weights[0]);
        TEST_ASSERT_EQUAL_DOUBLE(-1.0, weights[1]);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_every_kind_draws_bit_for_bit_the_documented_samples_and_leaves_the_rng_alike);
    RUN_TEST(test_the_homogenized_draw_uses_as_many_generator_steps_as_the_stratified_one_plus_its_shift);
    RUN_TEST(test_the_draw_refuses_exactly_the_outputs_that_share_a_byte_with_what_it_touches);
    RUN_TEST(test_bin_points_refuses_a_corrupted_importance_object_writing_nothing);
    return UNITY_END();
}
