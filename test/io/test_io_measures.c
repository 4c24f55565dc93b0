/* Records of the measure accumulators (docs/format.md, kinds 8 to 11):
 * mcs_pcf, mcs_integrate, mcs_discrepancy and mcs_spacing. A loaded record
 * saves again to the same bytes, reads out and merges like the object that
 * was saved, and merges into itself; every truncation and changed byte is
 * refused; and each invariant the format lists is refused on its own (an
 * edit of one value of a valid record, its CRC rewritten), the destination
 * byte-identical after every refusal. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "io_fixtures.h"
#include "mcspec.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

#define BINS 8u
#define K 64u
#define REC_MAX 4096u

/* One accumulator of each kind; the pcf over its own buffer. */
typedef struct {
    mcs_pcf pcf;
    _Alignas(64) unsigned char mem[MCS_PCF_SIZE(BINS)];
    mcs_integrate in;
    mcs_discrepancy di;
    mcs_spacing sp;
} mset;

enum { KIND_PCF, KIND_INTEGRATE, KIND_DISCREPANCY, KIND_SPACING, KINDS };
static const char *const names[KINDS] = {"pcf", "integrate", "discrepancy", "spacing"};
static const size_t shape_lens[KINDS] = {5u, 2u, 1u, 1u};

static mset set_a, set_b, set_dst, set_before, set_c;
static uint8_t rec[REC_MAX], rec2[REC_MAX];
static _Alignas(64) unsigned char work[MCS_DISCREPANCY_STAR_WORK_SIZE(K) + MCS_SPACING_WORK_SIZE(K)];

static void init_set(mset *s, mcs_pcf_estimator estimator, size_t pcf_dim)
{
    memset(s, 0, sizeof *s);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_init(&s->pcf, pcf_dim, estimator, BINS, 2.0,
                                               estimator == MCS_PCF_GAUSSIAN ? 0.25 : 0.0,
                                               s->mem, sizeof s->mem));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrate_init(&s->in, MCS_INTEGRAND_GAUSSIAN, 2u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_discrepancy_init(&s->di, 2u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spacing_init(&s->sp, 2u));
}

/* sets seeded sets of k = K - (set % 3) 2D random points (the pcf's in
 * pcf_dim dimensions: the first k x pcf_dim coordinates). */
static void fill(mset *s, size_t sets, uint64_t seed)
{
    static double pts[2u * K];
    mcs_rng rng;
    mcs_integrand fs[3];
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, seed, 7u));
    for (size_t t = 0; t < sets; ++t) {
        const size_t k = K - t % 3u;
        for (size_t i = 0; i < 2u * k; ++i)
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_double(&rng, &pts[i]));
        size_t need = 0u;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_work_size(&s->pcf, k, &need));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_add(&s->pcf, k, pts, work, sizeof work));
        for (size_t i = 0; i < 3u; ++i)
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrand_draw(&fs[i], MCS_INTEGRAND_GAUSSIAN, 2u, &rng));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrate_add(&s->in, 3u, fs, k, pts,
                                                        t % 2u ? MCS_INTEGRATE_RANDOM
                                                               : MCS_INTEGRATE_NONE, 0u, 0u));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_discrepancy_add(&s->di, k, pts, t % 2u ? work : NULL,
                                                          sizeof work));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spacing_add(&s->sp, k, pts, work, sizeof work));
    }
}

static mcs_status save(int kind, const mset *s, size_t cap, void *buf, size_t *len)
{
    switch (kind) {
    case KIND_PCF: return mcs_io_save_pcf(&s->pcf, cap, buf, len);
    case KIND_INTEGRATE: return mcs_io_save_integrate(&s->in, cap, buf, len);
    case KIND_DISCREPANCY: return mcs_io_save_discrepancy(&s->di, cap, buf, len);
    default: return mcs_io_save_spacing(&s->sp, cap, buf, len);
    }
}

static mcs_status load(int kind, mset *s, size_t len, const void *buf)
{
    switch (kind) {
    case KIND_PCF: return mcs_io_load_pcf(&s->pcf, s->mem, sizeof s->mem, len, buf);
    case KIND_INTEGRATE: return mcs_io_load_integrate(&s->in, len, buf);
    case KIND_DISCREPANCY: return mcs_io_load_discrepancy(&s->di, len, buf);
    default: return mcs_io_load_spacing(&s->sp, len, buf);
    }
}

