/* Records (docs/format.md): round trips, the byte layout against an
 * independent writer and CRC, and every kind of corruption refused with the
 * destination byte-identical. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mcspec.h"
#include "spectra_ref.h"
#include "unity.h"

/* This Unity has no size_t assertion. */
#define ASSERT_SIZE(want, got) TEST_ASSERT_EQUAL_UINT64((uint64_t)(want), (uint64_t)(got))

void setUp(void) {}
void tearDown(void) {}

/* Record sizes by the documented formula; the buffers hold one N past the
 * capacities, for records a bigger build would write. */
#define SPEC_BYTES(n) (44u + 40u * ((n) / 2u + 1u))
#define MOMENT_BYTES(n) (44u + 8u * ((n) + (n) * ((n) + 1u) / 2u))
#define AUTOCORR_BYTES(n) (44u + 8u * ((n) + (n) / 2u + 1u))
#define WELFORD_BYTES 68u
#define REC_MAX (SPEC_BYTES(MCS_MAX_N + 2u) > MOMENT_BYTES(MCS_MAX_COV_N + 1u) \
                     ? SPEC_BYTES(MCS_MAX_N + 2u) : MOMENT_BYTES(MCS_MAX_COV_N + 1u))

static mcs_spectrum spec_a, spec_b, spec_dst, spec_before;
static mcs_moment mom_a, mom_b, mom_dst, mom_before;
static mcs_autocorr ac_a, ac_b, ac_dst, ac_before;
static mcs_welford wf_a, wf_b, wf_dst, wf_before;
static uint8_t rec[REC_MAX + 8u], rec2[REC_MAX + 8u], rec3[REC_MAX + 8u], guard[REC_MAX + 8u];
static size_t bins[64];
static double weights[64];

/* ---------------- the test's own writer: bitwise CRC, explicit bytes ---------------- */

static uint32_t ref_crc(const uint8_t *p, size_t len)
{
    uint32_t c = 0xffffffffu;
    for (size_t i = 0; i < len; ++i) {
        c ^= p[i];
        for (int b = 0; b < 8; ++b)
            c = (c & 1u) ? (c >> 1) ^ 0xedb88320u : c >> 1;
    }
    return ~c;
}

static void le(uint8_t *p, uint64_t v, size_t bytes)
{
    for (size_t i = 0; i < bytes; ++i)
        p[i] = (uint8_t)(v >> (8u * i));
}

static void le_f64(uint8_t *p, double v)
{
    uint64_t bits;
    memcpy(&bits, &v, sizeof bits);
    le(p, bits, 8u);
}

static uint64_t get_le(const uint8_t *p, size_t bytes)
{
    uint64_t v = 0u;
    for (size_t i = 0; i < bytes; ++i)
        v |= (uint64_t)p[i] << (8u * i);
    return v;
}

/* Rewrites the CRC of a record of len bytes after an edit. */
static void recrc(uint8_t *p, size_t len)
{
    le(p + len - 4u, ref_crc(p, len - 4u), 4u);
}

/* A record with the given header and p zero values (or values[] if not
 * NULL); returns its size. */
static size_t build(uint8_t *p, uint32_t version, uint32_t kind, uint32_t s,
                    const uint64_t *shape, uint64_t count, uint64_t np, const double *values)
{
    static const uint8_t magic[8] = {0x89u, 'M', 'C', 'S', 0x0du, 0x0au, 0x1au, 0x0au};
    memcpy(p, magic, 8u);
    le(p + 8, version, 2u);
    le(p + 10, kind, 2u);
    le(p + 12, s, 4u);
    le(p + 16, count, 8u);
    le(p + 24, np, 8u);
    for (size_t i = 0; i < s; ++i)
        le(p + 32 + 8u * i, shape[i], 8u);
    uint8_t *pl = p + 32 + 8u * s;
    for (size_t i = 0; i < np; ++i)
        le_f64(pl + 8u * i, values != NULL ? values[i] : 0.0);
    const size_t size = 36u + 8u * s + 8u * (size_t)np;
    recrc(p, size);
    return size;
}

static size_t payload_at(size_t s, size_t i)
{
    return 32u + 8u * s + 8u * i;
}

/* ---------------- one table drives the checks over every kind ---------------- */

