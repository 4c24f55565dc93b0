/* Provenance (docs/format.md, "Provenance"): version 2 records, the block's
 * bytes against an independent writer (io_fixtures.c), the round trip, the
 * rules on both the struct and the bytes (every truncation and changed byte
 * refused, nothing changed on error), and the union of merges: one value
 * for every order and tree, refusing the same trials twice, another run and
 * a union past the caps. */
#include <stdio.h>
#include <string.h>

#include "io_fixtures.h"
#include "mcspec.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

static io_set set_a, set_dst, set_before;
static uint8_t rec[IO_REC_MAX + MCS_IO_PROV_MAX_BYTES + 8u];
static uint8_t plain[IO_REC_MAX + 8u], want[IO_REC_MAX + MCS_IO_PROV_MAX_BYTES + 8u];
static mcs_io_provenance prov, back, other, before;

#define ASSERT_SIZE(w, got) TEST_ASSERT_EQUAL_UINT64((uint64_t)(w), (uint64_t)(got))

/* The provenance of streams [first, end) of a stratified run (P streams,
 * T trials, seed), N = 16, K = 5, with or without an importance function. */
static void pattern(mcs_io_provenance *p, uint64_t seed, uint64_t first, uint64_t end,
                    uint64_t streams)
{
    memset(p, 0, sizeof *p);
    p->source = MCS_IO_SOURCE_PATTERN;
    p->dim = 1u;
    (void)snprintf(p->pattern, sizeof p->pattern, "stratified");
    p->n = 16u;
    p->k = 5u;
    p->streams = streams;
    p->trials = 10u * streams + 3u;
    p->nranges = 1u;
    p->range[0] = (mcs_io_streams){seed, first, end};
}

static void points(mcs_io_provenance *p, uint32_t crc, const char *name)
{
    memset(p, 0, sizeof *p);
    p->source = MCS_IO_SOURCE_POINTS;
    p->ninputs = 1u;
    p->input[0].crc = crc;
    p->input[0].bytes = 1000u + crc;
    (void)snprintf(p->input[0].name, sizeof p->input[0].name, "%s", name);
}

/* A spectrum record (N = 16) in rec; its size. */
static size_t spectrum_record(void)
{
    io_fill(&set_a, 16u, 7u, 3u);
    size_t len = io_save(&io_kinds[0], &set_a.spec, rec);
    memcpy(plain, rec, len);
    return len;
}

static void expect_set(const mcs_io_provenance *p, size_t *len, mcs_status want_st)
{
    const size_t len0 = *len;
    memcpy(want, rec, sizeof rec);
    TEST_ASSERT_EQUAL_INT(want_st, mcs_io_set_provenance(p, sizeof rec, rec, len));
    if (want_st != MCS_OK) {
        ASSERT_SIZE(len0, *len);
        TEST_ASSERT_EQUAL_MEMORY(want, rec, sizeof rec);
    }
}

/* ---------------- version 2, the round trip ---------------- */

static void test_a_saved_record_is_version_1_without_provenance(void)
{
    size_t len = spectrum_record();
    mcs_io_info info;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_peek(len, rec, &info));
    TEST_ASSERT_EQUAL_UINT32(1u, info.version);
    memset(&prov, 0xa5, sizeof prov);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_peek_provenance(len, rec, &prov));
    memset(&back, 0, sizeof back);
    TEST_ASSERT_EQUAL_MEMORY(&back, &prov, sizeof prov); /* source NONE, all 0 */
    size_t bytes = 1u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_provenance_bytes(&prov, &bytes));
    ASSERT_SIZE(0u, bytes);
}

