/* Records (docs/format.md), the bad path: every truncation, every changed
 * byte, wrong version, kind and shape, sizes above this build's capacities,
 * non-finite values and broken invariants (the last ones with a valid CRC,
 * written by the independent writer of io_fixtures.c): each refused with the
 * status that says which, the destination byte-identical. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "io_fixtures.h"
#include "mcspec.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

static io_set set_a, set_dst, set_before;
static uint8_t rec[IO_REC_MAX + 8u], rec2[IO_REC_MAX + 8u];

/* Fresh, different destinations and their snapshot. */
static void dirty_destinations(void)
{
    io_fill(&set_dst, 12u, 3u, 99u);
    memcpy(&set_before, &set_dst, sizeof set_dst);
}

static void refused(const io_kind_ops *o, mcs_status want, size_t len, const uint8_t *buf,
                    const char *what, size_t at)
{
    io_expect_refused(o, &set_dst, &set_before, want, len, buf, what, at);
}

static size_t save_a(const io_kind_ops *o, uint8_t *buf)
{
    return io_save(o, io_obj(&set_a, o), buf);
}

/* ---------------- truncation, changed bytes ---------------- */

static void test_every_truncation_and_an_extra_byte_are_refused(void)
{
    io_fill(&set_a, 20u, 9u, 5u);
    dirty_destinations();
    for (size_t i = 0; i < IO_NKINDS; ++i) {
        const io_kind_ops *o = &io_kinds[i];
        size_t len = save_a(o, rec);
        for (size_t cut = 0; cut < len; ++cut)
            refused(o, MCS_ERR_TRUNCATED, cut, rec, "truncated to", cut);
        rec[len] = 0u;
        refused(o, MCS_ERR_FORMAT, len + 1u, rec, "one byte added at", len);
    }
}

/* The status a changed byte at offset `at` must give: the magic, the version
 * and the two length fields are read before the checksum. */
static int flip_status_ok(size_t at, mcs_status st)
{
    if (at < 8u)
        return st == MCS_ERR_MAGIC;
    if (at < 10u)
        return st == MCS_ERR_VERSION;
    if ((at >= 12u && at < 16u) || (at >= 24u && at < 32u))
        return st == MCS_ERR_FORMAT || st == MCS_ERR_TRUNCATED;
    return st == MCS_ERR_CHECKSUM;
}

static void test_every_changed_byte_is_refused(void)
{
    static const uint8_t flips[] = {0x01u, 0x02u, 0x04u, 0x08u, 0x10u, 0x20u, 0x40u, 0x80u, 0xffu};
    io_fill(&set_a, 6u, 11u, 6u); /* small records: every byte, nine ways */
    dirty_destinations();
    for (size_t i = 0; i < IO_NKINDS; ++i) {
        const io_kind_ops *o = &io_kinds[i];
        void *dst = io_obj(&set_dst, o);
        const void *before = io_obj(&set_before, o);
        size_t len = save_a(o, rec);
        for (size_t at = 0; at < len; ++at) {
            for (size_t f = 0; f < sizeof flips; ++f) {
                rec[at] ^= flips[f];
                mcs_status st = o->load(dst, len, rec);
                rec[at] ^= flips[f];
                if (!flip_status_ok(at, st) || memcmp(dst, before, o->obj_size) != 0) {
                    char msg[160];
                    (void)snprintf(msg, sizeof msg, "%s: byte %zu ^ 0x%02x gave %s", o->name, at,
                                   flips[f], mcs_status_str(st));
                    TEST_FAIL_MESSAGE(msg);
                }
            }
        }
        TEST_ASSERT_EQUAL_INT(MCS_OK, o->load(dst, len, rec)); /* restored: loads */
        memcpy(dst, before, o->obj_size);
    }
}

/* ---------------- hand-built headers with a valid CRC ---------------- */

#define SP16 IO_SPECTRUM_VALUES(16u)

static void test_wrong_version_kind_and_shape_are_refused(void)
{
    const uint64_t sixteen = 16u, two[2] = {16u, 1u};
    const io_kind_ops *sp = &io_kinds[0];
    dirty_destinations();
    /* 1 and 2 are read (2: with a provenance block, test_io_provenance.c). */
    static const uint32_t versions[] = {0u, 3u, 0xffffu};
    for (size_t v = 0; v < 3u; ++v) {
        size_t len = io_build(rec, versions[v], 1u, 1u, &sixteen, 0u, SP16, NULL);
        refused(sp, MCS_ERR_VERSION, len, rec, "version", versions[v]);
    }
    /* A valid spectrum record is no other kind; unknown kinds are no kind. */
    size_t len = io_build(rec, 1u, MCS_IO_KIND_SPECTRUM, 1u, &sixteen, 0u, SP16, NULL);
    TEST_ASSERT_EQUAL_INT(MCS_OK, sp->load(io_obj(&set_a, sp), len, rec));
    for (size_t i = 1; i < IO_NKINDS; ++i)
        refused(&io_kinds[i], MCS_ERR_KIND, len, rec, "spectrum record as kind", i + 1u);
    static const uint32_t unknown[] = {0u, IO_NKINDS + 1u, 0xffffu};
    for (size_t u = 0; u < 3u; ++u) {
        len = io_build(rec, 1u, unknown[u], 1u, &sixteen, 0u, SP16, NULL);
        refused(sp, MCS_ERR_KIND, len, rec, "kind", unknown[u]);
    }
    len = io_build(rec, 1u, 1u, 2u, two, 0u, SP16, NULL);
    refused(sp, MCS_ERR_FORMAT, len, rec, "two shape words", 2u);
    len = io_build(rec, 1u, 1u, 0u, NULL, 0u, SP16, NULL);
    refused(sp, MCS_ERR_FORMAT, len, rec, "no shape word", 0u);
    len = io_build(rec, 1u, 1u, 1u, &sixteen, 0u, SP16 + 1u, NULL);
    refused(sp, MCS_ERR_FORMAT, len, rec, "one value too many", SP16 + 1u);
    len = io_build(rec, 1u, 1u, 1u, &sixteen, 0u, SP16 - 1u, NULL);
    refused(sp, MCS_ERR_FORMAT, len, rec, "one value too few", SP16 - 1u);
    len = io_build(rec, 1u, 4u, 1u, &sixteen, 0u, 4u, NULL);
    refused(&io_kinds[3], MCS_ERR_FORMAT, len, rec, "welford with a shape", 1u);
    len = io_build(rec, 1u, 7u, 1u, &sixteen, 0u, 5u * 16u * 9u, NULL);
    refused(&io_kinds[6], MCS_ERR_FORMAT, len, rec, "spectrum2d with one side", 1u);
    static const uint64_t nine[9] = {16u, 1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u};
    len = io_build(rec, 1u, 1u, 9u, nine, 0u, SP16, NULL);
    refused(sp, MCS_ERR_FORMAT, len, rec, "nine shape words", 9u);
}

