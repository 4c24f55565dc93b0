#include "mcspec/pointset.h"
#include "pointset_internal.h"

#include <math.h>
#include <string.h>

#define B ((size_t)MCS_POINTSET_BLOCK)

/* Blocks of B frequencies up to F, and the sums' length (whole blocks). */
static size_t blocks_of(size_t fmax)
{
    return fmax / B + 1u;
}

/* The arrays of the buffer, by their names in the layout: the statistics,
 * then the scratch. */
enum { MEAN, M2, RE, IM, LOW, HIGH, STAGE };

static mcs_status layout_of(size_t fmax, unsigned flags, mcs_ps_layout *lay)
{
    memset(lay, 0, sizeof *lay);
    if (fmax == 0u || fmax > (size_t)MCS_POINTSET_MAX_FREQ)
        return MCS_ERR_FREQ_RANGE;
    if ((flags & ~(unsigned)MCS_POINTSET_DIRECT_ONLY) != 0u)
        return MCS_ERR_DOMAIN;
    const size_t blocks = blocks_of(fmax), d = sizeof(double);
    lay->shape[0] = fmax;
    mcs_ps_carve c = {0u, 0};
    (void)mcs_ps_take(&c, 1u, sizeof(mcs_ps_head));
    lay->at[MEAN] = mcs_ps_take(&c, fmax + 1u, d);
    lay->at[M2] = mcs_ps_take(&c, fmax + 1u, d);
    lay->stats = c.at;
    lay->at[RE] = mcs_ps_take(&c, blocks * B, d);
    lay->at[IM] = mcs_ps_take(&c, blocks * B, d);
    lay->at[LOW] = mcs_ps_take(&c, 8u * B, d);
    lay->at[HIGH] = mcs_ps_take(&c, 8u * blocks, d);
#if MCS_CONFIG_NUFFT /* else no NUFFT memory and no plan (config.h) */
    if ((flags & MCS_POINTSET_DIRECT_ONLY) == 0u) {
        const size_t modes = 2u * (2u * fmax + 1u);
        const size_t stage_len =
            modes > MCS_POINTSET_STAGE_MIN ? modes : (size_t)MCS_POINTSET_STAGE_MIN;
        lay->at[STAGE] = mcs_ps_take(&c, stage_len, d);
        if (mcs_nufft_size(1u, fmax, MCS_POINTSET_NUFFT_TOL, &lay->plan_bytes) != MCS_OK)
            return MCS_ERR_FREQ_RANGE;
        lay->plan = mcs_ps_take(&c, lay->plan_bytes, 1u);
    }
#endif
    lay->total = mcs_ps_total(&c);
    return lay->total == SIZE_MAX ? MCS_ERR_FREQ_RANGE : MCS_OK;
}

static uintptr_t key_of(const mcs_pointset *a)
{
    enum { OWN = 15 };
    uintptr_t w[OWN + MCS_PS_PLAN_WORDS] = {
        (uintptr_t)a->freq_max, (uintptr_t)a->flags, (uintptr_t)a->path,  (uintptr_t)a->wrap,
        (uintptr_t)a->mem,      (uintptr_t)a->bytes, (uintptr_t)a->state, (uintptr_t)a->mean,
        (uintptr_t)a->m2,       (uintptr_t)a->re,    (uintptr_t)a->im,    (uintptr_t)a->low,
        (uintptr_t)a->high,     (uintptr_t)a->stage, (uintptr_t)0x31u};
    mcs_ps_plan_words(&a->plan, w + OWN);
    return mcs_ps_hash(w, sizeof w / sizeof w[0]);
}

static uint64_t count_of(const mcs_pointset *acc)
{
    return ((const mcs_ps_head *)(const void *)acc->state)->count;
}

/* MCS_ERR_NULL without acc, MCS_ERR_UNINIT unless init set its header,
 * MCS_ERR_INVARIANT for a buffer whose head no longer says F. */
