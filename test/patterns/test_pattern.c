#include "mcspec.h"
#include "unity.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define GUARD_BIN ((size_t)0xA5A5A5A5u)
#define GUARD_W (-12345.0)
#define MAXK 64

static mcs_importance imp;
static mcs_importance imp_copy;
static size_t bins[MAXK + 1];
static double weights[MAXK + 1];
static double points[MAXK + 1];

static const mcs_pattern_kind all_kinds[MCS_PATTERN_KIND_COUNT] = {
    MCS_PATTERN_RANDOM, MCS_PATTERN_STRATIFIED, MCS_PATTERN_HOMOGENIZED, MCS_PATTERN_UNIFORM,
    MCS_PATTERN_JITTER};

/* A lumpy importance function: weights 1 + (b*7 mod 5), no zeros. */
static void lumpy_importance(size_t n)
{
    double w[MCS_MAX_N];
    for (size_t b = 0; b < n; ++b)
        w[b] = 1.0 + (double)((b * 7u) % 5u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, n, w));
}

static void set_guards(size_t k)
{
    bins[k] = GUARD_BIN;
    weights[k] = GUARD_W;
    points[k] = GUARD_W;
}

static void assert_guards(size_t k)
{
    TEST_ASSERT_EQUAL_UINT(GUARD_BIN, bins[k]);
    TEST_ASSERT_EQUAL_DOUBLE(GUARD_W, weights[k]);
    TEST_ASSERT_EQUAL_DOUBLE(GUARD_W, points[k]);
}

static void test_every_kind_gives_bins_in_range_points_in_their_bins_and_weights_one_over_p(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 1u, 1u);
    const size_t shapes[3][2] = {{16u, 4u}, {13u, 5u}, {7u, 20u}};
    for (int with_imp = 0; with_imp < 2; ++with_imp) {
        for (int s = 0; s < 3; ++s) {
            size_t n = shapes[s][0], k = shapes[s][1];
            lumpy_importance(n);
            for (int kind = 0; kind < MCS_PATTERN_KIND_COUNT; ++kind) {
                if (with_imp && all_kinds[kind] == MCS_PATTERN_HOMOGENIZED)
                    continue;
                mcs_pattern pat;
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, all_kinds[kind], n, k,
                                                               with_imp ? &imp : NULL));
                for (int t = 0; t < 200; ++t) {
                    set_guards(k);
                    TEST_ASSERT_EQUAL_INT(MCS_OK,
                                          mcs_pattern_draw(&pat, &rng, k, bins, weights, points));
                    assert_guards(k);
                    for (size_t j = 0; j < k; ++j) {
                        TEST_ASSERT_TRUE(bins[j] < n);
                        TEST_ASSERT_TRUE(points[j] >= 0.0 && points[j] < 1.0);
                        TEST_ASSERT_EQUAL_UINT(bins[j], (size_t)floor(points[j] * (double)n));
                        double w = with_imp ? 1.0 / imp.p[bins[j]] : 1.0;
                        TEST_ASSERT_EQUAL_DOUBLE(w, weights[j]);
                    }
                }
            }
        }
    }
}

static void test_stratified_has_exactly_one_sample_per_stratum_when_k_divides_n(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 2u, 3u);
    mcs_pattern pat;
    mcs_pattern_init(&pat, MCS_PATTERN_STRATIFIED, 64u, 8u, NULL);
    for (int t = 0; t < 1000; ++t) {
        mcs_pattern_draw(&pat, &rng, 8u, bins, weights, NULL);
        for (size_t j = 0; j < 8u; ++j)
            TEST_ASSERT_EQUAL_UINT(j, bins[j] / 8u);
    }
}

static void test_uniform_is_deterministic_at_bin_centres_of_the_strata(void)
{
    mcs_rng rng, before;
    mcs_rng_seed(&rng, 5u, 6u);
    before = rng;
    mcs_pattern pat;
    mcs_pattern_init(&pat, MCS_PATTERN_UNIFORM, 30u, 7u, NULL);
    size_t first[7];
    mcs_pattern_draw(&pat, &rng, 7u, first, weights, points);
    for (size_t j = 0; j < 7u; ++j) {
        TEST_ASSERT_EQUAL_DOUBLE(((double)j + 0.5) / 7.0, points[j]);
        TEST_ASSERT_EQUAL_UINT((size_t)floor(30.0 * ((double)j + 0.5) / 7.0), first[j]);
    }
    for (int t = 0; t < 10; ++t) {
        mcs_pattern_draw(&pat, &rng, 7u, bins, weights, NULL);
        TEST_ASSERT_EQUAL_MEMORY(first, bins, sizeof first);
    }
    /* It consumes no randomness. */
    TEST_ASSERT_EQUAL_MEMORY(&before, &rng, sizeof rng);
}