static void test_a_pattern_provenance_round_trips_and_the_record_still_loads(void)
{
    size_t len = spectrum_record();
    const size_t len0 = len;
    pattern(&prov, 9u, 2u, 3u, 4u);
    prov.importance = 1u;
    prov.importance_crc = 0xdeadbeefu;
    size_t bytes = 0u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_provenance_bytes(&prov, &bytes));
    ASSERT_SIZE(64u + 24u, bytes);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_set_provenance(&prov, sizeof rec, rec, &len));
    ASSERT_SIZE(len0 + bytes, len);
    mcs_io_info info;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_peek(len, rec, &info));
    TEST_ASSERT_EQUAL_UINT32(2u, info.version);
    ASSERT_SIZE(len, info.size);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_peek_provenance(len, rec, &back));
    TEST_ASSERT_EQUAL_MEMORY(&prov, &back, sizeof prov);
    /* The statistics load as from the plain record, bit for bit. */
    static mcs_spectrum a, b;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_load_spectrum(&a, len, rec));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_load_spectrum(&b, len0, plain));
    TEST_ASSERT_EQUAL_MEMORY(&b, &a, sizeof a);
    /* No provenance again: the saved bytes. */
    memset(&other, 0, sizeof other);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_set_provenance(&other, sizeof rec, rec, &len));
    ASSERT_SIZE(len0, len);
    TEST_ASSERT_EQUAL_MEMORY(plain, rec, len0);
}

static void test_every_kind_takes_a_provenance_and_loads_as_before(void)
{
    static uint8_t buf[IO_REC_MAX + MCS_IO_PROV_MAX_BYTES];
    io_fill(&set_a, 12u, 5u, 8u);
    io_fill(&set_dst, 9u, 2u, 1u);
    memcpy(&set_before, &set_dst, sizeof set_dst);
    points(&prov, 0x1234u, "sets.txt");
    for (size_t i = 0; i < IO_NKINDS; ++i) {
        const io_kind_ops *o = &io_kinds[i];
        size_t len = io_save(o, io_obj(&set_a, o), buf);
        TEST_ASSERT_EQUAL_INT(MCS_OK, o->load(io_obj(&set_before, o), len, buf));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_set_provenance(&prov, sizeof buf, buf, &len));
        TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_OK, o->load(io_obj(&set_dst, o), len, buf), o->name);
        io_assert_same(o, io_obj(&set_before, o), io_obj(&set_dst, o), o->name);
    }
}

static void test_setting_a_provenance_twice_keeps_one_block(void)
{
    size_t len = spectrum_record();
    points(&prov, 7u, "a.txt");
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_set_provenance(&prov, sizeof rec, rec, &len));
    pattern(&prov, 1u, 0u, 1u, 1u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_set_provenance(&prov, sizeof rec, rec, &len));
    size_t plain_len = 0u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_save_spectrum(&set_a.spec, 0u, NULL, &plain_len));
    ASSERT_SIZE(plain_len + 64u + 24u, len);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_peek_provenance(len, rec, &back));
    TEST_ASSERT_EQUAL_MEMORY(&prov, &back, sizeof prov);
}

/* The block by the independent writer: the layout of docs/format.md. */
static void test_the_blocks_are_the_documented_bytes(void)
{
    size_t len = spectrum_record();
    const size_t base = len - 4u;
    pattern(&prov, 0x0102030405060708u, 1u, 3u, 5u);
    prov.importance = 1u;
    prov.importance_crc = 0xa1b2c3d4u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_set_provenance(&prov, sizeof rec, rec, &len));
    memset(want, 0, sizeof want);
    memcpy(want, plain, base);
    io_put_le(want + 8u, 2u, 2u);
    uint8_t *b = want + base;
    io_put_le(b, 88u, 4u);        /* block bytes */
    io_put_le(b + 4u, 1u, 2u);    /* pattern */
    io_put_le(b + 6u, 1u, 2u);    /* one range */
    io_put_le(b + 8u, 1u, 2u);    /* dim */
    io_put_le(b + 10u, 1u, 2u);   /* importance */
    io_put_le(b + 12u, 0xa1b2c3d4u, 4u);
    memcpy(b + 16u, "stratified", 10u);
    io_put_le(b + 32u, 16u, 8u);  /* N */
    io_put_le(b + 40u, 5u, 8u);   /* K */
    io_put_le(b + 48u, 5u, 8u);   /* P */
    io_put_le(b + 56u, 53u, 8u);  /* T */
    io_put_le(b + 64u, 0x0102030405060708u, 8u);
    io_put_le(b + 72u, 1u, 8u);
    io_put_le(b + 80u, 3u, 8u);
    io_put_le(b + 88u, io_ref_crc(want, base + 88u), 4u);
    ASSERT_SIZE(base + 92u, len);
    TEST_ASSERT_EQUAL_HEX8_ARRAY(want, rec, len);

    len = base + 4u;
    memcpy(rec, plain, len);
    points(&prov, 0x11223344u, "dir/pts.txt");
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_set_provenance(&prov, sizeof rec, rec, &len));
    memset(want, 0, sizeof want);
    memcpy(want, plain, base);
    io_put_le(want + 8u, 2u, 2u);
    io_put_le(b, 88u, 4u);
    io_put_le(b + 4u, 2u, 2u);    /* points */
    io_put_le(b + 6u, 1u, 2u);    /* one input */
    io_put_le(b + 8u, 0x11223344u, 4u);
    io_put_le(b + 16u, 1000u + 0x11223344u, 8u);
    memcpy(b + 24u, "dir/pts.txt", 11u);
    io_put_le(b + 88u, io_ref_crc(want, base + 88u), 4u);
    ASSERT_SIZE(base + 92u, len);
    TEST_ASSERT_EQUAL_HEX8_ARRAY(want, rec, len);
}

