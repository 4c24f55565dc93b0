/* Tests for the binned 2D spectrum (mcs_spectrum2d) holding values no calls
 * produce (overwritten): each call that reads them returns
 * MCS_ERR_INVARIANT with every output and both objects byte for byte
 * unchanged, never a NaN or a negative power with MCS_OK. (A NaN twiddle
 * gave 48 NaN outputs of mcs_spectrum2d_transform with MCS_OK.) */
#include "mcspec.h"
#include "points_ref.h"
#include "unity.h"

#include <float.h>
#include <math.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define SENTINEL (-7.25e300)
#define NX 5u /* odd: one pad column */
#define NY 6u
#define NPLANE (NX * NY)

/* The accumulators with their buffers: what "unchanged" compares. */
typedef struct {
    mcs_spectrum2d h;
    _Alignas(64) unsigned char mem[MCS_SPECTRUM2D_SIZE(NX, NY)];
} obj;
static obj o_acc, o_other, acc_copy, other_copy;
#define acc (o_acc.h)
#define other (o_other.h)
static double pts[2 * 16], s_in[NPLANE], f_re[NPLANE], f_im[NPLANE];
static struct {
    double scalar[2];
    double re[NPLANE], im[NPLANE];
} out, out_sentinel;

static void fill_outputs(void)
{
    out.scalar[0] = out.scalar[1] = SENTINEL;
    for (size_t j = 0; j < NPLANE; ++j)
        out.re[j] = out.im[j] = SENTINEL;
    memcpy(&out_sentinel, &out, sizeof out);
}

/* Two accumulators of 12 trials of 7 weighted points each, and the inputs. */
static void prepare(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 31u, 7u);
    const double w[7] = {1.0, 0.5, 2.0, 1.5, 0.25, 3.0, 1.0};
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_init(&acc, NX, NY, o_acc.mem, sizeof o_acc.mem));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_init(&other, NX, NY, o_other.mem, sizeof o_other.mem));
    for (int t = 0; t < 24; ++t) {
        points_uniform(&rng, 14u, pts);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_add_points(t % 2 ? &acc : &other, 7u, pts, w));
    }
    for (size_t j = 0; j < NPLANE; ++j) {
        s_in[j] = (double)(j % 3u);
        f_re[j] = 1.0 / (1.0 + (double)j);
        f_im[j] = 0.5 - f_re[j];
    }
}

/* The calls: what == 0 those reading the twiddles (transform, add), 1 the
 * read-outs of one wave vector (k1, k2), 2 those reading every cell (add,
 * merge both ways and into itself, variance14). */
static void assert_refused(int what, size_t k1, size_t k2, const char *msg)
{
    memcpy(&acc_copy, &o_acc, sizeof o_acc);
    memcpy(&other_copy, &o_other, sizeof o_other);
    mcs_status st[6];
    int calls = 0;
    fill_outputs();
    if (what == 0) {
        st[calls++] = mcs_spectrum2d_transform(&acc, s_in, out.re, out.im);
        st[calls++] = mcs_spectrum2d_add_points(&acc, 7u, pts, NULL);
        st[calls++] = mcs_spectrum2d_merge(&other, &acc);
    } else if (what == 1) {
        st[calls++] = mcs_spectrum2d_mean(&acc, k1, k2, &out.scalar[0], &out.scalar[1]);
        st[calls++] = mcs_spectrum2d_power(&acc, k1, k2, &out.scalar[0]);
        st[calls++] = mcs_spectrum2d_power_stderr(&acc, k1, k2, &out.scalar[0]);
        st[calls++] = mcs_spectrum2d_mean_stderr(&acc, k1, k2, &out.scalar[0]);
        st[calls++] = mcs_spectrum2d_variance14(&acc, 7u, f_re, f_im, &out.scalar[0]);
    } else {
        st[calls++] = mcs_spectrum2d_add_points(&acc, 7u, pts, NULL);
        st[calls++] = mcs_spectrum2d_merge(&acc, &other);
        st[calls++] = mcs_spectrum2d_merge(&other, &acc);
        st[calls++] = mcs_spectrum2d_merge(&acc, &acc);
        st[calls++] = mcs_spectrum2d_variance14(&acc, 7u, f_re, f_im, &out.scalar[0]);
    }
    for (int c = 0; c < calls; ++c)
        TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_ERR_INVARIANT, st[c], msg);
    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(&out_sentinel, &out, sizeof out, msg);
    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(&acc_copy, &o_acc, sizeof o_acc, msg);
    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(&other_copy, &o_other, sizeof o_other, msg);
}