static void test_jitter_samples_are_exactly_n_over_k_bins_apart_when_k_divides_n(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 8u, 9u);
    mcs_pattern pat;
    mcs_pattern_init(&pat, MCS_PATTERN_JITTER, 96u, 12u, NULL);
    int offsets_seen[8] = {0};
    for (int t = 0; t < 400; ++t) {
        mcs_pattern_draw(&pat, &rng, 12u, bins, weights, NULL);
        for (size_t j = 1; j < 12u; ++j)
            TEST_ASSERT_EQUAL_UINT(8u, bins[j] - bins[j - 1u]);
        offsets_seen[bins[0]] = 1;
    }
    for (int o = 0; o < 8; ++o) /* and the common offset is random */
        TEST_ASSERT_TRUE(offsets_seen[o]);
}

static void test_homogenized_is_a_cyclic_shift_of_the_stratified_pattern(void)
{
    const size_t n = 20u, k = 6u; /* strata do not line up with bins */
    mcs_rng a, b;
    mcs_rng_seed(&a, 10u, 11u);
    mcs_pattern hom, strat;
    mcs_pattern_init(&hom, MCS_PATTERN_HOMOGENIZED, n, k, NULL);
    mcs_pattern_init(&strat, MCS_PATTERN_STRATIFIED, n, k, NULL);
    size_t sb[6];
    double sp[6];
    int shift_seen[20] = {0};
    for (int t = 0; t < 2000; ++t) {
        b = a;
        mcs_pattern_draw(&hom, &a, k, bins, weights, points);
        mcs_pattern_draw(&strat, &b, k, sb, weights, sp);
        uint32_t shift;
        mcs_rng_bounded(&b, (uint32_t)n, &shift); /* drawn after the strata */
        TEST_ASSERT_EQUAL_MEMORY(&a, &b, sizeof a);
        shift_seen[shift] = 1;
        for (size_t j = 0; j < k; ++j) {
            TEST_ASSERT_EQUAL_UINT((sb[j] + shift) % n, bins[j]);
            /* same offset inside the bin */
            double off_s = sp[j] * (double)n - (double)sb[j];
            double off_h = points[j] * (double)n - (double)bins[j];
            TEST_ASSERT_DOUBLE_WITHIN(1e-12, off_s, off_h);
        }
    }
    for (size_t d = 0; d < n; ++d)
        TEST_ASSERT_TRUE(shift_seen[d]);
}

/* Mean bin count r_n over trials against K g_n, each within 5 standard errors
 * estimated from the trials themselves. */
static void check_histogram(mcs_pattern_kind kind, size_t n, size_t k, int with_imp, uint64_t seed)
{
    enum { TRIALS = 20000 };
    static mcs_welford count[MCS_MAX_N];
    double r[64];
    lumpy_importance(n);
    mcs_pattern pat;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, kind, n, k, with_imp ? &imp : NULL));
    mcs_rng rng;
    mcs_rng_seed(&rng, seed, 77u);
    for (size_t b = 0; b < n; ++b)
        mcs_welford_init(&count[b]);
    for (int t = 0; t < TRIALS; ++t) {
        memset(r, 0, sizeof r);
        mcs_pattern_draw(&pat, &rng, k, bins, weights, NULL);
        for (size_t j = 0; j < k; ++j)
            r[bins[j]] += 1.0;
        for (size_t b = 0; b < n; ++b)
            mcs_welford_add(&count[b], r[b]);
    }
    for (size_t b = 0; b < n; ++b) {
        double g = with_imp ? imp.g[b] : 1.0 / (double)n, mean, se;
        mcs_welford_mean(&count[b], &mean);
        mcs_welford_stderr(&count[b], &se);
        char msg[96];
        snprintf(msg, sizeof msg, "kind %s n %zu k %zu imp %d bin %zu", mcs_pattern_kind_str(kind),
                 n, k, with_imp, b);
        TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(5.0 * se + 1e-12, (double)k * g, mean, msg);
    }
}