static mcs_status check_acc(const mcs_pointset *acc)
{
    if (acc == NULL)
        return MCS_ERR_NULL;
    if (acc->freq_max == 0u || acc->freq_max > (size_t)MCS_POINTSET_MAX_FREQ ||
        acc->key != key_of(acc) || acc->state == NULL)
        return MCS_ERR_UNINIT;
    const mcs_ps_head *head = (const mcs_ps_head *)(const void *)acc->state;
    return head->shape[0] == acc->freq_max ? MCS_OK : MCS_ERR_INVARIANT;
}

/* *acc <- the header over mem for the checked layout lay of (fmax, flags),
 * the statistics zeroed (src NULL) or src's, with src's path and wrap. */
static void set_up(mcs_pointset *acc, size_t fmax, unsigned flags, void *mem,
                   const mcs_ps_layout *lay, const mcs_pointset *src)
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
    acc->re = mcs_ps_array(base, lay, RE);
    acc->im = mcs_ps_array(base, lay, IM);
    acc->low = mcs_ps_array(base, lay, LOW);
    acc->high = mcs_ps_array(base, lay, HIGH);
#if MCS_CONFIG_NUFFT
    if ((flags & MCS_POINTSET_DIRECT_ONLY) == 0u) {
        acc->stage = mcs_ps_array(base, lay, STAGE);
        /* cannot fail: the size query took the same arguments */
        (void)mcs_nufft_init(&acc->plan, 1u, fmax, MCS_POINTSET_NUFFT_TOL, base + lay->plan,
                             lay->plan_bytes);
    }
#endif
    acc->key = key_of(acc);
}

mcs_status mcs_pointset_size(size_t freq_max, unsigned flags, size_t *bytes)
{
    mcs_ps_layout lay;
    return mcs_ps_size_(layout_of(freq_max, flags, &lay), &lay, bytes);
}

mcs_status mcs_pointset_init(mcs_pointset *acc, size_t freq_max, unsigned flags, void *mem,
                             size_t bytes)
{
    const mcs_ps_span to = {acc, sizeof *acc, mem, bytes};
    mcs_ps_layout lay;
    mcs_status st = mcs_ps_check_init_(&to, layout_of(freq_max, flags, &lay), &lay);
    if (st == MCS_OK)
        set_up(acc, freq_max, flags, mem, &lay, NULL);
    return st;
}

mcs_status mcs_pointset_copy(mcs_pointset *dst, void *mem, size_t bytes, const mcs_pointset *src)
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

mcs_status mcs_pointset_set_path(mcs_pointset *acc, mcs_pointset_path path)
{
    mcs_status st = check_acc(acc);
    if (st != MCS_OK)
        return st;
    if (path != MCS_POINTSET_PATH_AUTO && path != MCS_POINTSET_PATH_DIRECT &&
        path != MCS_POINTSET_PATH_NUFFT)
        return MCS_ERR_DOMAIN;
    if (path == MCS_POINTSET_PATH_NUFFT && mcs_ps_direct_only(acc->flags))
        return MCS_ERR_DOMAIN;
    acc->path = path;
    acc->key = key_of(acc);
    return MCS_OK;
}

mcs_status mcs_pointset_set_wrap(mcs_pointset *acc, int wrap)
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
static size_t chunk_of(const mcs_pointset *acc)
{
    const size_t modes = 2u * (2u * acc->freq_max + 1u);
    return modes > MCS_POINTSET_STAGE_MIN ? modes : (size_t)MCS_POINTSET_STAGE_MIN;
}

/* The path of a trial of k points (acc checked). */
static mcs_status path_of(const mcs_pointset *acc, size_t k, mcs_pointset_path *out)
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
                : mcs_ps_auto_path_(1, acc->freq_max, acc->plan.n, chunk_of(acc), k);
    *out = p;
    return MCS_OK;
}

mcs_status mcs_pointset_path_for(const mcs_pointset *acc, size_t k, mcs_pointset_path *path)
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

/* Phase rows of point slot p for point q of k (a padding slot past the
 * last point contributes 0): low[b] = e^{-2 pi i b x}, b < B, and
 * high[a] = e^{-2 pi i a B x}, a < blocks. B x mod 1 is exact (B is a power
 * of two), so the high row is the phase row of that fraction. */
