/* The float-sample calls (issue 9): each _f call on float points gives the
 * bits of its double call on the same points widened to double (a float
 * widens exactly), on every path of the spectrum accumulator, and refuses
 * bad input with the double call's status, changing nothing. */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "mcspec.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

#define MAX_K 160u /* more than one chunk of MCS_SPECTRUM_CHUNK samples */

static mcs_spectrum sp_f, sp_d, sp_before;
/* The objects over caller memory, each with its buffer (the whole is what
 * "changes nothing" compares; two objects compare by their records). */
#define S2_SIDE 33u
#define P1_FREQ 1024u
#define P2_FREQ 64u
typedef struct {
    mcs_spectrum2d h;
    _Alignas(64) unsigned char mem[MCS_SPECTRUM2D_SIZE(S2_SIDE, S2_SIDE)];
} s2_obj;
typedef struct {
    mcs_pointset h;
    _Alignas(64) unsigned char mem[MCS_POINTSET_SIZE(P1_FREQ)];
} p1_obj;
typedef struct {
    mcs_pointset2d h;
    _Alignas(64) unsigned char mem[MCS_POINTSET2D_SIZE(P2_FREQ)];
} p2_obj;
static s2_obj o_s2_f, o_s2_d, s2_before;
static p1_obj o_ps_f, o_ps_d, ps_before;
static p2_obj o_p2_f, o_p2_d, p2_before;
#define s2_f (o_s2_f.h)
#define s2_d (o_s2_d.h)
#define ps_f (o_ps_f.h)
#define ps_d (o_ps_d.h)
#define p2_f (o_p2_f.h)
#define p2_d (o_p2_d.h)
static unsigned char rec_a[1u << 18], rec_b[1u << 18];

/* The same statistics, bit for bit: the same record. */
#define ASSERT_SAME_RECORD(save, a, b)                                                    \
    do {                                                                                  \
        size_t la_ = 0u, lb_ = 0u;                                                        \
        TEST_ASSERT_EQUAL_INT(MCS_OK, save(a, sizeof rec_a, rec_a, &la_));                 \
        TEST_ASSERT_EQUAL_INT(MCS_OK, save(b, sizeof rec_b, rec_b, &lb_));                 \
        TEST_ASSERT_EQUAL_UINT64((uint64_t)la_, (uint64_t)lb_);                           \
        TEST_ASSERT_EQUAL_HEX8_ARRAY(rec_a, rec_b, la_);                                  \
    } while (0)
static float xf[2u * MAX_K];
static double xd[2u * MAX_K], weights[MAX_K];

/* The largest float below 1: inside [0,1). */
static const float below_one = 0x1.fffffep-1f;

/* Random floats in [0,1): 24-bit fractions, every one exact as a float;
 * every seventh is the largest float below 1, to test the edge. xd[] gets
 * the same values widened. Weights in (0, 2]. */
static void draw(mcs_rng *rng, size_t count)
{
    for (size_t j = 0; j < count; ++j) {
        uint32_t u = 0u;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_u32(rng, &u));
        xf[j] = j % 7u == 6u ? below_one : (float)(u >> 8) * 0x1p-24f;
        xd[j] = (double)xf[j];
        weights[j % MAX_K] = 2.0 - (double)(u & 0xffu) / 128.0;
    }
}

static size_t cap_n(size_t n)
{
    return n < (size_t)MCS_MAX_N ? n : (size_t)MCS_MAX_N;
}

static void spectrum_case(size_t n, size_t k, mcs_spectrum_path path, int weighted)
{
    mcs_rng rng;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, 0xf10a7u + n * 31u + k, (uint64_t)path));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&sp_f, n));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&sp_d, n));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_set_path(&sp_f, path));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_set_path(&sp_d, path));
    const double *w = weighted ? weights : NULL;
    for (int t = 0; t < 9; ++t) {
        draw(&rng, k);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_points_f(&sp_f, k, xf, w));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_points(&sp_d, k, xd, w));
    }
    /* The whole object, scratch included, but for the plan: every path read
     * the same values. (FFTW's work area in the plan starts at the object's
     * address rounded up to 64 bytes, so two objects placed at different
     * alignments, as under ASan, differ there.) */
    const size_t plan_at = offsetof(mcs_spectrum, plan), after = offsetof(mcs_spectrum, mean_re);
    TEST_ASSERT_EQUAL_MEMORY(&sp_d, &sp_f, plan_at);
    TEST_ASSERT_EQUAL_MEMORY((const char *)&sp_d + after, (const char *)&sp_f + after,
                             sizeof sp_f - after);
    double re_f, im_f, re_d, im_d;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean(&sp_f, n / 2u, &re_f, &im_f));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean(&sp_d, n / 2u, &re_d, &im_d));
    TEST_ASSERT_EQUAL_MEMORY(&re_d, &re_f, sizeof re_f);
    TEST_ASSERT_EQUAL_MEMORY(&im_d, &im_f, sizeof im_f);
}

