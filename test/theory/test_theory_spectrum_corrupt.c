/* Tests for the exact spectra at any N (mcs_theory_spectrum) read from an
 * object whose body no call produced: every read-out either refuses it
 * (MCS_ERR_INVARIANT, nothing written) or gives a finite value, >= 0 for a
 * power or a variance; and the cross moment at k = l is the power read-out.
 * (test_theory_spectrum.c holds the sound objects; it is near its size
 * limit.) */
#include "mcspec.h"
#include "theory_ref.h"
#include "unity.h"

#include <float.h>
#include <math.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define SENTINEL (-7.25e300)

static const mcs_pattern_kind all_kinds[MCS_PATTERN_KIND_COUNT] = {
    MCS_PATTERN_RANDOM, MCS_PATTERN_STRATIFIED, MCS_PATTERN_HOMOGENIZED, MCS_PATTERN_UNIFORM,
    MCS_PATTERN_JITTER};

static mcs_theory_spectrum ts, sound, ts_copy;
static mcs_importance imp;

static void spectrum_init(mcs_theory_spectrum *t, mcs_pattern_kind kind, size_t n, size_t k,
                          const mcs_importance *im)
{
    mcs_pattern pat;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, kind, n, k, im));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_init(t, &pat));
}

/* ---- k = l --------------------------------------------------------------- */

static void test_the_cross_moment_at_k_equal_l_is_the_power_read_out_bit_for_bit(void)
{
    for (size_t n = 1; n <= 90u; n += 11u)
        for (size_t k = 1; k <= 2u * n + 3u; k += n / 2u + 2u) {
            theory_lumpy_importance(&imp, n);
            for (int j = 0; j < 2 * MCS_PATTERN_KIND_COUNT; ++j) {
                const mcs_importance *im = j % 2 ? &imp : NULL;
                if (im != NULL && all_kinds[j / 2] == MCS_PATTERN_HOMOGENIZED)
                    continue;
                spectrum_init(&ts, all_kinds[j / 2], n, k, im);
                for (size_t q = 0; q < n; ++q) {
                    double p = SENTINEL, re = SENTINEL, im_part = SENTINEL;
                    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_power(&ts, q, &p));
                    TEST_ASSERT_EQUAL_INT(MCS_OK,
                                          mcs_theory_spectrum_cross(&ts, q, q, &re, &im_part));
                    TEST_ASSERT_EQUAL_MEMORY(&p, &re, sizeof p);
                    TEST_ASSERT_TRUE(im_part == 0.0 && !signbit(im_part));
                    TEST_ASSERT_TRUE(p >= 0.0);
                }
            }
        }
}

/* ---- corrupted bodies ---------------------------------------------------- */

static const double specials[] = {-1.0, -1e-300, -0.0, 0.0, 0.5, 2.5, -2.5, 1e300, -1e300,
                                  DBL_MAX, 4.9406564584124654e-324, (double)INFINITY,
                                  -(double)INFINITY, (double)NAN};
#define NSPECIALS (sizeof specials / sizeof specials[0])

/* Field f of the body as doubles (the seven arrays of doubles in the struct). */
#define FIELDS 7
static double *field(mcs_theory_spectrum *t, int f)
{
    double *const fields[FIELDS] = {t->mean_s, t->edge,    t->length,   t->inv_p,
                                    t->cos_table, t->sin_table, t->edge_lo};
    return fields[f];
}

/* One read-out of each kind at frequencies a, b: refused with nothing
 * written, or finite (and >= 0 where a power or variance). */
static void assert_read_outs_sound(size_t n, size_t k, size_t a, size_t b, const double *f)
{
    double p = SENTINEL, re = SENTINEL, im = SENTINEL, v = SENTINEL;
    mcs_status st = mcs_theory_spectrum_power(&ts, a, &p);
    TEST_ASSERT_TRUE(st == MCS_OK ? isfinite(p) && p >= 0.0
                                  : st == MCS_ERR_INVARIANT && p == SENTINEL);
    const int diagonal = a == b;
    for (int c = 0; c < 2; ++c) {
        re = im = SENTINEL;
        st = c == 0 ? mcs_theory_spectrum_cross(&ts, a, b, &re, &im)
                    : mcs_theory_spectrum_covariance(&ts, a, b, &re, &im);
        TEST_ASSERT_TRUE(st == MCS_OK ? isfinite(re) && isfinite(im) && (!diagonal || re >= 0.0)
                                      : st == MCS_ERR_INVARIANT && re == SENTINEL &&
                                            im == SENTINEL);
    }
    st = mcs_theory_spectrum_variance(&ts, n, k, f, &v);
    TEST_ASSERT_TRUE(st == MCS_OK ? isfinite(v) && v >= 0.0
                                  : st == MCS_ERR_INVARIANT && v == SENTINEL);
    v = SENTINEL;
    st = mcs_theory_spectrum_estimator_mean(&ts, n, k, f, &v);
    TEST_ASSERT_TRUE(st == MCS_OK ? isfinite(v) : st == MCS_ERR_INVARIANT && v == SENTINEL);
}

