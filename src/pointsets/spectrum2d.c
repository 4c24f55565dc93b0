#include "mcspec/spectrum2d.h"
#include "mcspec/spectrum.h"
#include "pointset_internal.h"

#include <math.h>
#include <string.h>

/* Layout: wave vector (k1, k2), k2 = 0..N2/2, at k2 * stride + k1 with
 * stride = N1 rounded up to even (the pad column stays 0, never read); the
 * arrays in the caller's buffer behind the head (shape words, count). */

enum { XR = 0, XI = 1, YR = 2, YI = 3 };

static size_t stride_of(size_t n_x)
{
    return n_x + n_x % 2u;
}

/* Stored wave vectors of an N1 x N2 plane: rows k2 = 0..N2/2. */
static size_t cells_for(size_t n_x, size_t n_y)
{
    return stride_of(n_x) * (n_y / 2u + 1u);
}

static size_t cells_of(const mcs_spectrum2d *acc)
{
    return cells_for(acc->n_x, acc->n_y);
}

/* Entries of each per-point twiddle row: N1 padded to even (x rows) or
 * N2/2 + 1 (y rows), whichever is more. */
static size_t row_len_for(size_t n_x, size_t n_y)
{
    const size_t x = stride_of(n_x), y = n_y / 2u + 1u;
    return x > y ? x : y;
}

static int side_ok(size_t n)
{
    return n >= 1u && n <= (size_t)MCS_SPECTRUM2D_MAX_SIDE;
}

/* The arrays of the buffer, by their names in the layout: the statistics,
 * then the twiddles and the scratch. */
enum { MEAN_RE, MEAN_IM, M2_S, MEAN_POW, M2_POW, COS_X, SIN_X, COS_Y, SIN_Y, RE, IM, ROWS };

static mcs_status layout_of(size_t n_x, size_t n_y, mcs_ps_layout *lay)
{
    memset(lay, 0, sizeof *lay);
    if (!side_ok(n_x) || !side_ok(n_y))
        return MCS_ERR_N_RANGE;
    const size_t cells = cells_for(n_x, n_y), d = sizeof(double);
    lay->shape[0] = n_x;
    lay->shape[1] = n_y;
    mcs_ps_carve c = {0u, 0};
    (void)mcs_ps_take(&c, 1u, sizeof(mcs_ps_head));
    lay->at[MEAN_RE] = mcs_ps_take(&c, cells, d);
    lay->at[MEAN_IM] = mcs_ps_take(&c, cells, d);
    lay->at[M2_S] = mcs_ps_take(&c, cells, d);
    lay->at[MEAN_POW] = mcs_ps_take(&c, cells, d);
    lay->at[M2_POW] = mcs_ps_take(&c, cells, d);
    lay->stats = c.at;
    lay->at[COS_X] = mcs_ps_take(&c, n_x, d);
    lay->at[SIN_X] = mcs_ps_take(&c, n_x, d);
    lay->at[COS_Y] = mcs_ps_take(&c, n_y, d);
    lay->at[SIN_Y] = mcs_ps_take(&c, n_y, d);
    lay->at[RE] = mcs_ps_take(&c, cells, d);
    lay->at[IM] = mcs_ps_take(&c, cells, d);
    lay->at[ROWS] = mcs_ps_take(&c, 16u * row_len_for(n_x, n_y), d);
    lay->total = mcs_ps_total(&c);
    return lay->total == SIZE_MAX ? MCS_ERR_N_RANGE : MCS_OK;
}

static uintptr_t key_of(const mcs_spectrum2d *a)
{
    const uintptr_t words[] = {
        (uintptr_t)a->n_x,     (uintptr_t)a->n_y,     (uintptr_t)a->wrap,  (uintptr_t)a->mem,
        (uintptr_t)a->bytes,   (uintptr_t)a->state,   (uintptr_t)a->mean_re,
        (uintptr_t)a->mean_im, (uintptr_t)a->m2_s,    (uintptr_t)a->mean_pow,
        (uintptr_t)a->m2_pow,  (uintptr_t)a->cos_x,   (uintptr_t)a->sin_x, (uintptr_t)a->cos_y,
        (uintptr_t)a->sin_y,   (uintptr_t)a->re,      (uintptr_t)a->im,    (uintptr_t)a->rows,
        (uintptr_t)0x73u};
    return mcs_ps_hash(words, sizeof words / sizeof words[0]);
}