static void test_spectrum_float_points_equal_the_widened_double_points_on_every_path(void)
{
    static const mcs_spectrum_path paths[] = {MCS_SPECTRUM_PATH_SPARSE, MCS_SPECTRUM_PATH_FFT,
                                              MCS_SPECTRUM_PATH_PAIR, MCS_SPECTRUM_PATH_AUTO};
    static const size_t ns[] = {1u, 2u, 7u, 64u, 97u, 1024u};
    static const size_t ks[] = {1u, 3u, 8u, 64u, MAX_K};
    for (size_t a = 0; a < sizeof ns / sizeof ns[0]; ++a)
        for (size_t b = 0; b < sizeof ks / sizeof ks[0]; ++b)
            for (size_t p = 0; p < sizeof paths / sizeof paths[0]; ++p) {
                spectrum_case(cap_n(ns[a]), ks[b], paths[p], 0);
                spectrum_case(cap_n(ns[a]), ks[b], paths[p], 1);
            }
}

static void test_spectrum2d_float_points_equal_the_widened_double_points(void)
{
    static const size_t sides[][2] = {{1u, 1u}, {4u, 7u}, {16u, 16u}, {33u, 20u}};
    static const size_t ks[] = {1u, 5u, 64u, MAX_K};
    mcs_rng rng;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, 0x2df1u, 3u));
    for (size_t a = 0; a < sizeof sides / sizeof sides[0]; ++a)
        for (size_t b = 0; b < sizeof ks / sizeof ks[0]; ++b) {
            const size_t nx = sides[a][0], ny = sides[a][1];
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_init(&s2_f, nx, ny, o_s2_f.mem, sizeof o_s2_f.mem));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_init(&s2_d, nx, ny, o_s2_d.mem, sizeof o_s2_d.mem));
            for (int t = 0; t < 5; ++t) {
                draw(&rng, 2u * ks[b]);
                const double *w = t % 2 ? weights : NULL;
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_add_points_f(&s2_f, ks[b], xf, w));
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_add_points(&s2_d, ks[b], xd, w));
            }
            ASSERT_SAME_RECORD(mcs_io_save_spectrum2d, &s2_d, &s2_f);
        }
}

static size_t cap_freq(size_t f, size_t cap)
{
    return f < cap ? f : cap;
}

/* Both point-set spectra on the same trials: the 1D one reads the first k
 * values, the 2D one 2 k. */
static void test_point_sets_of_float_points_equal_the_widened_double_points(void)
{
    static const size_t fmax[] = {1u, 5u, 16u, 1024u};
    static const size_t ks[] = {1u, 3u, 64u, MAX_K};
    mcs_rng rng;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, 0x9051u, 4u));
    for (size_t a = 0; a < sizeof fmax / sizeof fmax[0]; ++a)
        for (size_t b = 0; b < sizeof ks / sizeof ks[0]; ++b) {
            const size_t f1 = cap_freq(fmax[a], P1_FREQ);
            const size_t f2 = cap_freq(fmax[a], P2_FREQ);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(&ps_f, f1, 0u, o_ps_f.mem, sizeof o_ps_f.mem));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(&ps_d, f1, 0u, o_ps_d.mem, sizeof o_ps_d.mem));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_init(&p2_f, f2, 0u, o_p2_f.mem, sizeof o_p2_f.mem));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_init(&p2_d, f2, 0u, o_p2_d.mem, sizeof o_p2_d.mem));
            for (int t = 0; t < 3; ++t) {
                draw(&rng, 2u * ks[b]);
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add_f(&ps_f, ks[b], xf));
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add(&ps_d, ks[b], xd));
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add_f(&p2_f, ks[b], xf));
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add(&p2_d, ks[b], xd));
            }
            ASSERT_SAME_RECORD(mcs_io_save_pointset, &ps_d, &ps_f);
            ASSERT_SAME_RECORD(mcs_io_save_pointset2d, &p2_d, &p2_f);
        }
}

