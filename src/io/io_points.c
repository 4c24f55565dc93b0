/* The record kinds of the point-set and 2D accumulators (docs/format.md):
 * mcs_pointset (kind 5), mcs_pointset2d (6) and mcs_spectrum2d (7). As in
 * io_kinds.c: sizes for a shape and a table of fields in payload order,
 * which io.c walks to save, check and load. Only the entries in use are
 * written, so the bytes depend on F or N1, N2 and nothing else.
 *
 * These objects keep their statistics in a caller buffer behind a head
 * (pointsets/pointset_internal.h: the shape words, then the trial count),
 * so the walker's object is that head and each table is made per call with
 * the offsets of the object's arrays from it. A load cannot set the object
 * up before the record has passed every check (nothing may change on
 * error), and the walker sets it up only after them, through the kind's
 * init: so a load walks the record twice, first with an init that stops
 * the walk once the record passed (CHECKED), then, once the caller's buffer
 * is known to hold the object and the object is set up over it, to store
 * the values. */
#include "io_internal.h"
#include "measures/pcf_internal.h"
#include "pointsets/pointset_internal.h"

#include <math.h>
#include <string.h>

/* The dry walk's init: every check passed. mcs_io_load returns no such
 * status of its own before it calls init. */
#define CHECKED MCS_ERR_ALIAS

static mcs_status count_of_head(const void *obj, uint64_t *count)
{
    memcpy(count, (const unsigned char *)obj + offsetof(mcs_ps_head, count), sizeof *count);
    return MCS_OK;
}

static mcs_status init_checked(void *obj, const uint64_t *shape)
{
    (void)obj;
    (void)shape;
    return CHECKED;
}

static mcs_status init_ready(void *obj, const uint64_t *shape)
{
    (void)obj;
    (void)shape;
    return MCS_OK; /* set up by the object's own init already */
}

/* Byte offset of an array from the head it follows. */
static size_t at(const void *state, const double *array)
{
    return (size_t)((const unsigned char *)(const void *)array - (const unsigned char *)state);
}

static io_field rows_of(size_t offset, unsigned char rows, unsigned char len,
                        unsigned char stride, unsigned rules)
{
    io_field f = {offset, IO_AS_ROWS, rows, len, stride, rules};
    return f;
}

/* The fields common to every kind here. */
static void kind_base(io_kind *k, uint32_t kind, uint32_t shape_len,
                      mcs_status (*sizes)(const uint64_t *, size_t *))
{
    memset(k, 0, sizeof *k);
    k->kind = kind;
    k->shape_len = shape_len;
    k->sizes = sizes;
    k->shape_at[0] = offsetof(mcs_ps_head, shape);
    k->shape_at[1] = offsetof(mcs_ps_head, shape) + sizeof(size_t);
    k->count = count_of_head;
    k->init = init_checked;
    k->count_at = offsetof(mcs_ps_head, count);
}

/* The memory checks of a load once the record passed: the caller's buffer
 * (need bytes of it) against the object and the record, and those two
 * against each other. Six arguments: a seventh would be pushed, a frame gcc
 * calls dynamic (make stack). */
static mcs_status check_load_alias(const void *acc, size_t acc_bytes, const void *mem,
                                   size_t need, const void *buf, size_t len)
{
    if (mcs_overlap_(mem, need, acc, acc_bytes) || mcs_overlap_(mem, need, buf, len) ||
        mcs_overlap_(acc, acc_bytes, buf, len))
        return MCS_ERR_ALIAS;
    return MCS_OK;
}

/* A save's record buffer must not overlap the object it reads. */
static int save_overlaps(const void *acc, size_t acc_bytes, const void *mem, size_t bytes,
                         const void *buf, size_t cap)
{
    return buf != NULL && (mcs_overlap_(buf, cap, acc, acc_bytes) || mcs_overlap_(buf, cap, mem, bytes));
}

static uint64_t shape_word(const void *buf, size_t len, size_t i)
{
    mcs_io_info info;
    (void)mcs_io_peek(len, buf, &info); /* cannot fail: the record passed */
    return info.shape[i];
}