static mcs_status merge(int kind, mset *d, const mset *s)
{
    switch (kind) {
    case KIND_PCF: return mcs_pcf_merge(&d->pcf, &s->pcf);
    case KIND_INTEGRATE: return mcs_integrate_merge(&d->in, &s->in);
    case KIND_DISCREPANCY: return mcs_discrepancy_merge(&d->di, &s->di);
    default: return mcs_spacing_merge(&d->sp, &s->sp);
    }
}

static size_t saved(int kind, const mset *s, uint8_t *buf)
{
    size_t need = 0u, len = 0u;
    TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_OK, save(kind, s, 0u, NULL, &need), names[kind]);
    TEST_ASSERT_TRUE(need <= REC_MAX);
    TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_OK, save(kind, s, REC_MAX, buf, &len), names[kind]);
    TEST_ASSERT_EQUAL_UINT64(need, len);
    return len;
}

/* A fresh destination, different from what is loaded, and its snapshot. */
static void dirty(void)
{
    init_set(&set_dst, MCS_PCF_RDF, 2u);
    fill(&set_dst, 3u, 99u);
    memcpy(&set_before, &set_dst, sizeof set_dst);
}

static void refused(int kind, mcs_status want, size_t len, const uint8_t *buf, const char *what)
{
    char msg[160];
    snprintf(msg, sizeof msg, "%s: %s", names[kind], what);
    TEST_ASSERT_EQUAL_INT_MESSAGE(want, load(kind, &set_dst, len, buf), msg);
    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(&set_before, &set_dst, sizeof set_dst, msg);
}

/* ---------------- the good path ---------------- */

static void test_each_kind_loads_saves_again_to_the_same_bytes_and_reads_out_the_same(void)
{
    init_set(&set_a, MCS_PCF_RDF, 2u);
    fill(&set_a, 7u, 1u);
    dirty();
    for (int kind = 0; kind < KINDS; ++kind) {
        const size_t len = saved(kind, &set_a, rec);
        TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_OK, load(kind, &set_dst, len, rec), names[kind]);
        TEST_ASSERT_EQUAL_UINT64(len, saved(kind, &set_dst, rec2));
        TEST_ASSERT_EQUAL_MEMORY_MESSAGE(rec, rec2, len, names[kind]);
        size_t need = 1u;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_load_size(len, rec, 0u, &need));
        TEST_ASSERT_EQUAL_UINT64(kind == KIND_PCF ? MCS_PCF_SIZE(BINS) : 0u, need);
    }
    /* The objects themselves: the fixed ones byte for byte, the pcf by its
     * header fields and arrays (its pointers are into another buffer). */
    TEST_ASSERT_EQUAL_MEMORY(&set_a.in, &set_dst.in, sizeof set_a.in);
    TEST_ASSERT_EQUAL_MEMORY(&set_a.di, &set_dst.di, sizeof set_a.di);
    TEST_ASSERT_EQUAL_MEMORY(&set_a.sp, &set_dst.sp, sizeof set_a.sp);
    const mcs_pcf *p = &set_a.pcf, *q = &set_dst.pcf;
    TEST_ASSERT_TRUE(p->dim == q->dim && p->estimator == q->estimator && p->bins == q->bins &&
                     p->radius == q->radius && p->sigma == q->sigma && p->count == q->count &&
                     p->k_min == q->k_min && p->k_max == q->k_max && p->bytes == q->bytes);
    TEST_ASSERT_EQUAL_MEMORY(p->mean, q->mean, 2u * BINS * sizeof(double));
    double ra[BINS], ma[BINS], sa[BINS], rb[BINS], mb[BINS], sb[BINS];
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_read_all(p, BINS, ra, ma, sa));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_read_all(q, BINS, rb, mb, sb));
    TEST_ASSERT_EQUAL_MEMORY(ma, mb, sizeof ma);
    TEST_ASSERT_EQUAL_MEMORY(sa, sb, sizeof sa);
    double e1 = 0.0, e2 = 1.0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_discrepancy_exact_random(&set_dst.di, MCS_DISCREPANCY_L2_STAR, &e1));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_discrepancy_exact_random(&set_a.di, MCS_DISCREPANCY_L2_STAR, &e2));
    TEST_ASSERT_EQUAL_DOUBLE(e2, e1);
}