static void test_bin_points_float_equals_the_widened_double_points(void)
{
    static mcs_importance imp;
    static double g[97];
    static size_t bins_f[MAX_K], bins_d[MAX_K];
    static double w_f[MAX_K], w_d[MAX_K];
    for (size_t i = 0; i < 97u; ++i)
        g[i] = 1.0 + (double)(i % 5u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, cap_n(97u), g));
    mcs_rng rng;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, 0xb1au, 6u));
    static const size_t ns[] = {1u, 7u, 97u, 4096u};
    for (size_t a = 0; a < sizeof ns / sizeof ns[0]; ++a)
        for (size_t k = 1u; k <= MAX_K; k += 53u) {
            const size_t n = cap_n(ns[a]);
            const mcs_importance *ip = n == imp.n ? &imp : NULL;
            draw(&rng, k);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_bin_points_f(n, k, ip, xf, bins_f, w_f));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_bin_points(n, k, ip, xd, bins_d, w_d));
            TEST_ASSERT_EQUAL_MEMORY(bins_d, bins_f, k * sizeof bins_f[0]);
            TEST_ASSERT_EQUAL_MEMORY(w_d, w_f, k * sizeof w_f[0]);
        }
}

/* An integrand that records what it was given: the _f call must pass each
 * x_j widened, exactly the double call's argument. */
typedef struct {
    size_t calls;
    double seen[MAX_K];
} recorder;

static double recorded(double x, void *ctx)
{
    recorder *r = ctx;
    r->seen[r->calls++ % MAX_K] = x;
    return sin(7.0 * x) + x * x;
}

static void test_estimate_points_float_equals_the_widened_double_points(void)
{
    static recorder rf, rd;
    mcs_rng rng;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, 0xe57u, 7u));
    for (size_t k = 1u; k <= MAX_K; k += 31u) {
        draw(&rng, k);
        double out_f = 0.0, out_d = 1.0;
        memset(&rf, 0, sizeof rf);
        memset(&rd, 0, sizeof rd);
        const double *w = k % 2u ? weights : NULL;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_estimate_points_f(k, recorded, &rf, xf, w, &out_f));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_estimate_points(k, recorded, &rd, xd, w, &out_d));
        TEST_ASSERT_EQUAL_MEMORY(&out_d, &out_f, sizeof out_f);
        TEST_ASSERT_EQUAL_UINT64(k, rf.calls);
        TEST_ASSERT_EQUAL_MEMORY(rd.seen, rf.seen, k * sizeof rf.seen[0]);
    }
}

/* ---- bad input: the double call's status, nothing changed ---- */

/* Points that break [0,1) one way each, with the status the double call
 * gives for their widened values. */
static void bad_points(float bad[6])
{
    bad[0] = 1.0f;
    bad[1] = -0x1p-149f; /* the negative float nearest 0 */
    bad[2] = NAN;
    bad[3] = INFINITY;
    bad[4] = -INFINITY;
    bad[5] = 1.5f;
}

#define SPEC_UNCHANGED(status, call)                                                         \
    do {                                                                                     \
        memcpy(&sp_before, &sp_f, sizeof sp_f);                                              \
        TEST_ASSERT_EQUAL_INT((status), (call));                                             \
        TEST_ASSERT_EQUAL_MEMORY(&sp_before, &sp_f, sizeof sp_f);                            \
    } while (0)