static void test_bin_histograms_match_k_g_n_for_every_kind_with_and_without_importance(void)
{
    const mcs_pattern_kind kinds[4] = {MCS_PATTERN_RANDOM, MCS_PATTERN_STRATIFIED,
                                       MCS_PATTERN_HOMOGENIZED, MCS_PATTERN_JITTER};
    for (int i = 0; i < 4; ++i) {
        check_histogram(kinds[i], 16u, 4u, 0, 100u + (uint64_t)i);
        check_histogram(kinds[i], 13u, 5u, 0, 200u + (uint64_t)i);
        if (kinds[i] != MCS_PATTERN_HOMOGENIZED) {
            check_histogram(kinds[i], 16u, 4u, 1, 300u + (uint64_t)i);
            check_histogram(kinds[i], 13u, 5u, 1, 400u + (uint64_t)i);
        }
    }
}

static void test_uniform_histogram_is_exactly_one_per_bin_when_k_equals_n(void)
{
    /* The only uniform case whose histogram can equal K g_n: deterministic. */
    check_histogram(MCS_PATTERN_UNIFORM, 24u, 24u, 0, 5u);
}

static void test_bin_points_maps_caller_points_to_bins_and_weights(void)
{
    lumpy_importance(10u);
    const double pts[4] = {0.0, 0.05, 0.55, nextafter(1.0, 0.0)};
    set_guards(4u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_bin_points(10u, 4u, NULL, pts, bins, weights));
    assert_guards(4u);
    const size_t expect[4] = {0u, 0u, 5u, 9u};
    for (int j = 0; j < 4; ++j) {
        TEST_ASSERT_EQUAL_UINT(expect[j], bins[j]);
        TEST_ASSERT_EQUAL_DOUBLE(1.0, weights[j]);
    }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_bin_points(10u, 4u, &imp, pts, bins, weights));
    for (int j = 0; j < 4; ++j)
        TEST_ASSERT_EQUAL_DOUBLE(1.0 / imp.p[expect[j]], weights[j]);
}

static void test_dense_form_sums_weights_per_bin(void)
{
    const size_t b[5] = {3u, 0u, 3u, 7u, 3u};
    const double w[5] = {0.5, 2.0, 0.25, 1.0, 1.0};
    double s[9];
    s[8] = GUARD_W;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_dense(8u, 5u, b, w, s));
    const double expect[8] = {2.0, 0.0, 0.0, 1.75, 0.0, 0.0, 0.0, 1.0};
    TEST_ASSERT_EQUAL_DOUBLE_ARRAY(expect, s, 8);
    TEST_ASSERT_EQUAL_DOUBLE(GUARD_W, s[8]);
}

static void test_bad_pattern_configuration_returns_an_error_and_changes_nothing(void)
{
    lumpy_importance(8u);
    mcs_pattern pat, copy;
    memset(&pat, 0, sizeof pat); /* defined padding, so the byte comparison below is sound */
    mcs_pattern_init(&pat, MCS_PATTERN_RANDOM, 8u, 2u, NULL);
    memcpy(&copy, &pat, sizeof pat);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pattern_init(NULL, MCS_PATTERN_RANDOM, 8u, 2u, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_N_RANGE, mcs_pattern_init(&pat, MCS_PATTERN_RANDOM, 0u, 2u, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_N_RANGE,
                          mcs_pattern_init(&pat, MCS_PATTERN_RANDOM, MCS_MAX_N + 1u, 2u, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_pattern_init(&pat, MCS_PATTERN_RANDOM, 8u, 0u, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_pattern_init(&pat, (mcs_pattern_kind)17, 8u, 2u, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND,
                          mcs_pattern_init(&pat, MCS_PATTERN_HOMOGENIZED, 8u, 2u, &imp));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH,
                          mcs_pattern_init(&pat, MCS_PATTERN_RANDOM, 9u, 2u, &imp));
    memset(&imp_copy, 0, sizeof imp_copy);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT,
                          mcs_pattern_init(&pat, MCS_PATTERN_RANDOM, 8u, 2u, &imp_copy));
    TEST_ASSERT_EQUAL_MEMORY(&copy, &pat, sizeof pat);
    TEST_ASSERT_EQUAL_STRING("stratified", mcs_pattern_kind_str(MCS_PATTERN_STRATIFIED));
    TEST_ASSERT_EQUAL_STRING("unknown", mcs_pattern_kind_str((mcs_pattern_kind)17));
}

static void test_bad_draw_writes_nothing_and_does_not_advance_the_rng(void)
{
    mcs_pattern pat, zero;
    mcs_pattern_init(&pat, MCS_PATTERN_RANDOM, 8u, 3u, NULL);
    memset(&zero, 0, sizeof zero);
    mcs_rng rng, before;
    mcs_rng_seed(&rng, 1u, 2u);
    before = rng;
    for (int j = 0; j < 4; ++j) {
        bins[j] = GUARD_BIN;
        weights[j] = GUARD_W;
        points[j] = GUARD_W;
    }
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pattern_draw(NULL, &rng, 3u, bins, weights, points));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pattern_draw(&pat, NULL, 3u, bins, weights, points));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pattern_draw(&pat, &rng, 3u, NULL, weights, points));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pattern_draw(&pat, &rng, 3u, bins, NULL, points));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, mcs_pattern_draw(&pat, &rng, 2u, bins, weights, points));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_pattern_draw(&zero, &rng, 3u, bins, weights, points));
    TEST_ASSERT_EQUAL_MEMORY(&before, &rng, sizeof rng);
    for (int j = 0; j < 4; ++j) {
        TEST_ASSERT_EQUAL_UINT(GUARD_BIN, bins[j]);
        TEST_ASSERT_EQUAL_DOUBLE(GUARD_W, weights[j]);
        TEST_ASSERT_EQUAL_DOUBLE(GUARD_W, points[j]);
    }
}

