#include "mcspec/io.h"
#include "mcspec/pointset.h"
#include "mcspec/rng.h"
#include "nufft_skip.h"
#include "points_ref.h"
#include "unity.h"

#include <math.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define MAXK 512

/* An accumulator and its buffer (for F up to 300): the whole is what "changes
 * nothing" compares. */
typedef struct {
    mcs_pointset h;
    _Alignas(64) unsigned char mem[MCS_POINTSET_SIZE(300u)];
} obj;
static obj o_acc, o_acc2, o_acc3, o_snap;
#define acc (o_acc.h)
#define acc2 (o_acc2.h)
#define acc3 (o_acc3.h)
static double x[MAXK];

static mcs_status init(mcs_pointset *a, size_t f)
{
    obj *o = (obj *)(void *)a;
    return mcs_pointset_init(&o->h, f, 0u, o->mem, sizeof o->mem);
}

static void fill_stratified(mcs_rng *rng, size_t k, double *p)
{
    for (size_t j = 0; j < k; ++j) {
        double u = 0.0;
        mcs_rng_double(rng, &u);
        p[j] = ((double)j + u) / (double)k;
    }
}

static void test_one_trial_matches_the_direct_sum_at_every_frequency(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 1u, 1u);
    const size_t ks[4] = {1u, 3u, 37u, 500u};
    for (int c = 0; c < 4; ++c) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc, 300u));
        points_uniform(&rng, ks[c], x);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add(&acc, ks[c], x));
        for (long f = -300; f <= 300; ++f) {
            double p = 0.0;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_power(&acc, f, &p));
            TEST_ASSERT_DOUBLE_WITHIN(1e-12 * (double)ks[c], points_periodogram(1u, ks[c], x, f, 0), p);
        }
        double p0 = 0.0;
        mcs_pointset_power(&acc, 0, &p0);
        TEST_ASSERT_DOUBLE_WITHIN(1e-13 * (double)ks[c], (double)ks[c], p0);
    }
}

/* <P(f)> over T trials against the exact unbinned spectra, every f in 1..F,
 * within 5 standard errors; T is large enough that sinc instead of sinc^2
 * (or a missing 1) would fail. */
static void test_random_and_stratified_points_match_their_exact_spectra(void)
{
    enum { T = 20000, K = 8, F = 40 };
    mcs_rng rng;
    mcs_rng_seed(&rng, 2u, 3u);
    for (int strat = 0; strat < 2; ++strat) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc, F));
        for (int t = 0; t < T; ++t) {
            if (strat)
                fill_stratified(&rng, K, x);
            else
                points_uniform(&rng, K, x);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add(&acc, K, x));
        }
        mcs_pattern_kind kind = strat ? MCS_PATTERN_STRATIFIED : MCS_PATTERN_RANDOM;
        for (long f = 1; f <= F; ++f) {
            double p = 0.0, se = 0.0, ex = 0.0;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_power(&acc, f, &p));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_power_stderr(&acc, f, &se));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_exact_power(kind, K, f, &ex));
            TEST_ASSERT_DOUBLE_WITHIN(5.0 * se + 1e-12, ex, p);
        }
    }
}

static void test_uniform_jitter_points_give_the_exact_comb(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 4u, 4u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc, 50u));
    for (int t = 0; t < 20; ++t) {
        double beta = 0.0;
        mcs_rng_double(&rng, &beta);
        for (size_t j = 0; j < 6u; ++j)
            x[j] = ((double)j + beta) / 6.0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add(&acc, 6u, x));
    }
    for (long f = 0; f <= 50; ++f) {
        double p = 0.0, ex = 0.0, ex_u = 0.0;
        mcs_pointset_power(&acc, f, &p);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_exact_power(MCS_PATTERN_JITTER, 6u, f, &ex));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_exact_power(MCS_PATTERN_UNIFORM, 6u, f, &ex_u));
        TEST_ASSERT_EQUAL_DOUBLE(ex, ex_u);
        TEST_ASSERT_DOUBLE_WITHIN(1e-12, ex, p);
        TEST_ASSERT_EQUAL_DOUBLE(f % 6 == 0 ? 6.0 : 0.0, ex);
    }
}

