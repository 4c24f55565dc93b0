#include "mcspec/pointset2d.h"
#include "pointset_internal.h"

#include <math.h>
#include <string.h>

/* Layout: wave vector (fx, fy), fy = 0..F, fx = -F..F, at fy (2F+2) + fx + F
 * (column 2F+1 of each row is padding that stays 0 and is never read).
 * The fy = 0 row is stored whole; (fx, fy > 0) stands for itself and for
 * (-fx, -fy), so whole-plane sums weigh the fy = 0 row 1 and the rest 2. */

enum { XR = 0, XI = 1, YR = 2, YI = 3 };

/* An exactly empty annulus (a grid's) measures as rounding residue, around
 * K 1e-32; below this its mean counts as 0. */
#define RING_ZERO 1e-20

/* Stored wave vectors: (2F + 2) columns by F + 1 rows. */
static size_t cells_of(size_t fmax)
{
    return (2u * fmax + 2u) * (fmax + 1u);
}

/* The arrays of the buffer, by their names in the layout: the statistics,
 * then the scratch. */
enum { MEAN, M2, RING_MEAN, RING_M2, RE, IM, PHASE, STAGE };

/* The checks of a size query and the layout for (fmax, flags). */
static mcs_status layout_of(size_t fmax, unsigned flags, mcs_ps_layout *lay)
{
    memset(lay, 0, sizeof *lay);
    if (fmax == 0u || fmax > (size_t)MCS_POINTSET2D_MAX_FREQ)
        return MCS_ERR_FREQ_RANGE;
    if ((flags & ~(unsigned)MCS_POINTSET_DIRECT_ONLY) != 0u)
        return MCS_ERR_DOMAIN;
    const size_t cells = cells_of(fmax), radii = fmax + 1u, side = 2u * fmax + 1u;
    const size_t d = sizeof(double);
    lay->shape[0] = fmax;
    mcs_ps_carve c = {0u, 0};
    (void)mcs_ps_take(&c, 1u, sizeof(mcs_ps_head));
    lay->at[MEAN] = mcs_ps_take(&c, cells, d);
    lay->at[M2] = mcs_ps_take(&c, cells, d);
    lay->at[RING_MEAN] = mcs_ps_take(&c, radii, d);
    lay->at[RING_M2] = mcs_ps_take(&c, radii, d);
    lay->stats = c.at;
    lay->at[RE] = mcs_ps_take(&c, cells, d);
    lay->at[IM] = mcs_ps_take(&c, cells, d);
    lay->at[PHASE] = mcs_ps_take(&c, 16u * (side + 1u), d);
#if MCS_CONFIG_NUFFT /* else no NUFFT memory and no plan (config.h) */
    if ((flags & MCS_POINTSET_DIRECT_ONLY) == 0u) {
        const size_t modes = 2u * side * side; /* within the caps: no overflow */
        const size_t stage_len =
            modes > MCS_POINTSET_STAGE_MIN ? modes : (size_t)MCS_POINTSET_STAGE_MIN;
        lay->at[STAGE] = mcs_ps_take(&c, stage_len, d);
        mcs_status st = mcs_nufft_size(2u, fmax, MCS_POINTSET_NUFFT_TOL, &lay->plan_bytes);
        if (st != MCS_OK)
            return MCS_ERR_FREQ_RANGE;
        lay->plan = mcs_ps_take(&c, lay->plan_bytes, 1u);
    }
#endif
    lay->total = mcs_ps_total(&c);
    return lay->total == SIZE_MAX ? MCS_ERR_FREQ_RANGE : MCS_OK;
}