static void test_bad_points_or_bins_return_an_error_and_leave_outputs_untouched(void)
{
    lumpy_importance(8u);
    const double bad_pts[3] = {0.1, 1.0, 0.2};
    const double neg_pts[3] = {0.1, -0.0625, 0.2};
    const double nan_pts[3] = {0.1, NAN, 0.2};
    const double ok_pts[3] = {0.1, 0.3, 0.2};
    for (int j = 0; j < 4; ++j) {
        bins[j] = GUARD_BIN;
        weights[j] = GUARD_W;
    }
    TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_pattern_bin_points(8u, 3u, NULL, bad_pts, bins, weights));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_pattern_bin_points(8u, 3u, NULL, neg_pts, bins, weights));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_pattern_bin_points(8u, 3u, NULL, nan_pts, bins, weights));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pattern_bin_points(8u, 3u, NULL, NULL, bins, weights));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pattern_bin_points(8u, 3u, NULL, ok_pts, NULL, weights));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pattern_bin_points(8u, 3u, NULL, ok_pts, bins, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_N_RANGE, mcs_pattern_bin_points(0u, 3u, NULL, ok_pts, bins, weights));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_N_RANGE,
                          mcs_pattern_bin_points(MCS_MAX_N + 1u, 3u, NULL, ok_pts, bins, weights));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_pattern_bin_points(8u, 0u, NULL, ok_pts, bins, weights));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, mcs_pattern_bin_points(9u, 3u, &imp, ok_pts, bins, weights));
    for (int j = 0; j < 4; ++j) {
        TEST_ASSERT_EQUAL_UINT(GUARD_BIN, bins[j]);
        TEST_ASSERT_EQUAL_DOUBLE(GUARD_W, weights[j]);
    }

    const size_t b_ok[3] = {1u, 2u, 3u}, b_bad[3] = {1u, 8u, 3u};
    const double w_ok[3] = {1.0, 1.0, 1.0}, w_nan[3] = {1.0, NAN, 1.0}, w_neg[3] = {1.0, -1.0, 1.0};
    double s[8], s_copy[8];
    for (int i = 0; i < 8; ++i)
        s[i] = s_copy[i] = GUARD_W;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_BIN_RANGE, mcs_pattern_dense(8u, 3u, b_bad, w_ok, s));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NOT_FINITE, mcs_pattern_dense(8u, 3u, b_ok, w_nan, s));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NEGATIVE, mcs_pattern_dense(8u, 3u, b_ok, w_neg, s));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pattern_dense(8u, 3u, NULL, w_ok, s));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pattern_dense(8u, 3u, b_ok, NULL, s));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pattern_dense(8u, 3u, b_ok, w_ok, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_N_RANGE, mcs_pattern_dense(0u, 3u, b_ok, w_ok, s));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_N_RANGE, mcs_pattern_dense(MCS_MAX_N + 1u, 3u, b_ok, w_ok, s));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_pattern_dense(8u, 0u, b_ok, w_ok, s));
    TEST_ASSERT_EQUAL_MEMORY(s_copy, s, sizeof s);
}