typedef struct {
    const char *name;
    void *dst, *before;
    size_t obj_size, shape_len;
    mcs_status (*load)(void *dst, size_t len, const void *buf);
    mcs_status (*save)(const void *src, size_t cap, void *buf, size_t *len);
    const void *src;
} kind_ops;

static mcs_status ld_spec(void *d, size_t len, const void *b) { return mcs_io_load_spectrum(d, len, b); }
static mcs_status ld_mom(void *d, size_t len, const void *b) { return mcs_io_load_moment(d, len, b); }
static mcs_status ld_ac(void *d, size_t len, const void *b) { return mcs_io_load_autocorr(d, len, b); }
static mcs_status ld_wf(void *d, size_t len, const void *b) { return mcs_io_load_welford(d, len, b); }
static mcs_status sv_spec(const void *s, size_t c, void *b, size_t *l) { return mcs_io_save_spectrum(s, c, b, l); }
static mcs_status sv_mom(const void *s, size_t c, void *b, size_t *l) { return mcs_io_save_moment(s, c, b, l); }
static mcs_status sv_ac(const void *s, size_t c, void *b, size_t *l) { return mcs_io_save_autocorr(s, c, b, l); }
static mcs_status sv_wf(const void *s, size_t c, void *b, size_t *l) { return mcs_io_save_welford(s, c, b, l); }

static const kind_ops kinds[] = {
    {"spectrum", &spec_dst, &spec_before, sizeof spec_dst, 1u, ld_spec, sv_spec, &spec_a},
    {"moment", &mom_dst, &mom_before, sizeof mom_dst, 1u, ld_mom, sv_mom, &mom_a},
    {"autocorr", &ac_dst, &ac_before, sizeof ac_dst, 1u, ld_ac, sv_ac, &ac_a},
    {"welford", &wf_dst, &wf_before, sizeof wf_dst, 0u, ld_wf, sv_wf, &wf_a},
};
#define NKINDS (sizeof kinds / sizeof kinds[0])

/* Stratified trials of k samples into all four accumulators of one side. */
static void fill(mcs_spectrum *s, mcs_moment *m, mcs_autocorr *a, mcs_welford *w, size_t n,
                 size_t trials, uint64_t seed)
{
    spectra_stream st;
    const size_t k = 5u;
    spectra_stream_init(&st, MCS_PATTERN_STRATIFIED, n, k, NULL, seed, 0x10u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(s, n));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(m, n <= MCS_MAX_COV_N ? n : MCS_MAX_COV_N));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_init(a, n));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_init(w));
    for (size_t t = 0; t < trials; ++t) {
        spectra_stream_draw(&st, bins, weights, NULL);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(s, k, bins, weights));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_add_bins(a, k, bins, weights));
        for (size_t j = 0; j < k; ++j)
            bins[j] %= m->n;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_add_bins(m, k, bins, weights));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_add(w, (double)bins[0] + 0.25 * weights[1]));
    }
}

/* Fresh, different destinations, and their snapshots. */
static void dirty_destinations(void)
{
    fill(&spec_dst, &mom_dst, &ac_dst, &wf_dst, 12u, 3u, 99u);
    memcpy(&spec_before, &spec_dst, sizeof spec_dst);
    memcpy(&mom_before, &mom_dst, sizeof mom_dst);
    memcpy(&ac_before, &ac_dst, sizeof ac_dst);
    memcpy(&wf_before, &wf_dst, sizeof wf_dst);
}

static size_t save(const kind_ops *o, const void *src, uint8_t *buf)
{
    size_t len = 0u, qlen = 0u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, o->save(src, 0u, NULL, &qlen));
    TEST_ASSERT_EQUAL_INT(MCS_OK, o->save(src, REC_MAX, buf, &len));
    ASSERT_SIZE(qlen, len);
    return len;
}

static void expect_refused(const kind_ops *o, mcs_status want, size_t len, const uint8_t *buf,
                           const char *what, size_t at)
{
    mcs_status got = o->load(o->dst, len, buf);
    if (got != want || memcmp(o->dst, o->before, o->obj_size) != 0) {
        char msg[200];
        (void)snprintf(msg, sizeof msg, "%s, %s at %zu: want %s, got %s%s", o->name, what, at,
                       mcs_status_str(want), mcs_status_str(got),
                       got == want ? " but the destination changed" : "");
        TEST_FAIL_MESSAGE(msg);
    }
}

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
    TEST_ASSERT_EQUAL_HEX32(ref_crc(rec, 1000u), c);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_io_crc32(1u, NULL, &c));
    TEST_ASSERT_EQUAL_HEX32(ref_crc(rec, 1000u), c);
}