static void test_a_loaded_record_merges_into_itself_and_as_the_saved_object_merges(void)
{
    init_set(&set_a, MCS_PCF_GAUSSIAN, 1u);
    fill(&set_a, 5u, 2u);
    init_set(&set_b, MCS_PCF_GAUSSIAN, 1u);
    fill(&set_b, 4u, 3u);
    for (int kind = 0; kind < KINDS; ++kind) {
        /* the original merged with b */
        init_set(&set_c, MCS_PCF_GAUSSIAN, 1u);
        TEST_ASSERT_EQUAL_INT(MCS_OK, merge(kind, &set_c, &set_a));
        TEST_ASSERT_EQUAL_INT(MCS_OK, merge(kind, &set_c, &set_b));
        const size_t want = saved(kind, &set_c, rec2);
        /* the loaded one merged with b */
        init_set(&set_dst, MCS_PCF_GAUSSIAN, 1u);
        size_t len = saved(kind, &set_a, rec);
        TEST_ASSERT_EQUAL_INT(MCS_OK, load(kind, &set_dst, len, rec));
        TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_OK, merge(kind, &set_dst, &set_b), names[kind]);
        TEST_ASSERT_EQUAL_UINT64(want, saved(kind, &set_dst, rec));
        TEST_ASSERT_EQUAL_MEMORY_MESSAGE(rec2, rec, want, names[kind]);
        /* and into itself */
        TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_OK, merge(kind, &set_dst, &set_dst), names[kind]);
        (void)saved(kind, &set_dst, rec);
    }
}

static void test_empty_accumulators_round_trip(void)
{
    init_set(&set_a, MCS_PCF_RDF, 2u);
    for (int kind = 0; kind < KINDS; ++kind) {
        dirty();
        const size_t len = saved(kind, &set_a, rec);
        TEST_ASSERT_EQUAL_INT(MCS_OK, load(kind, &set_dst, len, rec));
        TEST_ASSERT_EQUAL_UINT64(len, saved(kind, &set_dst, rec2));
        TEST_ASSERT_EQUAL_MEMORY(rec, rec2, len);
    }
}

static void test_saving_refuses_uninitialised_objects_and_small_buffers(void)
{
    init_set(&set_a, MCS_PCF_RDF, 2u);
    fill(&set_a, 3u, 4u);
    memset(&set_b, 0, sizeof set_b);
    for (int kind = 0; kind < KINDS; ++kind) {
        size_t len = 77u, need = 0u;
        memset(rec, 0xa5, sizeof rec);
        TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, save(kind, &set_b, REC_MAX, rec, &len));
        TEST_ASSERT_EQUAL_INT(MCS_OK, save(kind, &set_a, 0u, NULL, &need));
        TEST_ASSERT_EQUAL_INT(MCS_ERR_SPACE, save(kind, &set_a, need - 1u, rec, &len));
        TEST_ASSERT_EQUAL_UINT64(77u, len);
        TEST_ASSERT_EACH_EQUAL_HEX8(0xa5, rec, REC_MAX);
        TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, save(kind, &set_a, REC_MAX, rec, NULL));
    }
    size_t len = 0u;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_io_save_pcf(&set_a.pcf, sizeof set_a.mem,
                                                         set_a.mem, &len));
}

/* ---------------- the bad path ---------------- */