static const mcs_ps_head *head_of(const mcs_spectrum2d *acc)
{
    return (const mcs_ps_head *)(const void *)acc->state;
}

static uint64_t count_of(const mcs_spectrum2d *acc)
{
    return head_of(acc)->count;
}

/* MCS_ERR_NULL without acc, MCS_ERR_UNINIT unless init set its header,
 * MCS_ERR_INVARIANT for a buffer whose head no longer says N1, N2 or whose
 * count is past the largest. O(1). */
static mcs_status check_acc(const mcs_spectrum2d *acc)
{
    if (acc == NULL)
        return MCS_ERR_NULL;
    if (!side_ok(acc->n_x) || !side_ok(acc->n_y) || acc->key != key_of(acc) || acc->state == NULL)
        return MCS_ERR_UNINIT;
    const mcs_ps_head *head = head_of(acc);
    if (head->shape[0] != acc->n_x || head->shape[1] != acc->n_y)
        return MCS_ERR_INVARIANT;
    return head->count <= MCS_SPECTRUM_MAX_COUNT ? MCS_OK : MCS_ERR_INVARIANT;
}

/* What trials within MCS_SPECTRUM_MAX_SUM give (spectrum2d.h): |S_k| <=
 * 2^100, so |<S_k>| <= 2^100 and <|S_k|^2> in [0, 2^200], and over c
 * trials each M2 is at most (c - 1) times the square of the largest gap
 * from the mean (2^202 for S_k, 2^400 for |S_k|^2, as for welford), here
 * with room for rounding: no mean without a trial, no spread with one. */
#define MAX_ABS_S 0x1p101
#define MAX_POWER 0x1p202
#define SPREAD_S 0x1p204
#define SPREAD_POWER 0x1p404

static int in_range(double x, double lo, double hi)
{
    return x >= lo && x <= hi; /* NaN is in no range */
}

/* The twiddles init builds: in [-1, 1]. O(N1 + N2). */
static int twiddles_sound(const mcs_spectrum2d *acc)
{
    int sound = 1;
    for (size_t t = 0; t < acc->n_x; ++t)
        sound &= in_range(acc->cos_x[t], -1.0, 1.0) & in_range(acc->sin_x[t], -1.0, 1.0);
    for (size_t t = 0; t < acc->n_y; ++t)
        sound &= in_range(acc->cos_y[t], -1.0, 1.0) & in_range(acc->sin_y[t], -1.0, 1.0);
    return sound;
}

/* The statistics of stored cell i within the bounds above. O(1). */
static int cell_sound(const mcs_spectrum2d *acc, size_t i)
{
    const double some = count_of(acc) > 0u ? 1.0 : 0.0;
    const double spread = count_of(acc) > 0u ? (double)(count_of(acc) - 1u) : 0.0;
    return fabs(acc->mean_re[i]) <= some * MAX_ABS_S &&
           fabs(acc->mean_im[i]) <= some * MAX_ABS_S &&
           in_range(acc->mean_pow[i], 0.0, some * MAX_POWER) &&
           in_range(acc->m2_s[i], 0.0, spread * SPREAD_S) &&
           in_range(acc->m2_pow[i], 0.0, spread * SPREAD_POWER);
}

/* check_acc, then every stored cell, the pad column 0 (no call writes it)
 * and the twiddles: what an add or a merge reads. O(N1 N2). */
static mcs_status check_body(const mcs_spectrum2d *acc)
{
    mcs_status st = check_acc(acc);
    if (st != MCS_OK)
        return st;
    const size_t stride = stride_of(acc->n_x);
    int sound = twiddles_sound(acc);
    for (size_t k2 = 0; k2 <= acc->n_y / 2u; ++k2) {
        for (size_t k1 = 0; k1 < acc->n_x; ++k1)
            sound &= cell_sound(acc, k2 * stride + k1);
        if (stride > acc->n_x) {
            const size_t pad = k2 * stride + acc->n_x;
            sound &= acc->mean_re[pad] == 0.0 && acc->mean_im[pad] == 0.0 &&
                     acc->mean_pow[pad] == 0.0 && acc->m2_s[pad] == 0.0 &&
                     acc->m2_pow[pad] == 0.0;
        }
    }
    return sound ? MCS_OK : MCS_ERR_INVARIANT;
}