/* A zero record of kind o with shape, and the status it must give. */
static void shape_case(size_t kind_index, const uint64_t *shape, uint64_t np, mcs_status want)
{
    const io_kind_ops *o = &io_kinds[kind_index];
    size_t len = io_build(rec, 1u, o->kind, (uint32_t)o->shape_len, shape, 0u, np, NULL);
    if (want == MCS_OK)
        TEST_ASSERT_EQUAL_INT(MCS_OK, o->load(io_obj(&set_a, o), len, rec));
    else
        refused(o, want, len, rec, "shape word", (size_t)shape[0]);
}

static void test_sizes_above_this_builds_capacities_are_refused(void)
{
    const uint64_t n = MCS_MAX_N, c = MCS_MAX_COV_N, zero = 0u;
    dirty_destinations();
    for (uint64_t d = 0; d < 2u; ++d) { /* d = 0: the largest that fits; 1: one more */
        const mcs_status range = d == 0u ? MCS_OK : MCS_ERR_N_RANGE;
        const uint64_t sn = n + d, cn = c + d;
        shape_case(0u, &sn, IO_SPECTRUM_VALUES(sn), range);
        shape_case(1u, &cn, IO_MOMENT_VALUES(cn), range);
        shape_case(2u, &sn, 2u * sn + 2u * (sn / 2u + 1u) + 2u, range);
    }
    /* The objects over caller memory take shapes up to their caps, which a
     * record of every value would take gigabytes to reach: at the cap the
     * shape passes and the short payload is what is wrong (FORMAT), one past
     * it the shape is (the shape is read first). */
    for (uint64_t d = 0; d < 2u; ++d) {
        const mcs_status freq = d == 0u ? MCS_ERR_FORMAT : MCS_ERR_FREQ_RANGE;
        const mcs_status range = d == 0u ? MCS_ERR_FORMAT : MCS_ERR_N_RANGE;
        const uint64_t p1 = MCS_POINTSET_MAX_FREQ + d, p2 = MCS_POINTSET2D_MAX_FREQ + d;
        const uint64_t side_x[2] = {MCS_SPECTRUM2D_MAX_SIDE + d, 2u};
        const uint64_t side_y[2] = {3u, MCS_SPECTRUM2D_MAX_SIDE + d};
        shape_case(4u, &p1, 5u, freq);
        shape_case(5u, &p2, 5u, freq);
        shape_case(6u, side_x, 5u, range);
        shape_case(6u, side_y, 5u, range);
    }
    const uint64_t zeros[2] = {0u, 4u};
    for (size_t i = 0; i < IO_NKINDS; ++i)
        if (i != 3u)
            shape_case(i, i == 6u ? zeros : &zero, 5u,
                       i == 4u || i == 5u ? MCS_ERR_FREQ_RANGE : MCS_ERR_N_RANGE);
}

/* ---------------- values: non-finite and broken invariants, valid CRC ---------------- */

static void set_value(uint8_t *p, size_t len, size_t shape_len, size_t i, double v)
{
    io_put_f64(p + io_payload_at(shape_len, i), v);
    io_recrc(p, len);
}

static void set_count(uint8_t *p, size_t len, uint64_t count)
{
    io_put_le(p + 16, count, 8u);
    io_recrc(p, len);
}

/* A record whose object does not fit the caller's buffer: MCS_ERR_SPACE
 * after every check of the record itself, nothing written; the size the
 * load asks for is the object's size query, and exactly that much loads. */