static void test_every_truncation_and_every_changed_byte_are_refused(void)
{
    init_set(&set_a, MCS_PCF_RDF, 2u);
    fill(&set_a, 4u, 5u);
    dirty();
    for (int kind = 0; kind < KINDS; ++kind) {
        const size_t len = saved(kind, &set_a, rec);
        for (size_t cut = 0; cut < len; ++cut)
            refused(kind, MCS_ERR_TRUNCATED, cut, rec, "truncated");
        for (size_t at = 0; at < len; ++at) {
            rec[at] ^= 0x10u;
            const mcs_status st = load(kind, &set_dst, len, rec);
            TEST_ASSERT_TRUE(st != MCS_OK);
            TEST_ASSERT_EQUAL_MEMORY(&set_before, &set_dst, sizeof set_dst);
            rec[at] ^= 0x10u;
        }
        /* another kind's loader refuses it */
        const int other = (kind + 1) % KINDS;
        refused(other, MCS_ERR_KIND, len, rec, "loaded as another kind");
    }
}

/* Edit e of a saved record: payload value `at` (or, at < 0, shape word
 * -at - 1 as raw bits; or the header count) set, the CRC rewritten. */
typedef struct {
    int kind;
    int at;          /* payload index; SHAPE(i) for shape word i; COUNT for the header's */
    double value;    /* for a payload value */
    uint64_t bits;   /* for a shape word or the count */
    mcs_status want;
    const char *what;
} edit;

#define SHAPE(i) (-1 - (i))
#define COUNT (-100)

static void apply(const edit *e, uint8_t *buf, size_t len)
{
    const size_t s = shape_lens[e->kind];
    if (e->at == COUNT)
        io_put_le(buf + 16u, e->bits, 8u);
    else if (e->at < 0)
        io_put_le(buf + 32u + 8u * (size_t)(-e->at - 1), e->bits, 8u);
    else
        io_put_f64(buf + io_payload_at(s, (size_t)e->at), e->value);
    io_recrc(buf, len);
}

/* Payload indices (docs/format.md): pcf k_min 0, k_max 1, mean 2.., M2
 * 2 + B..; integrate, spacing: k_min, k_max, counts 2 3, means 4 5, M2 6 7,
 * M3 8 9, M4 10 11; discrepancy: counts 2..9 (1/K, then the seven
 * measures), means 10..17, M2 18..25. */
