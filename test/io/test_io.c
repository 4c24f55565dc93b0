/* Records (docs/format.md), the good path: the CRC and the byte layout
 * against an independent writer, round trips of every kind bit-exact and
 * merging like the originals, the size query, and saving refused without a
 * byte written. The corruptions are test_io_corrupt.c. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "io_fixtures.h"
#include "mcspec.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

static io_set set_a, set_b, set_dst, set_loaded;
static uint8_t rec[IO_REC_MAX + 8u], rec2[IO_REC_MAX + 8u], rec3[IO_REC_MAX + 8u];
static uint8_t guard[IO_REC_MAX + 8u];

#define ASSERT_SIZE(want, got) TEST_ASSERT_EQUAL_UINT64((uint64_t)(want), (uint64_t)(got))

/* ---------------- CRC and byte layout ---------------- */

static void test_crc32_matches_the_ieee_check_value(void)
{
    uint32_t c = 1u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_crc32(9u, "123456789", &c));
    TEST_ASSERT_EQUAL_HEX32(0xcbf43926u, c);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_crc32(0u, NULL, &c));
    TEST_ASSERT_EQUAL_HEX32(0u, c);
    for (size_t i = 0; i < 1000u; ++i)
        rec[i] = (uint8_t)(i * 7u + (i >> 3));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_crc32(1000u, rec, &c));
    TEST_ASSERT_EQUAL_HEX32(io_ref_crc(rec, 1000u), c);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_io_crc32(1u, NULL, &c));
    TEST_ASSERT_EQUAL_HEX32(io_ref_crc(rec, 1000u), c);
}

static void test_a_welford_record_is_the_documented_bytes(void)
{
    /* 1 and 3: mean 2, M2 2, M3 0, M4 2. */
    static const uint8_t want[IO_WELFORD_BYTES - 4u] = {
        0x89, 'M', 'C', 'S', 0x0d, 0x0a, 0x1a, 0x0a, 1, 0, 4, 0, 0, 0, 0, 0,
        2, 0, 0, 0, 0, 0, 0, 0, 4, 0, 0, 0, 0, 0, 0, 0,
        0, 0, 0, 0, 0, 0, 0x00, 0x40, 0, 0, 0, 0, 0, 0, 0x00, 0x40,
        0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0x00, 0x40};
    mcs_welford w;
    size_t len = 0u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_init(&w));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_add(&w, 1.0));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_add(&w, 3.0));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_save_welford(&w, sizeof rec, rec, &len));
    ASSERT_SIZE(IO_WELFORD_BYTES, len);
    TEST_ASSERT_EQUAL_HEX8_ARRAY(want, rec, sizeof want);
    TEST_ASSERT_EQUAL_HEX32(io_ref_crc(want, sizeof want), (uint32_t)io_get_le(rec + 64, 4u));
}

static void test_a_spectrum_record_matches_the_independent_writer(void)
{
    static double values[3u + 5u * (16u / 2u + 1u) + 3u * 16u - 1u];
    io_fill(&set_a, 16u, 40u, 1u);
    const mcs_spectrum *s = &set_a.spec;
    const size_t h1 = 9u, np = 3u + 5u * h1 + 3u * 16u - 1u;
    values[0] = (double)s->units;
    values[1] = (double)s->open_count;
    values[2] = s->open_work;
    for (size_t k = 0; k < h1; ++k) {
        values[3u + k] = s->mean_re[k];
        values[3u + h1 + k] = s->mean_im[k];
        values[3u + 2u * h1 + k] = s->m2_s[k];
        values[3u + 3u * h1 + k] = s->mean_pow[k];
        values[3u + 4u * h1 + k] = s->m2_pow[k];
    }
    for (size_t j = 0; j < 16u; ++j)
        values[3u + 5u * h1 + j] = s->open_sum[j];
    for (size_t j = 1; j < 32u; ++j)
        values[3u + 5u * h1 + 16u + j - 1u] = s->open_pairs[j];
    const uint64_t shape = 16u;
    size_t want = io_build(rec2, 1u, 1u, 1u, &shape, 40u, np, values);
    size_t len = io_save(&io_kinds[0], s, rec);
    ASSERT_SIZE(IO_SPECTRUM_BYTES(16u), want);
    ASSERT_SIZE(want, len);
    TEST_ASSERT_EQUAL_HEX8_ARRAY(rec2, rec, len);
}