static uintptr_t key_of(const mcs_pointset2d *a)
{
    enum { OWN = 16 };
    uintptr_t w[OWN + MCS_PS_PLAN_WORDS] = {
        (uintptr_t)a->freq_max,  (uintptr_t)a->flags,   (uintptr_t)a->path,  (uintptr_t)a->wrap,
        (uintptr_t)a->mem,       (uintptr_t)a->bytes,   (uintptr_t)a->state, (uintptr_t)a->mean,
        (uintptr_t)a->m2,        (uintptr_t)a->ring_mean, (uintptr_t)a->ring_m2,
        (uintptr_t)a->re,        (uintptr_t)a->im,      (uintptr_t)a->phase, (uintptr_t)a->stage,
        (uintptr_t)0x32u};
    mcs_ps_plan_words(&a->plan, w + OWN);
    return mcs_ps_hash(w, sizeof w / sizeof w[0]);
}

static const mcs_ps_head *head_of(const mcs_pointset2d *acc)
{
    return (const mcs_ps_head *)(const void *)acc->state;
}

static uint64_t count_of(const mcs_pointset2d *acc)
{
    return head_of(acc)->count;
}

/* MCS_ERR_NULL without acc, MCS_ERR_UNINIT unless init set its header,
 * MCS_ERR_INVARIANT for a buffer whose head no longer says F. */
static mcs_status check_acc(const mcs_pointset2d *acc)
{
    if (acc == NULL)
        return MCS_ERR_NULL;
    if (acc->freq_max == 0u || acc->freq_max > (size_t)MCS_POINTSET2D_MAX_FREQ ||
        acc->key != key_of(acc) || acc->state == NULL)
        return MCS_ERR_UNINIT;
    return head_of(acc)->shape[0] == acc->freq_max ? MCS_OK : MCS_ERR_INVARIANT;
}

/* *acc <- the header over mem for the checked layout lay of (fmax, flags):
 * arrays at their offsets, the NUFFT plan built, the statistics zeroed
 * (src NULL) or src's, with src's path and wrap. */
static void set_up(mcs_pointset2d *acc, size_t fmax, unsigned flags, void *mem,
                   const mcs_ps_layout *lay, const mcs_pointset2d *src)
{
    /* src may be acc: what it says is read before acc is written */
    const mcs_pointset_path path = src != NULL ? src->path : mcs_ps_first_path(flags);
    const int wrap = src != NULL ? src->wrap : 0;
    unsigned char *base = mcs_ps_set_up_stats_(mem, lay, src != NULL ? src->state : NULL);
    memset(acc, 0, sizeof *acc);
    acc->freq_max = fmax;
    acc->flags = flags;
    acc->path = path;
    acc->wrap = wrap;
    acc->mem = mem;
    acc->bytes = lay->total;
    acc->state = (void *)base;
    acc->mean = mcs_ps_array(base, lay, MEAN);
    acc->m2 = mcs_ps_array(base, lay, M2);
    acc->ring_mean = mcs_ps_array(base, lay, RING_MEAN);
    acc->ring_m2 = mcs_ps_array(base, lay, RING_M2);
    acc->re = mcs_ps_array(base, lay, RE);
    acc->im = mcs_ps_array(base, lay, IM);
    acc->phase = mcs_ps_array(base, lay, PHASE);
#if MCS_CONFIG_NUFFT
    if ((flags & MCS_POINTSET_DIRECT_ONLY) == 0u) {
        acc->stage = mcs_ps_array(base, lay, STAGE);
        /* cannot fail: the size query took the same arguments */
        (void)mcs_nufft_init(&acc->plan, 2u, fmax, MCS_POINTSET_NUFFT_TOL, base + lay->plan,
                             lay->plan_bytes);
    }
#endif
    acc->key = key_of(acc);
}

mcs_status mcs_pointset2d_size(size_t freq_max, unsigned flags, size_t *bytes)
{
    mcs_ps_layout lay;
    return mcs_ps_size_(layout_of(freq_max, flags, &lay), &lay, bytes);
}

mcs_status mcs_pointset2d_init(mcs_pointset2d *acc, size_t freq_max, unsigned flags, void *mem,
                               size_t bytes)
{
    const mcs_ps_span to = {acc, sizeof *acc, mem, bytes};
    mcs_ps_layout lay;
    mcs_status st = mcs_ps_check_init_(&to, layout_of(freq_max, flags, &lay), &lay);
    if (st == MCS_OK)
        set_up(acc, freq_max, flags, mem, &lay, NULL);
    return st;
}