/* *acc <- the header over mem for the checked layout lay of N1 x N2:
 * arrays at their offsets, the twiddles built, the statistics zeroed (src
 * NULL) or src's, with src's wrap. */
static void set_up(mcs_spectrum2d *acc, size_t n_x, size_t n_y, void *mem,
                   const mcs_ps_layout *lay, const mcs_spectrum2d *src)
{
    const int wrap = src != NULL ? src->wrap : 0; /* src may be acc */
    unsigned char *base = mcs_ps_set_up_stats_(mem, lay, src != NULL ? src->state : NULL);
    memset(acc, 0, sizeof *acc);
    acc->n_x = n_x;
    acc->n_y = n_y;
    acc->wrap = wrap;
    acc->mem = mem;
    acc->bytes = lay->total;
    acc->state = (void *)base;
#define AT_(name) mcs_ps_array(base, lay, name)
    acc->mean_re = AT_(MEAN_RE);
    acc->mean_im = AT_(MEAN_IM);
    acc->m2_s = AT_(M2_S);
    acc->mean_pow = AT_(MEAN_POW);
    acc->m2_pow = AT_(M2_POW);
    acc->cos_x = AT_(COS_X);
    acc->sin_x = AT_(SIN_X);
    acc->cos_y = AT_(COS_Y);
    acc->sin_y = AT_(SIN_Y);
    acc->re = AT_(RE);
    acc->im = AT_(IM);
    acc->rows = AT_(ROWS);
#undef AT_
    mcs_twiddles_(n_x, acc->cos_x, acc->sin_x);
    mcs_twiddles_(n_y, acc->cos_y, acc->sin_y);
    acc->key = key_of(acc);
}

mcs_status mcs_spectrum2d_size(size_t n_x, size_t n_y, size_t *bytes)
{
    mcs_ps_layout lay;
    return mcs_ps_size_(layout_of(n_x, n_y, &lay), &lay, bytes);
}

mcs_status mcs_spectrum2d_init(mcs_spectrum2d *acc, size_t n_x, size_t n_y, void *mem,
                               size_t bytes)
{
    const mcs_ps_span to = {acc, sizeof *acc, mem, bytes};
    mcs_ps_layout lay;
    mcs_status st = mcs_ps_check_init_(&to, layout_of(n_x, n_y, &lay), &lay);
    if (st == MCS_OK)
        set_up(acc, n_x, n_y, mem, &lay, NULL);
    return st;
}

mcs_status mcs_spectrum2d_copy(mcs_spectrum2d *dst, void *mem, size_t bytes,
                               const mcs_spectrum2d *src)
{
    const mcs_ps_span to = {dst, sizeof *dst, mem, bytes};
    mcs_ps_span from = {src, sizeof *src, NULL, 0u};
    mcs_ps_layout lay;
    mcs_status st = check_acc(src);
    if (st == MCS_OK) {
        from.mem = src->mem;
        from.bytes = src->bytes;
        st = layout_of(src->n_x, src->n_y, &lay); /* MCS_OK: src passed init */
    }
    st = mcs_ps_check_copy_(&to, &from, st, &lay);
    if (st == MCS_OK)
        set_up(dst, src->n_x, src->n_y, mem, &lay, src);
    return st;
}

mcs_status mcs_spectrum2d_set_wrap(mcs_spectrum2d *acc, int wrap)
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

/* Twiddle rows of point slot p for point q of k, binned at (b1, b2), with its
 * weight (a padding slot past the last point has weight 0):
 * x row e^{-2 pi i k1 b1/N1}, k1 < N1; y row w e^{-2 pi i k2 b2/N2}, k2 <= N2/2.
 * Table indices advance by b mod N, so every twiddle is an exact entry. */