static void test_merge_of_halves_equals_one_pass(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 5u, 5u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc, 20u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc2, 20u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc3, 20u));
    for (int t = 0; t < 300; ++t) {
        size_t k = 1u + (size_t)t % 9u; /* trials of different K */
        points_uniform(&rng, k, x);
        mcs_pointset_add(&acc, k, x);
        mcs_pointset_add(t < 100 ? &acc2 : &acc3, k, x);
    }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_merge(&acc2, &acc3));
    uint64_t n = 0u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_count(&acc2, &n));
    TEST_ASSERT_EQUAL_UINT64(300u, n);
    for (long f = 0; f <= 20; ++f) {
        double a = 0.0, b = 0.0, sa = 0.0, sb = 0.0;
        mcs_pointset_power(&acc, f, &a);
        mcs_pointset_power(&acc2, f, &b);
        mcs_pointset_power_stderr(&acc, f, &sa);
        mcs_pointset_power_stderr(&acc2, f, &sb);
        points_assert_merged(a, sa, b, sb);
    }
    /* Merging an empty accumulator changes nothing; merging into itself doubles the count. */
    TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc3, 20u));
    o_snap = o_acc2;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_merge(&acc2, &acc3));
    TEST_ASSERT_EQUAL_MEMORY(&o_snap, &o_acc2, sizeof o_acc2);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_merge(&acc2, &acc2));
    mcs_pointset_count(&acc2, &n);
    TEST_ASSERT_EQUAL_UINT64(600u, n);
}