static const edit edits[] = {
    {KIND_PCF, SHAPE(0), 0, 3u, MCS_ERR_DOMAIN, "dim 3"},
    {KIND_PCF, SHAPE(1), 0, 2u, MCS_ERR_DOMAIN, "estimator 2"},
    {KIND_PCF, SHAPE(2), 0, 0u, MCS_ERR_N_RANGE, "no bins"},
    {KIND_PCF, SHAPE(2), 0, MCS_PCF_MAX_BINS + 1u, MCS_ERR_N_RANGE, "bins above the cap"},
    {KIND_PCF, SHAPE(2), 0, BINS - 1u, MCS_ERR_FORMAT, "bins not the payload's"},
    {KIND_PCF, SHAPE(3), 0, 0xbff0000000000000u, MCS_ERR_DOMAIN, "radius -1"},
    {KIND_PCF, SHAPE(3), 0, 0x7ff8000000000000u, MCS_ERR_DOMAIN, "radius NaN"},
    {KIND_PCF, SHAPE(4), 0, 0x3fd0000000000000u, MCS_ERR_DOMAIN, "an RDF with a sigma"},
    {KIND_PCF, SHAPE(4), 0, 0x8000000000000000u, MCS_ERR_DOMAIN, "an RDF sigma of -0"},
    {KIND_PCF, 0, 1.0, 0u, MCS_ERR_INVARIANT, "k_min 1"},
    {KIND_PCF, 0, 8.0, 0u, MCS_ERR_INVARIANT, "k_min whose cutoff passes 1/2"},
    {KIND_PCF, 0, 62.5, 0u, MCS_ERR_INVARIANT, "k_min not whole"},
    {KIND_PCF, 0, 65.0, 0u, MCS_ERR_INVARIANT, "k_min above k_max"},
    {KIND_PCF, 1, 1e300, 0u, MCS_ERR_INVARIANT, "k_max above 2^500"},
    {KIND_PCF, 2, -1e-3, 0u, MCS_ERR_INVARIANT, "a negative mean"},
    {KIND_PCF, 2, 1e6, 0u, MCS_ERR_INVARIANT, "a mean no pairs give"},
    {KIND_PCF, 3, NAN, 0u, MCS_ERR_NOT_FINITE, "a NaN mean"},
    {KIND_PCF, 2 + BINS, -1.0, 0u, MCS_ERR_INVARIANT, "a negative M2"},
    {KIND_PCF, COUNT, 0, 0u, MCS_ERR_INVARIANT, "data with no sets"},
    {KIND_PCF, COUNT, 0, 1u, MCS_ERR_INVARIANT, "a spread with one set"},
    {KIND_INTEGRATE, SHAPE(0), 0, MCS_INTEGRAND_FAMILIES, MCS_ERR_DOMAIN, "no such family"},
    {KIND_INTEGRATE, SHAPE(1), 0, 3u, MCS_ERR_DOMAIN, "dim 3"},
    {KIND_INTEGRATE, 0, 0.0, 0u, MCS_ERR_INVARIANT, "k_min 0"},
    {KIND_INTEGRATE, 0, 70.0, 0u, MCS_ERR_INVARIANT, "k_min above k_max"},
    {KIND_INTEGRATE, 2, 3.0, 0u, MCS_ERR_INVARIANT, "a set count not the header's"},
    {KIND_INTEGRATE, 3, 5.0, 0u, MCS_ERR_INVARIANT, "more exact sets than sets"},
    {KIND_INTEGRATE, 4, -1e-6, 0u, MCS_ERR_INVARIANT, "a negative MSE"},
    {KIND_INTEGRATE, 5, -1e-6, 0u, MCS_ERR_INVARIANT, "a negative exact MSE"},
    {KIND_INTEGRATE, 6, -1.0, 0u, MCS_ERR_INVARIANT, "a negative M2"},
    {KIND_INTEGRATE, 10, -1.0, 0u, MCS_ERR_INVARIANT, "a negative M4"},
    {KIND_DISCREPANCY, SHAPE(0), 0, 0u, MCS_ERR_DOMAIN, "dim 0"},
    {KIND_DISCREPANCY, SHAPE(0), 0, MCS_DISCREPANCY_MAX_DIM + 1u, MCS_ERR_DOMAIN, "dim 65"},
    {KIND_DISCREPANCY, 4, 3.0, 0u, MCS_ERR_INVARIANT, "L2 counts that differ"},
    {KIND_DISCREPANCY, 9, 5.0, 0u, MCS_ERR_INVARIANT, "more star sets than sets"},
    {KIND_DISCREPANCY, 10, 0.5, 0u, MCS_ERR_INVARIANT, "a mean 1/K above 1/k_min"},
    {KIND_DISCREPANCY, 10, 1e-3, 0u, MCS_ERR_INVARIANT, "a mean 1/K below 1/k_max"},
    {KIND_DISCREPANCY, 11, -1e-3, 0u, MCS_ERR_INVARIANT, "a negative L2 star"},
    {KIND_DISCREPANCY, 12, 10.0, 0u, MCS_ERR_INVARIANT, "a centred L2 above its bound"},
    {KIND_DISCREPANCY, 17, 1.5, 0u, MCS_ERR_INVARIANT, "a star above 1"},
    {KIND_DISCREPANCY, 17, -1e-20, 0u, MCS_ERR_INVARIANT, "a negative star"},
    {KIND_DISCREPANCY, 19, -1.0, 0u, MCS_ERR_INVARIANT, "a negative M2"},
    {KIND_SPACING, SHAPE(0), 0, MCS_SPACING_MAX_DIM + 1u, MCS_ERR_DOMAIN, "dim 9"},
    {KIND_SPACING, 0, 1.0, 0u, MCS_ERR_INVARIANT, "k_min 1"},
    {KIND_SPACING, 3, 3.0, 0u, MCS_ERR_INVARIANT, "counts that differ"},
    {KIND_SPACING, 4, -1e-3, 0u, MCS_ERR_INVARIANT, "a negative distance"},
    {KIND_SPACING, 4, 0.99, 0u, MCS_ERR_INVARIANT, "a minimum above the average minimum"},
    {KIND_SPACING, 5, 50.0, 0u, MCS_ERR_INVARIANT, "a distance past the torus"},
    {KIND_SPACING, 6, -1.0, 0u, MCS_ERR_INVARIANT, "a negative M2"},
};