/* ---- issue 10 items 3, 4, 10 and issue 12's flat importance function ---- */

/* Issue 10 item 3: a never-seeded rng is refused before anything is written
 * (a homogenized draw at N = 10 used to spin in the bounded shift draw). The
 * random kind comes first, so that without the fix the test fails, not hangs. */
static void test_a_never_seeded_rng_is_refused_by_every_kind(void)
{
    mcs_rng zero, before;
    memset(&zero, 0, sizeof zero);
    before = zero;
    const mcs_pattern_kind kinds[4] = {MCS_PATTERN_RANDOM, MCS_PATTERN_STRATIFIED,
                                       MCS_PATTERN_JITTER, MCS_PATTERN_HOMOGENIZED};
    for (int i = 0; i < 4; ++i) {
        mcs_pattern pat;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, kinds[i], 10u, 3u, NULL));
        set_guards(0u);
        TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT,
                              mcs_pattern_draw(&pat, &zero, 3u, bins, weights, points));
        assert_guards(0u);
        TEST_ASSERT_EQUAL_MEMORY(&before, &zero, sizeof zero);
    }
}

/* init refuses homogenized strata with an importance function; a pattern
 * edited into that state afterwards is refused by the draw, nothing written. */
static void test_a_homogenized_pattern_given_an_importance_object_later_is_refused(void)
{
    mcs_pattern pat;
    mcs_rng rng, before;
    lumpy_importance(10u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, MCS_PATTERN_HOMOGENIZED, 10u, 3u, NULL));
    pat.importance = &imp;
    mcs_rng_seed(&rng, 1u, 1u);
    before = rng;
    for (size_t j = 0; j <= 3u; ++j)
        set_guards(j);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_pattern_draw(&pat, &rng, 3u, bins, weights, points));
    for (size_t j = 0; j <= 3u; ++j)
        assert_guards(j);
    TEST_ASSERT_EQUAL_MEMORY(&before, &rng, sizeof rng);
}

/* Issue 10 item 4: K is bounded by MCS_MAX_K (pattern.h says why). */
static void test_k_above_the_documented_maximum_is_refused(void)
{
    mcs_pattern pat, copy;
    memset(&pat, 0, sizeof pat);
    copy = pat;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_pattern_init(&pat, MCS_PATTERN_UNIFORM, 8u,
                                                            (size_t)MCS_MAX_K + 1u, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE,
                          mcs_pattern_init(&pat, MCS_PATTERN_RANDOM, 8u, SIZE_MAX, NULL));
    TEST_ASSERT_EQUAL_MEMORY(&copy, &pat, sizeof pat);
    TEST_ASSERT_EQUAL_INT(MCS_OK,
                          mcs_pattern_init(&pat, MCS_PATTERN_UNIFORM, 8u, (size_t)MCS_MAX_K, NULL));
    pat.k = (size_t)MCS_MAX_K + 1u; /* a caller's edit is caught at the draw */
    mcs_rng rng;
    mcs_rng_seed(&rng, 1u, 1u);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_pattern_draw(&pat, &rng, pat.k, bins, weights, NULL));
}

/* One draw that must fail with MCS_ERR_ALIAS, writing nothing and leaving the
 * rng where it was. buf holds every array of the call. */
static double alias_buf[4 * MAXK];

static void expect_draw_alias(const mcs_pattern *pat, mcs_rng *rng, size_t *b, double *w,
                              double *x)
{
    for (size_t j = 0; j < 4u * MAXK; ++j)
        alias_buf[j] = GUARD_W;
    const mcs_rng before = *rng;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_pattern_draw(pat, rng, pat->k, b, w, x));
    TEST_ASSERT_EQUAL_MEMORY(&before, rng, sizeof before);
    for (size_t j = 0; j < 4u * MAXK; ++j)
        TEST_ASSERT_EQUAL_DOUBLE(GUARD_W, alias_buf[j]);
}

