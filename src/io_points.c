/* The record kinds of the point-set and 2D accumulators (docs/format.md):
 * mcs_pointset (kind 5), mcs_pointset2d (6) and mcs_spectrum2d (7). As in
 * io_kinds.c: a layout, an emit listing the values in payload order, and a
 * load decoding them in the same order into a freshly initialised object.
 * Only the entries in use are written, so the bytes depend on F or N1, N2
 * and not on MCS_MAX_FREQ_1D, MCS_MAX_FREQ or MCS_MAX_SIDE. */
#include "io_internal.h"

/* ---- pointset: mean P(f), then its M2, f = 0..F ---- */

static mcs_status layout_pointset(const uint64_t *shape, io_layout *lay)
{
    if (shape[0] == 0u || shape[0] > (uint64_t)MCS_MAX_FREQ_1D)
        return MCS_ERR_FREQ_RANGE;
    mcs_io_layout_start(lay, MCS_IO_KIND_POINTSET, 1u, shape);
    const size_t nf = (size_t)shape[0] + 1u;
    mcs_io_add_range(lay, nf, IO_RULE_NONNEG);                   /* a periodogram is >= 0 */
    mcs_io_add_range(lay, nf, IO_RULE_NONNEG | IO_RULE_SPREAD);  /* m2 */
    return MCS_OK;
}

static void emit_pointset(const void *obj, io_sink *sink)
{
    const mcs_pointset *acc = (const mcs_pointset *)obj;
    mcs_io_put_array(sink, acc->mean, acc->freq_max + 1u);
    mcs_io_put_array(sink, acc->m2, acc->freq_max + 1u);
}

mcs_status mcs_io_save_pointset(const mcs_pointset *acc, size_t cap, void *buf, size_t *len)
{
    uint64_t count;
    io_layout lay;
    if (acc == NULL || len == NULL)
        return MCS_ERR_NULL;
    mcs_status st = mcs_pointset_count(acc, &count); /* MCS_ERR_UNINIT */
    if (st != MCS_OK)
        return st;
    const uint64_t f = acc->freq_max;
    (void)layout_pointset(&f, &lay); /* cannot fail: acc->freq_max is in range */
    const io_source src = {acc, emit_pointset, count};
    return mcs_io_save_record(&lay, &src, cap, buf, len);
}

static const io_kind kind_pointset = {MCS_IO_KIND_POINTSET, 1u, layout_pointset};

mcs_status mcs_io_load_pointset(mcs_pointset *acc, size_t len, const void *buf)
{
    io_record rec;
    if (acc == NULL || buf == NULL)
        return MCS_ERR_NULL;
    mcs_status st = mcs_io_load_check(&kind_pointset, len, buf, &rec);
    if (st != MCS_OK)
        return st;
    const size_t nf = (size_t)rec.lay.shape[0] + 1u;
    st = mcs_pointset_init(acc, nf - 1u); /* leaves acc as it was on error */
    if (st != MCS_OK)
        return st;
    mcs_io_get_array(acc->mean, rec.payload, 0u, nf);
    mcs_io_get_array(acc->m2, rec.payload, nf, nf);
    acc->count = rec.count;
    return MCS_OK;
}

/* ---- pointset2d: mean and M2 of P at fy = 0..F, fx = -F..F (row by row),
 * then the mean and M2 of the annulus averages, radius 0..F ---- */

static mcs_status layout_pointset2d(const uint64_t *shape, io_layout *lay)
{
    if (shape[0] == 0u || shape[0] > (uint64_t)MCS_MAX_FREQ)
        return MCS_ERR_FREQ_RANGE;
    mcs_io_layout_start(lay, MCS_IO_KIND_POINTSET2D, 1u, shape);
    const size_t f = (size_t)shape[0], cells = (2u * f + 1u) * (f + 1u);
    mcs_io_add_range(lay, cells, IO_RULE_NONNEG);
    mcs_io_add_range(lay, cells, IO_RULE_NONNEG | IO_RULE_SPREAD);
    mcs_io_add_range(lay, f + 1u, IO_RULE_NONNEG);
    mcs_io_add_range(lay, f + 1u, IO_RULE_NONNEG | IO_RULE_SPREAD);
    return MCS_OK;
}

/* The (2F+1)-wide rows of a, stored 2F+2 apart (the pad is not written). */
static void put_rows(io_sink *sink, const double *a, size_t f)
{
    for (size_t fy = 0; fy <= f; ++fy)
        mcs_io_put_array(sink, a + fy * (2u * f + 2u), 2u * f + 1u);
}

static void get_rows(double *a, const uint8_t *payload, size_t first, size_t f)
{
    for (size_t fy = 0; fy <= f; ++fy)
        mcs_io_get_array(a + fy * (2u * f + 2u), payload, first + fy * (2u * f + 1u),
                         2u * f + 1u);
}

static void emit_pointset2d(const void *obj, io_sink *sink)
{
    const mcs_pointset2d *acc = (const mcs_pointset2d *)obj;
    const size_t f = acc->freq_max;
    put_rows(sink, acc->mean, f);
    put_rows(sink, acc->m2, f);
    mcs_io_put_array(sink, acc->ring_mean, f + 1u);
    mcs_io_put_array(sink, acc->ring_m2, f + 1u);
}

mcs_status mcs_io_save_pointset2d(const mcs_pointset2d *acc, size_t cap, void *buf, size_t *len)
{
    uint64_t count;
    io_layout lay;
    if (acc == NULL || len == NULL)
        return MCS_ERR_NULL;
    mcs_status st = mcs_pointset2d_count(acc, &count);
    if (st != MCS_OK)
        return st;
    const uint64_t f = acc->freq_max;
    (void)layout_pointset2d(&f, &lay);
    const io_source src = {acc, emit_pointset2d, count};
    return mcs_io_save_record(&lay, &src, cap, buf, len);
}