mcs_status mcs_pointset2d_copy(mcs_pointset2d *dst, void *mem, size_t bytes,
                               const mcs_pointset2d *src)
{
    const mcs_ps_span to = {dst, sizeof *dst, mem, bytes};
    mcs_ps_span from = {src, sizeof *src, NULL, 0u};
    mcs_ps_layout lay;
    mcs_status st = check_acc(src);
    if (st == MCS_OK) {
        from.mem = src->mem;
        from.bytes = src->bytes;
        st = layout_of(src->freq_max, src->flags, &lay); /* MCS_OK: src passed init */
    }
    st = mcs_ps_check_copy_(&to, &from, st, &lay);
    if (st == MCS_OK)
        set_up(dst, src->freq_max, src->flags, mem, &lay, src);
    return st;
}

mcs_status mcs_pointset2d_set_path(mcs_pointset2d *acc, mcs_pointset_path path)
{
    mcs_status st = check_acc(acc);
    if (st != MCS_OK)
        return st;
    const int direct_only = mcs_ps_direct_only(acc->flags);
    if (path != MCS_POINTSET_PATH_AUTO && path != MCS_POINTSET_PATH_DIRECT &&
        path != MCS_POINTSET_PATH_NUFFT)
        return MCS_ERR_DOMAIN;
    if (path == MCS_POINTSET_PATH_NUFFT && direct_only)
        return MCS_ERR_DOMAIN;
    acc->path = path;
    acc->key = key_of(acc);
    return MCS_OK;
}

mcs_status mcs_pointset2d_set_wrap(mcs_pointset2d *acc, int wrap)
{
    mcs_status st = check_acc(acc);
    if (st == MCS_OK && wrap != 0 && wrap != 1)
        st = MCS_ERR_DOMAIN;
    if (st != MCS_OK)
        return st;
    acc->wrap = wrap;
    acc->key = key_of(acc);
    return MCS_OK;
}

/* Points the NUFFT takes per transform: its output holds the staged ones. */
static size_t chunk_of(const mcs_pointset2d *acc)
{
    const size_t side = 2u * acc->freq_max + 1u, modes = 2u * side * side;
    return (modes > MCS_POINTSET_STAGE_MIN ? modes : (size_t)MCS_POINTSET_STAGE_MIN) / 2u;
}

/* The path of a trial of k points (acc checked). */
static mcs_status path_of(const mcs_pointset2d *acc, size_t k, mcs_pointset_path *out)
{
    if (k == 0u)
        return MCS_ERR_K_RANGE;
    mcs_pointset_path p = acc->path;
    if (mcs_ps_direct_only(acc->flags))
        p = MCS_POINTSET_PATH_DIRECT;
    else if (p == MCS_POINTSET_PATH_NUFFT && k > (size_t)MCS_POINTSET_NUFFT_MAX_K)
        return MCS_ERR_K_RANGE;
    else if (p == MCS_POINTSET_PATH_AUTO)
        p = k > (size_t)MCS_POINTSET_NUFFT_MAX_K
                ? MCS_POINTSET_PATH_DIRECT
                : mcs_ps_auto_path_(2, acc->freq_max, acc->plan.n, chunk_of(acc), k);
    *out = p;
    return MCS_OK;
}

mcs_status mcs_pointset2d_path_for(const mcs_pointset2d *acc, size_t k, mcs_pointset_path *path)
{
    mcs_status st = path == NULL ? MCS_ERR_NULL : check_acc(acc);
    mcs_pointset_path p = MCS_POINTSET_PATH_DIRECT;
    if (st == MCS_OK)
        st = path_of(acc, k, &p);
    if (st == MCS_OK)
        *path = p;
    return st;
}

/* ---- the direct path ---- */