/* ---- pointset: mean P(f) (a periodogram is >= 0), then its M2, f = 0..F ---- */

enum { PS_FREQS = 1 };

static mcs_status sizes_pointset(const uint64_t *shape, size_t *size)
{
    if (shape[0] == 0u || shape[0] > (uint64_t)MCS_POINTSET_MAX_FREQ)
        return MCS_ERR_FREQ_RANGE;
    size[PS_FREQS] = (size_t)shape[0] + 1u;
    return MCS_OK;
}

/* The table of a pointset record; the offsets are acc's (acc NULL: 0, for
 * the checking walk, which reads the payload only). */
static void kind_pointset(io_kind *k, const mcs_pointset *acc)
{
    kind_base(k, MCS_IO_KIND_POINTSET, 1u, sizes_pointset);
    k->nfields = 2u;
    k->fields[0] = rows_of(0u, IO_ONE, PS_FREQS, IO_ONE, IO_RULE_NONNEG);
    k->fields[1] = rows_of(0u, IO_ONE, PS_FREQS, IO_ONE, IO_RULE_M2);
    if (acc != NULL) {
        k->fields[0].offset = at(acc->state, acc->mean);
        k->fields[1].offset = at(acc->state, acc->m2);
    }
}

mcs_status mcs_io_save_pointset(const mcs_pointset *acc, size_t cap, void *buf, size_t *len)
{
    uint64_t count = 0u;
    mcs_status st = acc == NULL || len == NULL ? MCS_ERR_NULL : mcs_pointset_count(acc, &count);
    if (st == MCS_OK && save_overlaps(acc, sizeof *acc, acc->mem, acc->bytes, buf, cap))
        st = MCS_ERR_ALIAS;
    if (st != MCS_OK)
        return st;
    io_kind k;
    kind_pointset(&k, acc);
    return mcs_io_save(&k, acc->state, cap, buf, len);
}

mcs_status mcs_io_load_pointset(mcs_pointset *acc, unsigned flags, void *mem, size_t bytes,
                                size_t len, const void *buf)
{
    if (acc == NULL || mem == NULL || buf == NULL)
        return MCS_ERR_NULL;
    size_t need = 0u;
    if (mcs_pointset_size(1u, flags, &need) == MCS_ERR_DOMAIN)
        return MCS_ERR_DOMAIN;
    io_kind k;
    kind_pointset(&k, NULL);
    mcs_status st = mcs_io_load(&k, mem, len, buf); /* checks only */
    if (st != CHECKED)
        return st;
    const size_t f = (size_t)shape_word(buf, len, 0u);
    (void)mcs_pointset_size(f, flags, &need); /* cannot fail: F passed sizes_pointset */
    st = bytes < need ? MCS_ERR_SPACE : check_load_alias(acc, sizeof *acc, mem, need, buf, len);
    if (st != MCS_OK)
        return st;
    (void)mcs_pointset_init(acc, f, flags, mem, bytes); /* cannot fail: checked above */
    kind_pointset(&k, acc);
    k.init = init_ready;
    return mcs_io_load(&k, acc->state, len, buf);
}

/* ---- pointset2d: mean and M2 of P at fy = 0..F, fx = -F..F (row by row:
 * rows of 2F+1 stored 2F+2 apart, the pad not written), then the mean and
 * M2 of the annulus averages, radius 0..F ---- */

enum { P2_RADII = 1, P2_WIDTH = 2, P2_STRIDE = 3 };

static mcs_status sizes_pointset2d(const uint64_t *shape, size_t *size)
{
    if (shape[0] == 0u || shape[0] > (uint64_t)MCS_POINTSET2D_MAX_FREQ)
        return MCS_ERR_FREQ_RANGE;
    const size_t f = (size_t)shape[0];
    size[P2_RADII] = f + 1u;
    size[P2_WIDTH] = 2u * f + 1u;
    size[P2_STRIDE] = 2u * f + 2u;
    return MCS_OK;
}