/* ---------------- the bad path ---------------- */

static void dirty_destinations(void)
{
    io_fill(&set_dst, 12u, 3u, 99u);
    memcpy(&set_before, &set_dst, sizeof set_dst);
}

/* The status a changed byte at `at` of a version 2 record must give: the
 * magic, the version, the header's lengths and the block's length are read
 * before the checksum, everything else is covered by it. */
static int flip_ok(size_t at, size_t block, mcs_status st)
{
    if (at < 8u)
        return st == MCS_ERR_MAGIC;
    if (at < 10u)
        return st == MCS_ERR_VERSION || st == MCS_ERR_FORMAT; /* 2 -> 1: bytes after a v1 record */
    if ((at >= 12u && at < 16u) || (at >= 24u && at < 32u) || (at >= block && at < block + 4u))
        return st == MCS_ERR_FORMAT || st == MCS_ERR_TRUNCATED;
    return st == MCS_ERR_CHECKSUM;
}

static void test_every_truncation_and_changed_byte_of_a_version_2_record_is_refused(void)
{
    static const uint8_t flips[] = {0x01u, 0x03u, 0x10u, 0x80u, 0xffu};
    dirty_destinations();
    io_fill(&set_a, 4u, 3u, 6u);
    const io_kind_ops *o = &io_kinds[0];
    size_t len = io_save(o, &set_a.spec, rec);
    const size_t block = len - 4u;
    pattern(&prov, 5u, 0u, 2u, 3u);
    prov.n = 4u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_set_provenance(&prov, sizeof rec, rec, &len));
    for (size_t cut = 0; cut < len; ++cut) {
        io_expect_refused(o, &set_dst, &set_before, MCS_ERR_TRUNCATED, cut, rec, "cut", cut);
        TEST_ASSERT_EQUAL_INT(MCS_ERR_TRUNCATED, mcs_io_peek_provenance(cut, rec, &back));
    }
    rec[len] = 0u;
    io_expect_refused(o, &set_dst, &set_before, MCS_ERR_FORMAT, len + 1u, rec, "extra byte", len);
    memcpy(&before, &back, sizeof back);
    for (size_t at = 0; at < len; ++at)
        for (size_t f = 0; f < sizeof flips; ++f) {
            rec[at] ^= flips[f];
            const mcs_status st = mcs_io_load_spectrum(&set_dst.spec, len, rec);
            const mcs_status pst = mcs_io_peek_provenance(len, rec, &back);
            rec[at] ^= flips[f];
            if (!flip_ok(at, block, st) || st != pst ||
                memcmp(&set_dst.spec, &set_before.spec, sizeof set_dst.spec) != 0 ||
                memcmp(&back, &before, sizeof back) != 0) {
                char msg[160];
                (void)snprintf(msg, sizeof msg, "byte %zu ^ 0x%02x gave %s (peek %s)", at,
                               flips[f], mcs_status_str(st), mcs_status_str(pst));
                TEST_FAIL_MESSAGE(msg);
            }
        }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_load_spectrum(&set_dst.spec, len, rec));
}

/* A block edited at byte `at` (its CRC rewritten) must be refused with
 * MCS_ERR_FORMAT by load and peek. */