/* Phase rows of point slot p for point q of k (a padding slot past the last
 * point contributes 0): x row over fx = -F..F (negative fx by conjugation,
 * exactly), y row over fy = 0..F scaled by the amplitude. */
static void phase_rows(mcs_pointset2d *acc, int p, size_t k, const mcs_ps_points *pts, size_t q)
{
    const size_t fmax = acc->freq_max, stride = 2u * fmax + 2u;
    const double x = q < k ? mcs_ps_coord(pts, q, 0) : 0.0;
    const double y = q < k ? mcs_ps_coord(pts, q, 1) : 0.0;
    double *rows = acc->phase + (size_t)(4 * p) * stride;
    double *xr = rows + XR * stride, *xi = rows + XI * stride;
    mcs_ps_phase_row(x, 1.0, fmax, xr + fmax, xi + fmax);
    for (size_t f = 1; f <= fmax; ++f) {
        xr[fmax - f] = xr[fmax + f];
        xi[fmax - f] = -xi[fmax + f];
    }
    xr[2u * fmax + 1u] = 0.0; /* the padding column */
    xi[2u * fmax + 1u] = 0.0;
    mcs_ps_phase_row(y, q < k ? 1.0 : 0.0, fmax, rows + YR * stride, rows + YI * stride);
}

/* S(fx, fy) += sum over the four slots of ex_p(fx) ey_p(fy): one pass over
 * the stored wave vectors per four points. */
static void accumulate_four(mcs_pointset2d *acc)
{
    const size_t stride = 2u * acc->freq_max + 2u;
    const double *ph = acc->phase;
#define ROW_(p, r) (ph + (size_t)(4 * (p) + (r)) * stride)
    const double *const x[8] = {ROW_(0, XR), ROW_(0, XI), ROW_(1, XR), ROW_(1, XI),
                                ROW_(2, XR), ROW_(2, XI), ROW_(3, XR), ROW_(3, XI)};
    const double *const y[8] = {ROW_(0, YR), ROW_(0, YI), ROW_(1, YR), ROW_(1, YI),
                                ROW_(2, YR), ROW_(2, YI), ROW_(3, YR), ROW_(3, YI)};
#undef ROW_
    mcs_ps_outer4(acc->freq_max + 1u, stride, acc->re, acc->im, x, y);
}

static void direct_sums(mcs_pointset2d *acc, size_t k, const mcs_ps_points *pts)
{
    mcs_ps_clear(cells_of(acc->freq_max), acc->re, acc->im);
    for (size_t j = 0; j < k; j += 4u) {
        for (int p = 0; p < 4; ++p)
            phase_rows(acc, p, k, pts, j + (size_t)p);
        accumulate_four(acc);
    }
}

#if MCS_CONFIG_NUFFT /* else the NUFFT path is left out (config.h) */
/* ---- the NUFFT path ---- */

/* The sums from the NUFFT, chunk_of(acc) points per transform: the caller's
 * interleaved points where they are, others (planar, or with a wrapped 1.0)
 * staged as interleaved doubles in the output array, which the transform
 * may overwrite. Every layout and type of the same values hands the same
 * doubles to the same transforms, so gives the same bits. */