static void test_a_spectrum2d_record_skips_the_padding_column(void)
{
    /* N1 = 5 is stored 6 apart; the record holds rows of 5, k2 = 0..N2/2. */
    static double values[5u * 5u * 3u];
    io_fill(&set_a, 5u, 12u, 2u); /* 5 x 3 bins */
    const mcs_spectrum2d *s = &set_a.sp2.acc;
    TEST_ASSERT_EQUAL_UINT64(5u, s->n_x);
    TEST_ASSERT_EQUAL_UINT64(3u, s->n_y);
    const double *arrays[5] = {s->mean_re, s->mean_im, s->m2_s, s->mean_pow, s->m2_pow};
    for (size_t a = 0; a < 5u; ++a)
        for (size_t k2 = 0; k2 < 2u; ++k2)
            for (size_t k1 = 0; k1 < 5u; ++k1)
                values[a * 10u + k2 * 5u + k1] = arrays[a][k2 * 6u + k1];
    const uint64_t shape[2] = {5u, 3u};
    size_t want = io_build(rec2, 1u, 7u, 2u, shape, 12u, 50u, values);
    size_t len = io_save(&io_kinds[6], &set_a.sp2, rec);
    ASSERT_SIZE(IO_SPECTRUM2D_BYTES(5u, 3u), want);
    ASSERT_SIZE(want, len);
    TEST_ASSERT_EQUAL_HEX8_ARRAY(rec2, rec, len);
}

static void test_peek_reports_the_header_and_refuses_what_load_refuses(void)
{
    mcs_io_info info, before;
    io_fill(&set_a, 40u, 7u, 2u);
    size_t len = io_save(&io_kinds[2], &set_a.ac, rec);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_peek(len, rec, &info));
    TEST_ASSERT_EQUAL_UINT32(MCS_IO_KIND_AUTOCORR, info.kind);
    TEST_ASSERT_EQUAL_STRING("autocorr", mcs_io_kind_str(info.kind));
    TEST_ASSERT_EQUAL_UINT32(1u, info.shape_len);
    TEST_ASSERT_EQUAL_UINT64(40u, info.shape[0]);
    TEST_ASSERT_EQUAL_UINT64(7u, info.count);
    TEST_ASSERT_EQUAL_UINT64(2u * 40u + 2u * 21u + 2u, info.payload_len);
    ASSERT_SIZE(IO_AUTOCORR_BYTES(40u), info.size);
    memcpy(&before, &info, sizeof info);
    rec[len - 1u] ^= 1u;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_CHECKSUM, mcs_io_peek(len, rec, &info));
    TEST_ASSERT_EQUAL_MEMORY(&before, &info, sizeof info);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_io_peek(len, NULL, &info));
    /* A kind this build does not know still has a readable header. */
    const uint64_t shape[2] = {8u, 8u};
    len = io_build(rec, 1u, 77u, 2u, shape, 3u, 5u, NULL);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_peek(len, rec, &info));
    TEST_ASSERT_EQUAL_UINT32(77u, info.kind);
    TEST_ASSERT_EQUAL_STRING("unknown", mcs_io_kind_str(info.kind));
    TEST_ASSERT_EQUAL_UINT64(8u, info.shape[1]);
    for (uint32_t k = 1u; k <= IO_NKINDS; ++k)
        TEST_ASSERT_EQUAL_STRING(io_kinds[k - 1u].name, mcs_io_kind_str(k));
}

/* ---------------- round trips ---------------- */

/* Saved, loaded into a dirty destination, saved again: the same bytes; and
 * merging the loaded objects gives the bytes of merging the originals. */
static void round_trip(size_t n, size_t trials_a, size_t trials_b)
{
    io_fill(&set_a, n, trials_a, 3u + n);
    io_fill(&set_b, n, trials_b, 1000u + n);
    for (size_t i = 0; i < IO_NKINDS; ++i) {
        const io_kind_ops *o = &io_kinds[i];
        io_fill(&set_dst, 12u, 3u, 99u);
        void *a = io_obj(&set_a, o), *b = io_obj(&set_b, o);
        void *dst = io_obj(&set_dst, o), *loaded = io_obj(&set_loaded, o);
        size_t la = io_save(o, a, rec), lb = io_save(o, b, rec2);
        TEST_ASSERT_EQUAL_INT(MCS_OK, o->load(dst, la, rec));
        ASSERT_SIZE(la, io_save(o, dst, rec3));
        TEST_ASSERT_EQUAL_HEX8_ARRAY(rec, rec3, la);
        TEST_ASSERT_EQUAL_INT(MCS_OK, o->load(loaded, lb, rec2));
        TEST_ASSERT_EQUAL_INT(MCS_OK, o->merge(dst, loaded));
        TEST_ASSERT_EQUAL_INT(MCS_OK, o->merge(a, b));
        la = io_save(o, a, rec);
        ASSERT_SIZE(la, io_save(o, dst, rec3));
        TEST_ASSERT_EQUAL_HEX8_ARRAY(rec, rec3, la);
    }
}