static void crafted(size_t len, size_t at, uint64_t v, size_t bytes, const char *what)
{
    memcpy(want, rec, len);
    io_put_le(want + at, v, bytes);
    io_recrc(want, len);
    mcs_io_info info;
    TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_ERR_FORMAT, mcs_io_peek(len, want, &info), what);
    TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_ERR_FORMAT, mcs_io_peek_provenance(len, want, &back), what);
    TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_ERR_FORMAT, mcs_io_load_spectrum(&set_dst.spec, len, want),
                                  what);
    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(&set_before.spec, &set_dst.spec, sizeof set_dst.spec, what);
}

static void test_a_crafted_block_breaking_a_rule_is_refused(void)
{
    dirty_destinations();
    size_t len = spectrum_record();
    const size_t b = len - 4u;
    pattern(&prov, 5u, 0u, 1u, 4u);
    prov.nranges = 2u;
    prov.range[1] = (mcs_io_streams){5u, 2u, 4u};
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_set_provenance(&prov, sizeof rec, rec, &len));
    crafted(len, b + 4u, 0u, 2u, "source 0");
    crafted(len, b + 4u, 3u, 2u, "source 3");
    crafted(len, b + 6u, 1u, 2u, "one range in a block of two");
    crafted(len, b + 8u, 0u, 2u, "dim 0");
    crafted(len, b + 8u, 3u, 2u, "dim 3");
    crafted(len, b + 10u, 2u, 2u, "importance 2");
    crafted(len, b + 12u, 1u, 4u, "a checksum without importance");
    crafted(len, b + 16u, 0u, 1u, "an empty pattern name");
    crafted(len, b + 17u, ' ', 1u, "a space in the name");
    crafted(len, b + 27u, 'x', 1u, "a byte after the name's NUL");
    crafted(len, b + 24u, 0x4141414141414141u, 8u, "no NUL in the name");
    crafted(len, b + 32u, 0u, 8u, "N = 0 in 1D");
    crafted(len, b + 40u, 0u, 8u, "K = 0");
    crafted(len, b + 48u, 0u, 8u, "P = 0");
    crafted(len, b + 48u, 3u, 8u, "a range past P");
    crafted(len, b + 56u, 3u, 8u, "T < P");
    crafted(len, b + 72u, 1u, 8u, "an empty range");
    crafted(len, b + 96u, 1u, 8u, "a range touching the one before (not joined)");
    crafted(len, b + 96u, 0u, 8u, "overlapping ranges");
    crafted(len, b + 88u, 4u, 8u, "ranges out of order (seed)");

    len = b + 4u;
    memcpy(rec, plain, len);
    points(&prov, 10u, "a");
    prov.ninputs = 2u;
    prov.input[1] = prov.input[0];
    prov.input[1].crc = 20u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_set_provenance(&prov, sizeof rec, rec, &len));
    crafted(len, b + 6u, 0u, 2u, "no input");
    crafted(len, b + 8u + 80u, 10u, 4u, "the same input twice");
    crafted(len, b + 8u + 80u, 9u, 4u, "inputs out of order");
    crafted(len, b + 12u, 1u, 4u, "reserved bytes");
    crafted(len, b + 24u + 5u, 'x', 1u, "a byte after the name's NUL");
}

/* Rule r broken in *p, a valid provenance to start with; 0 past the last. */
static int break_rule(mcs_io_provenance *p, size_t r)
{
    pattern(p, 1u, 0u, 2u, 3u);
    switch (r) {
    case 0: p->source = 3u; break;
    case 1: p->dim = 0u; break;
    case 2: p->pattern[0] = '\0'; break;
    case 3: p->pattern[3] = ' '; break;
    case 4: memset(p->pattern, 'a', sizeof p->pattern); break;
    case 5: p->n = 0u; break;
    case 6: p->k = 0u; break;
    case 7: p->importance = 2u; break;
    case 8: p->importance_crc = 5u; break; /* a checksum without importance */
    case 9: p->streams = 0u; break;
    case 10: p->trials = 2u; break;          /* T < P */
    case 11: p->nranges = 0u; break;
    case 12: p->nranges = MCS_IO_PROV_MAX_RANGES + 1u; break;
    case 13: p->range[0].end = 4u; break;    /* past P */
    case 14: p->range[0].first = 2u; break;  /* empty */
    case 15: p->nranges = 2u, p->range[1] = (mcs_io_streams){1u, 2u, 3u}; break; /* touching */
    case 16: p->nranges = 2u, p->range[1] = (mcs_io_streams){0u, 2u, 3u}; break; /* seed order */
    case 17: points(p, 1u, "x"), p->ninputs = 0u; break;
    case 18: points(p, 1u, "x"), p->ninputs = MCS_IO_PROV_MAX_INPUTS + 1u; break;
    case 19: points(p, 1u, "x"), memset(p->input[0].name, 'y', MCS_IO_PROV_NAME_BYTES); break;
    case 20: points(p, 1u, "x"), p->ninputs = 2u, p->input[1] = p->input[0]; break;
    default: return 0;
    }
    return 1;
}