static void nufft_sums(mcs_pointset2d *acc, size_t k, const mcs_ps_points *pts, int ones)
{
    const size_t fmax = acc->freq_max, side = 2u * fmax + 1u, stride = side + 1u;
    const size_t chunk = chunk_of(acc);
    double *stage = acc->stage;
    mcs_ps_clear(cells_of(fmax), acc->re, acc->im);
    for (size_t j0 = 0; j0 < k; j0 += chunk) {
        const size_t m = k - j0 < chunk ? k - j0 : chunk;
        /* cannot fail: the points are checked, outside the buffer, m >= 1 */
        if (pts->interleaved && !ones && pts->f[0] != NULL) {
            (void)mcs_nufft_type1_f(&acc->plan, pts->f[0] + 2u * j0, m, stage);
        } else if (pts->interleaved && !ones) {
            (void)mcs_nufft_type1(&acc->plan, pts->d[0] + 2u * j0, m, stage);
        } else {
            for (size_t j = 0; j < m; ++j) {
                stage[2u * j] = mcs_ps_coord(pts, j0 + j, 0);
                stage[2u * j + 1u] = mcs_ps_coord(pts, j0 + j, 1);
            }
            (void)mcs_nufft_type1(&acc->plan, stage, m, stage);
        }
        /* c at (fx, fy >= 0) is complex mode (fy + F) side + fx + F */
        for (size_t fy = 0; fy <= fmax; ++fy) {
            const double *c = stage + 2u * (fy + fmax) * side;
            double *re = acc->re + fy * stride, *im = acc->im + fy * stride;
            for (size_t col = 0; col < side; ++col) {
                re[col] += c[2u * col];
                im[col] += c[2u * col + 1u];
            }
        }
    }
}
#endif

/* ---- the statistics, whichever path gave the sums ---- */

/* Per-trial P into the Welford means, and the per-trial annulus averages
 * into theirs. The ring sums and each row's annulus of every |fx| reuse the
 * phase scratch (free by now); along a row the annulus of |fx| only grows,
 * so it is found by steps instead of a square root per wave vector. */
static void update_statistics(mcs_pointset2d *acc, size_t k)
{
    const size_t fmax = acc->freq_max, row = 2u * fmax + 1u, stride = row + 1u;
    double *ring_sum = acc->phase, *ring_n = acc->phase + stride, *ring_at = acc->phase + 2u * stride;
    memset(ring_sum, 0, (fmax + 1u) * sizeof *ring_sum);
    memset(ring_n, 0, (fmax + 1u) * sizeof *ring_n);
    mcs_ps_head *head = (mcs_ps_head *)(void *)acc->state;
    const uint64_t count = ++head->count;
    const double inv_k = 1.0 / (double)k;
    for (size_t fy = 0; fy <= fmax; ++fy) {
        const double w = fy == 0u ? 1.0 : 2.0;
        size_t r = fy;
        for (size_t ax = 0; ax <= fmax; ++ax) {
            while ((r + 1u) * (r + 1u) <= ax * ax + fy * fy)
                ++r;
            ring_at[ax] = (double)r;
        }
        for (size_t c = 0; c < row; ++c) {
            const size_t i = fy * stride + c;
            const double p = (acc->re[i] * acc->re[i] + acc->im[i] * acc->im[i]) * inv_k;
            mcs_ps_welford(&acc->mean[i], &acc->m2[i], p, count);
            const size_t r_c = (size_t)ring_at[c >= fmax ? c - fmax : fmax - c];
            if (r_c <= fmax) {
                ring_sum[r_c] += w * p;
                ring_n[r_c] += w;
            }
        }
    }
    for (size_t q = 0; q <= fmax; ++q)
        mcs_ps_welford(&acc->ring_mean[q], &acc->ring_m2[q], ring_sum[q] / ring_n[q], count);
}

/* The body of every add: the checks in the order the header gives, then
 * the sums by the trial's path and the statistics. */
static mcs_status add_points(mcs_pointset2d *acc, size_t k, const mcs_ps_points *pts)
{
    mcs_status st = mcs_ps_points_null(pts) ? MCS_ERR_NULL : check_acc(acc);
    mcs_pointset_path path = MCS_POINTSET_PATH_DIRECT;
    if (st == MCS_OK)
        st = path_of(acc, k, &path);
    if (st == MCS_OK && k > SIZE_MAX / 2u)
        st = MCS_ERR_POINT_RANGE; /* 2 k coordinates cannot fit memory */
    if (st == MCS_OK && (mcs_ps_points_overlap(pts, k, acc, sizeof *acc) ||
                         mcs_ps_points_overlap(pts, k, acc->mem, acc->bytes)))
        st = MCS_ERR_ALIAS;
    int ones = 0;
    if (st == MCS_OK)
        st = mcs_ps_check_points(pts, k, acc->wrap, &ones);
    if (st == MCS_OK)
        st = mcs_check_count_(count_of(acc), 1u);
    if (st != MCS_OK)
        return st;
#if MCS_CONFIG_NUFFT
    if (path == MCS_POINTSET_PATH_NUFFT) {
        nufft_sums(acc, k, pts, ones);
    } else {
        direct_sums(acc, k, pts);
    }
#else /* path_of gave DIRECT: every object is direct only */
    (void)ones;
    direct_sums(acc, k, pts);
#endif
    update_statistics(acc, k);
    return MCS_OK;
}

