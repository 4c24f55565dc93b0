/* Record test fixtures (see io_fixtures.h). */
#include "io_fixtures.h"
#include "spectra_ref.h"
#include "unity.h"

#include <stddef.h>
#include <stdio.h>
#include <string.h>

#define LD(name, type) \
    static mcs_status ld_##name(void *d, size_t l, const void *b) { return mcs_io_load_##name((type *)d, l, b); }
#define SV(name, type) \
    static mcs_status sv_##name(const void *s, size_t c, void *b, size_t *l) \
    { return mcs_io_save_##name((const type *)s, c, b, l); }
#define MG(name, type) \
    static mcs_status mg_##name(void *d, const void *s) { return mcs_##name##_merge((type *)d, (const type *)s); }
#define KIND(name, type) LD(name, type) SV(name, type) MG(name, type)

/* The objects over caller memory: the same calls on the slot's header (its
 * first member: a NULL slot is a NULL header). */
#define SLOT_SV(name, slot) \
    static mcs_status sv_##name(const void *s, size_t c, void *b, size_t *l) \
    { return mcs_io_save_##name((const mcs_##name *)s, c, b, l); }
#define SLOT_MG(name, slot) \
    static mcs_status mg_##name(void *d, const void *s) \
    { return mcs_##name##_merge((mcs_##name *)d, (const mcs_##name *)s); }

KIND(spectrum, mcs_spectrum)
KIND(moment, mcs_moment)
KIND(autocorr, mcs_autocorr)
KIND(welford, mcs_welford)
SLOT_SV(pointset, io_pointset)
SLOT_MG(pointset, io_pointset)
SLOT_SV(pointset2d, io_pointset2d)
SLOT_MG(pointset2d, io_pointset2d)
SLOT_SV(spectrum2d, io_spectrum2d)
SLOT_MG(spectrum2d, io_spectrum2d)

static mcs_status ld_pointset(void *d, size_t l, const void *b)
{
    io_pointset *s = d;
    return mcs_io_load_pointset(d, 0u, s ? s->mem : NULL, sizeof s->mem, l, b);
}

static mcs_status ld_pointset2d(void *d, size_t l, const void *b)
{
    io_pointset2d *s = d;
    return mcs_io_load_pointset2d(d, IO_FIX_FLAGS_2D, s ? s->mem : NULL, sizeof s->mem, l, b);
}

static mcs_status ld_spectrum2d(void *d, size_t l, const void *b)
{
    io_spectrum2d *s = d;
    return mcs_io_load_spectrum2d(d, s ? s->mem : NULL, sizeof s->mem, l, b);
}

#define OPS(name, member, kind, shape_len) \
    {#name, kind, offsetof(io_set, member), sizeof(((io_set *)0)->member), shape_len, \
     ld_##name, sv_##name, mg_##name}

const io_kind_ops io_kinds[IO_NKINDS] = {
    OPS(spectrum, spec, MCS_IO_KIND_SPECTRUM, 1u),
    OPS(moment, mom, MCS_IO_KIND_MOMENT, 1u),
    OPS(autocorr, ac, MCS_IO_KIND_AUTOCORR, 1u),
    OPS(welford, wf, MCS_IO_KIND_WELFORD, 0u),
    OPS(pointset, ps, MCS_IO_KIND_POINTSET, 1u),
    OPS(pointset2d, ps2, MCS_IO_KIND_POINTSET2D, 1u),
    OPS(spectrum2d, sp2, MCS_IO_KIND_SPECTRUM2D, 2u),
};

void *io_obj(io_set *s, const io_kind_ops *o)
{
    return (char *)s + o->offset;
}

static size_t at_most(size_t v, size_t cap)
{
    return v < cap ? v : cap;
}

static void init_all(io_set *s, size_t n)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&s->spec, n));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&s->mom, at_most(n, MCS_MAX_COV_N)));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_init(&s->ac, n));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_init(&s->wf));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(&s->ps.acc, at_most(n, IO_FIX_FREQ_1D), 0u,
                                                    s->ps.mem, sizeof s->ps.mem));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_init(&s->ps2.acc, at_most(n, IO_FIX_FREQ_2D),
                                                      IO_FIX_FLAGS_2D, s->ps2.mem,
                                                      sizeof s->ps2.mem));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_init(&s->sp2.acc, at_most(n, IO_FIX_SIDE),
                                                      at_most(n / 2u + 1u, IO_FIX_SIDE),
                                                      s->sp2.mem, sizeof s->sp2.mem));
}

void io_fill(io_set *s, size_t n, size_t trials, uint64_t seed)
{
    enum { K = 5 };
    size_t bins[K];
    double weights[K], points[K], xy[2 * K];
    uint64_t state = 0x9e3779b97f4a7c15u ^ seed;
    spectra_stream st;
    spectra_stream_init(&st, MCS_PATTERN_STRATIFIED, n, K, NULL, seed, 0x10u);
    init_all(s, n);
    for (size_t t = 0; t < trials; ++t) {
        spectra_stream_draw(&st, bins, weights, points);
        for (size_t j = 0; j < 2u * K; ++j)
            xy[j] = spectra_uniform(&state, 0.0, 1.0);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(&s->spec, K, bins, weights));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_add_bins(&s->ac, K, bins, weights));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add(&s->ps.acc, K, points));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add(&s->ps2.acc, K, xy));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_add_points(&s->sp2.acc, K, xy, weights));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_add(&s->wf, (double)bins[0] + 0.25 * weights[1]));
        for (size_t j = 0; j < K; ++j)
            bins[j] %= s->mom.n;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_add_bins(&s->mom, K, bins, weights));
    }
}