static void twiddle_rows(mcs_spectrum2d *acc, int p, size_t k, const mcs_ps_points *pts,
                         const double *weights, size_t q)
{
    const size_t n1 = acc->n_x, n2 = acc->n_y, len = row_len_for(n1, n2);
    const size_t b1 = q < k ? mcs_point_bin_(mcs_ps_coord(pts, q, 0), n1) : 0u;
    const size_t b2 = q < k ? mcs_point_bin_(mcs_ps_coord(pts, q, 1), n2) : 0u;
    const double w = q >= k ? 0.0 : weights != NULL ? weights[q] : 1.0;
    double *rows = acc->rows + (size_t)(4 * p) * len;
    double *xr = rows + XR * len, *xi = rows + XI * len, *yr = rows + YR * len, *yi = rows + YI * len;
    for (size_t k1 = 0, t = 0; k1 < n1; ++k1) {
        xr[k1] = acc->cos_x[t];
        xi[k1] = -acc->sin_x[t];
        t += b1;
        t = t >= n1 ? t - n1 : t;
    }
    if (n1 % 2u) { /* the pad column */
        xr[n1] = 0.0;
        xi[n1] = 0.0;
    }
    for (size_t k2 = 0, t = 0; k2 <= n2 / 2u; ++k2) {
        yr[k2] = w * acc->cos_y[t];
        yi[k2] = -w * acc->sin_y[t];
        t += b2;
        t = t >= n2 ? t - n2 : t;
    }
}

static void accumulate_four(mcs_spectrum2d *acc)
{
    const size_t len = row_len_for(acc->n_x, acc->n_y);
    const double *r = acc->rows;
#define ROW_(p, q) (r + (size_t)(4 * (p) + (q)) * len)
    const double *const x[8] = {ROW_(0, XR), ROW_(0, XI), ROW_(1, XR), ROW_(1, XI),
                                ROW_(2, XR), ROW_(2, XI), ROW_(3, XR), ROW_(3, XI)};
    const double *const y[8] = {ROW_(0, YR), ROW_(0, YI), ROW_(1, YR), ROW_(1, YI),
                                ROW_(2, YR), ROW_(2, YI), ROW_(3, YR), ROW_(3, YI)};
#undef ROW_
    mcs_ps_outer4(acc->n_y / 2u + 1u, stride_of(acc->n_x), acc->re, acc->im, x, y);
}

/* Normalise the trial's S_k (eq. 7's N^{-1/2}) and update the statistics. */
static void update_statistics(mcs_spectrum2d *acc)
{
    const size_t n1 = acc->n_x, stride = stride_of(n1);
    const double scale = 1.0 / sqrt((double)n1 * (double)acc->n_y);
    const uint64_t count = ++((mcs_ps_head *)(void *)acc->state)->count;
    const double c = (double)count;
    for (size_t k2 = 0; k2 <= acc->n_y / 2u; ++k2)
        for (size_t k1 = 0; k1 < n1; ++k1) {
            size_t i = k2 * stride + k1;
            double sr = acc->re[i] * scale, si = acc->im[i] * scale;
            double dr = sr - acc->mean_re[i], di = si - acc->mean_im[i];
            acc->mean_re[i] += dr / c;
            acc->mean_im[i] += di / c;
            acc->m2_s[i] += dr * (sr - acc->mean_re[i]) + di * (si - acc->mean_im[i]);
            mcs_ps_welford(&acc->mean_pow[i], &acc->m2_pow[i], sr * sr + si * si, count);
        }
}

/* The checks of a trial: K >= 1, points and weights outside the object,
 * points[2 k] in [0,1) (or [0, 1] with wrap), weights[k] (if any) finite
 * and >= 0, in that order, then their sum at most MCS_SPECTRUM_MAX_SUM:
 * |S_k| <= 2^100 then, so no square or fourth power of the statistics can
 * overflow (as for the 1D accumulator, spectrum.h). */