static void test_a_welford_record_is_the_documented_bytes(void)
{
    /* 1 and 3: mean 2, M2 2, M3 0, M4 2. */
    static const uint8_t want[WELFORD_BYTES - 4u] = {
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
    ASSERT_SIZE(WELFORD_BYTES, len);
    TEST_ASSERT_EQUAL_HEX8_ARRAY(want, rec, sizeof want);
    TEST_ASSERT_EQUAL_HEX32(ref_crc(want, sizeof want), (uint32_t)get_le(rec + 64, 4u));
}

static void test_a_spectrum_record_matches_the_independent_writer(void)
{
    static double values[5u * (16u / 2u + 1u)];
    fill(&spec_a, &mom_a, &ac_a, &wf_a, 16u, 40u, 1u);
    const size_t h1 = 9u;
    for (size_t k = 0; k < h1; ++k) {
        values[k] = spec_a.mean_re[k];
        values[h1 + k] = spec_a.mean_im[k];
        values[2u * h1 + k] = spec_a.m2_s[k];
        values[3u * h1 + k] = spec_a.mean_pow[k];
        values[4u * h1 + k] = spec_a.m2_pow[k];
    }
    const uint64_t shape = 16u;
    size_t want = build(rec2, 1u, 1u, 1u, &shape, 40u, 5u * h1, values);
    size_t len = save(&kinds[0], &spec_a, rec);
    ASSERT_SIZE(SPEC_BYTES(16u), want);
    ASSERT_SIZE(want, len);
    TEST_ASSERT_EQUAL_HEX8_ARRAY(rec2, rec, len);
}

static void test_peek_reports_the_header_and_refuses_what_load_refuses(void)
{
    mcs_io_info info, before;
    fill(&spec_a, &mom_a, &ac_a, &wf_a, 40u, 7u, 2u);
    size_t len = save(&kinds[2], &ac_a, rec);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_peek(len, rec, &info));
    TEST_ASSERT_EQUAL_UINT32(MCS_IO_KIND_AUTOCORR, info.kind);
    TEST_ASSERT_EQUAL_STRING("autocorr", mcs_io_kind_str(info.kind));
    TEST_ASSERT_EQUAL_UINT32(1u, info.shape_len);
    TEST_ASSERT_EQUAL_UINT64(40u, info.shape[0]);
    TEST_ASSERT_EQUAL_UINT64(7u, info.count);
    TEST_ASSERT_EQUAL_UINT64(40u + 21u, info.payload_len);
    ASSERT_SIZE(AUTOCORR_BYTES(40u), info.size);
    memcpy(&before, &info, sizeof info);
    rec[len - 1u] ^= 1u;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_CHECKSUM, mcs_io_peek(len, rec, &info));
    TEST_ASSERT_EQUAL_MEMORY(&before, &info, sizeof info);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_io_peek(len, NULL, &info));
    /* A kind this build does not know still has a readable header. */
    const uint64_t shape[2] = {8u, 8u};
    len = build(rec, 1u, 77u, 2u, shape, 3u, 5u, NULL);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_peek(len, rec, &info));
    TEST_ASSERT_EQUAL_UINT32(77u, info.kind);
    TEST_ASSERT_EQUAL_STRING("unknown", mcs_io_kind_str(info.kind));
    TEST_ASSERT_EQUAL_UINT64(8u, info.shape[1]);
}

/* ---------------- round trips ---------------- */

/* Saved, loaded into a dirty destination, saved again: the same bytes, and
 * merging the loaded objects gives the bytes of merging the originals. */