static void test_bad_input_returns_an_error_and_changes_nothing(void)
{
    double out = -1.0;
    uint64_t n = 0u;
    memset(&o_acc2, 0, sizeof o_acc2); /* never initialised */
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pointset_init(NULL, 4u, 0u, o_acc2.mem, sizeof o_acc2.mem));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pointset_init(&acc2, 4u, 0u, NULL, sizeof o_acc2.mem));
    o_snap = o_acc2;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE, init(&acc2, 0u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE,
                          mcs_pointset_init(&acc2, MCS_POINTSET_MAX_FREQ + 1u, 0u, o_acc2.mem, SIZE_MAX));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_SPACE, init(&acc2, 4096u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_pointset_init(&acc2, 4u, 2u, o_acc2.mem, sizeof o_acc2.mem));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_pointset_init((mcs_pointset *)(void *)o_acc2.mem, 4u, 0u,
                                                           o_acc2.mem, sizeof o_acc2.mem));
    TEST_ASSERT_EQUAL_MEMORY(&o_snap, &o_acc2, sizeof o_acc2);

    TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc, 8u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_EMPTY, mcs_pointset_power(&acc, 1, &out));
    x[0] = 0.25;
    x[1] = 0.5;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add(&acc, 2u, x));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_EMPTY, mcs_pointset_power_stderr(&acc, 1, &out));
    o_snap = o_acc;
    const double bad[4] = {1.0, -0.0 - 1e-300, NAN, INFINITY};
    for (int b = 0; b < 4; ++b) {
        x[1] = bad[b];
        TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_pointset_add(&acc, 2u, x));
    }
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_pointset_add(&acc, 0u, x));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pointset_add(&acc, 2u, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pointset_add(NULL, 2u, x));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_pointset_add(&acc2, 2u, x));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_pointset_merge(&acc, &acc2));
    TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc3, 9u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, mcs_pointset_merge(&acc, &acc3));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pointset_merge(&acc, NULL));
    /* points inside the object's buffer: its scratch would be overwritten */
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_pointset_add(&acc, 2u, acc.re));
    TEST_ASSERT_EQUAL_MEMORY(&o_snap, &o_acc, sizeof o_acc);

    out = -1.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE, mcs_pointset_power(&acc, 9, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE, mcs_pointset_power(&acc, -9, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_pointset_power(&acc2, 1, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pointset_power(&acc, 1, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_pointset_count(&acc2, &n));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_pointset_exact_power(MCS_PATTERN_HOMOGENIZED, 4u, 1, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_pointset_exact_power((mcs_pattern_kind)9, 4u, 1, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_pointset_exact_power(MCS_PATTERN_RANDOM, 0u, 1, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pointset_exact_power(MCS_PATTERN_RANDOM, 4u, 1, NULL));
    TEST_ASSERT_EQUAL_DOUBLE(-1.0, out);
}

static uint64_t *count_of(void *a) { return &((mcs_pointset *)a)->state->count; }
static int add_one(void *a) { return mcs_pointset_add(a, 2u, x); }
static int merge(void *dst, const void *src) { return mcs_pointset_merge(dst, src); }

static void test_the_trial_count_stops_at_mcs_max_count_and_never_wraps(void)
{
    const points_counted kind = {sizeof o_acc, count_of, add_one, merge};
    for (int j = 0; j < 4; ++j)
        x[j] = 0.125 + 0.25 * j; /* two points in 1D or 2D */
    TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc, 8u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc2, 8u));
    points_assert_count_bound(&kind, &o_acc, &o_acc2, &o_acc3, &o_snap);
}


/* ---- run-time sizes over caller memory ---- */

/* The size macro is a constant expression at least the size query, which
 * grows with F and is smaller without the NUFFT; the caps are refused one
 * past them and their sizes fit size_t. */
static void test_the_size_macro_bounds_the_size_query_and_the_caps_fit(void)
{
    static char fits_a_static_buffer[MCS_POINTSET_SIZE(64u)];
    (void)fits_a_static_buffer;
    size_t prev = 0u, bytes = 0u, direct = 0u;
    for (size_t f = 1u; f <= 5000u; f += f < 200u ? 1u : 97u) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_size(f, 0u, &bytes));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_size(f, MCS_POINTSET_DIRECT_ONLY, &direct));
        TEST_ASSERT_TRUE(bytes <= MCS_POINTSET_SIZE(f));
        TEST_ASSERT_EQUAL_UINT64((uint64_t)MCS_POINTSET_SIZE_DIRECT(f), (uint64_t)direct);
        /* without the NUFFT (config.h) flags 0 take the direct size */
        TEST_ASSERT_TRUE((MCS_CONFIG_NUFFT ? direct < bytes : direct == bytes) && bytes >= prev);
        prev = bytes;
    }
    const size_t big[3] = {65536u, 1048576u, MCS_POINTSET_MAX_FREQ};
    for (int i = 0; i < 3; ++i) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_size(big[i], 0u, &bytes));
        TEST_ASSERT_TRUE(bytes <= MCS_POINTSET_SIZE(big[i]) && bytes < SIZE_MAX / 2u);
        TEST_ASSERT_TRUE(bytes > (MCS_CONFIG_NUFFT ? 100u : 30u) * big[i]); /* about 140 F, 34 F */
    }
    bytes = 7u;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE, mcs_pointset_size(MCS_POINTSET_MAX_FREQ + 1u, 0u, &bytes));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE, mcs_pointset_size(SIZE_MAX, 0u, &bytes));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE, mcs_pointset_size(0u, 0u, &bytes));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_pointset_size(4u, 3u, &bytes));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pointset_size(4u, 0u, NULL));
    TEST_ASSERT_EQUAL_UINT64(7u, bytes);
}

/* The buffer needs no alignment and exactly the size query's bytes; the
 * object works the same from any offset. */