static mcs_status check_trial(const mcs_spectrum2d *acc, size_t k, const mcs_ps_points *pts,
                              const double *weights)
{
    if (k == 0u)
        return MCS_ERR_K_RANGE;
    if (k > SIZE_MAX / 2u)
        return MCS_ERR_POINT_RANGE;
    const size_t wbytes = weights != NULL ? mcs_bytes_(k, sizeof *weights) : 0u;
    if (mcs_ps_points_overlap(pts, k, acc, sizeof *acc) ||
        mcs_ps_points_overlap(pts, k, acc->mem, acc->bytes) ||
        mcs_overlap_(weights, wbytes, acc, sizeof *acc) ||
        mcs_overlap_(weights, wbytes, acc->mem, acc->bytes))
        return MCS_ERR_ALIAS;
    int ones = 0;
    mcs_status st = mcs_ps_check_points(pts, k, acc->wrap, &ones);
    double sum = 0.0;
    for (size_t j = 0; st == MCS_OK && weights != NULL && j < k; ++j) {
        st = mcs_check_weight_(weights[j]);
        sum += weights[j];
    }
    return st == MCS_OK && !(sum <= MCS_SPECTRUM_MAX_SUM) ? MCS_ERR_MAGNITUDE : st;
}

/* The body of every add (interleaved or planar, double or float: the same
 * bits from the same values). */
static mcs_status add_points(mcs_spectrum2d *acc, size_t k, const mcs_ps_points *pts,
                             const double *weights)
{
    mcs_status st = mcs_ps_points_null(pts) ? MCS_ERR_NULL : check_body(acc);
    if (st == MCS_OK && count_of(acc) >= MCS_SPECTRUM_MAX_COUNT)
        st = MCS_ERR_COUNT;
    if (st == MCS_OK)
        st = check_trial(acc, k, pts, weights);
    if (st != MCS_OK)
        return st;
    mcs_ps_clear(cells_of(acc), acc->re, acc->im);
    for (size_t j = 0; j < k; j += 4u) {
        for (int p = 0; p < 4; ++p)
            twiddle_rows(acc, p, k, pts, weights, j + (size_t)p);
        accumulate_four(acc);
    }
    update_statistics(acc);
    return MCS_OK;
}

mcs_status mcs_spectrum2d_add_points(mcs_spectrum2d *acc, size_t k, const double *points,
                                     const double *weights)
{
    const mcs_ps_points pts = mcs_ps_points_d(points, NULL, 2);
    return add_points(acc, k, &pts, weights);
}

mcs_status mcs_spectrum2d_add_points_f(mcs_spectrum2d *acc, size_t k, const float *points,
                                       const double *weights)
{
    const mcs_ps_points pts = mcs_ps_points_f(points, NULL, 2);
    return add_points(acc, k, &pts, weights);
}

mcs_status mcs_spectrum2d_add_points_planar(mcs_spectrum2d *acc, size_t k, const double *x,
                                            const double *y, const double *weights)
{
    const mcs_ps_points pts = mcs_ps_points_d(x, y, 2);
    return y == NULL ? MCS_ERR_NULL : add_points(acc, k, &pts, weights);
}

mcs_status mcs_spectrum2d_add_points_planar_f(mcs_spectrum2d *acc, size_t k, const float *x,
                                              const float *y, const double *weights)
{
    const mcs_ps_points pts = mcs_ps_points_f(x, y, 2);
    return y == NULL ? MCS_ERR_NULL : add_points(acc, k, &pts, weights);
}

mcs_status mcs_spectrum2d_merge(mcs_spectrum2d *dst, const mcs_spectrum2d *src)
{
    mcs_status st = mcs_check_pair_(check_body(dst), check_body(src));
    if (st == MCS_OK)
        st = mcs_ps_check_merge(dst, src, sizeof *dst, dst->mem, dst->bytes, src->mem, src->bytes,
                                dst->n_x == src->n_x && dst->n_y == src->n_y, count_of(dst),
                                count_of(src));
    if (st != MCS_OK || count_of(src) == 0u)
        return st;
    const uint64_t na = count_of(dst), nb = count_of(src);
    const double n = (double)na + (double)nb, fb = (double)nb / n;
    const double cross = (double)na * (double)nb / n;
    const size_t cells = cells_of(dst);
    /* Chan et al. for the complex mean: the squared gap is |d|^2. */
    for (size_t i = 0; i < cells; ++i) {
        double dr = src->mean_re[i] - dst->mean_re[i], di = src->mean_im[i] - dst->mean_im[i];
        dst->mean_re[i] += dr * fb;
        dst->mean_im[i] += di * fb;
        dst->m2_s[i] += src->m2_s[i] + (dr * dr + di * di) * cross;
    }
    mcs_ps_chan_cells(cells, dst->mean_pow, dst->m2_pow, na, src->mean_pow, src->m2_pow, nb);
    ((mcs_ps_head *)(void *)dst->state)->count = na + nb;
    return MCS_OK;
}