static void test_a_buffer_too_small_for_the_record_is_refused_after_its_checks(void)
{
    io_fill(&set_a, 12u, 5u, 12u);
    dirty_destinations();
    static _Alignas(64) unsigned char mem[MCS_POINTSET2D_SIZE(12u)];
    static unsigned char snap[sizeof mem];
    mcs_pointset2d *dst = &set_dst.ps2.acc;
    const mcs_pointset2d before = *dst;
    size_t len = save_a(&io_kinds[5], rec), need = 0u, direct = 0u, size = 0u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_load_size(len, rec, 0u, &need));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_load_size(len, rec, MCS_POINTSET_DIRECT_ONLY, &direct));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_size(12u, 0u, &size));
    TEST_ASSERT_EQUAL_UINT64((uint64_t)size, (uint64_t)need);
    /* equal in a build without the NUFFT (MCS_CONFIG_NUFFT 0, config.h) */
    TEST_ASSERT_TRUE((MCS_CONFIG_NUFFT ? direct < need : direct == need) && need <= sizeof mem);
    memset(mem, 0x5a, sizeof mem);
    memcpy(snap, mem, sizeof mem);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_SPACE, mcs_io_load_pointset2d(dst, 0u, mem, need - 1u, len, rec));
    TEST_ASSERT_EQUAL_MEMORY(&before, dst, sizeof before);
    TEST_ASSERT_EQUAL_MEMORY(snap, mem, sizeof mem);
    /* A record that is wrong says so first, whatever the memory. */
    memcpy(rec2, rec, len);
    set_value(rec2, len, 1u, 0u, -1.0);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_io_load_pointset2d(dst, 0u, mem, 1u, len, rec2));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_io_load_pointset2d(dst, 2u, mem, need, len, rec));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_io_load_pointset2d(dst, 0u, rec, need, len, rec));
    TEST_ASSERT_EQUAL_MEMORY(&before, dst, sizeof before);
    TEST_ASSERT_EQUAL_MEMORY(snap, mem, sizeof mem);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_load_pointset2d(dst, 0u, mem, need, len, rec));
    size_t len2 = 0u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_save_pointset2d(dst, sizeof rec2, rec2, &len2));
    TEST_ASSERT_EQUAL_UINT64((uint64_t)len, (uint64_t)len2);
    TEST_ASSERT_EQUAL_HEX8_ARRAY(rec, rec2, len);
    /* The kinds whose objects hold their own arrays need none. */
    len = save_a(&io_kinds[0], rec);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_load_size(len, rec, 0u, &need));
    TEST_ASSERT_EQUAL_UINT64(0u, (uint64_t)need);
    len = save_a(&io_kinds[6], rec);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_load_size(len, rec, 0u, &need));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_size(set_a.sp2.acc.n_x, set_a.sp2.acc.n_y, &size));
    TEST_ASSERT_EQUAL_UINT64((uint64_t)size, (uint64_t)need);
    const uint64_t big = MCS_POINTSET_MAX_FREQ + 1u;
    len = io_build(rec, 1u, MCS_IO_KIND_POINTSET, 1u, &big, 0u, 5u, NULL);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE, mcs_io_load_size(len, rec, 0u, &need));
    rec[len - 1u] ^= 1u;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_CHECKSUM, mcs_io_load_size(len, rec, 0u, &need));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_io_load_size(len, NULL, 0u, &need));
}

static void test_non_finite_values_are_refused(void)
{
    const double bad[3] = {NAN, INFINITY, -INFINITY};
    io_fill(&set_a, 14u, 11u, 7u);
    dirty_destinations();
    for (size_t i = 0; i < IO_NKINDS; ++i) {
        const io_kind_ops *o = &io_kinds[i];
        const size_t len = save_a(o, rec);
        const size_t np = (size_t)io_get_le(rec + 24, 8u);
        const size_t at[3] = {0u, np / 2u, np - 1u};
        for (size_t a = 0; a < 3u; ++a) {
            for (size_t b = 0; b < 3u; ++b) {
                memcpy(rec2, rec, len);
                set_value(rec2, len, o->shape_len, at[a], bad[b]);
                refused(o, MCS_ERR_NOT_FINITE, len, rec2, "non-finite value", at[a]);
            }
        }
        /* Non-finite outranks a broken invariant elsewhere. */
        memcpy(rec2, rec, len);
        io_put_f64(rec2 + io_payload_at(o->shape_len, np - 1u), -1.0);
        set_value(rec2, len, o->shape_len, 0u, NAN);
        refused(o, MCS_ERR_NOT_FINITE, len, rec2, "NaN and a negative", 0u);
    }
}

/* Value i of the saved record of kind o (in rec, len bytes) set to v: want. */
static void expect_value(size_t kind_index, size_t len, size_t i, double v, mcs_status want)
{
    const io_kind_ops *o = &io_kinds[kind_index];
    memcpy(rec2, rec, len);
    set_value(rec2, len, o->shape_len, i, v);
    if (want == MCS_OK)
        TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_OK, o->load(io_obj(&set_a, o), len, rec2), o->name);
    else
        refused(o, want, len, rec2, "edited value", i);
}