static void test_any_alignment_and_exactly_the_queried_bytes_work(void)
{
    static _Alignas(64) unsigned char mem[MCS_POINTSET_SIZE(40u) + 64u];
    static _Alignas(64) unsigned char rec_a[4096], rec_b[4096];
    size_t bytes = 0u, la = 0u, lb = 0u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_size(40u, 0u, &bytes));
    mcs_rng rng;
    mcs_rng_seed(&rng, 7u, 7u);
    points_uniform(&rng, 100u, x);
    TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc, 40u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add(&acc, 100u, x));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_save_pointset(&acc, sizeof rec_a, rec_a, &la));
    for (size_t off = 1u; off < 64u; off += 9u) {
        TEST_ASSERT_EQUAL_INT(MCS_ERR_SPACE, mcs_pointset_init(&acc2, 40u, 0u, mem + off, bytes - 1u));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(&acc2, 40u, 0u, mem + off, bytes));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add(&acc2, 100u, x));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_save_pointset(&acc2, sizeof rec_b, rec_b, &lb));
        TEST_ASSERT_EQUAL_UINT64((uint64_t)la, (uint64_t)lb);
        TEST_ASSERT_EQUAL_HEX8_ARRAY(rec_a, rec_b, la);
    }
}

/* A copy has its own buffer: it reads out like the original, and neither
 * sees the other's later trials; merges refuse two objects that share a
 * buffer (a header copied byte for byte) or whose buffers overlap. */
static void test_a_copy_is_independent_and_shared_buffers_do_not_merge(void)
{
    static _Alignas(64) unsigned char mem[MCS_POINTSET_SIZE(30u)];
    mcs_rng rng;
    mcs_rng_seed(&rng, 8u, 8u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc, 30u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_set_wrap(&acc, 1));
    for (int t = 0; t < 5; ++t) {
        points_uniform(&rng, 50u, x);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add(&acc, 50u, x));
    }
    TEST_ASSERT_EQUAL_INT(MCS_ERR_SPACE, mcs_pointset_copy(&acc2, mem, 100u, &acc));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_pointset_copy(&acc2, acc.mem, sizeof mem, &acc));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_copy(&acc2, mem, sizeof mem, &acc));
    TEST_ASSERT_EQUAL_INT(1, acc2.wrap);
    for (long f = 0; f <= 30; ++f) {
        double a = 0.0, b = 0.0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_power_stderr(&acc, f, &a));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_power_stderr(&acc2, f, &b));
        TEST_ASSERT_EQUAL_DOUBLE(a, b);
    }
    points_uniform(&rng, 50u, x);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add(&acc2, 50u, x));
    uint64_t na = 0u, nb = 0u;
    mcs_pointset_count(&acc, &na);
    mcs_pointset_count(&acc2, &nb);
    TEST_ASSERT_EQUAL_UINT64(5u, na);
    TEST_ASSERT_EQUAL_UINT64(6u, nb);
    mcs_pointset shared = acc; /* not a copy: the same buffer */
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_pointset_merge(&acc, &shared));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_merge(&acc, &acc2));
    mcs_pointset_count(&acc, &na);
    TEST_ASSERT_EQUAL_UINT64(11u, na);
}

/* ---- the NUFFT path ---- */

/* max over every f of |P_a - P_b| / max(P_b, 1), of the means or of the
 * standard errors (scaled alike, by the mean P_b: the criterion is relative
 * to the periodogram's size, and a standard error near 0, as at f = 0 where
 * every P is K, has no relative accuracy of its own). */
static double worst_gap(const mcs_pointset *a, const mcs_pointset *b, int want_stderr)
{
    double worst = 0.0;
    for (long f = 0; f <= (long)a->freq_max; ++f) {
        double pa = 0.0, pb = 0.0, scale = 0.0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_power(b, f, &scale));
        if (want_stderr) {
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_power_stderr(a, f, &pa));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_power_stderr(b, f, &pb));
        } else {
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_power(a, f, &pa));
            pb = scale;
        }
        const double gap = fabs(pa - pb) / fmax(scale, 1.0);
        worst = gap > worst ? gap : worst;
    }
    return worst;
}

/* Random, jittered and clustered (half the points within 1e-3 of 0.3) sets. */
static void draw_set(int kind, mcs_rng *rng, size_t k, double *p)
{
    for (size_t j = 0; j < k; ++j) {
        double u = 0.0;
        mcs_rng_double(rng, &u);
        p[j] = kind == 0 ? u : kind == 1 ? ((double)j + u) / (double)k
                         : j % 2u ? 0.3 + 1e-3 * u : u;
    }
}