static void test_each_invariant_of_the_format_is_refused_on_its_own(void)
{
    init_set(&set_a, MCS_PCF_RDF, 2u);
    fill(&set_a, 4u, 6u); /* K = 64, 63, 62, 64: k_min 62, k_max 64 */
    dirty();
    for (size_t i = 0; i < sizeof edits / sizeof edits[0]; ++i) {
        const edit *e = &edits[i];
        const size_t len = saved(e->kind, &set_a, rec);
        apply(e, rec, len);
        refused(e->kind, e->want, len, rec, e->what);
    }
    /* the unedited records load, and a star on sets above its K cap is refused */
    for (int kind = 0; kind < KINDS; ++kind) {
        const size_t len = saved(kind, &set_a, rec);
        TEST_ASSERT_EQUAL_INT(MCS_OK, load(kind, &set_c, len, rec));
    }
    const size_t len = saved(KIND_DISCREPANCY, &set_a, rec);
    const edit big[3] = {{KIND_DISCREPANCY, 0, 5000.0, 0u, MCS_OK, ""},
                         {KIND_DISCREPANCY, 1, 5000.0, 0u, MCS_OK, ""},
                         {KIND_DISCREPANCY, 10, 1.0 / 5000.0, 0u, MCS_OK, ""}};
    for (size_t i = 0; i < 3u; ++i)
        apply(&big[i], rec, len);
    refused(KIND_DISCREPANCY, MCS_ERR_INVARIANT, len, rec, "a star of sets above its K cap");
    /* with the star's count 0 (and its values 0) the same sets load */
    const edit nostar[4] = {{KIND_DISCREPANCY, 9, 0.0, 0u, MCS_OK, ""},
                            {KIND_DISCREPANCY, 17, 0.0, 0u, MCS_OK, ""},
                            {KIND_DISCREPANCY, 25, 0.0, 0u, MCS_OK, ""},
                            {KIND_DISCREPANCY, 41, 0.0, 0u, MCS_OK, ""}};
    for (size_t i = 0; i < 4u; ++i)
        apply(&nostar[i], rec, len);
    io_put_f64(rec + io_payload_at(1u, 33u), 0.0);
    io_recrc(rec, len);
    TEST_ASSERT_EQUAL_INT(MCS_OK, load(KIND_DISCREPANCY, &set_c, len, rec));
}

static void test_a_pcf_load_checks_its_memory(void)
{
    init_set(&set_a, MCS_PCF_RDF, 2u);
    fill(&set_a, 3u, 8u);
    dirty();
    const size_t len = saved(KIND_PCF, &set_a, rec);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_io_load_pcf(&set_dst.pcf, NULL, 0u, len, rec));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_SPACE, mcs_io_load_pcf(&set_dst.pcf, set_dst.mem,
                                                         MCS_PCF_SIZE(BINS) - 1u, len, rec));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_io_load_pcf(&set_dst.pcf, (unsigned char *)&set_dst.pcf,
                                                         MCS_PCF_SIZE(BINS), len, rec));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_io_load_pcf(&set_dst.pcf, rec, MCS_PCF_SIZE(BINS),
                                                         len, rec));
    TEST_ASSERT_EQUAL_MEMORY(&set_before, &set_dst, sizeof set_dst);
    /* the size query reads the shape and refuses a bad one as the load does */
    size_t need = 0u;
    rec[32] = 3u;
    io_recrc(rec, len);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_io_load_size(len, rec, 0u, &need));
    TEST_ASSERT_EQUAL_UINT64(0u, need);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_each_kind_loads_saves_again_to_the_same_bytes_and_reads_out_the_same);
    RUN_TEST(test_a_loaded_record_merges_into_itself_and_as_the_saved_object_merges);
    RUN_TEST(test_empty_accumulators_round_trip);
    RUN_TEST(test_saving_refuses_uninitialised_objects_and_small_buffers);
    RUN_TEST(test_every_truncation_and_every_changed_byte_are_refused);
    RUN_TEST(test_each_invariant_of_the_format_is_refused_on_its_own);
    RUN_TEST(test_a_pcf_load_checks_its_memory);
    return UNITY_END();
}