static void test_spectrum_add_points_f_refuses_bad_input_and_changes_nothing(void)
{
    float x[4] = {0.1f, 0.2f, 0.3f, below_one}, bad[6];
    double w[4] = {1.0, 1.0, 1.0, 1.0};
    bad_points(bad);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&sp_f, cap_n(20u)));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_points_f(&sp_f, 4u, x, w));
    SPEC_UNCHANGED(MCS_ERR_NULL, mcs_spectrum_add_points_f(&sp_f, 4u, NULL, w));
    SPEC_UNCHANGED(MCS_ERR_NULL, mcs_spectrum_add_points_f(NULL, 4u, x, w));
    SPEC_UNCHANGED(MCS_ERR_K_RANGE, mcs_spectrum_add_points_f(&sp_f, 0u, x, w));
    for (int i = 0; i < 6; ++i) {
        const float keep = x[2];
        x[2] = bad[i];
        SPEC_UNCHANGED(MCS_ERR_POINT_RANGE, mcs_spectrum_add_points_f(&sp_f, 4u, x, w));
        SPEC_UNCHANGED(MCS_ERR_POINT_RANGE, mcs_spectrum_add_points_f(&sp_f, 4u, x, NULL));
        x[2] = keep;
    }
    w[1] = NAN;
    SPEC_UNCHANGED(MCS_ERR_NOT_FINITE, mcs_spectrum_add_points_f(&sp_f, 4u, x, w));
    w[1] = -1.0;
    SPEC_UNCHANGED(MCS_ERR_NEGATIVE, mcs_spectrum_add_points_f(&sp_f, 4u, x, w));
    w[1] = 0x1p101;
    SPEC_UNCHANGED(MCS_ERR_MAGNITUDE, mcs_spectrum_add_points_f(&sp_f, 4u, x, w));
    /* Float points inside the accumulator's own scratch. */
    SPEC_UNCHANGED(MCS_ERR_ALIAS,
                   mcs_spectrum_add_points_f(&sp_f, 4u, (const float *)(void *)sp_f.s, NULL));
    w[1] = 1.0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_points_f(&sp_f, 4u, x, w));
}

static void test_spectrum2d_add_points_f_refuses_bad_input_and_changes_nothing(void)
{
    float x[4] = {0.1f, below_one, 0.3f, 0.0f}, bad[6];
    bad_points(bad);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_init(&s2_f, 4u, 4u, o_s2_f.mem, sizeof o_s2_f.mem));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_add_points_f(&s2_f, 2u, x, NULL));
    memcpy(&s2_before, &o_s2_f, sizeof o_s2_f);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_spectrum2d_add_points_f(&s2_f, 2u, NULL, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_spectrum2d_add_points_f(NULL, 2u, x, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_spectrum2d_add_points_f(&s2_f, 0u, x, NULL));
    for (int i = 0; i < 6; ++i) {
        const float keep = x[3];
        x[3] = bad[i];
        TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE,
                              mcs_spectrum2d_add_points_f(&s2_f, 2u, x, NULL));
        x[3] = keep;
    }
    double w[2] = {1.0, INFINITY};
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NOT_FINITE, mcs_spectrum2d_add_points_f(&s2_f, 2u, x, w));
    w[1] = -0.5;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NEGATIVE, mcs_spectrum2d_add_points_f(&s2_f, 2u, x, w));
    TEST_ASSERT_EQUAL_MEMORY(&s2_before, &o_s2_f, sizeof o_s2_f);
}

static void test_pointset_add_f_calls_refuse_bad_input_and_change_nothing(void)
{
    float x[4] = {0.1f, below_one, 0.3f, 0.0f}, bad[6];
    bad_points(bad);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(&ps_f, 8u, 0u, o_ps_f.mem, sizeof o_ps_f.mem));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_init(&p2_f, 4u, 0u, o_p2_f.mem, sizeof o_p2_f.mem));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add_f(&ps_f, 4u, x));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add_f(&p2_f, 2u, x));
    memcpy(&ps_before, &o_ps_f, sizeof o_ps_f);
    memcpy(&p2_before, &o_p2_f, sizeof o_p2_f);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pointset_add_f(&ps_f, 4u, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pointset_add_f(NULL, 4u, x));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_pointset_add_f(&ps_f, 0u, x));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pointset2d_add_f(&p2_f, 2u, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pointset2d_add_f(NULL, 2u, x));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_pointset2d_add_f(&p2_f, 0u, x));
    for (int i = 0; i < 6; ++i) {
        const float keep = x[2];
        x[2] = bad[i];
        TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_pointset_add_f(&ps_f, 4u, x));
        TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_pointset2d_add_f(&p2_f, 2u, x));
        x[2] = keep;
    }
    TEST_ASSERT_EQUAL_MEMORY(&ps_before, &o_ps_f, sizeof o_ps_f);
    TEST_ASSERT_EQUAL_MEMORY(&p2_before, &o_p2_f, sizeof o_p2_f);
}