static void round_trip(size_t n, size_t trials_a, size_t trials_b)
{
    fill(&spec_a, &mom_a, &ac_a, &wf_a, n, trials_a, 3u + n);
    fill(&spec_b, &mom_b, &ac_b, &wf_b, n, trials_b, 1000u + n);
    const void *bsrc[NKINDS] = {&spec_b, &mom_b, &ac_b, &wf_b};
    const size_t want[NKINDS] = {SPEC_BYTES(n), MOMENT_BYTES(mom_a.n), AUTOCORR_BYTES(n),
                                 WELFORD_BYTES};
    for (size_t i = 0; i < NKINDS; ++i) {
        const kind_ops *o = &kinds[i];
        dirty_destinations();
        size_t la = save(o, o->src, rec), lb = save(o, bsrc[i], rec2);
        ASSERT_SIZE(want[i], la);
        TEST_ASSERT_EQUAL_INT(MCS_OK, o->load(o->dst, la, rec));
        ASSERT_SIZE(la, save(o, o->dst, rec3));
        TEST_ASSERT_EQUAL_HEX8_ARRAY(rec, rec3, la);
        /* before <- load(b), dst (= load(a)) <- dst merge before */
        TEST_ASSERT_EQUAL_INT(MCS_OK, o->load(o->before, lb, rec2));
        mcs_status st[2];
        switch (i) {
        case 0:
            st[0] = mcs_spectrum_merge(&spec_dst, &spec_before);
            st[1] = mcs_spectrum_merge(&spec_a, &spec_b);
            break;
        case 1:
            st[0] = mcs_moment_merge(&mom_dst, &mom_before);
            st[1] = mcs_moment_merge(&mom_a, &mom_b);
            break;
        case 2:
            st[0] = mcs_autocorr_merge(&ac_dst, &ac_before);
            st[1] = mcs_autocorr_merge(&ac_a, &ac_b);
            break;
        default:
            st[0] = mcs_welford_merge(&wf_dst, &wf_before);
            st[1] = mcs_welford_merge(&wf_a, &wf_b);
            break;
        }
        TEST_ASSERT_EQUAL_INT(MCS_OK, st[0]);
        TEST_ASSERT_EQUAL_INT(MCS_OK, st[1]);
        la = save(o, o->src, rec);
        ASSERT_SIZE(la, save(o, o->dst, rec3));
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

static void test_a_loaded_spectrum_reads_out_every_value_of_the_saved_one(void)
{
    fill(&spec_a, &mom_a, &ac_a, &wf_a, 30u, 50u, 4u);
    size_t len = save(&kinds[0], &spec_a, rec);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_load_spectrum(&spec_dst, len, rec));
    for (size_t f = 0; f < 30u; ++f) {
        double a[6], b[6];
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean(&spec_a, f, &a[0], &a[1]));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean(&spec_dst, f, &b[0], &b[1]));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(&spec_a, f, &a[2]));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(&spec_dst, f, &b[2]));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean_stderr(&spec_a, f, &a[3]));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean_stderr(&spec_dst, f, &b[3]));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power_stderr(&spec_a, f, &a[4]));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power_stderr(&spec_dst, f, &b[4]));
        TEST_ASSERT_EQUAL_MEMORY(a, b, 5u * sizeof a[0]);
    }
    /* The loaded object keeps accumulating like the original. */
    const size_t bb[2] = {3u, 17u};
    const double ww[2] = {1.0, 2.5};
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(&spec_a, 2u, bb, ww));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(&spec_dst, 2u, bb, ww));
    ASSERT_SIZE(len, save(&kinds[0], &spec_dst, rec3));
    ASSERT_SIZE(len, save(&kinds[0], &spec_a, rec));
    TEST_ASSERT_EQUAL_HEX8_ARRAY(rec, rec3, len);
}

/* ---------------- corruption: truncation, flipped bytes ---------------- */

static void test_every_truncation_and_an_extra_byte_are_refused(void)
{
    fill(&spec_a, &mom_a, &ac_a, &wf_a, 20u, 9u, 5u);
    for (size_t i = 0; i < NKINDS; ++i) {
        const kind_ops *o = &kinds[i];
        dirty_destinations();
        size_t len = save(o, o->src, rec);
        for (size_t cut = 0; cut < len; ++cut)
            expect_refused(o, MCS_ERR_TRUNCATED, cut, rec, "truncated to", cut);
        rec[len] = 0u;
        expect_refused(o, MCS_ERR_FORMAT, len + 1u, rec, "one byte added at", len);
    }
}

/* The status a changed byte at offset `at` must give: the magic, the
 * version and the two length fields are read before the checksum. */