mcs_status mcs_spectrum2d_count(const mcs_spectrum2d *acc, uint64_t *count)
{
    mcs_status st = count == NULL ? MCS_ERR_NULL : check_acc(acc);
    return mcs_ps_count_out(st, st == MCS_OK ? count_of(acc) : 0u, count);
}

/* The checks of a read-out at k = (k1, k2) with output out, and the stored
 * index of k; *conj = 1 when it is the mirror -k's entry. */
static mcs_status lookup(const mcs_spectrum2d *acc, size_t k1, size_t k2, const double *out,
                         size_t *index, int *conj)
{
    mcs_status st = out == NULL ? MCS_ERR_NULL : check_acc(acc);
    if (st != MCS_OK)
        return st;
    const size_t n1 = acc->n_x, n2 = acc->n_y;
    if (k1 >= n1 || k2 >= n2)
        return MCS_ERR_FREQ_RANGE;
    *conj = k2 > n2 / 2u;
    if (*conj) {
        k2 = n2 - k2;
        k1 = (n1 - k1) % n1;
    }
    *index = k2 * stride_of(n1) + k1;
    return cell_sound(acc, *index) ? MCS_OK : MCS_ERR_INVARIANT;
}

mcs_status mcs_spectrum2d_mean(const mcs_spectrum2d *acc, size_t freq_k, size_t freq_l,
                               double *re, double *im)
{
    size_t i = 0u;
    int conj = 0;
    mcs_status st = im == NULL ? MCS_ERR_NULL : lookup(acc, freq_k, freq_l, re, &i, &conj);
    if (st == MCS_OK && re == im)
        st = MCS_ERR_ALIAS; /* one place cannot hold both parts */
    if (st == MCS_OK)
        st = mcs_ps_read(acc->mean_re[i], 0.0, count_of(acc), 0, re);
    if (st == MCS_OK)
        *im = conj ? -acc->mean_im[i] : acc->mean_im[i];
    return st;
}

/* <|S_k|^2> (what 0), its standard error (1), or that of <S_k> (2). */
static mcs_status read_stat(const mcs_spectrum2d *acc, size_t k1, size_t k2, int what,
                            double *out)
{
    size_t i = 0u;
    int conj = 0;
    mcs_status st = lookup(acc, k1, k2, out, &i, &conj);
    if (st != MCS_OK)
        return st;
    if (what == 2)
        return mcs_ps_read(0.0, acc->m2_s[i], count_of(acc), 1, out);
    return mcs_ps_read(acc->mean_pow[i], acc->m2_pow[i], count_of(acc), what, out);
}

mcs_status mcs_spectrum2d_power(const mcs_spectrum2d *acc, size_t freq_k, size_t freq_l,
                                double *out)
{
    return read_stat(acc, freq_k, freq_l, 0, out);
}

mcs_status mcs_spectrum2d_power_stderr(const mcs_spectrum2d *acc, size_t freq_k, size_t freq_l,
                                       double *out)
{
    return read_stat(acc, freq_k, freq_l, 1, out);
}

mcs_status mcs_spectrum2d_mean_stderr(const mcs_spectrum2d *acc, size_t freq_k, size_t freq_l,
                                      double *out)
{
    return read_stat(acc, freq_k, freq_l, 2, out);
}

/* S_k over k2 <= N2/2 by direct sums over the non-zero s_n (exact table
 * indices), then the rest by S_{-k} = conj(S_k). */