static void test_broken_invariants_are_refused(void)
{
    const double big = MCS_IO_MAX_MAGNITUDE;
    const size_t h1 = 8u, f2 = 14u;
    const size_t cells2 = (2u * f2 + 1u) * (f2 + 1u);
    io_fill(&set_a, 14u, 40u, 8u); /* closed units and an open batch (AUTO picks PAIR) */
    dirty_destinations();
    TEST_ASSERT_TRUE(set_a.spec.units >= 2u && set_a.spec.open_count > 0u);
    size_t len = save_a(&io_kinds[0], rec);
    const size_t h0 = 3u; /* units, open_count, open_work come first */
    expect_value(0u, len, h0 + 2u * h1 + 3u, -1.0, MCS_ERR_INVARIANT);      /* m2_s */
    expect_value(0u, len, h0 + 3u * h1, -0.5, MCS_ERR_INVARIANT);           /* mean_pow */
    expect_value(0u, len, h0 + 5u * h1 - 1u, -1e-300, MCS_ERR_INVARIANT);   /* m2_pow */
    expect_value(0u, len, h0 + 2u * h1 + 3u, -0.0, MCS_OK);                 /* -0 is 0 */
    expect_value(0u, len, h0 + h1 + 2u, -7.0, MCS_OK); /* a mean of S_k may be negative */
    expect_value(0u, len, h0 + 1u, -MCS_SPECTRUM_MAX_SUM / 4.0, MCS_OK); /* |S_k| <= 2^100 / sqrt(14) */
    expect_value(0u, len, h0 + 1u, -2.0 * big, MCS_ERR_INVARIANT);
    expect_value(0u, len, h0 + 3u * h1 + 1u, 1.0000001 * big, MCS_ERR_INVARIANT);
    expect_value(0u, len, h0 + 5u * h1 + 3u * 14u - 2u, -1.0, MCS_ERR_INVARIANT); /* open_pairs */
    len = save_a(&io_kinds[1], rec);
    /* moment: batch_count, batch_sparse, shift, sum_d, lo_d, two triangles, the batch */
    const size_t mo_batch = 2u + 3u * 14u + 14u * 15u, mo_w = mo_batch + 2u * 14u;
    const double open = (double)set_a.mom.batch_count, sparse = (double)set_a.mom.batch_sparse;
    /* trials as s (sparse, on no bin of the shift) and as d = s - c */
    TEST_ASSERT_TRUE(open >= 30.0 && sparse > 0.0 && sparse < open);
    expect_value(1u, len, 2u + 2u, -1.0, MCS_ERR_INVARIANT);  /* shift: a trial's s */
    expect_value(1u, len, 0u, 40.0, MCS_ERR_INVARIANT);       /* the first trial is no batch's */
    expect_value(1u, len, 0u, 0.0, MCS_ERR_INVARIANT);        /* an empty batch with sums */
    expect_value(1u, len, 1u, open + 1.0, MCS_ERR_INVARIANT); /* more sparse trials than trials */
    expect_value(1u, len, 1u, 0.0, MCS_ERR_INVARIANT);        /* sums of s without s trials */
    expect_value(1u, len, mo_batch + 3u, -1.0, MCS_ERR_INVARIANT); /* batch_s: sums of s */
    expect_value(1u, len, 1u, open, MCS_ERR_INVARIANT); /* batch_d without d trials */
    expect_value(1u, len, mo_w + 5u, 0x1p461, MCS_ERR_INVARIANT);   /* beyond 2^14 trials' */
    expect_value(1u, len, mo_batch + 1u, 0x1p241, MCS_ERR_INVARIANT);
    expect_value(1u, len, 2u + 5u, 0x1p241, MCS_ERR_INVARIANT);     /* a shift no trial gives */
    len = save_a(&io_kinds[2], rec);
    expect_value(2u, len, 2u, -1.0, MCS_ERR_INVARIANT);               /* sum_s */
    expect_value(2u, len, 14u, -1.0, MCS_ERR_INVARIANT);              /* sum_dc */
    /* sum_lag[7] (N/2, halved) a little larger: a sum of lags is not pinned */
    expect_value(2u, len, 2u * 14u + 1u + 7u, set_a.ac.sum_lag[7] + 0.5, MCS_OK);
    len = save_a(&io_kinds[3], rec);
    expect_value(3u, len, 1u, -1.0, MCS_ERR_INVARIANT);  /* m2 */
    expect_value(3u, len, 3u, -1.0, MCS_ERR_INVARIANT);  /* m4 */
    expect_value(3u, len, 2u, -5.0, MCS_OK);             /* m3 has either sign */
    expect_value(3u, len, 0u, -5.0, MCS_OK);             /* so has the mean */
    len = save_a(&io_kinds[4], rec);
    expect_value(4u, len, 3u, -0.25, MCS_ERR_INVARIANT);       /* a mean periodogram */
    expect_value(4u, len, 14u + 1u + 3u, -1.0, MCS_ERR_INVARIANT); /* m2 */
    len = save_a(&io_kinds[5], rec);
    expect_value(5u, len, cells2 - 1u, -1.0, MCS_ERR_INVARIANT);       /* mean P */
    expect_value(5u, len, 2u * cells2 + f2, -1.0, MCS_ERR_INVARIANT);  /* a ring's mean */
    len = save_a(&io_kinds[6], rec);
    const size_t cells = set_a.sp2.acc.n_x * (set_a.sp2.acc.n_y / 2u + 1u);
    expect_value(6u, len, 2u * cells, -1.0, MCS_ERR_INVARIANT);  /* m2_s */
    expect_value(6u, len, cells, -3.0, MCS_OK);                  /* mean_im */
}

/* Value i of the saved record in rec (kind o). */
static double rec_value(const io_kind_ops *o, size_t i)
{
    const uint64_t bits = io_get_le(rec + io_payload_at(o->shape_len, i), 8u);
    double v;
    memcpy(&v, &bits, sizeof v);
    return v;
}

/* Issue 22 item 3: moment and autocorr records that load and then lie. Each
 * edit keeps every value finite, each rule of docs/format.md's value list
 * and the checksum, and breaks one of the invariants the sums of trials
 * keep (docs/format.md, kinds 2 and 3): each is refused, the destination
 * byte-identical. The two reported: an open-batch diagonal entry of 0.5 set
 * to 0 loaded and read Var[I] = -0.00444; a lag-0 sum of -1 loaded and read
 * powers 1.25, -0.75, -0.75, -0.75; and a compensation of 1e-300 on a zero
 * sum loaded, merged into a valid object and left one save refused. */