mcs_status mcs_pointset2d_add(mcs_pointset2d *acc, size_t k, const double *points)
{
    const mcs_ps_points pts = mcs_ps_points_d(points, NULL, 2);
    return add_points(acc, k, &pts);
}

mcs_status mcs_pointset2d_add_f(mcs_pointset2d *acc, size_t k, const float *points)
{
    const mcs_ps_points pts = mcs_ps_points_f(points, NULL, 2);
    return add_points(acc, k, &pts);
}

mcs_status mcs_pointset2d_add_planar(mcs_pointset2d *acc, size_t k, const double *x,
                                     const double *y)
{
    const mcs_ps_points pts = mcs_ps_points_d(x, y, 2);
    return y == NULL ? MCS_ERR_NULL : add_points(acc, k, &pts);
}

mcs_status mcs_pointset2d_add_planar_f(mcs_pointset2d *acc, size_t k, const float *x,
                                       const float *y)
{
    const mcs_ps_points pts = mcs_ps_points_f(x, y, 2);
    return y == NULL ? MCS_ERR_NULL : add_points(acc, k, &pts);
}

mcs_status mcs_pointset2d_merge(mcs_pointset2d *dst, const mcs_pointset2d *src)
{
    mcs_status st = mcs_check_pair_(check_acc(dst), check_acc(src));
    if (st == MCS_OK)
        st = mcs_ps_check_merge(dst, src, sizeof *dst, dst->mem, dst->bytes, src->mem, src->bytes,
                                dst->freq_max == src->freq_max, count_of(dst), count_of(src));
    if (st != MCS_OK || count_of(src) == 0u)
        return st;
    const uint64_t na = count_of(dst), nb = count_of(src);
    const size_t fmax = dst->freq_max;
    mcs_ps_chan_cells(cells_of(fmax), dst->mean, dst->m2, na, src->mean, src->m2, nb);
    mcs_ps_chan_cells(fmax + 1u, dst->ring_mean, dst->ring_m2, na, src->ring_mean, src->ring_m2,
                      nb);
    ((mcs_ps_head *)(void *)dst->state)->count = na + nb;
    return MCS_OK;
}

mcs_status mcs_pointset2d_count(const mcs_pointset2d *acc, uint64_t *count)
{
    mcs_status st = count == NULL ? MCS_ERR_NULL : check_acc(acc);
    return mcs_ps_count_out(st, st == MCS_OK ? count_of(acc) : 0u, count);
}

/* <P(fx, fy)> (want_stderr 0) or its standard error (1), read at the stored
 * mirror (-fx, -fy) when fy < 0. */
static mcs_status read_power(const mcs_pointset2d *acc, long fx, long fy, int want_stderr,
                             double *out)
{
    mcs_status st = out == NULL ? MCS_ERR_NULL : check_acc(acc);
    if (st != MCS_OK)
        return st;
    const size_t fmax = acc->freq_max;
    if (mcs_ps_abs(fx) > fmax || mcs_ps_abs(fy) > fmax)
        return MCS_ERR_FREQ_RANGE;
    if (fy < 0) {
        fx = -fx;
        fy = -fy;
    }
    const size_t i = (size_t)fy * (2u * fmax + 2u) + (size_t)(fx + (long)fmax);
    return mcs_ps_read(acc->mean[i], acc->m2[i], count_of(acc), want_stderr, out);
}