static int flip_status_ok(size_t at, size_t shape_len, mcs_status st)
{
    if (at < 8u)
        return st == MCS_ERR_MAGIC;
    if (at < 10u)
        return st == MCS_ERR_VERSION;
    if ((at >= 12u && at < 16u) || (at >= 24u && at < 32u))
        return st == MCS_ERR_FORMAT || st == MCS_ERR_TRUNCATED;
    (void)shape_len;
    return st == MCS_ERR_CHECKSUM;
}

static void test_every_flipped_byte_is_refused(void)
{
    static const uint8_t flips[] = {0x01u, 0x02u, 0x04u, 0x08u, 0x10u, 0x20u, 0x40u, 0x80u, 0xffu};
    fill(&spec_a, &mom_a, &ac_a, &wf_a, 14u, 11u, 6u);
    for (size_t i = 0; i < NKINDS; ++i) {
        const kind_ops *o = &kinds[i];
        dirty_destinations();
        size_t len = save(o, o->src, rec);
        for (size_t at = 0; at < len; ++at) {
            for (size_t f = 0; f < sizeof flips; ++f) {
                rec[at] ^= flips[f];
                mcs_status st = o->load(o->dst, len, rec);
                rec[at] ^= flips[f];
                if (!flip_status_ok(at, o->shape_len, st) ||
                    memcmp(o->dst, o->before, o->obj_size) != 0) {
                    char msg[160];
                    (void)snprintf(msg, sizeof msg, "%s: byte %zu ^ 0x%02x gave %s", o->name, at,
                                   flips[f], mcs_status_str(st));
                    TEST_FAIL_MESSAGE(msg);
                }
            }
        }
        TEST_ASSERT_EQUAL_INT(MCS_OK, o->load(o->dst, len, rec)); /* restored: loads */
    }
}

/* ---------------- hand-built headers with a valid CRC ---------------- */

static void test_wrong_version_kind_and_shape_are_refused(void)
{
    const uint64_t sixteen = 16u, two[2] = {16u, 1u};
    dirty_destinations();
    const kind_ops *sp = &kinds[0];
    static const uint32_t versions[] = {0u, 2u, 0xffffu};
    for (size_t v = 0; v < 3u; ++v) {
        size_t len = build(rec, versions[v], 1u, 1u, &sixteen, 0u, 45u, NULL);
        expect_refused(sp, MCS_ERR_VERSION, len, rec, "version", versions[v]);
    }
    /* The same valid record is each kind but one; unknown kinds are no kind. */
    size_t len = build(rec, 1u, MCS_IO_KIND_SPECTRUM, 1u, &sixteen, 0u, 45u, NULL);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_load_spectrum(&spec_dst, len, rec));
    dirty_destinations();
    for (size_t i = 1; i < NKINDS; ++i)
        expect_refused(&kinds[i], MCS_ERR_KIND, len, rec, "spectrum record as kind", i);
    static const uint32_t unknown[] = {0u, 5u, 0xffffu};
    for (size_t u = 0; u < 3u; ++u) {
        len = build(rec, 1u, unknown[u], 1u, &sixteen, 0u, 45u, NULL);
        expect_refused(sp, MCS_ERR_KIND, len, rec, "kind", unknown[u]);
    }
    len = build(rec, 1u, 1u, 2u, two, 0u, 45u, NULL);
    expect_refused(sp, MCS_ERR_FORMAT, len, rec, "two shape words", 2u);
    len = build(rec, 1u, 1u, 0u, NULL, 0u, 45u, NULL);
    expect_refused(sp, MCS_ERR_FORMAT, len, rec, "no shape word", 0u);
    len = build(rec, 1u, 1u, 1u, &sixteen, 0u, 46u, NULL);
    expect_refused(sp, MCS_ERR_FORMAT, len, rec, "one value too many", 46u);
    len = build(rec, 1u, 1u, 1u, &sixteen, 0u, 44u, NULL);
    expect_refused(sp, MCS_ERR_FORMAT, len, rec, "one value too few", 44u);
    len = build(rec, 1u, 4u, 1u, &sixteen, 0u, 4u, NULL);
    expect_refused(&kinds[3], MCS_ERR_FORMAT, len, rec, "welford with a shape", 1u);
    static const uint64_t nine[9] = {16u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u};
    len = build(rec, 1u, 1u, 9u, nine, 0u, 45u, NULL);
    expect_refused(sp, MCS_ERR_FORMAT, len, rec, "nine shape words", 9u);
}