static void test_moment_and_autocorr_records_no_trials_give_are_refused(void)
{
    enum { N = 14 };
    const io_kind_ops *mo = &io_kinds[1], *ac = &io_kinds[2];
    const mcs_moment *m = &set_a.mom;
    const size_t tri = N * (N + 1u) / 2u, at_d = 2u + N, at_lo = 2u + 2u * N;
    const size_t at_dd = 2u + 3u * N, at_bs = at_dd + 2u * tri, at_w = at_bs + 2u * N;
    /* a few trials, so that a batch diagonal entry is 0.5 (half of one
     * trial's d^2 or s^2 = 1), as in the report */
    size_t half = N, trials = 8u;
    for (; trials < 40u && half == N; ++trials) {
        io_fill(&set_a, N, trials, 8u);
        for (size_t b = 0; b < N && half == N; ++b)
            if (m->batch_w[b * N + b] == 0.5 && m->sum_dd[b * N + b] > 0.0 &&
                m->sum_dd[(b + 1u) % N * N + (b + 1u) % N] > 0.0 && b + 1u < N)
                half = b;
    }
    TEST_ASSERT_TRUE(half < N);
    dirty_destinations();
    size_t len = save_a(mo, rec);
    expect_value(1u, len, at_w + half * N + half, 0.0, MCS_ERR_INVARIANT);
    expect_value(1u, len, at_w + half * N + half, -0.5, MCS_ERR_INVARIANT); /* negative */
    expect_value(1u, len, at_w + half * N + half, 0.5, MCS_OK);            /* as saved */
    /* a closed diagonal (a sum of squares) below 0, and an entry beyond
     * Cauchy-Schwarz: |D_mn| <= sqrt(D_m D_n) */
    const size_t row = half;
    const size_t diag = at_dd + row * N - row * (row - 1u) / 2u; /* (row, row) upper */
    expect_value(1u, len, diag, -1.0, MCS_ERR_INVARIANT);
    const double dm = m->sum_dd[row * N + row], dn = m->sum_dd[(row + 1u) * N + row + 1u];
    expect_value(1u, len, diag + 1u, 4.0 * sqrt(dm * dn) + 1.0, MCS_ERR_INVARIANT);
    expect_value(1u, len, diag + 1u, rec_value(mo, diag + 1u), MCS_OK);
    /* a first sum past its variance (F^2 <= T D) or making a sum of s < 0 */
    const double t = (double)m->count;
    expect_value(1u, len, at_d + row, 10.0 * sqrt(t * (dm + 1.0)) + 10.0, MCS_ERR_INVARIANT);
    expect_value(1u, len, at_d + row, -10.0 * sqrt(t * (dm + 1.0)) - 10.0, MCS_ERR_INVARIANT);
    /* compensations: within an ulp of their sum, 0 on a zero sum */
    const double f = m->sum_d[row];
    expect_value(1u, len, at_lo + row, 0.5 * DBL_EPSILON * f, MCS_OK);
    expect_value(1u, len, at_lo + row, 4.0 * DBL_EPSILON * f + 1e-300, MCS_ERR_INVARIANT);
    size_t zero = tri;
    for (size_t i = 0; i < tri && zero == tri; ++i)
        if (rec_value(mo, at_dd + i) == 0.0)
            zero = i;
    if (zero < tri)
        expect_value(1u, len, at_dd + tri + zero, 1e-300, MCS_ERR_INVARIANT);
    /* batch_s (sums of trials added as s) on a bin of the shift */
    size_t bin_s = N;
    for (size_t b = 0; b < N && bin_s == N; ++b)
        if (m->batch_s[b] > 0.0 && m->shift[b] == 0.0)
            bin_s = b;
    TEST_ASSERT_TRUE(bin_s < N);
    expect_value(1u, len, 2u + bin_s, 1.0, MCS_ERR_INVARIANT);

    io_fill(&set_a, N, 40u, 8u);
    dirty_destinations();
    len = save_a(ac, rec);
    const double l0 = set_a.ac.sum_lag[0];
    TEST_ASSERT_TRUE(l0 > 0.0 && set_a.ac.sum_dc == 0.0); /* K = 5 < N: pairs, none centred */
    expect_value(2u, len, 2u * N + 1u, -1.0, MCS_ERR_INVARIANT);          /* lag 0 */
    expect_value(2u, len, 2u * N + 1u + 3u, 2.0 * l0 * 1.001 + 1.0, MCS_ERR_INVARIANT);
    expect_value(2u, len, 2u * N + 1u + 7u, l0 * 1.001 + 1.0, MCS_ERR_INVARIANT); /* N/2 */
    expect_value(2u, len, 2u * N + 1u + 3u, -2.0 * l0 * 1.001 - 1.0, MCS_ERR_INVARIANT);
    expect_value(2u, len, 2u * N + 2u * (N / 2u + 1u) + 1u, 1e-300, MCS_ERR_INVARIANT); /* lo_dc */
    expect_value(2u, len, N + 1u, 4.0 * DBL_EPSILON * set_a.ac.sum_s[0], MCS_ERR_INVARIANT);
    expect_value(2u, len, N + 1u, 0.5 * DBL_EPSILON * set_a.ac.sum_s[0], MCS_OK); /* lo_s[0] */
    /* every trial weighs 5: T sum S_t^2 = (sum S_t)^2, so more total weight
     * is a negative variance of S_0, and sum_dc > (sum S_t)^2 / N too */
    expect_value(2u, len, 0u, set_a.ac.sum_s[0] + 1.0, MCS_ERR_INVARIANT);
    expect_value(2u, len, N, 200.0 * 200.0 / N * 1.01, MCS_ERR_INVARIANT);
}

/* Sums that pass every check of one bin or two but whose spectrum is
 * negative beyond rounding: the loader computes the powers itself and
 * refuses them, so that every record it loads reads out (a power read-out
 * refuses what no trials give). Autocorr, N = 4, two trials of s = (1, 0,
 * 0, 0): lag sums 1, 0, 0, edited to 1, 1.5, -0.75 (<|S_2|^2> = -5/16);
 * moment, N = 3, five trials of s = 0, its sums of d d^T edited to [[1, -1,
 * -1], [-1, 1, -1], [-1, -1, 1]] (<|S_0|^2> = -1/5). */