/* K = 65536 points at F = 2048, two trials per kind: the NUFFT path agrees
 * with the direct sum to 1e-9 max(P, 1) at every frequency, for the means
 * and the standard errors (the same Welford update either way). */
static void test_the_nufft_path_agrees_with_the_direct_sum(void)
{
    MCS_TEST_NEEDS_NUFFT();
    enum { K = 65536, F = 2048, T = 2 };
    static double pts[K];
    size_t bytes = 0u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_size(F, 0u, &bytes));
    static _Alignas(64) unsigned char mem_d[MCS_POINTSET_SIZE(F)], mem_n[MCS_POINTSET_SIZE(F)];
    static mcs_pointset d, n;
    mcs_rng rng;
    mcs_rng_seed(&rng, 9u, 9u);
    for (int kind = 0; kind < 3; ++kind) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(&d, F, 0u, mem_d, sizeof mem_d));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(&n, F, 0u, mem_n, sizeof mem_n));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_set_path(&d, MCS_POINTSET_PATH_DIRECT));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_set_path(&n, MCS_POINTSET_PATH_NUFFT));
        for (int t = 0; t < T; ++t) {
            draw_set(kind, &rng, K, pts);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add(&d, K, pts));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add(&n, K, pts));
        }
        const double mean_gap = worst_gap(&n, &d, 0), se_gap = worst_gap(&n, &d, 1);
        TEST_ASSERT_TRUE(mean_gap <= 1e-9);
        TEST_ASSERT_TRUE(se_gap <= 1e-9);
    }
}

/* The wrapped 1.0 (pointset_set_wrap) is 0.0 exactly, on either path and
 * for float points; 1.5, -0.1 and NaN are still refused. Without wrap 1.0
 * is refused. */
static void test_wrap_takes_one_as_zero_and_still_refuses_the_rest(void)
{
    static _Alignas(64) unsigned char mem_b[MCS_POINTSET_SIZE(300u)];
    static mcs_pointset b;
    static double zero[300];
    static float xf[300];
    mcs_rng rng;
    mcs_rng_seed(&rng, 10u, 10u);
    for (int path = MCS_POINTSET_PATH_DIRECT; path <= MCS_TEST_LAST_PATH; ++path) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc, 200u));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(&b, 200u, 0u, mem_b, sizeof mem_b));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_set_path(&acc, (mcs_pointset_path)path));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_set_path(&b, (mcs_pointset_path)path));
        points_uniform(&rng, 300u, x);
        for (size_t j = 0; j < 300u; ++j) {
            x[j] = j % 7u == 3u ? 1.0 : x[j];
            zero[j] = x[j] == 1.0 ? 0.0 : x[j];
            xf[j] = j % 7u == 3u ? 1.0f : 0.5f * (float)(j % 2u);
        }
        TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_pointset_add(&acc, 300u, x));
        TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_pointset_add_f(&acc, 300u, xf));
        TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_pointset_set_wrap(&acc, 2));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_set_wrap(&acc, 1));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add(&acc, 300u, x));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add(&b, 300u, zero));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add_f(&acc, 300u, xf));
        for (size_t j = 0; j < 300u; ++j)
            zero[j] = xf[j] == 1.0f ? 0.0 : (double)xf[j];
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add(&b, 300u, zero));
        TEST_ASSERT_EQUAL_MEMORY(b.mean, acc.mean, 201u * sizeof(double));
        TEST_ASSERT_EQUAL_MEMORY(b.m2, acc.m2, 201u * sizeof(double));
        memcpy(&o_snap, &o_acc, sizeof o_acc);
        const double bad[3] = {1.5, -0.1, NAN};
        for (int i = 0; i < 3; ++i) {
            x[5] = bad[i];
            TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_pointset_add(&acc, 300u, x));
        }
        TEST_ASSERT_EQUAL_MEMORY(&o_snap, &o_acc, sizeof o_acc);
    }
}