static const io_kind kind_pointset2d = {MCS_IO_KIND_POINTSET2D, 1u, layout_pointset2d};

mcs_status mcs_io_load_pointset2d(mcs_pointset2d *acc, size_t len, const void *buf)
{
    io_record rec;
    if (acc == NULL || buf == NULL)
        return MCS_ERR_NULL;
    mcs_status st = mcs_io_load_check(&kind_pointset2d, len, buf, &rec);
    if (st != MCS_OK)
        return st;
    const size_t f = (size_t)rec.lay.shape[0], cells = (2u * f + 1u) * (f + 1u);
    st = mcs_pointset2d_init(acc, f);
    if (st != MCS_OK)
        return st;
    get_rows(acc->mean, rec.payload, 0u, f);
    get_rows(acc->m2, rec.payload, cells, f);
    mcs_io_get_array(acc->ring_mean, rec.payload, 2u * cells, f + 1u);
    mcs_io_get_array(acc->ring_m2, rec.payload, 2u * cells + f + 1u, f + 1u);
    acc->count = rec.count;
    return MCS_OK;
}

/* ---- spectrum2d: five arrays over k2 = 0..N2/2, k1 = 0..N1-1 ---- */

static mcs_status layout_spectrum2d(const uint64_t *shape, io_layout *lay)
{
    if (shape[0] == 0u || shape[0] > (uint64_t)MCS_MAX_SIDE || shape[1] == 0u ||
        shape[1] > (uint64_t)MCS_MAX_SIDE)
        return MCS_ERR_N_RANGE;
    mcs_io_layout_start(lay, MCS_IO_KIND_SPECTRUM2D, 2u, shape);
    const size_t cells = (size_t)shape[0] * ((size_t)shape[1] / 2u + 1u);
    mcs_io_add_range(lay, 2u * cells, 0u);                          /* mean_re, mean_im */
    mcs_io_add_range(lay, cells, IO_RULE_NONNEG | IO_RULE_SPREAD);  /* m2_s */
    mcs_io_add_range(lay, cells, IO_RULE_NONNEG);                   /* mean_pow */
    mcs_io_add_range(lay, cells, IO_RULE_NONNEG | IO_RULE_SPREAD);  /* m2_pow */
    return MCS_OK;
}

/* Rows k2 = 0..N2/2 of N1 values, stored N1 rounded up to even apart. */
static void put_grid(io_sink *sink, const double *a, size_t n_x, size_t n_y)
{
    const size_t stride = n_x + n_x % 2u;
    for (size_t k2 = 0; k2 <= n_y / 2u; ++k2)
        mcs_io_put_array(sink, a + k2 * stride, n_x);
}

static void get_grid(double *a, const uint8_t *payload, size_t first, size_t n_x, size_t n_y)
{
    const size_t stride = n_x + n_x % 2u;
    for (size_t k2 = 0; k2 <= n_y / 2u; ++k2)
        mcs_io_get_array(a + k2 * stride, payload, first + k2 * n_x, n_x);
}

static void emit_spectrum2d(const void *obj, io_sink *sink)
{
    const mcs_spectrum2d *acc = (const mcs_spectrum2d *)obj;
    put_grid(sink, acc->mean_re, acc->n_x, acc->n_y);
    put_grid(sink, acc->mean_im, acc->n_x, acc->n_y);
    put_grid(sink, acc->m2_s, acc->n_x, acc->n_y);
    put_grid(sink, acc->mean_pow, acc->n_x, acc->n_y);
    put_grid(sink, acc->m2_pow, acc->n_x, acc->n_y);
}

mcs_status mcs_io_save_spectrum2d(const mcs_spectrum2d *acc, size_t cap, void *buf, size_t *len)
{
    uint64_t count;
    io_layout lay;
    if (acc == NULL || len == NULL)
        return MCS_ERR_NULL;
    mcs_status st = mcs_spectrum2d_count(acc, &count);
    if (st != MCS_OK)
        return st;
    const uint64_t shape[2] = {acc->n_x, acc->n_y};
    (void)layout_spectrum2d(shape, &lay);
    const io_source src = {acc, emit_spectrum2d, count};
    return mcs_io_save_record(&lay, &src, cap, buf, len);
}

static const io_kind kind_spectrum2d = {MCS_IO_KIND_SPECTRUM2D, 2u, layout_spectrum2d};

mcs_status mcs_io_load_spectrum2d(mcs_spectrum2d *acc, size_t len, const void *buf)
{
    io_record rec;
    if (acc == NULL || buf == NULL)
        return MCS_ERR_NULL;
    mcs_status st = mcs_io_load_check(&kind_spectrum2d, len, buf, &rec);
    if (st != MCS_OK)
        return st;
    const size_t n_x = (size_t)rec.lay.shape[0], n_y = (size_t)rec.lay.shape[1];
    const size_t cells = n_x * (n_y / 2u + 1u);
    st = mcs_spectrum2d_init(acc, n_x, n_y);
    if (st != MCS_OK)
        return st;
    get_grid(acc->mean_re, rec.payload, 0u, n_x, n_y);
    get_grid(acc->mean_im, rec.payload, cells, n_x, n_y);
    get_grid(acc->m2_s, rec.payload, 2u * cells, n_x, n_y);
    get_grid(acc->mean_pow, rec.payload, 3u * cells, n_x, n_y);
    get_grid(acc->m2_pow, rec.payload, 4u * cells, n_x, n_y);
    acc->count = rec.count;
    return MCS_OK;
}