static void test_bin_points_f_refuses_bad_input_and_writes_nothing(void)
{
    float x[4] = {0.1f, below_one, 0.3f, 0.0f}, bad[6];
    size_t bins[4] = {7u, 7u, 7u, 7u};
    double w[4] = {-2.0, -2.0, -2.0, -2.0};
    const size_t bins0[4] = {7u, 7u, 7u, 7u};
    const double w0[4] = {-2.0, -2.0, -2.0, -2.0};
    bad_points(bad);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pattern_bin_points_f(8u, 4u, NULL, NULL, bins, w));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pattern_bin_points_f(8u, 4u, NULL, x, NULL, w));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pattern_bin_points_f(8u, 4u, NULL, x, bins, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_N_RANGE, mcs_pattern_bin_points_f(0u, 4u, NULL, x, bins, w));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_pattern_bin_points_f(8u, 0u, NULL, x, bins, w));
    /* The float array overlapping an output. */
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_pattern_bin_points_f(8u, 4u, NULL,
                                                                  (const float *)(void *)w,
                                                                  bins, w));
    for (int i = 0; i < 6; ++i) {
        const float keep = x[1];
        x[1] = bad[i];
        TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE,
                              mcs_pattern_bin_points_f(8u, 4u, NULL, x, bins, w));
        x[1] = keep;
    }
    TEST_ASSERT_EQUAL_MEMORY(bins0, bins, sizeof bins);
    TEST_ASSERT_EQUAL_MEMORY(w0, w, sizeof w);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_bin_points_f(8u, 4u, NULL, x, bins, w));
    TEST_ASSERT_EQUAL_UINT64(7u, bins[1]); /* the float below 1 lands in the last bin */
}

static double identity(double x, void *ctx)
{
    (void)ctx;
    return x;
}

static void test_estimate_points_f_refuses_bad_input_and_writes_nothing(void)
{
    float x[4] = {0.1f, below_one, 0.3f, 0.0f}, bad[6];
    double w[4] = {1.0, 1.0, 1.0, 1.0}, out = 42.0;
    bad_points(bad);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_estimate_points_f(4u, NULL, NULL, x, w, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_estimate_points_f(4u, identity, NULL, NULL, w, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_estimate_points_f(4u, identity, NULL, x, w, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_estimate_points_f(0u, identity, NULL, x, w, &out));
    for (int i = 0; i < 6; ++i) {
        const float keep = x[0];
        x[0] = bad[i];
        TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE,
                              mcs_estimate_points_f(4u, identity, NULL, x, w, &out));
        x[0] = keep;
    }
    w[3] = NAN;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NOT_FINITE,
                          mcs_estimate_points_f(4u, identity, NULL, x, w, &out));
    w[3] = -1.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NEGATIVE, mcs_estimate_points_f(4u, identity, NULL, x, w, &out));
    TEST_ASSERT_EQUAL_DOUBLE(42.0, out);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_spectrum_float_points_equal_the_widened_double_points_on_every_path);
    RUN_TEST(test_spectrum2d_float_points_equal_the_widened_double_points);
    RUN_TEST(test_point_sets_of_float_points_equal_the_widened_double_points);
    RUN_TEST(test_bin_points_float_equals_the_widened_double_points);
    RUN_TEST(test_estimate_points_float_equals_the_widened_double_points);
    RUN_TEST(test_spectrum_add_points_f_refuses_bad_input_and_changes_nothing);
    RUN_TEST(test_spectrum2d_add_points_f_refuses_bad_input_and_changes_nothing);
    RUN_TEST(test_pointset_add_f_calls_refuse_bad_input_and_change_nothing);
    RUN_TEST(test_bin_points_f_refuses_bad_input_and_writes_nothing);
    RUN_TEST(test_estimate_points_f_refuses_bad_input_and_writes_nothing);
    return UNITY_END();
}