static void test_a_provenance_breaking_a_rule_is_refused_and_changes_nothing(void)
{
    size_t len = spectrum_record();
    static mcs_io_provenance bad;
    for (size_t r = 0; break_rule(&bad, r); ++r) {
        size_t bytes = 77u;
        TEST_ASSERT_EQUAL_INT(MCS_ERR_FORMAT, mcs_io_provenance_bytes(&bad, &bytes));
        ASSERT_SIZE(77u, bytes);
        expect_set(&bad, &len, MCS_ERR_FORMAT);
        pattern(&prov, 1u, 0u, 1u, 3u);
        memcpy(&before, &prov, sizeof prov);
        TEST_ASSERT_EQUAL_INT(MCS_ERR_FORMAT, mcs_io_provenance_merge(&prov, &bad));
        TEST_ASSERT_EQUAL_INT(MCS_ERR_FORMAT, mcs_io_provenance_merge(&bad, &before));
        TEST_ASSERT_EQUAL_MEMORY(&before, &prov, sizeof prov);
    }
}

static void test_set_refuses_a_small_buffer_a_bad_record_and_null(void)
{
    size_t len = spectrum_record();
    pattern(&prov, 1u, 0u, 1u, 1u);
    memcpy(want, rec, len);
    size_t l2 = len;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_SPACE, mcs_io_set_provenance(&prov, len + 87u, rec, &l2));
    ASSERT_SIZE(len, l2);
    TEST_ASSERT_EQUAL_MEMORY(want, rec, len);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_set_provenance(&prov, len + 88u, rec, &l2));
    ASSERT_SIZE(len + 88u, l2);
    memcpy(rec, want, len);
    rec[20] ^= 1u;
    expect_set(&prov, &len, MCS_ERR_CHECKSUM);
    rec[20] ^= 1u;
    l2 = len - 1u;
    memcpy(want, rec, sizeof rec);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_TRUNCATED, mcs_io_set_provenance(&prov, sizeof rec, rec, &l2));
    TEST_ASSERT_EQUAL_MEMORY(want, rec, sizeof rec);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_io_set_provenance(NULL, sizeof rec, rec, &len));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_io_set_provenance(&prov, sizeof rec, NULL, &len));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_io_set_provenance(&prov, sizeof rec, rec, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_io_peek_provenance(len, NULL, &back));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_io_peek_provenance(len, rec, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_io_provenance_bytes(NULL, &len));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_io_provenance_bytes(&prov, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_io_provenance_merge(NULL, &prov));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_io_provenance_merge(&prov, NULL));
}

/* ---------------- the union ---------------- */

/* Merges the single streams order[0..p) of a P-stream run in the binomial
 * tree of record.h over that order; the result into *out. */
static void tree_union(const size_t *order, size_t p, mcs_io_provenance *out)
{
    static mcs_io_provenance level[8];
    static size_t leaves[8];
    size_t depth = 0u;
    for (size_t i = 0; i < p; ++i) {
        pattern(&level[depth], 3u, order[i], order[i] + 1u, p);
        leaves[depth++] = 1u;
        while (depth >= 2u && leaves[depth - 1u] == leaves[depth - 2u]) {
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_provenance_merge(&level[depth - 2u],
                                                                  &level[depth - 1u]));
            leaves[depth - 2u] *= 2u;
            --depth;
        }
    }
    while (depth >= 2u) {
        TEST_ASSERT_EQUAL_INT(MCS_OK,
                              mcs_io_provenance_merge(&level[depth - 2u], &level[depth - 1u]));
        --depth;
    }
    memcpy(out, &level[0], sizeof *out);
}

