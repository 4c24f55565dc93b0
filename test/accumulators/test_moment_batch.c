/* Tests for the moment accumulator's open batch (issue 11): trials go into
 * plain sums, as products of s or of d = s - c, and are folded into the
 * compensated sums every MCS_MOMENT_BATCH trials. Read-outs, merges and
 * records must see the batch whether it is open or folded, every kernel
 * (pairs of samples, dense rows of s, dense rows of d) must give the same
 * sums, and a corrupted batch must be refused. */
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "mcspec.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

#define N 16u
#define TRIALS (MCS_MOMENT_BATCH + 40u)

static mcs_moment mom, mom2, mom3, mom4;
static long double ref_s[N], ref_ss[N][N]; /* sums of s and s s^T in extended precision */
static uint8_t rec[1u << 17], rec2[1u << 17];

/* Trial t of a fixed sequence, as s[N] and (for the sparse form) bins and
 * weights: four shapes in turn, so every kernel sees trials: 3 random
 * samples (pairs of samples), 16 (past the pairs' rule at N = 16: dense
 * rows of s, which has fewer bins than d), one sample in each bin (dense
 * rows of d: as many bins as s), and a dense s given whole (rows of d). */
typedef struct {
    size_t k;
    int per_bin; /* one sample in each bin */
    size_t bins[N];
    double weights[N];
    double s[N];
} trial;

static void make_trial(mcs_rng *rng, size_t t, trial *out)
{
    static const size_t ks[4] = {3u, N, N, 0u};
    out->k = ks[(t + 3u) % 4u]; /* trial 1, the shift, has 3 samples */
    out->per_bin = (t + 3u) % 4u >= 2u;
    memset(out->s, 0, sizeof out->s);
    const size_t samples = out->k != 0u ? out->k : N;
    for (size_t j = 0; j < samples; ++j) {
        uint32_t b = 0u;
        double u = 0.0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_bounded(rng, N, &b));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_double(rng, &u));
        out->bins[j] = out->per_bin ? j : (size_t)b;
        out->weights[j] = 0.5 + 1.5 * u;
        out->s[out->bins[j]] += out->weights[j];
    }
}

static void add_trial(mcs_moment *acc, const trial *tr)
{
    if (tr->k != 0u)
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_add_bins(acc, tr->k, tr->bins, tr->weights));
    else
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_add_dense(acc, N, tr->s));
}

static void add_reference(const trial *tr)
{
    for (size_t m = 0; m < N; ++m) {
        ref_s[m] += tr->s[m];
        for (size_t q = 0; q < N; ++q)
            ref_ss[m][q] += (long double)tr->s[m] * tr->s[q];
    }
}

/* Every <s_m> and <s_m s_q> of acc within 1e-13 of the reference over
 * `trials` trials (relative to the largest second moment) and the rounding
 * the accumulator's sums may carry (moment.h: gamma = (MCS_MOMENT_BATCH +
 * 64) eps times sqrt(<d_m^2>) sqrt(<d_q^2>), d = s - c, and as much again
 * for each product with a mean), and exactly symmetric. */
static void expect_reference(const mcs_moment *acc, size_t trials)
{
    const long double t = (long double)trials;
    const double gamma = (MCS_MOMENT_BATCH + 64.0) * DBL_EPSILON;
    double scale = 0.0, root[N];
    for (size_t m = 0; m < N; ++m) {
        const long double c = acc->shift[m];
        const long double dd = ref_ss[m][m] / t - 2.0L * c * ref_s[m] / t + c * c;
        root[m] = (double)(sqrtl(dd > 0.0L ? dd : 0.0L) + fabsl(ref_s[m] / t));
        scale = fmax(scale, (double)(ref_ss[m][m] / t));
    }
    for (size_t m = 0; m < N; ++m) {
        double v = 0.0, w = 0.0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_bin_mean(acc, m, &v));
        TEST_ASSERT_DOUBLE_WITHIN(1e-13 * scale, (double)(ref_s[m] / trials), v);
        for (size_t q = 0; q < N; ++q) {
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_bin_second(acc, m, q, &v));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_bin_second(acc, q, m, &w));
            TEST_ASSERT_DOUBLE_WITHIN(1e-13 * scale + 4.0 * gamma * root[m] * root[q],
                                      (double)(ref_ss[m][q] / trials), v);
            TEST_ASSERT_EQUAL_MEMORY(&v, &w, sizeof v);
        }
    }
}