static void test_round_trips_are_bit_exact_and_merge_like_the_originals(void)
{
    static const size_t ns[] = {1u, 2u, 3u, 16u, 61u, 64u, 100u, MCS_MAX_N};
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; ++i) {
        round_trip(ns[i], 37u, 23u);
        round_trip(ns[i], 0u, 5u); /* an empty accumulator, and merging into one */
        round_trip(ns[i], 1u, 1u); /* one trial: no spread yet */
    }
}

static void test_the_expected_record_sizes_come_out(void)
{
    io_fill(&set_a, 61u, 2u, 5u);
    const size_t f1 = 61u, f2 = 61u;
    const size_t want[IO_NKINDS] = {
        IO_SPECTRUM_BYTES(61u), IO_MOMENT_BYTES(61u), IO_AUTOCORR_BYTES(61u), IO_WELFORD_BYTES,
        IO_POINTSET_BYTES(f1), IO_POINTSET2D_BYTES(f2),
        IO_SPECTRUM2D_BYTES(set_a.sp2.acc.n_x, set_a.sp2.acc.n_y)};
    for (size_t i = 0; i < IO_NKINDS; ++i)
        ASSERT_SIZE(want[i], io_save(&io_kinds[i], io_obj(&set_a, &io_kinds[i]), rec));
}

static void test_a_loaded_spectrum_reads_out_every_value_of_the_saved_one(void)
{
    io_fill(&set_a, 30u, 50u, 4u);
    mcs_spectrum *orig = &set_a.spec, *back = &set_dst.spec;
    size_t len = io_save(&io_kinds[0], orig, rec);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_load_spectrum(back, len, rec));
    for (size_t f = 0; f < 30u; ++f) {
        double a[5], b[5];
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean(orig, f, &a[0], &a[1]));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean(back, f, &b[0], &b[1]));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(orig, f, &a[2]));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(back, f, &b[2]));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean_stderr(orig, f, &a[3]));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean_stderr(back, f, &b[3]));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power_stderr(orig, f, &a[4]));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power_stderr(back, f, &b[4]));
        TEST_ASSERT_EQUAL_MEMORY(a, b, sizeof a);
    }
    /* The loaded object keeps accumulating like the original. */
    const size_t bb[2] = {3u, 17u};
    const double ww[2] = {1.0, 2.5};
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(orig, 2u, bb, ww));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(back, 2u, bb, ww));
    ASSERT_SIZE(len, io_save(&io_kinds[0], back, rec3));
    ASSERT_SIZE(len, io_save(&io_kinds[0], orig, rec));
    TEST_ASSERT_EQUAL_HEX8_ARRAY(rec, rec3, len);
}

static void test_a_loaded_2d_point_set_reads_out_its_radial_profile(void)
{
    io_fill(&set_a, 9u, 30u, 6u);
    mcs_pointset2d *orig = &set_a.ps2.acc, *back = &set_dst.ps2.acc;
    size_t len = io_save(&io_kinds[5], &set_a.ps2, rec);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_load_pointset2d(back, IO_FIX_FLAGS_2D, set_dst.ps2.mem,
                                                         sizeof set_dst.ps2.mem, len, rec));
    for (size_t r = 1; r <= orig->freq_max; ++r) {
        double a[3], b[3];
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_radial(orig, r, &a[0]));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_radial(back, r, &b[0]));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_radial_stderr(orig, r, &a[1]));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_radial_stderr(back, r, &b[1]));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_power(orig, -(long)r, (long)r / 2, &a[2]));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_power(back, -(long)r, (long)r / 2, &b[2]));
        TEST_ASSERT_EQUAL_MEMORY(a, b, sizeof a);
    }
}

/* ---------------- saving refused, nothing written ---------------- */