static void edit_record(const io_kind_ops *o, size_t len, size_t count, const size_t *at,
                        const double *v)
{
    memcpy(rec2, rec, len);
    for (size_t j = 0; j < count; ++j)
        io_put_f64(rec2 + io_payload_at(o->shape_len, at[j]), v[j]);
    io_recrc(rec2, len);
}

static void test_records_whose_spectrum_is_negative_are_refused(void)
{
    static mcs_autocorr ac;
    static mcs_moment mom;
    const size_t one[1] = {0u};
    const double w1[1] = {1.0}, w0[2] = {0.0, 0.0};
    const size_t two[2] = {0u, 1u};
    dirty_destinations();
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_init(&ac, 4u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_add_bins(&ac, 1u, one, w1));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_add_bins(&ac, 1u, one, w1));
    size_t len = io_save(&io_kinds[2], &ac, rec);
    const size_t lags[2] = {2u * 4u + 1u + 1u, 2u * 4u + 1u + 2u};
    const double bad_lags[2] = {1.5, -0.75}, ok_lags[2] = {0.25, -0.25};
    edit_record(&io_kinds[2], len, 2u, lags, bad_lags);
    refused(&io_kinds[2], MCS_ERR_INVARIANT, len, rec2, "autocorr spectrum < 0", 0u);
    edit_record(&io_kinds[2], len, 2u, lags, ok_lags); /* powers 1/4, 5/16, 1/8, 5/16 */
    TEST_ASSERT_EQUAL_INT(MCS_OK, io_kinds[2].load(io_obj(&set_a, &io_kinds[2]), len, rec2));
    double power[4];
    mcs_dft plan;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, 4u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_power(&set_a.ac, &plan, 4u, power));

    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&mom, 3u));
    for (int t = 0; t < 5; ++t)
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_add_bins(&mom, 2u, two, w0));
    len = io_save(&io_kinds[1], &mom, rec);
    /* sum_dd's upper triangle, row by row: (0,0) (0,1) (0,2) (1,1) (1,2) (2,2) */
    const size_t dd[6] = {2u + 9u, 2u + 10u, 2u + 11u, 2u + 12u, 2u + 13u, 2u + 14u};
    const double bad_dd[6] = {1.0, -1.0, -1.0, 1.0, -1.0, 1.0};
    const double ok_dd[6] = {1.0, -0.5, -0.5, 1.0, -0.5, 1.0}; /* psd: 3 (1 - 1) = 0 */
    edit_record(&io_kinds[1], len, 6u, dd, bad_dd);
    refused(&io_kinds[1], MCS_ERR_INVARIANT, len, rec2, "moment spectrum < 0", 0u);
    edit_record(&io_kinds[1], len, 6u, dd, ok_dd);
    TEST_ASSERT_EQUAL_INT(MCS_OK, io_kinds[1].load(io_obj(&set_a, &io_kinds[1]), len, rec2));
    for (size_t k = 0; k < 3u; ++k) {
        double p = -1.0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_power(&set_a.mom, k, &p));
        TEST_ASSERT_TRUE(p >= 0.0);
    }
}

/* fuzz_load: sums whose powers are all >= 0 but a variance is not (a large
 * mean hides it), so the record loaded and its covariance read-out refused
 * it. N = 3, five trials of s = (2, 2, 0) (the shift), sums of d d^T edited
 * to the ok matrix above and the sum of d on bin 0 to 1: every bin's
 * variance is >= 0 (1/5 - 1/25), but Cov(S_0, S_0) = (0 - 1/25) / 3 while
 * <|S_0|^2> is about 16/3. */
static void test_a_moment_record_whose_variance_is_negative_is_refused(void)
{
    static mcs_moment mom;
    const size_t two[2] = {0u, 1u};
    const double w2[2] = {2.0, 2.0};
    dirty_destinations();
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&mom, 3u));
    for (int t = 0; t < 5; ++t)
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_add_bins(&mom, 2u, two, w2));
    const size_t len = io_save(&io_kinds[1], &mom, rec);
    const size_t at[7] = {2u + 3u, 2u + 9u, 2u + 10u, 2u + 11u, 2u + 12u, 2u + 13u, 2u + 14u};
    const double v[7] = {1.0, 1.0, -0.5, -0.5, 1.0, -0.5, 1.0};
    edit_record(&io_kinds[1], len, 7u, at, v);
    refused(&io_kinds[1], MCS_ERR_INVARIANT, len, rec2, "moment variance < 0", 0u);
}