static void test_read_outs_see_the_open_batch_before_and_after_it_is_folded(void)
{
    mcs_rng rng;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, 11u, 3u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&mom, N));
    memset(ref_s, 0, sizeof ref_s);
    memset(ref_ss, 0, sizeof ref_ss);
    int saw_s = 0, saw_d = 0, full = 0, folded = 0;
    for (size_t t = 1; t <= TRIALS; ++t) {
        trial tr;
        make_trial(&rng, t, &tr);
        const uint64_t sparse = mom.batch_sparse, open = mom.batch_count;
        add_trial(&mom, &tr);
        add_reference(&tr);
        if (t > 1u && mom.batch_count == open + 1u) {
            saw_s |= tr.k == N && !tr.per_bin && mom.batch_sparse == sparse + 1u; /* rows of s */
            saw_d |= tr.k == N && tr.per_bin && mom.batch_sparse == sparse;       /* rows of d */
        }
        if (t == 1u) {
            TEST_ASSERT_EQUAL_UINT64(0u, mom.batch_count); /* the first trial is the shift */
        } else if (mom.batch_count == MCS_MOMENT_BATCH - 1u) { /* a full open batch */
            expect_reference(&mom, t);
            full = 1;
        } else if (full && !folded && mom.batch_count == 0u) { /* just folded */
            expect_reference(&mom, t);
            folded = 1;
        }
    }
    TEST_ASSERT_TRUE(saw_s && saw_d && full && folded);
    TEST_ASSERT_TRUE(mom.batch_count > 0u && mom.batch_count < 100u);
    expect_reference(&mom, TRIALS); /* the closed sums and a new open batch */
}

/* Merges of objects with open batches, folded ones, or both, and a saved and
 * loaded copy: the same read-outs as one pass over all trials. */
static void test_merges_and_records_include_the_open_batch(void)
{
    mcs_rng rng;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, 5u, 9u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&mom, N));  /* trials 1..T1 (folded once) */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&mom2, N)); /* trials T1+1..TRIALS */
    memset(ref_s, 0, sizeof ref_s);
    memset(ref_ss, 0, sizeof ref_ss);
    const size_t t1 = TRIALS - 25u;
    for (size_t t = 1; t <= TRIALS; ++t) {
        trial tr;
        make_trial(&rng, t, &tr);
        add_trial(t <= t1 ? &mom : &mom2, &tr);
        add_reference(&tr);
    }
    TEST_ASSERT_TRUE(mom.batch_count != 0u && mom2.batch_count != 0u);
    memcpy(&mom3, &mom2, sizeof mom3);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_merge(&mom3, &mom)); /* into the small one */
    expect_reference(&mom3, TRIALS);
    size_t len = 0u, len2 = 0u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_save_moment(&mom2, sizeof rec, rec, &len));
    memcpy(&mom4, &mom, sizeof mom4);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_merge(&mom, &mom2)); /* into the big one */
    expect_reference(&mom, TRIALS);
    /* a saved and loaded copy is the saved object: the same record, and it
     * merges to the same bits */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_load_moment(&mom3, len, rec));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_save_moment(&mom3, sizeof rec2, rec2, &len2));
    TEST_ASSERT_EQUAL_UINT64(len, len2);
    TEST_ASSERT_EQUAL_MEMORY(rec, rec2, len);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_merge(&mom4, &mom3));
    TEST_ASSERT_EQUAL_MEMORY(&mom, &mom4, sizeof mom);
    /* a self-merge folds the batch and doubles every sum: the same averages */
    double before[N], after[N];
    for (size_t m = 0; m < N; ++m)
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_bin_second(&mom2, m, (m * 7u) % N, &before[m]));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_merge(&mom2, &mom2));
    TEST_ASSERT_EQUAL_UINT64(0u, mom2.batch_count);
    for (size_t m = 0; m < N; ++m) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_bin_second(&mom2, m, (m * 7u) % N, &after[m]));
        TEST_ASSERT_DOUBLE_WITHIN(1e-14 * fabs(before[m]), before[m], after[m]);
    }
}