static void test_the_streams_of_a_run_merged_in_any_order_are_one_range(void)
{
    /* Every permutation of 5 streams (Heap's algorithm). */
    size_t order[5] = {0u, 1u, 2u, 3u, 4u}, c[5] = {0u, 0u, 0u, 0u, 0u};
    pattern(&before, 3u, 0u, 5u, 5u);
    tree_union(order, 5u, &back);
    TEST_ASSERT_EQUAL_MEMORY(&before, &back, sizeof back);
    for (size_t i = 1; i < 5u;) {
        if (c[i] < i) {
            const size_t j = i % 2u == 0u ? 0u : c[i], t = order[j];
            order[j] = order[i];
            order[i] = t;
            tree_union(order, 5u, &back);
            TEST_ASSERT_EQUAL_MEMORY(&before, &back, sizeof back);
            ++c[i];
            i = 1u;
        } else {
            c[i++] = 0u;
        }
    }
}

static void test_a_union_with_gaps_is_sorted_and_joins_what_touches(void)
{
    pattern(&prov, 3u, 4u, 5u, 9u);
    pattern(&other, 3u, 0u, 1u, 9u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_provenance_merge(&prov, &other));
    pattern(&other, 3u, 7u, 9u, 9u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_provenance_merge(&prov, &other));
    TEST_ASSERT_EQUAL_UINT32(3u, prov.nranges);
    TEST_ASSERT_EQUAL_UINT64(0u, prov.range[0].first);
    TEST_ASSERT_EQUAL_UINT64(4u, prov.range[1].first);
    TEST_ASSERT_EQUAL_UINT64(9u, prov.range[2].end);
    pattern(&other, 3u, 1u, 4u, 9u); /* fills the first gap: [0, 5) */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_provenance_merge(&prov, &other));
    TEST_ASSERT_EQUAL_UINT32(2u, prov.nranges);
    TEST_ASSERT_EQUAL_UINT64(5u, prov.range[0].end);
    /* Another seed of the same run: its own ranges, after the first seed's. */
    pattern(&other, 2u, 5u, 7u, 9u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_provenance_merge(&prov, &other));
    TEST_ASSERT_EQUAL_UINT32(3u, prov.nranges);
    TEST_ASSERT_EQUAL_UINT64(2u, prov.range[0].seed);
    TEST_ASSERT_EQUAL_UINT64(3u, prov.range[1].seed);
    pattern(&other, 3u, 5u, 7u, 9u); /* [0, 9) of seed 3 */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_provenance_merge(&prov, &other));
    TEST_ASSERT_EQUAL_UINT32(2u, prov.nranges);
    TEST_ASSERT_EQUAL_UINT64(0u, prov.range[1].first);
    TEST_ASSERT_EQUAL_UINT64(9u, prov.range[1].end);
}

static void expect_merge(mcs_status want_st, mcs_io_provenance *dst, const mcs_io_provenance *src,
                         const char *what)
{
    memcpy(&before, dst, sizeof before);
    TEST_ASSERT_EQUAL_INT_MESSAGE(want_st, mcs_io_provenance_merge(dst, src), what);
    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(&before, dst, sizeof before, what);
}

static void test_merge_refuses_the_same_trials_twice_and_another_run(void)
{
    pattern(&prov, 3u, 0u, 2u, 4u);
    pattern(&other, 3u, 1u, 2u, 4u);
    expect_merge(MCS_ERR_ALIAS, &prov, &other, "a stream in both");
    pattern(&other, 3u, 0u, 4u, 4u);
    expect_merge(MCS_ERR_ALIAS, &prov, &other, "a range inside the other");
    expect_merge(MCS_ERR_ALIAS, &prov, &prov, "itself");
    const char *fields[] = {"dim", "pattern", "n", "k", "importance", "crc", "streams", "trials"};
    for (size_t f = 0; f < 8u; ++f) {
        pattern(&other, 3u, 2u, 3u, 4u);
        switch (f) {
        case 0: other.dim = 2u; break;
        case 1: other.pattern[0] = 'S'; break;
        case 2: other.n = 17u; break;
        case 3: other.k = 6u; break;
        case 4: other.importance = 1u; break;
        case 5: other.importance = 1u, prov.importance = 1u, other.importance_crc = 1u; break;
        case 6: other.streams = 5u; break;
        default: other.trials += 1u; break;
        }
        expect_merge(MCS_ERR_MISMATCH, &prov, &other, fields[f]);
        prov.importance = 0u;
    }
    points(&other, 1u, "a");
    expect_merge(MCS_ERR_KIND, &prov, &other, "points into a pattern");
    memset(&other, 0, sizeof other);
    expect_merge(MCS_ERR_KIND, &prov, &other, "no provenance");
    expect_merge(MCS_ERR_KIND, &other, &other, "none and none");
}