static void test_n_above_this_builds_capacity_is_refused(void)
{
    const uint64_t spec_n = MCS_MAX_N + 1u, cov_n = MCS_MAX_COV_N + 1u, zero = 0u;
    dirty_destinations();
    size_t len = build(rec, 1u, 1u, 1u, &spec_n, 0u, 5u * (spec_n / 2u + 1u), NULL);
    expect_refused(&kinds[0], MCS_ERR_N_RANGE, len, rec, "spectrum N", (size_t)spec_n);
    len = build(rec, 1u, 2u, 1u, &cov_n, 0u, cov_n + cov_n * (cov_n + 1u) / 2u, NULL);
    expect_refused(&kinds[1], MCS_ERR_N_RANGE, len, rec, "moment N", (size_t)cov_n);
    len = build(rec, 1u, 3u, 1u, &spec_n, 0u, spec_n + spec_n / 2u + 1u, NULL);
    expect_refused(&kinds[2], MCS_ERR_N_RANGE, len, rec, "autocorr N", (size_t)spec_n);
    for (size_t i = 0; i < 3u; ++i) {
        len = build(rec, 1u, (uint32_t)i + 1u, 1u, &zero, 0u, 5u, NULL);
        expect_refused(&kinds[i], MCS_ERR_N_RANGE, len, rec, "N = 0, kind", i + 1u);
    }
    /* The largest N this build holds loads. */
    const uint64_t max_n = MCS_MAX_N;
    len = build(rec, 1u, 1u, 1u, &max_n, 0u, 5u * (max_n / 2u + 1u), NULL);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_load_spectrum(&spec_dst, len, rec));
    ASSERT_SIZE(MCS_MAX_N, spec_dst.n);
}

/* ---------------- values: non-finite and broken invariants, valid CRC ---------------- */

static void set_value(uint8_t *p, size_t len, size_t shape_len, size_t i, double v)
{
    le_f64(p + payload_at(shape_len, i), v);
    recrc(p, len);
}

static void set_count(uint8_t *p, size_t len, uint64_t count)
{
    le(p + 16, count, 8u);
    recrc(p, len);
}

static void test_non_finite_values_are_refused(void)
{
    const double bad[3] = {NAN, INFINITY, -INFINITY};
    fill(&spec_a, &mom_a, &ac_a, &wf_a, 14u, 11u, 7u);
    for (size_t i = 0; i < NKINDS; ++i) {
        const kind_ops *o = &kinds[i];
        dirty_destinations();
        const size_t len = save(o, o->src, rec);
        const size_t np = (size_t)get_le(rec + 24, 8u);
        const size_t at[3] = {0u, np / 2u, np - 1u};
        for (size_t a = 0; a < 3u; ++a) {
            for (size_t b = 0; b < 3u; ++b) {
                memcpy(rec2, rec, len);
                set_value(rec2, len, o->shape_len, at[a], bad[b]);
                expect_refused(o, MCS_ERR_NOT_FINITE, len, rec2, "non-finite value", at[a]);
            }
        }
        /* Non-finite outranks a broken invariant elsewhere. */
        memcpy(rec2, rec, len);
        le_f64(rec2 + payload_at(o->shape_len, np - 1u), -1.0);
        set_value(rec2, len, o->shape_len, 0u, NAN);
        expect_refused(o, MCS_ERR_NOT_FINITE, len, rec2, "NaN and a negative", 0u);
    }
}

/* Edits value i of the saved record of kind o (in rec, len bytes) to v and
 * expects `want`. */
static void expect_value(const kind_ops *o, size_t len, size_t i, double v, mcs_status want)
{
    memcpy(rec2, rec, len);
    set_value(rec2, len, o->shape_len, i, v);
    if (want == MCS_OK) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, o->load(o->dst, len, rec2));
        dirty_destinations();
    } else {
        expect_refused(o, want, len, rec2, "edited value", i);
    }
}