/* Issue 10 item 10: overlapping arrays are refused (pattern.h says which). */
static void test_overlapping_arrays_are_refused_and_nothing_is_written(void)
{
    mcs_pattern pat;
    mcs_rng rng;
    mcs_rng_seed(&rng, 3u, 4u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, MCS_PATTERN_JITTER, 16u, 8u, NULL));
    double *w = alias_buf, *x = alias_buf + MAXK;
    size_t *b = (size_t *)(void *)(alias_buf + 2 * MAXK);
    expect_draw_alias(&pat, &rng, b, w, w);                 /* points == weights */
    expect_draw_alias(&pat, &rng, b, w, w + 7);             /* partial overlap */
    expect_draw_alias(&pat, &rng, (size_t *)(void *)(x + 4), w, x); /* bins in points */
    /* an output over the generator itself */
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_pattern_draw(&pat, &rng, 8u, bins, weights,
                                                          (double *)(void *)&rng));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_draw(&pat, &rng, 8u, b, w, x)); /* disjoint */

    const size_t db[3] = {1u, 2u, 1u};
    double s[8] = {0.5, 2.0, 0.25, 1, 1, 1, 1, 1}, copy[8];
    memcpy(copy, s, sizeof s);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_pattern_dense(8u, 3u, db, s, s)); /* s == weights */
    TEST_ASSERT_EQUAL_MEMORY(copy, s, sizeof s);
    double pts[4] = {0.1, 0.2, 0.3, 0.4}, pcopy[4];
    memcpy(pcopy, pts, sizeof pts);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_pattern_bin_points(8u, 4u, NULL, pts, bins, pts));
    TEST_ASSERT_EQUAL_MEMORY(pcopy, pts, sizeof pts);
}

/* Issue 12: a flat importance function is the uniform density; a pattern
 * with one draws bin for bin (and point for point) what it draws without,
 * for every kind defined with one (homogenized is not). N = 10, K = 5
 * uniform used to give 1 2 5 7 9: the rounded sum of ten 1/10 put u = 3/10
 * below its edge. */
static void test_a_flat_importance_function_reproduces_the_pattern_without_one(void)
{
    const size_t shapes[4][2] = {{10u, 5u}, {24u, 6u}, {7u, 20u}, {30u, 7u}};
    static size_t bins2[MAXK];
    static double weights2[MAXK], points2[MAXK];
    for (int sh = 0; sh < 4; ++sh) {
        const size_t n = shapes[sh][0], k = shapes[sh][1];
        double w[30];
        for (size_t b = 0; b < n; ++b)
            w[b] = 0.1;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, n, w));
        for (int kind = 0; kind < MCS_PATTERN_KIND_COUNT; ++kind) {
            mcs_pattern with, without;
            if (all_kinds[kind] == MCS_PATTERN_HOMOGENIZED) { /* not defined with one */
                TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND,
                                      mcs_pattern_init(&with, all_kinds[kind], n, k, &imp));
                continue;
            }
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&with, all_kinds[kind], n, k, &imp));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&without, all_kinds[kind], n, k, NULL));
            mcs_rng r1, r2;
            mcs_rng_seed(&r1, 40u + (uint64_t)sh, 41u);
            r2 = r1;
            for (int t = 0; t < 300; ++t) {
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_draw(&with, &r1, k, bins, weights, points));
                TEST_ASSERT_EQUAL_INT(MCS_OK,
                                      mcs_pattern_draw(&without, &r2, k, bins2, weights2, points2));
                TEST_ASSERT_EQUAL_MEMORY(bins2, bins, k * sizeof bins[0]);
                TEST_ASSERT_EQUAL_MEMORY(weights2, weights, k * sizeof weights[0]);
                TEST_ASSERT_EQUAL_MEMORY(points2, points, k * sizeof points[0]);
            }
        }
    }
    const size_t expect[5] = {1u, 3u, 5u, 7u, 9u};
    double w[10] = {2, 2, 2, 2, 2, 2, 2, 2, 2, 2};
    mcs_pattern uni;
    mcs_rng rng;
    mcs_rng_seed(&rng, 1u, 2u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, 10u, w));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&uni, MCS_PATTERN_UNIFORM, 10u, 5u, &imp));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_draw(&uni, &rng, 5u, bins, weights, NULL));
    TEST_ASSERT_EQUAL_UINT_ARRAY(expect, bins, 5);
}

/* Issue 23 item 4: an importance function with bins of g_n = 0 (leading,
 * inner and trailing): no kind ever draws one (every sample weighs 1/p > 0
 * of a bin in the support, and the point lies in it), over many trials and
 * K not dividing N; a renderer's own sample in such a bin is binned with
 * weight 0 (s_n = 0 there, as in every drawn trial). */