mcs_status mcs_spectrum2d_transform(const mcs_spectrum2d *acc, const double *s, double *re,
                                    double *im)
{
    mcs_status st = s == NULL || re == NULL || im == NULL ? MCS_ERR_NULL : check_acc(acc);
    if (st == MCS_OK && !twiddles_sound(acc))
        st = MCS_ERR_INVARIANT; /* a NaN twiddle made every output NaN */
    if (st != MCS_OK)
        return st;
    const size_t n1 = acc->n_x, n2 = acc->n_y, n = n1 * n2, bytes = n * sizeof(double);
    /* The outputs are written while s is read: no two may overlap. */
    if (mcs_overlap_(s, bytes, re, bytes) || mcs_overlap_(s, bytes, im, bytes) ||
        mcs_overlap_(re, bytes, im, bytes))
        return MCS_ERR_ALIAS;
    double total = 0.0; /* sum |s_n| bounds every partial sum (dft.h) */
    for (size_t j = 0; j < n; ++j)
        total += fabs(s[j]);
    if (!(total <= MCS_DFT_MAX_ABS_SUM))
        return mcs_all_finite_(n, s) ? MCS_ERR_MAGNITUDE : MCS_ERR_NOT_FINITE;
    memset(re, 0, n * sizeof *re);
    memset(im, 0, n * sizeof *im);
    for (size_t b2 = 0; b2 < n2; ++b2)
        for (size_t b1 = 0; b1 < n1; ++b1) {
            const double v = s[b2 * n1 + b1];
            if (v == 0.0)
                continue;
            for (size_t k2 = 0, t2 = 0; k2 <= n2 / 2u; ++k2, t2 = (t2 + b2) % n2) {
                const double cy = acc->cos_y[t2], sy = acc->sin_y[t2];
                for (size_t k1 = 0, t1 = 0; k1 < n1; ++k1, t1 = (t1 + b1) % n1) {
                    const double cx = acc->cos_x[t1], sx = acc->sin_x[t1];
                    re[k2 * n1 + k1] += v * (cx * cy - sx * sy);
                    im[k2 * n1 + k1] -= v * (sx * cy + cx * sy);
                }
            }
        }
    const double scale = 1.0 / sqrt((double)n);
    for (size_t i = 0; i < (n2 / 2u + 1u) * n1; ++i) {
        re[i] *= scale;
        im[i] *= scale;
    }
    for (size_t k2 = n2 / 2u + 1u; k2 < n2; ++k2)
        for (size_t k1 = 0; k1 < n1; ++k1) {
            size_t mirror = (n2 - k2) * n1 + (n1 - k1) % n1;
            re[k2 * n1 + k1] = re[mirror];
            im[k2 * n1 + k1] = -im[mirror];
        }
    return MCS_OK;
}

mcs_status mcs_spectrum2d_variance14(const mcs_spectrum2d *acc, size_t k, const double *f_re,
                                     const double *f_im, double *out)
{
    mcs_status st = f_re == NULL || f_im == NULL || out == NULL ? MCS_ERR_NULL : check_body(acc);
    if (st == MCS_OK && k == 0u)
        st = MCS_ERR_K_RANGE;
    if (st == MCS_OK && count_of(acc) == 0u)
        st = MCS_ERR_EMPTY;
    if (st != MCS_OK)
        return st;
    const size_t n1 = acc->n_x, n2 = acc->n_y;
    if (!mcs_all_finite_(n1 * n2, f_re) || !mcs_all_finite_(n1 * n2, f_im))
        return MCS_ERR_NOT_FINITE;
    double sum = 0.0;
    for (size_t k2 = 0; k2 < n2 && st == MCS_OK; ++k2)
        for (size_t k1 = 0; k1 < n1 && st == MCS_OK; ++k1) {
            if (k1 == 0u && k2 == 0u)
                continue;
            double p = 0.0;
            st = mcs_spectrum2d_power(acc, k1, k2, &p); /* cannot fail: checked above */
            size_t i = k2 * n1 + k1;
            sum += (f_re[i] * f_re[i] + f_im[i] * f_im[i]) * p;
        }
    if (st != MCS_OK)
        return st;
    /* |F_k|^2 of a finite f can overflow: refused, never returned as inf. */
    const double v = sum / ((double)k * (double)k);
    return isfinite(v) ? mcs_set_(out, v) : MCS_ERR_MAGNITUDE;
}