static void kind_pointset2d(io_kind *k, const mcs_pointset2d *acc)
{
    kind_base(k, MCS_IO_KIND_POINTSET2D, 1u, sizes_pointset2d);
    k->nfields = 4u;
    k->fields[0] = rows_of(0u, P2_RADII, P2_WIDTH, P2_STRIDE, IO_RULE_NONNEG);
    k->fields[1] = rows_of(0u, P2_RADII, P2_WIDTH, P2_STRIDE, IO_RULE_M2);
    k->fields[2] = rows_of(0u, IO_ONE, P2_RADII, IO_ONE, IO_RULE_NONNEG);
    k->fields[3] = rows_of(0u, IO_ONE, P2_RADII, IO_ONE, IO_RULE_M2);
    if (acc != NULL) {
        const double *const arrays[4] = {acc->mean, acc->m2, acc->ring_mean, acc->ring_m2};
        for (size_t i = 0; i < 4u; ++i)
            k->fields[i].offset = at(acc->state, arrays[i]);
    }
}

mcs_status mcs_io_save_pointset2d(const mcs_pointset2d *acc, size_t cap, void *buf, size_t *len)
{
    uint64_t count = 0u;
    mcs_status st = acc == NULL || len == NULL ? MCS_ERR_NULL : mcs_pointset2d_count(acc, &count);
    if (st == MCS_OK && save_overlaps(acc, sizeof *acc, acc->mem, acc->bytes, buf, cap))
        st = MCS_ERR_ALIAS;
    if (st != MCS_OK)
        return st;
    io_kind k;
    kind_pointset2d(&k, acc);
    return mcs_io_save(&k, acc->state, cap, buf, len);
}

mcs_status mcs_io_load_pointset2d(mcs_pointset2d *acc, unsigned flags, void *mem, size_t bytes,
                                  size_t len, const void *buf)
{
    if (acc == NULL || mem == NULL || buf == NULL)
        return MCS_ERR_NULL;
    size_t need = 0u;
    if (mcs_pointset2d_size(1u, flags, &need) == MCS_ERR_DOMAIN)
        return MCS_ERR_DOMAIN;
    io_kind k;
    kind_pointset2d(&k, NULL);
    mcs_status st = mcs_io_load(&k, mem, len, buf); /* checks only */
    if (st != CHECKED)
        return st;
    const size_t f = (size_t)shape_word(buf, len, 0u);
    (void)mcs_pointset2d_size(f, flags, &need); /* cannot fail: F passed sizes_pointset2d */
    st = bytes < need ? MCS_ERR_SPACE : check_load_alias(acc, sizeof *acc, mem, need, buf, len);
    if (st != MCS_OK)
        return st;
    (void)mcs_pointset2d_init(acc, f, flags, mem, bytes); /* cannot fail: checked above */
    kind_pointset2d(&k, acc);
    k.init = init_ready;
    return mcs_io_load(&k, acc->state, len, buf);
}

/* ---- spectrum2d: five arrays over k2 = 0..N2/2, k1 = 0..N1-1 (rows of N1
 * stored N1 rounded up to even apart) ---- */

enum { S2_ROWS = 1, S2_WIDTH = 2, S2_STRIDE = 3 };

static mcs_status sizes_spectrum2d(const uint64_t *shape, size_t *size)
{
    if (shape[0] == 0u || shape[0] > (uint64_t)MCS_SPECTRUM2D_MAX_SIDE || shape[1] == 0u ||
        shape[1] > (uint64_t)MCS_SPECTRUM2D_MAX_SIDE)
        return MCS_ERR_N_RANGE;
    const size_t n_x = (size_t)shape[0];
    size[S2_ROWS] = (size_t)shape[1] / 2u + 1u;
    size[S2_WIDTH] = n_x;
    size[S2_STRIDE] = n_x + n_x % 2u;
    return MCS_OK;
}