static void phase_rows(mcs_pointset *acc, int p, size_t k, const mcs_ps_points *pts, size_t q)
{
    const double x = q < k ? mcs_ps_coord(pts, q, 0) : 0.0, amp = q < k ? 1.0 : 0.0;
    const size_t blocks = blocks_of(acc->freq_max);
    double *low = acc->low + (size_t)(2 * p) * B, *high = acc->high + (size_t)(2 * p) * blocks;
    mcs_ps_phase_row(x, 1.0, B - 1u, low, low + B);
    double xb = (double)B * x;
    mcs_ps_phase_row(xb - floor(xb), amp, blocks - 1u, high, high + blocks);
}

/* S(a B + b) += sum over the four slots of high_p[a] low_p[b]. */
static void accumulate_four(mcs_pointset *acc)
{
    const size_t blocks = blocks_of(acc->freq_max);
    const double *lo = acc->low, *hi = acc->high;
    const double *const x[8] = {lo,          lo + B,      lo + 2u * B, lo + 3u * B,
                                lo + 4u * B, lo + 5u * B, lo + 6u * B, lo + 7u * B};
    const double *const y[8] = {hi,              hi + blocks,     hi + 2u * blocks,
                                hi + 3u * blocks, hi + 4u * blocks, hi + 5u * blocks,
                                hi + 6u * blocks, hi + 7u * blocks};
    mcs_ps_outer4(blocks, B, acc->re, acc->im, x, y);
}

static void direct_sums(mcs_pointset *acc, size_t k, const mcs_ps_points *pts)
{
    mcs_ps_clear(blocks_of(acc->freq_max) * B, acc->re, acc->im);
    for (size_t j = 0; j < k; j += 4u) {
        for (int p = 0; p < 4; ++p)
            phase_rows(acc, p, k, pts, j + (size_t)p);
        accumulate_four(acc);
    }
}

#if MCS_CONFIG_NUFFT /* else the NUFFT path is left out (config.h) */
/* ---- the NUFFT path ---- */

/* The sums from the NUFFT, chunk_of(acc) points per transform: the caller's
 * points where they are, wrapped ones staged in the output array (which the
 * transform may overwrite); the same values give the same bits either way. */
static void nufft_sums(mcs_pointset *acc, size_t k, const mcs_ps_points *pts, int ones)
{
    const size_t fmax = acc->freq_max, chunk = chunk_of(acc);
    double *stage = acc->stage;
    mcs_ps_clear(blocks_of(fmax) * B, acc->re, acc->im);
    for (size_t j0 = 0; j0 < k; j0 += chunk) {
        const size_t m = k - j0 < chunk ? k - j0 : chunk;
        /* cannot fail: the points are checked, outside the buffer, m >= 1 */
        if (!ones && pts->f[0] != NULL) {
            (void)mcs_nufft_type1_f(&acc->plan, pts->f[0] + j0, m, stage);
        } else if (!ones) {
            (void)mcs_nufft_type1(&acc->plan, pts->d[0] + j0, m, stage);
        } else {
            for (size_t j = 0; j < m; ++j)
                stage[j] = mcs_ps_coord(pts, j0 + j, 0);
            (void)mcs_nufft_type1(&acc->plan, stage, m, stage);
        }
        const double *c = stage + 2u * fmax; /* c_f at complex index f + F */
        for (size_t f = 0; f <= fmax; ++f) {
            acc->re[f] += c[2u * f];
            acc->im[f] += c[2u * f + 1u];
        }
    }
}
#endif

/* The body of every add: the checks in the order the header gives, then
 * the sums by the trial's path and the Welford update. */