/* Every double of the body's first n (+1) entries set to each special value,
 * every kind, with and without importance; the object is unchanged after
 * (each value checked in place, then the whole object once per kind). */
static void test_a_corrupted_body_is_refused_or_reads_finite_never_negative_powers(void)
{
    const size_t n = 12u, k = 5u;
    double f[12];
    theory_lumpy_importance(&imp, n);
    theory_make_f(n, f, 0.7);
    for (int j = 0; j < 2 * MCS_PATTERN_KIND_COUNT; ++j) {
        const mcs_importance *im = j % 2 ? &imp : NULL;
        if (im != NULL && all_kinds[j / 2] == MCS_PATTERN_HOMOGENIZED)
            continue;
        spectrum_init(&sound, all_kinds[j / 2], n, k, im);
        memcpy(&ts, &sound, sizeof ts);
        for (int fi = 0; fi < FIELDS; ++fi)
            for (size_t b = 0; b <= n; ++b)
                for (size_t s = 0; s < NSPECIALS; ++s) {
                    field(&ts, fi)[b] = specials[s];
                    for (size_t a = 0; a < n; a += 5u)
                        assert_read_outs_sound(n, k, a, (a * 7u) % n, f);
                    TEST_ASSERT_EQUAL_MEMORY(&specials[s], &field(&ts, fi)[b], sizeof(double));
                    field(&ts, fi)[b] = field(&sound, fi)[b];
                }
        TEST_ASSERT_EQUAL_MEMORY(&sound, &ts, sizeof ts);
    }
}

/* A stratified pattern whose bin edge 3 was moved past edge 4 read a power
 * of -0.075 with MCS_OK (the overlaps of the strata went negative). */
static void test_edges_out_of_order_are_refused_not_read_as_a_negative_power(void)
{
    spectrum_init(&ts, MCS_PATTERN_STRATIFIED, 12u, 5u, NULL);
    ts.edge[3] = 2.5;
    memcpy(&ts_copy, &ts, sizeof ts);
    double p = SENTINEL, re = SENTINEL, im = SENTINEL;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_theory_spectrum_power(&ts, 2u, &p));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_theory_spectrum_cross(&ts, 2u, 2u, &re, &im));
    TEST_ASSERT_EQUAL_DOUBLE(SENTINEL, p);
    TEST_ASSERT_EQUAL_DOUBLE(SENTINEL, re);
    TEST_ASSERT_EQUAL_DOUBLE(SENTINEL, im);
    static double power[12];
    for (size_t q = 0; q < 12u; ++q)
        power[q] = SENTINEL;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_theory_power_spectrum(&ts, 12u, power));
    for (size_t q = 0; q < 12u; ++q)
        TEST_ASSERT_EQUAL_DOUBLE(SENTINEL, power[q]);
    TEST_ASSERT_EQUAL_MEMORY(&ts_copy, &ts, sizeof ts);
}

/* The jitter breakpoint order indexes the edges: an entry outside [1, N)
 * read far outside the object (SEGV under ASan before the check). */
static void test_a_jitter_order_entry_out_of_range_is_refused_not_followed(void)
{
    const size_t bad[4] = {0u, 12u, (size_t)1 << 40, SIZE_MAX};
    for (size_t i = 0; i < 4u; ++i) {
        spectrum_init(&ts, MCS_PATTERN_JITTER, 12u, 5u, NULL);
        ts.order[3] = bad[i];
        memcpy(&ts_copy, &ts, sizeof ts);
        double p = SENTINEL;
        TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_theory_spectrum_power(&ts, 1u, &p));
        TEST_ASSERT_EQUAL_DOUBLE(SENTINEL, p);
        TEST_ASSERT_EQUAL_MEMORY(&ts_copy, &ts, sizeof ts);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_the_cross_moment_at_k_equal_l_is_the_power_read_out_bit_for_bit);
    RUN_TEST(test_edges_out_of_order_are_refused_not_read_as_a_negative_power);
    RUN_TEST(test_a_jitter_order_entry_out_of_range_is_refused_not_followed);
    RUN_TEST(test_a_corrupted_body_is_refused_or_reads_finite_never_negative_powers);
    return UNITY_END();
}