/* The spectrum's counts and open batch (docs/format.md, kind 1). */
static void test_spectrum_units_and_open_batch_that_do_not_fit_are_refused(void)
{
    const size_t h1 = 8u, sums = 3u + 5u * h1, m2 = 3u + 2u * h1;
    io_fill(&set_a, 14u, 40u, 8u);
    dirty_destinations();
    const double units = (double)set_a.spec.units, open = (double)set_a.spec.open_count;
    TEST_ASSERT_TRUE(units >= 2.0 && open > 0.0);
    size_t len = save_a(&io_kinds[0], rec);
    expect_value(0u, len, 0u, units + 0.5, MCS_ERR_INVARIANT);          /* not whole */
    expect_value(0u, len, 0u, 40.0 - open + 1.0, MCS_ERR_INVARIANT);   /* more units than trials */
    expect_value(0u, len, 0u, 40.0 - open, MCS_OK);                    /* one trial per unit */
    expect_value(0u, len, 1u, 41.0, MCS_ERR_INVARIANT);                /* open above count */
    expect_value(0u, len, 2u, open - 1.0, MCS_ERR_INVARIANT);          /* < 1 pair a trial */
    /* Without units the closed statistics are 0, with 1 unit the M2s. */
    memcpy(rec2, rec, len);
    set_value(rec2, len, 1u, 0u, 0.0);
    refused(&io_kinds[0], MCS_ERR_INVARIANT, len, rec2, "no units, closed data", 0u);
    memcpy(rec2, rec, len);
    set_value(rec2, len, 1u, 0u, 1.0);
    refused(&io_kinds[0], MCS_ERR_INVARIANT, len, rec2, "one unit with spread", m2);
    /* Without an open batch its work and sums are 0. */
    memcpy(rec2, rec, len);
    set_value(rec2, len, 1u, 0u, 40.0);
    set_value(rec2, len, 1u, 1u, 0.0);
    refused(&io_kinds[0], MCS_ERR_INVARIANT, len, rec2, "no open batch, open work", 2u);
    set_value(rec2, len, 1u, 2u, 0.0);
    refused(&io_kinds[0], MCS_ERR_INVARIANT, len, rec2, "no open batch, open sums", sums);
}

/* Beyond what the add limit allows (docs/format.md, kind 1): no trial has
 * |S_k| above L = MCS_SPECTRUM_MAX_SUM / sqrt(N), no open sum is above
 * open_count MCS_SPECTRUM_MAX_SUM. fuzz_load: a mean of 5.2e120 beside an M2
 * of 0.15 loaded, merged into an M2 of 3.5e242 and save refused it. */
static void test_spectrum_values_past_the_add_limit_are_refused(void)
{
    const size_t h1 = 8u, mean_im = 3u + h1, m2_s = 3u + 2u * h1, sums = 3u + 5u * h1;
    io_fill(&set_a, 14u, 40u, 8u);
    dirty_destinations();
    const double l = MCS_SPECTRUM_MAX_SUM / sqrt(14.0), open = (double)set_a.spec.open_count;
    size_t len = save_a(&io_kinds[0], rec);
    expect_value(0u, len, mean_im + 3u, 0.5 * l, MCS_OK);
    expect_value(0u, len, mean_im + 3u, 2.0 * l, MCS_ERR_INVARIANT);
    expect_value(0u, len, mean_im + 3u, 5.2e120, MCS_ERR_INVARIANT);
    expect_value(0u, len, m2_s + 3u, 40.0 * l * l, MCS_OK);
    expect_value(0u, len, m2_s + 3u, 200.0 * l * l, MCS_ERR_INVARIANT);
    expect_value(0u, len, sums + 2u, 0.5 * open * MCS_SPECTRUM_MAX_SUM, MCS_OK);
    expect_value(0u, len, sums + 2u, 2.0 * open * MCS_SPECTRUM_MAX_SUM, MCS_ERR_INVARIANT);
}

/* fuzz_load (issue 22): an autocorr record of N = 7 and 4.8e15 trials whose
 * lag sums are a few DBL_TRUE_MIN loaded, and its power read-out refused it:
 * <A(0)> = 2 L_0 / T underflowed to 0, so the rounding bound was 0, and the
 * transform's underflow left powers of -4.9e-324. The bound now has an
 * absolute term for underflow; every power reads >= 0. */
static const uint8_t tiny_lags_record[] = {
    0x89, 0x4d, 0x43, 0x53, 0x0d, 0x0a, 0x1a, 0x0a, 0x01, 0x00, 0x03, 0x00,
    0x01, 0x00, 0x00, 0x00, 0x05, 0x00, 0x00, 0x00, 0x00, 0xff, 0x10, 0x00,
    0x18, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x07, 0x00, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x00, 0xfe, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x00, 0x04, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0xf0, 0x3f, 0x09, 0x00, 0xff, 0xff, 0x55, 0x51, 0xc7, 0x33, 0x54, 0x0c,
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x20, 0x00, 0x00, 0x00, 0x00, 0x27,
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x00, 0x71, 0xd3, 0x34, 0x70,
};

/* A fuzz record as it was found, copied into rec2 with its CRC rewritten
 * (io_recrc): its length. */
static size_t fuzz_record(const uint8_t *found, size_t len)
{
    memcpy(rec2, found, len);
    io_recrc(rec2, len);
    return len;
}

static void test_an_autocorr_record_of_subnormal_lags_reads_out(void)
{
    static mcs_autocorr ac;
    const size_t len = fuzz_record(tiny_lags_record, sizeof tiny_lags_record);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_load_autocorr(&ac, len, rec2));
    double power[7];
    mcs_dft plan;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, 7u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_power(&ac, &plan, 7u, power));
    for (size_t k = 0; k < 7u; ++k)
        TEST_ASSERT_TRUE(power[k] >= 0.0);
}

/* fuzz_load (issue 22): a moment record of N = 2 and 2^52 + 1 trials whose
 * sums are a few DBL_TRUE_MIN loaded, and its covariance read-out refused
 * it: every relative bound underflowed to 0 and the variance at k = 1 read
 * -4.9e-324. The bounds now have an absolute term for underflow. */
static const uint8_t tiny_moment_record[] = {
    0x89, 0x4d, 0x43, 0x53, 0x0d, 0x0a, 0x1a, 0x0a, 0x01, 0x00, 0x02, 0x00,
    0x01, 0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x00, 0x00, 0x10, 0x00,
    0x16, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x00, 0x00, 0xf0, 0x3f, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x40,
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x09, 0x00,
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,
    0x00, 0xaa, 0x0f, 0x81,
};