static void kind_spectrum2d(io_kind *k, const mcs_spectrum2d *acc)
{
    static const unsigned rules[5] = {0u, 0u, IO_RULE_M2, IO_RULE_NONNEG, IO_RULE_M2};
    kind_base(k, MCS_IO_KIND_SPECTRUM2D, 2u, sizes_spectrum2d);
    k->nfields = 5u;
    for (size_t i = 0; i < 5u; ++i)
        k->fields[i] = rows_of(0u, S2_ROWS, S2_WIDTH, S2_STRIDE, rules[i]);
    if (acc != NULL) {
        const double *const arrays[5] = {acc->mean_re, acc->mean_im, acc->m2_s, acc->mean_pow,
                                         acc->m2_pow};
        for (size_t i = 0; i < 5u; ++i)
            k->fields[i].offset = at(acc->state, arrays[i]);
    }
}

mcs_status mcs_io_save_spectrum2d(const mcs_spectrum2d *acc, size_t cap, void *buf, size_t *len)
{
    uint64_t count = 0u;
    mcs_status st = acc == NULL || len == NULL ? MCS_ERR_NULL : mcs_spectrum2d_count(acc, &count);
    if (st == MCS_OK && save_overlaps(acc, sizeof *acc, acc->mem, acc->bytes, buf, cap))
        st = MCS_ERR_ALIAS;
    if (st != MCS_OK)
        return st;
    io_kind k;
    kind_spectrum2d(&k, acc);
    return mcs_io_save(&k, acc->state, cap, buf, len);
}

mcs_status mcs_io_load_spectrum2d(mcs_spectrum2d *acc, void *mem, size_t bytes, size_t len,
                                  const void *buf)
{
    if (acc == NULL || mem == NULL || buf == NULL)
        return MCS_ERR_NULL;
    io_kind k;
    kind_spectrum2d(&k, NULL);
    mcs_status st = mcs_io_load(&k, mem, len, buf); /* checks only */
    if (st != CHECKED)
        return st;
    const size_t n_x = (size_t)shape_word(buf, len, 0u), n_y = (size_t)shape_word(buf, len, 1u);
    size_t need = 0u;
    (void)mcs_spectrum2d_size(n_x, n_y, &need); /* cannot fail: the sides passed */
    st = bytes < need ? MCS_ERR_SPACE : check_load_alias(acc, sizeof *acc, mem, need, buf, len);
    if (st != MCS_OK)
        return st;
    (void)mcs_spectrum2d_init(acc, n_x, n_y, mem, bytes); /* cannot fail: checked above */
    kind_spectrum2d(&k, acc);
    k.init = init_ready;
    return mcs_io_load(&k, acc->state, len, buf);
}

/* ---- pcf: shape [dim, estimator, B, radius, sigma] (the last two as the
 * bits of their doubles), payload k_min, k_max, then mean[B] and M2[B]: the
 * header is the caller's struct and the arrays are in its buffer, so the
 * walker's object is the header and the arrays are reached through its
 * pointers (IO_AS_POINTED) ---- */

enum { PC_BINS = 1 };

static double double_of(uint64_t bits)
{
    double v;
    memcpy(&v, &bits, sizeof v);
    return v;
}

static uint64_t bits_of(double v)
{
    uint64_t bits;
    memcpy(&bits, &v, sizeof bits);
    return bits;
}

/* The header a shape describes, without a buffer (for the checks). */
static mcs_pcf pcf_of_shape(const uint64_t *shape)
{
    mcs_pcf h;
    memset(&h, 0, sizeof h);
    h.dim = (size_t)shape[0];
    h.estimator = shape[1] == 1u ? MCS_PCF_GAUSSIAN : MCS_PCF_RDF;
    h.bins = (size_t)shape[2];
    h.radius = double_of(shape[3]);
    h.sigma = double_of(shape[4]);
    return h;
}

static int positive_finite(double x)
{
    return isfinite(x) && x > 0.0;
}

/* A shape mcs_pcf_init takes and leaves as it is: sigma exactly +0 for the
 * RDF (init stores 0), positive and finite for the kernel. */
static mcs_status sizes_pcf(const uint64_t *shape, size_t *size)
{
    if ((shape[0] != 1u && shape[0] != 2u) || shape[1] > 1u)
        return MCS_ERR_DOMAIN;
    if (shape[2] == 0u || shape[2] > (uint64_t)MCS_PCF_MAX_BINS)
        return MCS_ERR_N_RANGE;
    const double radius = double_of(shape[3]), sigma = double_of(shape[4]);
    if (!positive_finite(radius) || (shape[1] == 1u ? !positive_finite(sigma) : shape[4] != 0u))
        return MCS_ERR_DOMAIN;
    size[PC_BINS] = (size_t)shape[2];
    return MCS_OK;
}