static mcs_status add_points(mcs_pointset *acc, size_t k, const mcs_ps_points *pts)
{
    mcs_status st = mcs_ps_points_null(pts) ? MCS_ERR_NULL : check_acc(acc);
    mcs_pointset_path path = MCS_POINTSET_PATH_DIRECT;
    if (st == MCS_OK)
        st = path_of(acc, k, &path);
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
    mcs_ps_head *head = (mcs_ps_head *)(void *)acc->state;
    const uint64_t count = ++head->count;
    const double inv_k = 1.0 / (double)k;
    for (size_t f = 0; f <= acc->freq_max; ++f) {
        double p = (acc->re[f] * acc->re[f] + acc->im[f] * acc->im[f]) * inv_k;
        mcs_ps_welford(&acc->mean[f], &acc->m2[f], p, count);
    }
    return MCS_OK;
}

mcs_status mcs_pointset_add(mcs_pointset *acc, size_t k, const double *points)
{
    const mcs_ps_points pts = mcs_ps_points_d(points, NULL, 1);
    return add_points(acc, k, &pts);
}

mcs_status mcs_pointset_add_f(mcs_pointset *acc, size_t k, const float *points)
{
    const mcs_ps_points pts = mcs_ps_points_f(points, NULL, 1);
    return add_points(acc, k, &pts);
}

mcs_status mcs_pointset_merge(mcs_pointset *dst, const mcs_pointset *src)
{
    mcs_status st = mcs_check_pair_(check_acc(dst), check_acc(src));
    if (st == MCS_OK)
        st = mcs_ps_check_merge(dst, src, sizeof *dst, dst->mem, dst->bytes, src->mem, src->bytes,
                                dst->freq_max == src->freq_max, count_of(dst), count_of(src));
    if (st != MCS_OK || count_of(src) == 0u)
        return st;
    const uint64_t na = count_of(dst), nb = count_of(src);
    mcs_ps_chan_cells(dst->freq_max + 1u, dst->mean, dst->m2, na, src->mean, src->m2, nb);
    ((mcs_ps_head *)(void *)dst->state)->count = na + nb;
    return MCS_OK;
}

mcs_status mcs_pointset_count(const mcs_pointset *acc, uint64_t *count)
{
    mcs_status st = count == NULL ? MCS_ERR_NULL : check_acc(acc);
    return mcs_ps_count_out(st, st == MCS_OK ? count_of(acc) : 0u, count);
}

/* <P(freq)> (want_stderr 0) or its standard error (1). */
static mcs_status read_power(const mcs_pointset *acc, long freq, int want_stderr, double *out)
{
    mcs_status st = out == NULL ? MCS_ERR_NULL : check_acc(acc);
    if (st != MCS_OK)
        return st;
    const size_t f = mcs_ps_abs(freq);
    if (f > acc->freq_max)
        return MCS_ERR_FREQ_RANGE;
    return mcs_ps_read(acc->mean[f], acc->m2[f], count_of(acc), want_stderr, out);
}

mcs_status mcs_pointset_power(const mcs_pointset *acc, long freq, double *out)
{
    return read_power(acc, freq, 0, out);
}

mcs_status mcs_pointset_power_stderr(const mcs_pointset *acc, long freq, double *out)
{
    return read_power(acc, freq, 1, out);
}

mcs_status mcs_pointset_exact_power(mcs_pattern_kind kind, size_t k, long freq, double *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    if (k == 0u)
        return MCS_ERR_K_RANGE;
    if (kind != MCS_PATTERN_RANDOM && kind != MCS_PATTERN_STRATIFIED &&
        kind != MCS_PATTERN_UNIFORM && kind != MCS_PATTERN_JITTER)
        return MCS_ERR_KIND;
    const double kd = (double)k;
    const size_t f = mcs_ps_abs(freq);
    if (f == 0u) {
        *out = kd;
        return MCS_OK;
    }
    switch (kind) {
    case MCS_PATTERN_RANDOM: *out = 1.0; break;
    case MCS_PATTERN_STRATIFIED: *out = 1.0 - mcs_ps_sinc2(f, k); break;
    default: /* a comb: all K phases agree exactly when K divides f */
        *out = f % k == 0u ? kd : 0.0;
        break;
    }
    return MCS_OK;
}