static void test_no_kind_draws_a_bin_outside_the_support(void)
{
    const size_t n = 13u;
    double w[13];
    for (size_t b = 0; b < n; ++b)
        w[b] = (b == 0u || b == 5u || b == 6u || b == 12u) ? 0.0 : 1.0 + (double)((b * 7u) % 5u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, n, w));
    mcs_rng rng;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, 77u, 23u));
    static const size_t ks[] = {1u, 3u, 7u, 13u, 40u};
    for (size_t ki = 0; ki < sizeof ks / sizeof ks[0]; ++ki)
        for (int i = 0; i < MCS_PATTERN_KIND_COUNT; ++i) {
            if (all_kinds[i] == MCS_PATTERN_HOMOGENIZED)
                continue;
            mcs_pattern pat;
            const size_t k = ks[ki];
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, all_kinds[i], n, k, &imp));
            for (int t = 0; t < 2000; ++t) {
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_draw(&pat, &rng, k, bins, weights, points));
                for (size_t j = 0; j < k; ++j) {
                    TEST_ASSERT_TRUE(w[bins[j]] > 0.0);
                    TEST_ASSERT_EQUAL_DOUBLE(1.0 / imp.p[bins[j]], weights[j]);
                    TEST_ASSERT_EQUAL_UINT(bins[j], (size_t)(points[j] * (double)n));
                }
            }
        }
    const double x[4] = {0.01, 0.2, 0.45, 0.99}; /* bins 0, 2, 5, 12 */
    const float xf[4] = {0.01f, 0.2f, 0.45f, 0.99f};
    for (int f = 0; f < 2; ++f) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, f ? mcs_pattern_bin_points_f(n, 4u, &imp, xf, bins, weights)
                                        : mcs_pattern_bin_points(n, 4u, &imp, x, bins, weights));
        const size_t want[4] = {0u, 2u, 5u, 12u};
        for (size_t j = 0; j < 4u; ++j) {
            TEST_ASSERT_EQUAL_UINT(want[j], bins[j]);
            TEST_ASSERT_EQUAL_DOUBLE(j == 1u ? 1.0 / imp.p[2] : 0.0, weights[j]);
        }
    }
    /* a bin that is drawn but whose p was overwritten to 0 is refused */
    imp.p[2] = 0.0;
    bins[0] = GUARD_BIN;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_pattern_bin_points(n, 4u, &imp, x, bins, weights));
    TEST_ASSERT_EQUAL_UINT(GUARD_BIN, bins[0]);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_every_kind_gives_bins_in_range_points_in_their_bins_and_weights_one_over_p);
    RUN_TEST(test_stratified_has_exactly_one_sample_per_stratum_when_k_divides_n);
    RUN_TEST(test_uniform_is_deterministic_at_bin_centres_of_the_strata);
    RUN_TEST(test_jitter_samples_are_exactly_n_over_k_bins_apart_when_k_divides_n);
    RUN_TEST(test_homogenized_is_a_cyclic_shift_of_the_stratified_pattern);
    RUN_TEST(test_bin_histograms_match_k_g_n_for_every_kind_with_and_without_importance);
    RUN_TEST(test_uniform_histogram_is_exactly_one_per_bin_when_k_equals_n);
    RUN_TEST(test_bin_points_maps_caller_points_to_bins_and_weights);
    RUN_TEST(test_dense_form_sums_weights_per_bin);
    RUN_TEST(test_bad_pattern_configuration_returns_an_error_and_changes_nothing);
    RUN_TEST(test_bad_draw_writes_nothing_and_does_not_advance_the_rng);
    RUN_TEST(test_bad_points_or_bins_return_an_error_and_leave_outputs_untouched);
    RUN_TEST(test_a_never_seeded_rng_is_refused_by_every_kind);
    RUN_TEST(test_a_homogenized_pattern_given_an_importance_object_later_is_refused);
    RUN_TEST(test_k_above_the_documented_maximum_is_refused);
    RUN_TEST(test_overlapping_arrays_are_refused_and_nothing_is_written);
    RUN_TEST(test_a_flat_importance_function_reproduces_the_pattern_without_one);
    RUN_TEST(test_no_kind_draws_a_bin_outside_the_support);
    return UNITY_END();
}