static void test_a_moment_record_of_subnormal_sums_reads_out(void)
{
    static mcs_moment mo;
    static double cre[4], cim[4];
    const size_t len = fuzz_record(tiny_moment_record, sizeof tiny_moment_record);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_load_moment(&mo, len, rec2));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_covariance_matrix(&mo, 2u, cre, cim));
    TEST_ASSERT_TRUE(cre[0] >= 0.0 && cre[3] >= 0.0);
}

/* fuzz_load: an empty spectrum whose units (or open count) read -0.0 loaded
 * as 0 and saved back as +0.0, other bytes. A count is a whole number written
 * as +0.0 or more; -0.0 is refused, as a fraction is. */
static void test_a_count_written_as_minus_zero_is_refused(void)
{
    static mcs_spectrum empty;
    dirty_destinations();
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&empty, 14u));
    size_t len = 0u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_save_spectrum(&empty, sizeof rec, rec, &len));
    expect_value(0u, len, 0u, 0.0, MCS_OK);
    expect_value(0u, len, 0u, -0.0, MCS_ERR_INVARIANT); /* units */
    expect_value(0u, len, 1u, -0.0, MCS_ERR_INVARIANT); /* open_count */
}

static void test_counts_that_do_not_fit_the_data_are_refused(void)
{
    io_fill(&set_a, 14u, 11u, 9u);
    dirty_destinations();
    for (size_t i = 0; i < IO_NKINDS; ++i) {
        const io_kind_ops *o = &io_kinds[i];
        const size_t len = save_a(o, rec);
        memcpy(rec2, rec, len);
        set_count(rec2, len, 0u);
        refused(o, MCS_ERR_INVARIANT, len, rec2, "zero count with data", 0u);
        set_count(rec2, len, MCS_IO_MAX_COUNT + 1u);
        refused(o, MCS_ERR_INVARIANT, len, rec2, "count above 2^53", 0u);
        set_count(rec2, len, UINT64_MAX);
        refused(o, MCS_ERR_INVARIANT, len, rec2, "count 2^64 - 1", 0u);
        set_count(rec2, len, MCS_IO_MAX_COUNT);
        if (o->kind == MCS_IO_KIND_SPECTRUM) /* the closed units take the new trials */
            set_value(rec2, len, 1u, 0u,
                      (double)(MCS_IO_MAX_COUNT - set_a.spec.open_count));
        TEST_ASSERT_EQUAL_INT(MCS_OK, o->load(io_obj(&set_a, o), len, rec2));
        if (o->kind == MCS_IO_KIND_AUTOCORR)
            continue; /* its sums are of s: any count >= 1 fits */
        /* One trial has no spread: M2 != 0 cannot be. */
        set_count(rec2, len, 1u);
        refused(o, MCS_ERR_INVARIANT, len, rec2, "one trial with spread", 1u);
    }
    size_t len = save_a(&io_kinds[3], rec);
    set_count(rec, len, 1u);
    set_value(rec, len, 0u, 1u, 0.0);
    set_value(rec, len, 0u, 3u, 0.0);
    refused(&io_kinds[3], MCS_ERR_INVARIANT, len, rec, "one value with m3", 2u);
    set_value(rec, len, 0u, 2u, 0.0);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_load_welford(&set_a.wf, len, rec));
}

/* fuzz_load: a welford record of 20 values with m3 = -1.3e118 (above what
 * values up to MCS_WELFORD_MAX_ABS give, (count - 1) 2^336) loaded, and then
 * every read-out refused it. The loader now applies welford's own check. */
static void test_a_welford_record_its_read_outs_would_refuse_is_refused(void)
{
    size_t len = save_a(&io_kinds[3], rec);
    set_count(rec, len, 20u);
    set_value(rec, len, 0u, 0u, 0.25);
    set_value(rec, len, 0u, 1u, 2.0);
    set_value(rec, len, 0u, 3u, 8.0);
    set_value(rec, len, 0u, 2u, -1.3e118);
    refused(&io_kinds[3], MCS_ERR_INVARIANT, len, rec, "m3 beyond its bound", 2u);
    set_value(rec, len, 0u, 2u, -1.0);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_load_welford(&set_a.wf, len, rec));
    double v = 0.0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_mean(&set_a.wf, &v));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_a_welford_record_its_read_outs_would_refuse_is_refused);
    RUN_TEST(test_every_truncation_and_an_extra_byte_are_refused);
    RUN_TEST(test_every_changed_byte_is_refused);
    RUN_TEST(test_wrong_version_kind_and_shape_are_refused);
    RUN_TEST(test_sizes_above_this_builds_capacities_are_refused);
    RUN_TEST(test_a_buffer_too_small_for_the_record_is_refused_after_its_checks);
    RUN_TEST(test_non_finite_values_are_refused);
    RUN_TEST(test_broken_invariants_are_refused);
    RUN_TEST(test_moment_and_autocorr_records_no_trials_give_are_refused);
    RUN_TEST(test_records_whose_spectrum_is_negative_are_refused);
    RUN_TEST(test_a_moment_record_whose_variance_is_negative_is_refused);
    RUN_TEST(test_an_autocorr_record_of_subnormal_lags_reads_out);
    RUN_TEST(test_a_moment_record_of_subnormal_sums_reads_out);
    RUN_TEST(test_spectrum_units_and_open_batch_that_do_not_fit_are_refused);
    RUN_TEST(test_spectrum_values_past_the_add_limit_are_refused);
    RUN_TEST(test_counts_that_do_not_fit_the_data_are_refused);
    RUN_TEST(test_a_count_written_as_minus_zero_is_refused);
    return UNITY_END();
}