void io_assert_same(const io_kind_ops *o, const void *a, const void *b, const char *what)
{
    static uint8_t ra[IO_REC_MAX], rb[IO_REC_MAX];
    if (o->kind != MCS_IO_KIND_POINTSET && o->kind != MCS_IO_KIND_POINTSET2D &&
        o->kind != MCS_IO_KIND_SPECTRUM2D) {
        TEST_ASSERT_EQUAL_MEMORY_MESSAGE(a, b, o->obj_size, what);
        return;
    }
    size_t la = 0u, lb = 0u;
    TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_OK, o->save(a, sizeof ra, ra, &la), what);
    TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_OK, o->save(b, sizeof rb, rb, &lb), what);
    TEST_ASSERT_EQUAL_UINT64_MESSAGE((uint64_t)la, (uint64_t)lb, what);
    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(ra, rb, la, what);
    /* the settings: the headers' fields before their pointers */
    const size_t settings = o->kind == MCS_IO_KIND_SPECTRUM2D ? offsetof(mcs_spectrum2d, mem)
                                                              : offsetof(mcs_pointset, mem);
    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(a, b, settings, what);
}

size_t io_save(const io_kind_ops *o, const void *src, uint8_t *buf)
{
    size_t len = 0u, qlen = 0u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, o->save(src, 0u, NULL, &qlen));
    TEST_ASSERT_EQUAL_INT(MCS_OK, o->save(src, IO_REC_MAX, buf, &len));
    TEST_ASSERT_EQUAL_UINT64((uint64_t)qlen, (uint64_t)len);
    return len;
}

void io_expect_refused(const io_kind_ops *o, io_set *dst, const io_set *before, mcs_status want,
                       size_t len, const uint8_t *buf, const char *what, size_t at)
{
    void *d = io_obj(dst, o);
    const void *b = (const char *)before + o->offset;
    mcs_status got = o->load(d, len, buf);
    if (got != want || memcmp(d, b, o->obj_size) != 0) {
        char msg[200];
        (void)snprintf(msg, sizeof msg, "%s, %s at %zu: want %s, got %s%s", o->name, what, at,
                       mcs_status_str(want), mcs_status_str(got),
                       got == want ? " but the destination changed" : "");
        TEST_FAIL_MESSAGE(msg);
    }
}

uint32_t io_ref_crc(const uint8_t *p, size_t len)
{
    uint32_t c = 0xffffffffu;
    for (size_t i = 0; i < len; ++i) {
        c ^= p[i];
        for (int b = 0; b < 8; ++b)
            c = (c & 1u) ? (c >> 1) ^ 0xedb88320u : c >> 1;
    }
    return ~c;
}

void io_put_le(uint8_t *p, uint64_t v, size_t bytes)
{
    for (size_t i = 0; i < bytes; ++i)
        p[i] = (uint8_t)(v >> (8u * i));
}

void io_put_f64(uint8_t *p, double v)
{
    uint64_t bits;
    memcpy(&bits, &v, sizeof bits);
    io_put_le(p, bits, 8u);
}

uint64_t io_get_le(const uint8_t *p, size_t bytes)
{
    uint64_t v = 0u;
    for (size_t i = 0; i < bytes; ++i)
        v |= (uint64_t)p[i] << (8u * i);
    return v;
}

void io_recrc(uint8_t *p, size_t len)
{
    io_put_le(p + len - 4u, io_ref_crc(p, len - 4u), 4u);
}

size_t io_payload_at(size_t s, size_t i)
{
    return 32u + 8u * s + 8u * i;
}

size_t io_build(uint8_t *p, uint32_t version, uint32_t kind, uint32_t s, const uint64_t *shape,
                uint64_t count, uint64_t np, const double *values)
{
    static const uint8_t magic[8] = {0x89u, 'M', 'C', 'S', 0x0du, 0x0au, 0x1au, 0x0au};
    memcpy(p, magic, 8u);
    io_put_le(p + 8, version, 2u);
    io_put_le(p + 10, kind, 2u);
    io_put_le(p + 12, s, 4u);
    io_put_le(p + 16, count, 8u);
    io_put_le(p + 24, np, 8u);
    for (size_t i = 0; i < s; ++i)
        io_put_le(p + 32 + 8u * i, shape[i], 8u);
    for (size_t i = 0; i < np; ++i)
        io_put_f64(p + io_payload_at(s, i), values != NULL ? values[i] : 0.0);
    const size_t size = 36u + 8u * s + 8u * (size_t)np;
    io_recrc(p, size);
    return size;
}