/* AUTO takes the direct sum for few points or a low F and the NUFFT for
 * many points at a high F; a forced path is kept, and sets past the NUFFT's
 * K go to the direct sum (AUTO) or are refused (forced). */
static void test_auto_picks_the_nufft_for_large_k_f_and_the_direct_sum_for_small(void)
{
    static _Alignas(64) unsigned char mem[MCS_POINTSET_SIZE(4096u)];
    static mcs_pointset a;
    mcs_pointset_path p = MCS_POINTSET_PATH_AUTO;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(&a, 4096u, 0u, mem, sizeof mem));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_path_for(&a, 65536u, &p));
#if !MCS_CONFIG_NUFFT
    /* Built without the NUFFT (config.h): AUTO is the direct sum, the NUFFT refused. */
    TEST_ASSERT_EQUAL_INT(MCS_POINTSET_PATH_DIRECT, p);
    TEST_ASSERT_EQUAL_INT(MCS_POINTSET_PATH_AUTO, a.path);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_pointset_set_path(&a, MCS_POINTSET_PATH_NUFFT));
    TEST_ASSERT_EQUAL_INT(MCS_POINTSET_PATH_AUTO, a.path);
    TEST_ASSERT_TRUE(a.stage == NULL && a.plan.dim == 0u);
    MCS_TEST_NEEDS_NUFFT();
#endif
    TEST_ASSERT_EQUAL_INT(MCS_POINTSET_PATH_NUFFT, p);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_path_for(&a, 4u, &p));
    TEST_ASSERT_EQUAL_INT(MCS_POINTSET_PATH_DIRECT, p);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_path_for(&a, MCS_POINTSET_NUFFT_MAX_K + 1u, &p));
    TEST_ASSERT_EQUAL_INT(MCS_POINTSET_PATH_DIRECT, p);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_set_path(&a, MCS_POINTSET_PATH_NUFFT));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_path_for(&a, 4u, &p));
    TEST_ASSERT_EQUAL_INT(MCS_POINTSET_PATH_NUFFT, p);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_pointset_path_for(&a, MCS_POINTSET_NUFFT_MAX_K + 1u, &p));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_pointset_set_path(&a, (mcs_pointset_path)3));
    TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc, 8u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_path_for(&acc, 65536u, &p));
    TEST_ASSERT_EQUAL_INT(MCS_POINTSET_PATH_DIRECT, p); /* F = 8: the direct sum is cheaper */
    /* Without the NUFFT's memory the direct sum is the only path. */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(&a, 4096u, MCS_POINTSET_DIRECT_ONLY, mem, sizeof mem));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_pointset_set_path(&a, MCS_POINTSET_PATH_NUFFT));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_path_for(&a, 65536u, &p));
    TEST_ASSERT_EQUAL_INT(MCS_POINTSET_PATH_DIRECT, p);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_path_for(&a, MCS_POINTSET_NUFFT_MAX_K + 1u, &p));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_one_trial_matches_the_direct_sum_at_every_frequency);
    RUN_TEST(test_random_and_stratified_points_match_their_exact_spectra);
    RUN_TEST(test_uniform_jitter_points_give_the_exact_comb);
    RUN_TEST(test_merge_of_halves_equals_one_pass);
    RUN_TEST(test_bad_input_returns_an_error_and_changes_nothing);
    RUN_TEST(test_the_trial_count_stops_at_mcs_max_count_and_never_wraps);
    RUN_TEST(test_the_size_macro_bounds_the_size_query_and_the_caps_fit);
    RUN_TEST(test_any_alignment_and_exactly_the_queried_bytes_work);
    RUN_TEST(test_a_copy_is_independent_and_shared_buffers_do_not_merge);
    RUN_TEST(test_the_nufft_path_agrees_with_the_direct_sum);
    RUN_TEST(test_wrap_takes_one_as_zero_and_still_refuses_the_rest);
    RUN_TEST(test_auto_picks_the_nufft_for_large_k_f_and_the_direct_sum_for_small);
    return UNITY_END();
}