mcs_status mcs_pointset2d_power(const mcs_pointset2d *acc, long freq_x, long freq_y, double *out)
{
    return read_power(acc, freq_x, freq_y, 0, out);
}

mcs_status mcs_pointset2d_power_stderr(const mcs_pointset2d *acc, long freq_x, long freq_y,
                                       double *out)
{
    return read_power(acc, freq_x, freq_y, 1, out);
}

/* The checks of a read-out of annulus radius. */
static mcs_status check_radius(const mcs_pointset2d *acc, size_t radius, const double *out)
{
    mcs_status st = out == NULL ? MCS_ERR_NULL : check_acc(acc);
    return st == MCS_OK && radius > acc->freq_max ? MCS_ERR_FREQ_RANGE : st;
}

mcs_status mcs_pointset2d_radial(const mcs_pointset2d *acc, size_t radius, double *out)
{
    mcs_status st = check_radius(acc, radius, out);
    return st != MCS_OK ? st
                        : mcs_ps_read(acc->ring_mean[radius], 0.0, count_of(acc), 0, out);
}

mcs_status mcs_pointset2d_radial_stderr(const mcs_pointset2d *acc, size_t radius, double *out)
{
    mcs_status st = check_radius(acc, radius, out);
    return st != MCS_OK ? st
                        : mcs_ps_read(0.0, acc->ring_m2[radius], count_of(acc), 1, out);
}

/* The mean periodogram over annulus r (r <= F), the whole plane counted:
 * its rows fy = 0..r, in each the columns fx = -hi..-lo and lo..hi in
 * ascending order (as a pass over the whole row would meet them; the
 * stored half plane stands for both signs of fy). */
static void ring_moments(const mcs_pointset2d *acc, size_t r, mcs_ps_ring *g)
{
    const size_t fmax = acc->freq_max, stride = 2u * fmax + 2u;
    for (int pass = 0; pass < 2; ++pass)
        for (size_t fy = 0; fy <= r; ++fy) {
            size_t lo, hi;
            mcs_ps_ring_span(r, fy, &lo, &hi);
            const double w = fy == 0u ? 1.0 : 2.0;
            const double *centre = acc->mean + fy * stride + fmax;
            for (size_t ax = hi; ax >= lo && ax > 0u; --ax)
                mcs_ps_ring_add(g, pass, w, *(centre - ax));
            for (size_t ax = lo; ax <= hi; ++ax)
                mcs_ps_ring_add(g, pass, w, centre[ax]);
        }
}

mcs_status mcs_pointset2d_anisotropy(const mcs_pointset2d *acc, size_t radius, double *out_db)
{
    mcs_status st = check_radius(acc, radius, out_db);
    if (st == MCS_OK && count_of(acc) == 0u)
        st = MCS_ERR_EMPTY;
    if (st != MCS_OK)
        return st;
    mcs_ps_ring g = {0.0, 0.0, 0.0};
    ring_moments(acc, radius, &g);
    return mcs_ps_ring_db(&g, RING_ZERO, 0.0, out_db);
}

/* Integer wave vectors of the whole plane with |f|^2 < q: row fy (and -fy),
 * fy^2 < q, holds the fx with fx^2 <= q - fy^2 - 1. O(sqrt q) steps. */
static size_t disc_size(size_t q)
{
    size_t n = 0u;
    for (size_t fy = 0; fy * fy < q; ++fy)
        n += (fy > 0u ? 2u : 1u) * (2u * mcs_ps_isqrt(q - fy * fy - 1u) + 1u);
    return n;
}

mcs_status mcs_pointset2d_ring_size(size_t radius, size_t *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    if (radius > (size_t)MCS_POINTSET2D_MAX_FREQ)
        return MCS_ERR_FREQ_RANGE;
    *out = disc_size((radius + 1u) * (radius + 1u)) - disc_size(radius * radius);
    return MCS_OK;
}
