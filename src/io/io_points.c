/* The record kinds of the point-set and 2D accumulators (docs/format.md):
 * mcs_pointset (kind 5), mcs_pointset2d (6) and mcs_spectrum2d (7). As in
 * io_kinds.c: sizes for a shape and a table of fields in payload order,
 * which io.c walks to save, check and load. Only the entries in use are
 * written, so the bytes depend on F or N1, N2 and nothing else.
 *
 * These objects keep their statistics in a caller buffer behind a head
 * (pointsets/pointset_internal.h: the shape words, then the trial count),
 * so the walker's object is that head and each table is made per call with
 * the offsets of the object's arrays from it; io_mem.c saves and loads
 * them (a load walks the record twice, io_internal.h says why). */
#include "io_internal.h"
#include "measures/pcf_internal.h"
#include "pointsets/pointset_internal.h"

#include <math.h>
#include <string.h>

static mcs_status count_of_head(const void *obj, uint64_t *count)
{
    memcpy(count, (const unsigned char *)obj + offsetof(mcs_ps_head, count), sizeof *count);
    return MCS_OK;
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
    k->init = mcs_io_init_checked;
    k->count_at = offsetof(mcs_ps_head, count);
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
static void kind_pointset(io_kind *k, const void *obj)
{
    const mcs_pointset *acc = obj;
    kind_base(k, MCS_IO_KIND_POINTSET, 1u, sizes_pointset);
    k->nfields = 2u;
    k->fields[0] = rows_of(0u, IO_ONE, PS_FREQS, IO_ONE, IO_RULE_NONNEG);
    k->fields[1] = rows_of(0u, IO_ONE, PS_FREQS, IO_ONE, IO_RULE_M2);
    if (acc != NULL) {
        k->fields[0].offset = at(acc->state, acc->mean);
        k->fields[1].offset = at(acc->state, acc->m2);
    }
}

static void *state_pointset(const void *acc) { return ((const mcs_pointset *)acc)->state; }
static mcs_status count_pointset(const void *acc, uint64_t *count)
{
    return mcs_pointset_count(acc, count);
}
static mcs_status size_pointset(const uint64_t *shape, unsigned flags, size_t *need)
{
    return mcs_pointset_size((size_t)shape[0], flags, need);
}
static mcs_status init_pointset(void *acc, const uint64_t *shape, unsigned flags, void *mem,
                                size_t bytes)
{
    return mcs_pointset_init(acc, (size_t)shape[0], flags, mem, bytes);
}

static const io_mem_kind mem_pointset = {
    kind_pointset, state_pointset, sizeof(mcs_pointset), offsetof(mcs_pointset, mem),
    offsetof(mcs_pointset, bytes), count_pointset, size_pointset, init_pointset};

mcs_status mcs_io_save_pointset(const mcs_pointset *acc, size_t cap, void *buf, size_t *len)
{
    return mcs_io_save_mem(&mem_pointset, acc, cap, buf, len);
}

mcs_status mcs_io_load_pointset(mcs_pointset *acc, unsigned flags, void *mem, size_t bytes,
                                size_t len, const void *buf)
{
    const io_mem_arg arg = {mem, bytes, flags};
    return mcs_io_load_mem(&mem_pointset, acc, &arg, len, buf);
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

static void kind_pointset2d(io_kind *k, const void *obj)
{
    const mcs_pointset2d *acc = obj;
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

static void *state_pointset2d(const void *acc) { return ((const mcs_pointset2d *)acc)->state; }
static mcs_status count_pointset2d(const void *acc, uint64_t *count)
{
    return mcs_pointset2d_count(acc, count);
}
static mcs_status size_pointset2d(const uint64_t *shape, unsigned flags, size_t *need)
{
    return mcs_pointset2d_size((size_t)shape[0], flags, need);
}
static mcs_status init_pointset2d(void *acc, const uint64_t *shape, unsigned flags, void *mem,
                                  size_t bytes)
{
    return mcs_pointset2d_init(acc, (size_t)shape[0], flags, mem, bytes);
}

static const io_mem_kind mem_pointset2d = {
    kind_pointset2d, state_pointset2d, sizeof(mcs_pointset2d), offsetof(mcs_pointset2d, mem),
    offsetof(mcs_pointset2d, bytes), count_pointset2d, size_pointset2d, init_pointset2d};

mcs_status mcs_io_save_pointset2d(const mcs_pointset2d *acc, size_t cap, void *buf, size_t *len)
{
    return mcs_io_save_mem(&mem_pointset2d, acc, cap, buf, len);
}

mcs_status mcs_io_load_pointset2d(mcs_pointset2d *acc, unsigned flags, void *mem, size_t bytes,
                                  size_t len, const void *buf)
{
    const io_mem_arg arg = {mem, bytes, flags};
    return mcs_io_load_mem(&mem_pointset2d, acc, &arg, len, buf);
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

static void kind_spectrum2d(io_kind *k, const void *obj)
{
    static const unsigned rules[5] = {0u, 0u, IO_RULE_M2, IO_RULE_NONNEG, IO_RULE_M2};
    const mcs_spectrum2d *acc = obj;
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

static void *state_spectrum2d(const void *acc) { return ((const mcs_spectrum2d *)acc)->state; }
static mcs_status count_spectrum2d(const void *acc, uint64_t *count)
{
    return mcs_spectrum2d_count(acc, count);
}
/* No flags: the load passes 0. */
static mcs_status size_spectrum2d(const uint64_t *shape, unsigned flags, size_t *need)
{
    (void)flags;
    return mcs_spectrum2d_size((size_t)shape[0], (size_t)shape[1], need);
}
static mcs_status init_spectrum2d(void *acc, const uint64_t *shape, unsigned flags, void *mem,
                                  size_t bytes)
{
    (void)flags;
    return mcs_spectrum2d_init(acc, (size_t)shape[0], (size_t)shape[1], mem, bytes);
}

static const io_mem_kind mem_spectrum2d = {
    kind_spectrum2d, state_spectrum2d, sizeof(mcs_spectrum2d), offsetof(mcs_spectrum2d, mem),
    offsetof(mcs_spectrum2d, bytes), count_spectrum2d, size_spectrum2d, init_spectrum2d};

mcs_status mcs_io_save_spectrum2d(const mcs_spectrum2d *acc, size_t cap, void *buf, size_t *len)
{
    return mcs_io_save_mem(&mem_spectrum2d, acc, cap, buf, len);
}

mcs_status mcs_io_load_spectrum2d(mcs_spectrum2d *acc, void *mem, size_t bytes, size_t len,
                                  const void *buf)
{
    const io_mem_arg arg = {mem, bytes, 0u};
    return mcs_io_load_mem(&mem_spectrum2d, acc, &arg, len, buf);
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
    case MCS_IO_KIND_PCF:
        if (info.shape_len != 5u)
            return MCS_ERR_FORMAT;
        st = mcs_io_pcf_need(shape, &need);
        break;
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