static void test_broken_invariants_are_refused(void)
{
    fill(&spec_a, &mom_a, &ac_a, &wf_a, 14u, 11u, 8u);
    dirty_destinations();
    const size_t h1 = 8u;
    size_t len = save(&kinds[0], &spec_a, rec);
    expect_value(&kinds[0], len, 2u * h1 + 3u, -1.0, MCS_ERR_INVARIANT);       /* m2_s */
    expect_value(&kinds[0], len, 3u * h1, -0.5, MCS_ERR_INVARIANT);            /* mean_pow */
    expect_value(&kinds[0], len, 5u * h1 - 1u, -1e-300, MCS_ERR_INVARIANT);   /* m2_pow */
    expect_value(&kinds[0], len, 2u * h1 + 3u, -0.0, MCS_OK);                  /* -0 is 0 */
    expect_value(&kinds[0], len, h1 + 2u, -7.0, MCS_OK); /* means may be negative */
    expect_value(&kinds[0], len, 1u, -MCS_IO_MAX_MAGNITUDE, MCS_OK);
    expect_value(&kinds[0], len, 1u, -2.0 * MCS_IO_MAX_MAGNITUDE, MCS_ERR_INVARIANT);
    expect_value(&kinds[0], len, 3u * h1 + 1u, 1.0000001 * MCS_IO_MAX_MAGNITUDE,
                 MCS_ERR_INVARIANT);
    len = save(&kinds[1], &mom_a, rec);
    expect_value(&kinds[1], len, 2u, -1.0, MCS_ERR_INVARIANT);      /* sum_s */
    expect_value(&kinds[1], len, 14u + 3u, -2.0, MCS_ERR_INVARIANT); /* sum_ss[0][3] */
    len = save(&kinds[2], &ac_a, rec);
    expect_value(&kinds[2], len, 14u + 7u, -1.0, MCS_ERR_INVARIANT); /* sum_a[7] */
    len = save(&kinds[3], &wf_a, rec);
    expect_value(&kinds[3], len, 1u, -1.0, MCS_ERR_INVARIANT);  /* m2 */
    expect_value(&kinds[3], len, 3u, -1.0, MCS_ERR_INVARIANT);  /* m4 */
    expect_value(&kinds[3], len, 2u, -5.0, MCS_OK);             /* m3 has either sign */
    expect_value(&kinds[3], len, 0u, -5.0, MCS_OK);             /* so has the mean */
}

static void test_counts_that_do_not_fit_the_data_are_refused(void)
{
    fill(&spec_a, &mom_a, &ac_a, &wf_a, 14u, 11u, 9u);
    for (size_t i = 0; i < NKINDS; ++i) {
        const kind_ops *o = &kinds[i];
        dirty_destinations();
        const size_t len = save(o, o->src, rec);
        memcpy(rec2, rec, len);
        set_count(rec2, len, 0u);
        expect_refused(o, MCS_ERR_INVARIANT, len, rec2, "zero count with data", 0u);
        set_count(rec2, len, MCS_IO_MAX_COUNT + 1u);
        expect_refused(o, MCS_ERR_INVARIANT, len, rec2, "count above 2^53", 0u);
        set_count(rec2, len, UINT64_MAX);
        expect_refused(o, MCS_ERR_INVARIANT, len, rec2, "count 2^64 - 1", 0u);
        set_count(rec2, len, MCS_IO_MAX_COUNT);
        TEST_ASSERT_EQUAL_INT(MCS_OK, o->load(o->dst, len, rec2));
    }
    /* One trial has no spread: a spectrum or welford with M2 != 0 cannot be. */
    dirty_destinations();
    size_t len = save(&kinds[0], &spec_a, rec);
    set_count(rec, len, 1u);
    expect_refused(&kinds[0], MCS_ERR_INVARIANT, len, rec, "one trial with spread", 1u);
    len = save(&kinds[3], &wf_a, rec);
    set_count(rec, len, 1u);
    expect_refused(&kinds[3], MCS_ERR_INVARIANT, len, rec, "one value with spread", 1u);
    set_value(rec, len, 0u, 1u, 0.0);
    set_value(rec, len, 0u, 3u, 0.0);
    expect_refused(&kinds[3], MCS_ERR_INVARIANT, len, rec, "one value with m3", 2u);
    set_value(rec, len, 0u, 2u, 0.0);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_load_welford(&wf_dst, len, rec));
}

/* ---------------- saving: sizes, space, bad objects ---------------- */