static void test_merge_refuses_a_union_past_the_caps(void)
{
    const uint64_t p = 2u * MCS_IO_PROV_MAX_RANGES + 2u;
    pattern(&prov, 1u, 0u, 1u, p);
    for (uint64_t s = 2u; s < 2u * MCS_IO_PROV_MAX_RANGES; s += 2u) {
        pattern(&other, 1u, s, s + 1u, p);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_provenance_merge(&prov, &other));
    }
    TEST_ASSERT_EQUAL_UINT32(MCS_IO_PROV_MAX_RANGES, prov.nranges);
    pattern(&other, 1u, 2u * MCS_IO_PROV_MAX_RANGES, 2u * MCS_IO_PROV_MAX_RANGES + 1u, p);
    expect_merge(MCS_ERR_SPACE, &prov, &other, "one range too many");
    pattern(&other, 1u, 1u, 2u, p); /* joins two: fits */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_provenance_merge(&prov, &other));
    TEST_ASSERT_EQUAL_UINT32(MCS_IO_PROV_MAX_RANGES - 1u, prov.nranges);

    points(&prov, 100u, "first");
    for (uint32_t i = 1; i < MCS_IO_PROV_MAX_INPUTS; ++i) {
        points(&other, 100u - i, "more");
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_provenance_merge(&prov, &other));
    }
    points(&other, 200u, "one too many");
    expect_merge(MCS_ERR_SPACE, &prov, &other, "one input too many");
}

static void test_inputs_merge_sorted_and_the_same_input_twice_is_refused(void)
{
    points(&prov, 30u, "c");
    points(&other, 10u, "a");
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_provenance_merge(&prov, &other));
    points(&other, 20u, "b");
    points(&back, 40u, "d");
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_provenance_merge(&other, &back));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_provenance_merge(&prov, &other));
    TEST_ASSERT_EQUAL_UINT32(4u, prov.ninputs);
    for (uint32_t i = 0; i < 4u; ++i) {
        TEST_ASSERT_EQUAL_UINT32(10u * (i + 1u), prov.input[i].crc);
        TEST_ASSERT_EQUAL_UINT64(1000u + 10u * (i + 1u), prov.input[i].bytes);
        TEST_ASSERT_EQUAL_INT('a' + (int)i, prov.input[i].name[0]);
    }
    points(&other, 20u, "b again");
    expect_merge(MCS_ERR_ALIAS, &prov, &other, "an input in both");
    expect_merge(MCS_ERR_ALIAS, &prov, &prov, "itself");
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_a_saved_record_is_version_1_without_provenance);
    RUN_TEST(test_a_pattern_provenance_round_trips_and_the_record_still_loads);
    RUN_TEST(test_every_kind_takes_a_provenance_and_loads_as_before);
    RUN_TEST(test_setting_a_provenance_twice_keeps_one_block);
    RUN_TEST(test_the_blocks_are_the_documented_bytes);
    RUN_TEST(test_every_truncation_and_changed_byte_of_a_version_2_record_is_refused);
    RUN_TEST(test_a_crafted_block_breaking_a_rule_is_refused);
    RUN_TEST(test_a_provenance_breaking_a_rule_is_refused_and_changes_nothing);
    RUN_TEST(test_set_refuses_a_small_buffer_a_bad_record_and_null);
    RUN_TEST(test_the_streams_of_a_run_merged_in_any_order_are_one_range);
    RUN_TEST(test_a_union_with_gaps_is_sorted_and_joins_what_touches);
    RUN_TEST(test_merge_refuses_the_same_trials_twice_and_another_run);
    RUN_TEST(test_merge_refuses_a_union_past_the_caps);
    RUN_TEST(test_inputs_merge_sorted_and_the_same_input_twice_is_refused);
    return UNITY_END();
}