static void test_a_twiddle_outside_its_range_is_refused_by_transform_add_and_merge(void)
{
    static const double bad[4] = {(double)NAN, 1.5, -1e9, 1e300};
    prepare();
    double *const tables[4] = {acc.cos_x, acc.sin_x, acc.cos_y, acc.sin_y};
    for (int t = 0; t < 4; ++t)
        for (size_t j = 0; j < (t < 2 ? NX : NY); j += 2u)
            for (int v = 0; v < 4; ++v) {
                const double keep = tables[t][j];
                tables[t][j] = bad[v];
                assert_refused(0, 0u, 0u, "twiddle");
                tables[t][j] = keep;
            }
}

/* A statistic of wave vector (k1, k2) NaN, infinite, huge, or negative where
 * it cannot be (a mean power or M2): the read-outs of (k1, k2) and of its
 * mirror (served from it by S_{-k} = conj(S_k)) refuse it, and so does
 * every call that reads all cells. */
static void test_a_corrupted_statistic_is_refused_where_it_is_read(void)
{
    static const double bad[5] = {(double)NAN, (double)INFINITY, 1e300, -DBL_MAX, -1e-3};
    prepare();
    double *const fields[5] = {acc.mean_re, acc.mean_im, acc.mean_pow, acc.m2_s, acc.m2_pow};
    const size_t stride = NX + 1u;
    for (int fi = 0; fi < 5; ++fi)
        for (size_t k2 = 0; k2 <= NY / 2u; k2 += 2u)
            for (size_t k1 = 1; k1 < NX; k1 += 3u)
                for (int v = 0; v < 5; ++v) {
                    if (fi < 2 && v == 4)
                        continue; /* a mean may be negative */
                    double *x = &fields[fi][k2 * stride + k1];
                    const double keep = *x;
                    *x = bad[v];
                    assert_refused(1, k1, k2, "statistic");
                    if (k2 > 0u && 2u * k2 < NY) /* rows 0 and N2/2 store both */
                        assert_refused(1, (NX - k1) % NX, NY - k2, "statistic, mirror");
                    assert_refused(2, 0u, 0u, "statistic");
                    *x = keep;
                }
}

/* A count past MCS_MAX_COUNT, a spread with one trial, a mean with none,
 * and the pad column (never written by a call) not 0. */
static void test_counts_and_cells_no_calls_produce_are_refused(void)
{
    prepare();
    acc.state->count = (uint64_t)MCS_MAX_COUNT + 1u;
    uint64_t c = 5u;
    memcpy(&acc_copy, &o_acc, sizeof o_acc);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_spectrum2d_count(&acc, &c));
    TEST_ASSERT_EQUAL_UINT64(5u, c);
    assert_refused(1, 1u, 1u, "count");
    assert_refused(2, 0u, 0u, "count");

    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_init(&acc, NX, NY, o_acc.mem, sizeof o_acc.mem));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_add_points(&acc, 7u, pts, NULL));
    acc.m2_pow[NX + 2u] = 1.0;
    assert_refused(1, 1u, 1u, "spread with one trial");
    assert_refused(2, 0u, 0u, "spread with one trial");

    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_init(&acc, NX, NY, o_acc.mem, sizeof o_acc.mem));
    acc.mean_pow[1] = 1.0;
    assert_refused(2, 0u, 0u, "mean with no trial");
    memcpy(&acc_copy, &o_acc, sizeof o_acc);
    double p = SENTINEL;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_spectrum2d_power(&acc, 1u, 0u, &p));
    TEST_ASSERT_EQUAL_DOUBLE(SENTINEL, p);

    prepare();
    acc.mean_pow[NX] = 0.5; /* row 0, the pad column k1 = N1 */
    assert_refused(2, 0u, 0u, "pad");

    /* a buffer whose head no longer says N1, N2 (overwritten, or another
     * object's) */
    prepare();
    acc.state->shape[1] = NY + 2u;
    assert_refused(1, 1u, 1u, "shape");
    assert_refused(2, 0u, 0u, "shape");
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_a_twiddle_outside_its_range_is_refused_by_transform_add_and_merge);
    RUN_TEST(test_a_corrupted_statistic_is_refused_where_it_is_read);
    RUN_TEST(test_counts_and_cells_no_calls_produce_are_refused);
    return UNITY_END();
}