static void test_save_refuses_a_short_buffer_and_bad_objects_writing_nothing(void)
{
    fill(&spec_a, &mom_a, &ac_a, &wf_a, 10u, 4u, 10u);
    for (size_t i = 0; i < NKINDS; ++i) {
        const kind_ops *o = &kinds[i];
        size_t need = 0u, len = 12345u;
        TEST_ASSERT_EQUAL_INT(MCS_OK, o->save(o->src, 0u, NULL, &need));
        memset(rec, 0xa5, need);
        memcpy(guard, rec, need);
        TEST_ASSERT_EQUAL_INT(MCS_ERR_SPACE, o->save(o->src, need - 1u, rec, &len));
        ASSERT_SIZE(12345u, len);
        TEST_ASSERT_EQUAL_MEMORY(guard, rec, need);
        TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, o->save(NULL, need, rec, &len));
        TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, o->save(o->src, need, rec, NULL));
        TEST_ASSERT_EQUAL_MEMORY(guard, rec, need);
        TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, o->load(o->dst, need, NULL));
        TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, o->load(NULL, need, rec));
    }
    /* Objects never initialised. */
    size_t len = 1u;
    memset(&spec_b, 0, sizeof spec_b);
    memset(&mom_b, 0, sizeof mom_b);
    memset(&ac_b, 0, sizeof ac_b);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_io_save_spectrum(&spec_b, REC_MAX, rec, &len));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_io_save_moment(&mom_b, REC_MAX, rec, &len));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_io_save_autocorr(&ac_b, REC_MAX, rec, &len));
    /* Sums overflowed by huge weights: load would refuse them, so save does. */
    const size_t bb[2] = {1u, 2u};
    const double huge[2] = {1e200, 1e200};
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(&spec_a, 2u, bb, huge));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_add_bins(&mom_a, 2u, bb, huge));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_add_bins(&ac_a, 2u, bb, huge));
    wf_a.count = MCS_IO_MAX_COUNT + 1u;
    const mcs_status want[NKINDS] = {MCS_ERR_NOT_FINITE, MCS_ERR_NOT_FINITE, MCS_ERR_NOT_FINITE,
                                     MCS_ERR_INVARIANT};
    for (size_t i = 0; i < NKINDS; ++i) {
        memset(rec, 0xa5, 64u);
        len = 1u;
        TEST_ASSERT_EQUAL_INT(want[i], kinds[i].save(kinds[i].src, REC_MAX, rec, &len));
        TEST_ASSERT_EQUAL_INT(want[i], kinds[i].save(kinds[i].src, 0u, NULL, &len));
        ASSERT_SIZE(1u, len);
        TEST_ASSERT_EQUAL_MEMORY(guard, rec, 64u);
    }
}

static void test_record_sizes_follow_the_documented_formula(void)
{
    static const size_t ns[] = {1u, 2u, 5u, 64u, 1024u, MCS_MAX_N};
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; ++i) {
        size_t n = ns[i], len = 0u;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&spec_a, n));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_save_spectrum(&spec_a, 0u, NULL, &len));
        ASSERT_SIZE(SPEC_BYTES(n), len);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_init(&ac_a, n));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_save_autocorr(&ac_a, 0u, NULL, &len));
        ASSERT_SIZE(AUTOCORR_BYTES(n), len);
        if (n <= MCS_MAX_COV_N) {
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&mom_a, n));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_save_moment(&mom_a, 0u, NULL, &len));
            ASSERT_SIZE(MOMENT_BYTES(n), len);
        }
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_crc32_matches_the_ieee_check_value);
    RUN_TEST(test_a_welford_record_is_the_documented_bytes);
    RUN_TEST(test_a_spectrum_record_matches_the_independent_writer);
    RUN_TEST(test_peek_reports_the_header_and_refuses_what_load_refuses);
    RUN_TEST(test_round_trips_are_bit_exact_and_merge_like_the_originals);
    RUN_TEST(test_a_loaded_spectrum_reads_out_every_value_of_the_saved_one);
    RUN_TEST(test_every_truncation_and_an_extra_byte_are_refused);
    RUN_TEST(test_every_flipped_byte_is_refused);
    RUN_TEST(test_wrong_version_kind_and_shape_are_refused);
    RUN_TEST(test_n_above_this_builds_capacity_is_refused);
    RUN_TEST(test_non_finite_values_are_refused);
    RUN_TEST(test_broken_invariants_are_refused);
    RUN_TEST(test_counts_that_do_not_fit_the_data_are_refused);
    RUN_TEST(test_save_refuses_a_short_buffer_and_bad_objects_writing_nothing);
    RUN_TEST(test_record_sizes_follow_the_documented_formula);
    return UNITY_END();
}