static void shape_pcf(const void *obj, uint64_t *shape)
{
    const mcs_pcf *acc = (const mcs_pcf *)obj;
    shape[0] = acc->dim;
    shape[1] = acc->estimator == MCS_PCF_GAUSSIAN ? 1u : 0u;
    shape[2] = acc->bins;
    shape[3] = bits_of(acc->radius);
    shape[4] = bits_of(acc->sigma);
}

static mcs_status count_pcf(const void *obj, uint64_t *count)
{
    return mcs_pcf_count((const mcs_pcf *)obj, count);
}

/* The largest g one set of k points can give in bin b: every pair in the
 * bin (RDF), or every pair at the kernel's peak (Gaussian); it grows with
 * k, so the one of k_max bounds the mean over the sets. */
static double pcf_bound(const mcs_pcf *h, size_t k, size_t b)
{
    const double s = mcs_pcf_spacing_(h->dim, k), width = h->radius / (double)h->bins * s;
    if (h->estimator == MCS_PCF_RDF)
        return 1.0 / mcs_pcf_ring_(h->dim, (double)b * width, (double)(b + 1u) * width);
    const double r = ((double)b + 0.5) * width, sigma = h->sigma * s;
    const double peak = 1.0 / (sigma * sqrt(2.0 * 3.14159265358979323846));
    return peak / (h->dim == 1u ? 2.0 : 2.0 * 3.14159265358979323846 * r);
}

/* The invariants of pcf.h's state check (pcf.c, mcs_pcf_check_) on the
 * values, and what the adds imply: 2 <= k_min <= k_max with the cutoff at
 * k_min within 1/2 (mcs_pcf_add refuses other sets); the means >= 0 (the
 * rule) and at most pcf_bound at k_max. */
static int pcf_ok(const io_values *values, uint64_t count)
{
    const double k_min = mcs_io_value(values, 0u), k_max = mcs_io_value(values, 1u);
    if (count == 0u)
        return 1; /* every value 0: the rules */
    if (!(k_min >= 2.0 && k_min <= k_max))
        return 0;
    const mcs_pcf h = pcf_of_shape(values->shape);
    size_t side = 0u, need = 0u;
    if (mcs_pcf_set_check_(&h, (size_t)k_min, &side, &need) != MCS_OK ||
        mcs_pcf_set_check_(&h, (size_t)k_max, &side, &need) != MCS_OK)
        return 0;
    const double slack = 1.0 + 0x1p-20;
    for (size_t b = 0; b < h.bins; ++b)
        if (!(mcs_io_value(values, 2u + b) <= pcf_bound(&h, (size_t)k_max, b) * slack))
            return 0;
    return 1;
}

static const io_kind kind_pcf = {
    .kind = MCS_IO_KIND_PCF,
    .shape_len = 5u,
    .sizes = sizes_pcf,
    .count = count_pcf,
    .init = init_checked,
    .count_at = offsetof(mcs_pcf, count),
    .valid = pcf_ok,
    .nfields = 4u,
    .fields = {IO_SIZE(mcs_pcf, k_min, IO_RULE_NONNEG), IO_SIZE(mcs_pcf, k_max, IO_RULE_NONNEG),
               IO_POINTED(mcs_pcf, mean, PC_BINS, IO_RULE_NONNEG),
               IO_POINTED(mcs_pcf, m2, PC_BINS, IO_RULE_M2)},
    .shape_of = shape_pcf};

mcs_status mcs_io_save_pcf(const mcs_pcf *acc, size_t cap, void *buf, size_t *len)
{
    uint64_t count = 0u;
    mcs_status st = acc == NULL || len == NULL ? MCS_ERR_NULL : mcs_pcf_count(acc, &count);
    if (st == MCS_OK && save_overlaps(acc, sizeof *acc, acc->mem, acc->bytes, buf, cap))
        st = MCS_ERR_ALIAS;
    return st != MCS_OK ? st : mcs_io_save(&kind_pcf, acc, cap, buf, len);
}