static void test_save_refuses_a_short_buffer_and_bad_objects_writing_nothing(void)
{
    io_fill(&set_a, 10u, 4u, 10u);
    for (size_t i = 0; i < IO_NKINDS; ++i) {
        const io_kind_ops *o = &io_kinds[i];
        const void *src = io_obj(&set_a, o);
        size_t need = 0u, len = 12345u;
        TEST_ASSERT_EQUAL_INT(MCS_OK, o->save(src, 0u, NULL, &need));
        memset(rec, 0xa5, need);
        memcpy(guard, rec, need);
        TEST_ASSERT_EQUAL_INT(MCS_ERR_SPACE, o->save(src, need - 1u, rec, &len));
        ASSERT_SIZE(12345u, len);
        TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, o->save(NULL, need, rec, &len));
        TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, o->save(src, need, rec, NULL));
        TEST_ASSERT_EQUAL_MEMORY(guard, rec, need);
        TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, o->load(io_obj(&set_dst, o), need, NULL));
        TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, o->load(NULL, need, rec));
        /* Never initialised (welford has no such state: all zero is empty). */
        memset(io_obj(&set_b, o), 0, o->obj_size);
        TEST_ASSERT_EQUAL_INT(i == 3u ? MCS_OK : MCS_ERR_UNINIT,
                              o->save(io_obj(&set_b, o), IO_REC_MAX, rec2, &len));
    }
    /* Sums overflowed by huge weights: load would refuse them, so save does.
     * The moment and autocorr accumulators refuse such a trial themselves
     * (MCS_MOMENT_MAX_TRIAL), so their sums are overwritten instead. */
    const size_t bb[2] = {1u, 2u};
    const double huge[2] = {1e200, 1e200}, pts[4] = {0.1, 0.2, 0.3, 0.4};
    set_a.spec.mean_pow[1] = INFINITY; /* the spectrum refuses such weights; write one */
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MAGNITUDE, mcs_moment_add_bins(&set_a.mom, 2u, bb, huge));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MAGNITUDE, mcs_autocorr_add_bins(&set_a.ac, 2u, bb, huge));
    set_a.mom.sum_dd[1] = INFINITY;
    set_a.ac.sum_lag[1] = INFINITY;
    /* The 2D spectrum refuses them too (its weights' sum bound): overwritten. */
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MAGNITUDE,
                          mcs_spectrum2d_add_points(&set_a.sp2.acc, 2u, pts, huge));
    set_a.sp2.acc.mean_pow[1] = INFINITY;
    set_a.wf.count = MCS_IO_MAX_COUNT + 1u;
    set_a.ps.acc.state->count = MCS_IO_MAX_COUNT + 1u;
    set_a.ps2.acc.m2[0] = -1.0;
    const mcs_status want[IO_NKINDS] = {MCS_ERR_NOT_FINITE, MCS_ERR_NOT_FINITE,
                                        MCS_ERR_NOT_FINITE, MCS_ERR_INVARIANT,
                                        MCS_ERR_INVARIANT,  MCS_ERR_INVARIANT,
                                        MCS_ERR_NOT_FINITE};
    for (size_t i = 0; i < IO_NKINDS; ++i) {
        const io_kind_ops *o = &io_kinds[i];
        size_t len2 = 1u;
        memset(rec, 0xa5, 64u);
        TEST_ASSERT_EQUAL_INT(want[i], o->save(io_obj(&set_a, o), IO_REC_MAX, rec, &len2));
        TEST_ASSERT_EQUAL_INT(want[i], o->save(io_obj(&set_a, o), 0u, NULL, &len2));
        ASSERT_SIZE(1u, len2);
        TEST_ASSERT_EQUAL_MEMORY(guard, rec, 64u);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_crc32_matches_the_ieee_check_value);
    RUN_TEST(test_a_welford_record_is_the_documented_bytes);
    RUN_TEST(test_a_spectrum_record_matches_the_independent_writer);
    RUN_TEST(test_a_spectrum2d_record_skips_the_padding_column);
    RUN_TEST(test_peek_reports_the_header_and_refuses_what_load_refuses);
    RUN_TEST(test_round_trips_are_bit_exact_and_merge_like_the_originals);
    RUN_TEST(test_the_expected_record_sizes_come_out);
    RUN_TEST(test_a_loaded_spectrum_reads_out_every_value_of_the_saved_one);
    RUN_TEST(test_a_loaded_2d_point_set_reads_out_its_radial_profile);
    RUN_TEST(test_save_refuses_a_short_buffer_and_bad_objects_writing_nothing);
    return UNITY_END();
}
