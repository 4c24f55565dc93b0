/* The record kinds of the point-set and 2D accumulators (docs/format.md):
 * mcs_pointset (kind 5), mcs_pointset2d (6) and mcs_spectrum2d (7). As in
 * io_kinds.c: sizes for a shape and a table of fields in payload order,
 * which io.c walks to save, check and load. Only the entries in use are
 * written, so the bytes depend on F or N1, N2 and not on MCS_MAX_FREQ_1D,
 * MCS_MAX_FREQ or MCS_MAX_SIDE. */
#include "io_internal.h"

/* ---- pointset: mean P(f) (a periodogram is >= 0), then its M2, f = 0..F ---- */

enum { PS_FREQS = 1 };

static mcs_status sizes_pointset(const uint64_t *shape, size_t *size)
{
    if (shape[0] == 0u || shape[0] > (uint64_t)MCS_MAX_FREQ_1D)
        return MCS_ERR_FREQ_RANGE;
    size[PS_FREQS] = (size_t)shape[0] + 1u;
    return MCS_OK;
}

static mcs_status count_pointset(const void *obj, uint64_t *count)
{
    return mcs_pointset_count((const mcs_pointset *)obj, count);
}

static mcs_status init_pointset(void *obj, const uint64_t *shape)
{
    return mcs_pointset_init((mcs_pointset *)obj, (size_t)shape[0]);
}

static const io_kind kind_pointset = {
    MCS_IO_KIND_POINTSET, 1u, sizes_pointset, {offsetof(mcs_pointset, freq_max)},
    count_pointset, init_pointset, offsetof(mcs_pointset, count), NULL, 2u,
    {IO_ARRAY(mcs_pointset, mean, PS_FREQS, IO_RULE_NONNEG),
     IO_ARRAY(mcs_pointset, m2, PS_FREQS, IO_RULE_M2)}};

mcs_status mcs_io_save_pointset(const mcs_pointset *acc, size_t cap, void *buf, size_t *len)
{
    return mcs_io_save(&kind_pointset, acc, cap, buf, len);
}

mcs_status mcs_io_load_pointset(mcs_pointset *acc, size_t len, const void *buf)
{
    return mcs_io_load(&kind_pointset, acc, len, buf);
}

/* ---- pointset2d: mean and M2 of P at fy = 0..F, fx = -F..F (row by row:
 * rows of 2F+1 stored 2F+2 apart, the pad not written), then the mean and
 * M2 of the annulus averages, radius 0..F ---- */

enum { P2_RADII = 1, P2_WIDTH = 2, P2_STRIDE = 3 };

static mcs_status sizes_pointset2d(const uint64_t *shape, size_t *size)
{
    if (shape[0] == 0u || shape[0] > (uint64_t)MCS_MAX_FREQ)
        return MCS_ERR_FREQ_RANGE;
    const size_t f = (size_t)shape[0];
    size[P2_RADII] = f + 1u;
    size[P2_WIDTH] = 2u * f + 1u;
    size[P2_STRIDE] = 2u * f + 2u;
    return MCS_OK;
}

static mcs_status count_pointset2d(const void *obj, uint64_t *count)
{
    return mcs_pointset2d_count((const mcs_pointset2d *)obj, count);
}

static mcs_status init_pointset2d(void *obj, const uint64_t *shape)
{
    return mcs_pointset2d_init((mcs_pointset2d *)obj, (size_t)shape[0]);
}

static const io_kind kind_pointset2d = {
    MCS_IO_KIND_POINTSET2D, 1u, sizes_pointset2d, {offsetof(mcs_pointset2d, freq_max)},
    count_pointset2d, init_pointset2d, offsetof(mcs_pointset2d, count), NULL, 4u,
    {IO_GRID(mcs_pointset2d, mean, P2_RADII, P2_WIDTH, P2_STRIDE, IO_RULE_NONNEG),
     IO_GRID(mcs_pointset2d, m2, P2_RADII, P2_WIDTH, P2_STRIDE, IO_RULE_M2),
     IO_ARRAY(mcs_pointset2d, ring_mean, P2_RADII, IO_RULE_NONNEG),
     IO_ARRAY(mcs_pointset2d, ring_m2, P2_RADII, IO_RULE_M2)}};

mcs_status mcs_io_save_pointset2d(const mcs_pointset2d *acc, size_t cap, void *buf, size_t *len)
{
    return mcs_io_save(&kind_pointset2d, acc, cap, buf, len);
}

mcs_status mcs_io_load_pointset2d(mcs_pointset2d *acc, size_t len, const void *buf)
{
    return mcs_io_load(&kind_pointset2d, acc, len, buf);
}

/* ---- spectrum2d: five arrays over k2 = 0..N2/2, k1 = 0..N1-1 (rows of N1
 * stored N1 rounded up to even apart) ---- */

enum { S2_ROWS = 1, S2_WIDTH = 2, S2_STRIDE = 3 };

static mcs_status sizes_spectrum2d(const uint64_t *shape, size_t *size)
{
    if (shape[0] == 0u || shape[0] > (uint64_t)MCS_MAX_SIDE || shape[1] == 0u ||
        shape[1] > (uint64_t)MCS_MAX_SIDE)
        return MCS_ERR_N_RANGE;
    const size_t n_x = (size_t)shape[0];
    size[S2_ROWS] = (size_t)shape[1] / 2u + 1u;
    size[S2_WIDTH] = n_x;
    size[S2_STRIDE] = n_x + n_x % 2u;
    return MCS_OK;
}

static mcs_status count_spectrum2d(const void *obj, uint64_t *count)
{
    return mcs_spectrum2d_count((const mcs_spectrum2d *)obj, count);
}

static mcs_status init_spectrum2d(void *obj, const uint64_t *shape)
{
    return mcs_spectrum2d_init((mcs_spectrum2d *)obj, (size_t)shape[0], (size_t)shape[1]);
}

#define S2_GRID(member, rules) IO_GRID(mcs_spectrum2d, member, S2_ROWS, S2_WIDTH, S2_STRIDE, rules)

static const io_kind kind_spectrum2d = {
    MCS_IO_KIND_SPECTRUM2D, 2u, sizes_spectrum2d,
    {offsetof(mcs_spectrum2d, n_x), offsetof(mcs_spectrum2d, n_y)},
    count_spectrum2d, init_spectrum2d, offsetof(mcs_spectrum2d, count), NULL, 5u,
    {S2_GRID(mean_re, 0u), S2_GRID(mean_im, 0u), S2_GRID(m2_s, IO_RULE_M2),
     S2_GRID(mean_pow, IO_RULE_NONNEG), S2_GRID(m2_pow, IO_RULE_M2)}};

mcs_status mcs_io_save_spectrum2d(const mcs_spectrum2d *acc, size_t cap, void *buf, size_t *len)
{
    return mcs_io_save(&kind_spectrum2d, acc, cap, buf, len);
}

mcs_status mcs_io_load_spectrum2d(mcs_spectrum2d *acc, size_t len, const void *buf)
{
    return mcs_io_load(&kind_spectrum2d, acc, len, buf);
}