mcs_status mcs_io_load_pcf(mcs_pcf *acc, void *mem, size_t bytes, size_t len, const void *buf)
{
    if (acc == NULL || mem == NULL || buf == NULL)
        return MCS_ERR_NULL;
    mcs_status st = mcs_io_load(&kind_pcf, acc, len, buf); /* checks only */
    if (st != CHECKED)
        return st;
    uint64_t shape[5];
    for (size_t i = 0; i < 5u; ++i)
        shape[i] = shape_word(buf, len, i);
    const mcs_pcf h = pcf_of_shape(shape);
    const size_t need = MCS_PCF_SIZE(h.bins);
    st = bytes < need ? MCS_ERR_SPACE : check_load_alias(acc, sizeof *acc, mem, need, buf, len);
    if (st != MCS_OK)
        return st;
    /* cannot fail: the shape passed sizes_pcf and the memory was checked */
    (void)mcs_pcf_init(acc, h.dim, h.estimator, h.bins, h.radius, h.sigma, mem, bytes);
    io_kind k = kind_pcf;
    k.init = init_ready;
    return mcs_io_load(&k, acc, len, buf);
}

/* ---- the memory a load needs ---- */

mcs_status mcs_io_load_size(size_t len, const void *buf, unsigned flags, size_t *bytes)
{
    if (buf == NULL || bytes == NULL)
        return MCS_ERR_NULL;
    size_t need = 0u;
    if (mcs_pointset_size(1u, flags, &need) == MCS_ERR_DOMAIN)
        return MCS_ERR_DOMAIN;
    mcs_io_info info;
    mcs_status st = mcs_io_peek(len, buf, &info);
    if (st != MCS_OK)
        return st;
    const uint64_t *shape = info.shape;
    switch (info.kind) {
    case MCS_IO_KIND_SPECTRUM:
    case MCS_IO_KIND_MOMENT:
    case MCS_IO_KIND_AUTOCORR:
    case MCS_IO_KIND_WELFORD:
    case MCS_IO_KIND_INTEGRATE:
    case MCS_IO_KIND_DISCREPANCY:
    case MCS_IO_KIND_SPACING: need = 0u; break;
    case MCS_IO_KIND_PCF: {
        size_t size[IO_MAX_DIMS];
        if (info.shape_len != 5u)
            return MCS_ERR_FORMAT;
        st = sizes_pcf(shape, size);
        if (st == MCS_OK)
            need = MCS_PCF_SIZE(shape[2]);
        break;
    }
    case MCS_IO_KIND_POINTSET:
    case MCS_IO_KIND_POINTSET2D: {
        if (info.shape_len != 1u)
            return MCS_ERR_FORMAT;
        const uint64_t cap = info.kind == MCS_IO_KIND_POINTSET ? MCS_POINTSET_MAX_FREQ
                                                               : MCS_POINTSET2D_MAX_FREQ;
        if (shape[0] == 0u || shape[0] > cap)
            return MCS_ERR_FREQ_RANGE;
        st = info.kind == MCS_IO_KIND_POINTSET ? mcs_pointset_size((size_t)shape[0], flags, &need)
                                               : mcs_pointset2d_size((size_t)shape[0], flags, &need);
        break;
    }
    case MCS_IO_KIND_SPECTRUM2D:
        if (info.shape_len != 2u)
            return MCS_ERR_FORMAT;
        if (shape[0] == 0u || shape[0] > MCS_SPECTRUM2D_MAX_SIDE || shape[1] == 0u ||
            shape[1] > MCS_SPECTRUM2D_MAX_SIDE)
            return MCS_ERR_N_RANGE;
        st = mcs_spectrum2d_size((size_t)shape[0], (size_t)shape[1], &need);
        break;
    default: return MCS_ERR_KIND;
    }
    if (st == MCS_OK)
        *bytes = need;
    return st;
}