/* The dense rows have a baseline and an AVX2 copy (on x86-64), picked at
 * init: the same trials through either give the same bits. Where the CPU
 * has no AVX2 both objects run the baseline copy. */
static void test_both_copies_of_the_row_kernel_give_the_same_bits(void)
{
    mcs_rng rng;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, 8u, 1u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&mom, N));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&mom2, N));
    mom2.simd = 0;
    for (size_t t = 1; t <= 200u; ++t) {
        trial tr;
        make_trial(&rng, t, &tr);
        add_trial(&mom, &tr);
        add_trial(&mom2, &tr);
    }
    TEST_ASSERT_TRUE(mom.batch_count > 190u && mom.batch_sparse > 0u &&
                     mom.batch_sparse < mom.batch_count);
    TEST_ASSERT_EQUAL_MEMORY(mom.batch_w, mom2.batch_w, sizeof mom.batch_w);
    TEST_ASSERT_EQUAL_MEMORY(mom.batch_s, mom2.batch_s, sizeof mom.batch_s);
    TEST_ASSERT_EQUAL_MEMORY(mom.batch_d, mom2.batch_d, sizeof mom.batch_d);
}

/* A batch whose counts or values no trials give is refused by adds, merges
 * and read-outs alike, with nothing written. */
static void test_a_corrupted_batch_is_refused_and_nothing_changes(void)
{
    mcs_rng rng;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, 2u, 2u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&mom, N));
    trial tr;
    for (size_t t = 1; t <= 10u; ++t) {
        make_trial(&rng, t, &tr);
        add_trial(&mom, &tr);
    }
    for (int c = 0; c < 8; ++c) {
        memcpy(&mom2, &mom, sizeof mom2);
        switch (c) {
        case 0: mom2.batch_count = mom2.count; break; /* the first trial is no batch's */
        case 1: mom2.batch_count = MCS_MOMENT_BATCH; break;
        case 2: mom2.batch_sparse = mom2.batch_count + 1u; break;
        case 3: mom2.simd = 2; break;
        case 4: mom2.batch_w[3u * N + 5u] = NAN; break;
        case 5: mom2.batch_s[1] = INFINITY; break;
        case 6: mom2.batch_w[7] = 0x1p461; break; /* no 2^14 trials of 2^220 give it */
        default: mom2.shift[2] = 0x1p241; break;   /* no trial gives it */
        }
        memcpy(&mom3, &mom2, sizeof mom3);
        double v = 7.0;
        const mcs_status add = c < 4 ? MCS_ERR_INVARIANT : MCS_OK; /* values: at read-out */
        if (c < 4) {
            TEST_ASSERT_EQUAL_INT(add, mcs_moment_add_bins(&mom2, tr.k != 0u ? tr.k : 3u,
                                                           tr.bins, tr.weights));
            TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_moment_merge(&mom2, &mom));
            TEST_ASSERT_EQUAL_MEMORY(&mom3, &mom2, sizeof mom2);
        }
        TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_moment_power(&mom2, 1u, &v));
        TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_moment_bin_second(&mom2, 3u, 5u, &v));
        TEST_ASSERT_EQUAL_DOUBLE(7.0, v);
        size_t len = 0u;
        TEST_ASSERT_TRUE(mcs_io_save_moment(&mom2, sizeof rec, rec, &len) != MCS_OK);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_read_outs_see_the_open_batch_before_and_after_it_is_folded);
    RUN_TEST(test_merges_and_records_include_the_open_batch);
    RUN_TEST(test_both_copies_of_the_row_kernel_give_the_same_bits);
    RUN_TEST(test_a_corrupted_batch_is_refused_and_nothing_changes);
    return UNITY_END();
}
