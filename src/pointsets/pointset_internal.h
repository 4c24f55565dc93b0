/* Helpers shared by the point-set periodogram accumulators (pointset.c,
 * pointset2d.c, pointset_exact.c) and the binned 2D spectrum (spectrum2d.c,
 * spectrum2d_exact.c), and by their records (io/io_points.c): the layout of
 * the caller's buffer, the checks of the size query, init and copy
 * (pointset_common.c), the caller's points (interleaved or planar, double or
 * float, wrapped or not), the outer-product kernel of a trial, the per-cell
 * Welford and Chan updates, the read-out of a mean or its standard error,
 * and the annulus arithmetic; private header. */
#ifndef MCSPEC_POINTSET_INTERNAL_H
#define MCSPEC_POINTSET_INTERNAL_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "accumulators/acc_internal.h"
#include "mcspec/pointset.h"
#include "mcspec/spectrum2d.h"
#include "mcspec/status.h"

_Static_assert(sizeof(mcs_pointset_head) == sizeof(mcs_spectrum2d_head) &&
                   offsetof(mcs_pointset_head, count) == offsetof(mcs_spectrum2d_head, count),
               "one head layout for every object over caller memory (io_points.c)");

/* ---- the caller's buffer ----
 * Every array starts at a multiple of MCS_PS_ALIGN from the first such
 * address in the buffer (a cache line), and the size asked of the caller
 * adds MCS_PS_ALIGN - 1 for that first step. The statistics come first,
 * behind a head that holds the shape words and the trial count (so a
 * buffer's statistics are one block: a copy is one memcpy, and a record's
 * fields are offsets from the head, io_points.c), then the scratch. */
#define MCS_PS_ALIGN 64u

typedef mcs_pointset_head mcs_ps_head; /* F (and 0), or N1, N2; trials added */

/* The first MCS_PS_ALIGN boundary at or after mem. */
static inline unsigned char *mcs_ps_aligned(void *mem)
{
    const uintptr_t at = (uintptr_t)mem;
    return (unsigned char *)mem + (MCS_PS_ALIGN - at % MCS_PS_ALIGN) % MCS_PS_ALIGN;
}

/* Offsets of a buffer's arrays, handed out in order: mcs_ps_take gives the
 * offset of count elements of elem bytes and moves on by their size rounded
 * up to MCS_PS_ALIGN; any size that would pass SIZE_MAX marks the layout
 * as overflowed (its total is then SIZE_MAX: refused as too large). */
typedef struct {
    size_t at;
    int overflow;
} mcs_ps_carve;

static inline size_t mcs_ps_take(mcs_ps_carve *c, size_t count, size_t elem)
{
    const size_t half = SIZE_MAX / 2u, off = c->at;
    if (c->overflow || (elem > 0u && count > half / elem)) {
        c->overflow = 1;
        return 0u;
    }
    const size_t bytes = (count * elem + (MCS_PS_ALIGN - 1u)) / MCS_PS_ALIGN * MCS_PS_ALIGN;
    if (bytes > half - off) { /* offsets stay below SIZE_MAX / 2 */
        c->overflow = 1;
        return 0u;
    }
    c->at = off + bytes;
    return off;
}

/* Bytes to ask of the caller for the offsets handed out, or SIZE_MAX. */
static inline size_t mcs_ps_total(const mcs_ps_carve *c)
{
    return c->overflow ? SIZE_MAX : c->at + (MCS_PS_ALIGN - 1u);
}

/* ---- an object's life cycle over the caller's buffer (pointset_common.c) ----
 * mcs_pointset, mcs_pointset2d and mcs_spectrum2d share the checks of their
 * size query, init and copy, and the set-up of the statistics in the
 * buffer. Each object's file keeps its layout (the offsets of its arrays
 * for its two arguments: F and flags, or N1 and N2) and the set-up of its
 * header, and calls these directly: no call goes through a function
 * pointer, so make stack follows every chain. */
#define MCS_PS_MAX_ARRAYS 12 /* spectrum2d's twelve */

typedef struct {
    size_t shape[2];              /* the head's shape words: F and 0, or N1 and N2 */
    size_t at[MCS_PS_MAX_ARRAYS]; /* the arrays' offsets from the head, by the file's names */
    size_t plan, plan_bytes;      /* the NUFFT plan's memory (0 bytes: no plan) */
    size_t stats;                 /* the end of the head and the statistics: a copy's bytes */
    size_t total;                 /* bytes to ask of the caller (SIZE_MAX: too large) */
} mcs_ps_layout;

/* An object header and the buffer it is, or is to be, over. */
typedef struct {
    const void *obj; /* the header */
    size_t hdr;      /* sizeof the header */
    const void *mem; /* the buffer, as given */
    size_t bytes;    /* its length */
} mcs_ps_span;

/* The size query once the layout gave st: *bytes = lay's total.
 * MCS_ERR_NULL before st; *bytes untouched on error. */
mcs_status mcs_ps_size_(mcs_status st, const mcs_ps_layout *lay, size_t *bytes);

/* The checks of an init of header to.obj over buffer to.mem[to.bytes] once
 * the layout gave st: MCS_ERR_NULL (no header or buffer), st, MCS_ERR_SPACE,
 * MCS_ERR_ALIAS (the buffer overlaps the header), in that order. */
mcs_status mcs_ps_check_init_(const mcs_ps_span *to, mcs_status st, const mcs_ps_layout *lay);

/* The checks of a copy of from (its own check and layout gave st, lay; from
 * read only if st is MCS_OK) to header to.obj over to.mem[to.bytes]: those
 * of an init, then MCS_ERR_ALIAS also where the buffer overlaps from's
 * header or buffer, or the headers overlap and are not one. */
mcs_status mcs_ps_check_copy_(const mcs_ps_span *to, const mcs_ps_span *from, mcs_status st,
                              const mcs_ps_layout *lay);

/* The head of a checked buffer mem for lay, its statistics zeroed under
 * the shape words (stats NULL: init) or copied from stats (a copy's source
 * head). */
unsigned char *mcs_ps_set_up_stats_(void *mem, const mcs_ps_layout *lay, const void *stats);

/* Whether an object of these flags leaves the NUFFT out: with
 * MCS_POINTSET_DIRECT_ONLY, and always in a build with MCS_CONFIG_NUFFT 0
 * (config.h), where the layout, the path and the checks are then those of
 * MCS_POINTSET_DIRECT_ONLY and no NUFFT code is referenced. */
static inline int mcs_ps_direct_only(unsigned flags)
{
#if MCS_CONFIG_NUFFT
    return (flags & MCS_POINTSET_DIRECT_ONLY) != 0u;
#else
    (void)flags;
    return 1;
#endif
}

/* A point-set accumulator's path after init: DIRECT with
 * MCS_POINTSET_DIRECT_ONLY among the flags, else AUTO. */
static inline mcs_pointset_path mcs_ps_first_path(unsigned flags)
{
    return (flags & MCS_POINTSET_DIRECT_ONLY) != 0u ? MCS_POINTSET_PATH_DIRECT
                                                    : MCS_POINTSET_PATH_AUTO;
}

/* A pointer to array `name` of lay in the buffer whose head is at base. */
static inline double *mcs_ps_array(unsigned char *base, const mcs_ps_layout *lay, int name)
{
    return (double *)(void *)(base + lay->at[name]);
}

/* A hash of an object header's words (its key): a header that init did not
 * set (zeroed, garbage, edited) fails it before any pointer is followed. */
static inline uintptr_t mcs_ps_hash(const uintptr_t *words, size_t n)
{
    uintptr_t h = (uintptr_t)0x70737431u; /* "pst1" */
    for (size_t j = 0; j < n; ++j) {
        h ^= words[j];
        h *= (uintptr_t)0x9e3779b1u;
        h ^= h >> 15;
    }
    return h;
}

/* The key's words of a NUFFT plan held in a header (all of its fields, the
 * doubles by their bits): a header whose plan was edited fails the
 * object's own check, before the plan is used. Writes 15 words. */
static inline void mcs_ps_plan_words(const mcs_nufft *p, uintptr_t *w)
{
    uint64_t beta = 0u, tol = 0u;
    memcpy(&beta, &p->beta, sizeof beta);
    memcpy(&tol, &p->tol, sizeof tol);
    w[0] = (uintptr_t)p->dim, w[1] = (uintptr_t)p->freq, w[2] = (uintptr_t)p->n;
    w[3] = (uintptr_t)p->width, w[4] = (uintptr_t)beta, w[5] = (uintptr_t)tol;
    w[6] = (uintptr_t)p->fft_len, w[7] = (uintptr_t)p->bytes, w[8] = (uintptr_t)p->mem;
    w[9] = (uintptr_t)p->grid, w[10] = (uintptr_t)p->scratch, w[11] = (uintptr_t)p->corr;
    w[12] = (uintptr_t)p->twiddle, w[13] = (uintptr_t)p->fft, w[14] = p->key;
}
#define MCS_PS_PLAN_WORDS 15

/* ---- the caller's points ----
 * d[c] (or f[c] for float points) is coordinate c of point 0, and point j's
 * is step elements further on: interleaved 2D points have d[1] = d[0] + 1
 * and step 2, planar ones their own arrays and step 1, 1D points step 1. */
typedef struct {
    const double *d[2];
    const float *f[2];
    size_t step;
    int dims;        /* 1 or 2 */
    int interleaved; /* d[0] (or f[0]) holds the points as the NUFFT takes them */
} mcs_ps_points;

static inline mcs_ps_points mcs_ps_points_d(const double *x, const double *y, int dims)
{
    mcs_ps_points p = {{x, y}, {NULL, NULL}, 1u, dims, 0};
    if (dims == 2 && y == NULL) { /* interleaved */
        p.d[1] = x != NULL ? x + 1 : NULL;
        p.step = 2u;
    }
    p.interleaved = dims == 1 || y == NULL;
    return p;
}

static inline mcs_ps_points mcs_ps_points_f(const float *x, const float *y, int dims)
{
    mcs_ps_points p = {{NULL, NULL}, {x, y}, 1u, dims, 0};
    if (dims == 2 && y == NULL) {
        p.f[1] = x != NULL ? x + 1 : NULL;
        p.step = 2u;
    }
    p.interleaved = dims == 1 || y == NULL;
    return p;
}

static inline int mcs_ps_points_null(const mcs_ps_points *p)
{
    const int c = p->dims - 1;
    return p->f[0] != NULL ? p->f[c] == NULL : (p->d[0] == NULL || p->d[c] == NULL);
}

/* Coordinate c of point j as given, widened exactly from float. */
static inline double mcs_ps_raw(const mcs_ps_points *p, size_t j, int c)
{
    return p->f[0] != NULL ? (double)p->f[c][j * p->step] : p->d[c][j * p->step];
}

/* The same, with 1.0 taken as 0.0 (a check let it in only under wrap). */
static inline double mcs_ps_coord(const mcs_ps_points *p, size_t j, int c)
{
    const double v = mcs_ps_raw(p, j, c);
    return v == 1.0 ? 0.0 : v;
}

/* Every coordinate of the k points in [0, 1), or [0, 1] with wrap (NaN in
 * neither): MCS_ERR_POINT_RANGE otherwise. *ones: some coordinate is 1.0. */
static inline mcs_status mcs_ps_check_points(const mcs_ps_points *p, size_t k, int wrap, int *ones)
{
    const double top = wrap ? 1.0 : 0x1.fffffffffffffp-1;
    int one = 0;
    for (size_t j = 0; j < k; ++j)
        for (int c = 0; c < p->dims; ++c) {
            const double v = mcs_ps_raw(p, j, c);
            if (!(v >= 0.0 && v <= top))
                return MCS_ERR_POINT_RANGE;
            one |= v == 1.0;
        }
    *ones = one;
    return MCS_OK;
}

/* Whether the k points share a byte with [obj, obj + bytes). */
static inline int mcs_ps_points_overlap(const mcs_ps_points *p, size_t k, const void *obj,
                                        size_t bytes)
{
    const size_t elem = p->f[0] != NULL ? sizeof(float) : sizeof(double);
    const size_t span = mcs_bytes_((k - 1u) * p->step + 1u, elem);
    int hit = 0;
    for (int c = 0; c < p->dims; ++c) {
        const void *a = p->f[0] != NULL ? (const void *)p->f[c] : (const void *)p->d[c];
        hit |= mcs_overlap_(a, span, obj, bytes);
    }
    return hit;
}

/* Phases are advanced by one complex multiplication per frequency; every
 * MCS_PS_ANCHOR steps they are recomputed from sin and cos, so rounding
 * accumulates over at most this many products (a few 1e-15 in all). */
#define MCS_PS_ANCHOR 32u

/* The first check of a point-set or binned 2D accumulator's init:
 * MCS_ERR_NULL without the object, MCS_ERR_FREQ_RANGE unless 1 <= f <= cap. */
static inline mcs_status mcs_ps_check_init(const void *acc, size_t freq_max, size_t cap)
{
    mcs_status st = mcs_check_init_(acc, freq_max, cap);
    return st == MCS_ERR_N_RANGE ? MCS_ERR_FREQ_RANGE : st;
}

/* A count read-out: *out = count when the object's own check gave st, MCS_OK
 * (count is read only then: the caller passes 0 otherwise). */
static inline mcs_status mcs_ps_count_out(mcs_status st, uint64_t count, uint64_t *out)
{
    if (st == MCS_OK)
        *out = count;
    return st;
}

/* e^{-2 pi i f x} for x in [0,1): f x reduced mod 1 first so the angle stays
 * in [0, 2 pi) however large f is. */
static inline void mcs_ps_phase(double x, size_t f, double *re, double *im)
{
    double t = (double)f * x;
    t -= floor(t);
    double a = MCS_TWO_PI * t;
    *re = cos(a);
    *im = -sin(a);
}

/* re[f] + i im[f] = amp e^{-2 pi i f x}, f = 0..fmax, by rotation with
 * re-anchoring (amp is 1 for a point, 0 for a padding slot). */
static inline void mcs_ps_phase_row(double x, double amp, size_t fmax, double *re, double *im)
{
    double wr, wi;
    mcs_ps_phase(x, 1u, &wr, &wi);
    for (size_t c = 0; c <= fmax; c += MCS_PS_ANCHOR) {
        double zr, zi;
        mcs_ps_phase(x, c, &zr, &zi);
        zr *= amp;
        zi *= amp;
        size_t end = fmax - c < MCS_PS_ANCHOR ? fmax + 1u : c + MCS_PS_ANCHOR;
        for (size_t f = c; f < end; ++f) {
            re[f] = zr;
            im[f] = zi;
            double t = zr * wr - zi * wi;
            zi = zr * wi + zi * wr;
            zr = t;
        }
    }
}

/* s[c] += sum over four points p of x_p[c] (a_p + i b_p), c < stride (even),
 * with y = (a_0, b_0, ..., a_3, b_3): one row of an outer-product sum.
 * restrict: the phase rows and the sums are disjoint parts of the
 * accumulator, which lets the compiler vectorise the loop. */
static inline void mcs_ps_row_update4(size_t stride, double *restrict sr, double *restrict si,
                       const double *restrict x0r, const double *restrict x0i,
                       const double *restrict x1r, const double *restrict x1i,
                       const double *restrict x2r, const double *restrict x2i,
                       const double *restrict x3r, const double *restrict x3i, const double *y)
{
    const double a0 = y[0], b0 = y[1], a1 = y[2], b1 = y[3];
    const double a2 = y[4], b2 = y[5], a3 = y[6], b3 = y[7];
    /* Two columns per step (stride is even): the pair is one vector operation
     * at -O2, where gcc vectorises straight-line code but not loops of
     * unknown length. */
    for (size_t c = 0; c < stride; c += 2u) {
        for (size_t d = c; d < c + 2u; ++d) {
            sr[d] += ((x0r[d] * a0 - x0i[d] * b0) + (x1r[d] * a1 - x1i[d] * b1)) +
                     ((x2r[d] * a2 - x2i[d] * b2) + (x3r[d] * a3 - x3i[d] * b3));
            si[d] += ((x0r[d] * b0 + x0i[d] * a0) + (x1r[d] * b1 + x1i[d] * a1)) +
                     ((x2r[d] * b2 + x2i[d] * a2) + (x3r[d] * b3 + x3i[d] * a3));
        }
    }
}

/* S[r stride + c] += sum over four points p of y_p[r] x_p[c], r < rows,
 * c < stride (even): a trial's sum over points as outer products of per-point
 * rows, four points per pass over S. x[2p], x[2p + 1] are point p's x row
 * (re, im), y[2p], y[2p + 1] its y row. */
static inline void mcs_ps_outer4(size_t rows, size_t stride, double *re, double *im,
                                 const double *const x[8], const double *const y[8])
{
    for (size_t r = 0; r < rows; ++r) {
        const double c[8] = {y[0][r], y[1][r], y[2][r], y[3][r],
                             y[4][r], y[5][r], y[6][r], y[7][r]};
        mcs_ps_row_update4(stride, re + r * stride, im + r * stride, x[0], x[1], x[2], x[3], x[4],
                           x[5], x[6], x[7], c);
    }
}

/* Zeroes a trial's sums re[cells], im[cells] before its points go in. */
static inline void mcs_ps_clear(size_t cells, double *re, double *im)
{
    memset(re, 0, cells * sizeof *re);
    memset(im, 0, cells * sizeof *im);
}

/* Welford update of (mean, m2) with value v as the count-th value. */
static inline void mcs_ps_welford(double *mean, double *m2, double v, uint64_t count)
{
    double d = v - *mean;
    *mean += d / (double)count;
    *m2 += d * (v - *mean);
}

/* Chan et al.: (mean_a, m2_a) over na values <- union with (mean_b, m2_b) over nb. */
static inline void mcs_ps_chan(double *mean_a, double *m2_a, uint64_t na, double mean_b,
                               double m2_b, uint64_t nb)
{
    double n = (double)na + (double)nb, d = mean_b - *mean_a;
    *mean_a += d * ((double)nb / n);
    *m2_a += m2_b + d * d * ((double)na * (double)nb / n);
}

/* (mean_a, m2_a) over na trials <- union with (mean_b, m2_b) over nb, cell by
 * cell over the first `cells` cells (Chan et al.). */
static inline void mcs_ps_chan_cells(size_t cells, double *mean_a, double *m2_a, uint64_t na,
                                     const double *mean_b, const double *m2_b, uint64_t nb)
{
    for (size_t i = 0; i < cells; ++i)
        mcs_ps_chan(&mean_a[i], &m2_a[i], na, mean_b[i], m2_b[i], nb);
}

/* sqrt(m2 / (T - 1) / T): standard error of a mean over T >= 2 trials. */
static inline double mcs_ps_stderr(double m2, uint64_t count)
{
    double t = (double)count;
    return sqrt(fmax(m2, 0.0) / (t - 1.0) / t);
}

/* A read-out of one cell over `count` trials: *out = its mean (want_stderr 0)
 * or the standard error of the mean (1). MCS_ERR_EMPTY without a trial, or
 * for the standard error without two; *out untouched then. */
static inline mcs_status mcs_ps_read(double mean, double m2, uint64_t count, int want_stderr,
                                     double *out)
{
    if (count < (want_stderr ? 2u : 1u))
        return MCS_ERR_EMPTY;
    *out = want_stderr ? mcs_ps_stderr(m2, count) : mean;
    return MCS_OK;
}

/* |f| as a size_t, without overflow at LONG_MIN. */
static inline size_t mcs_ps_abs(long f)
{
    return f < 0 ? (size_t)(-(f + 1)) + 1u : (size_t)f;
}

/* sinc^2(pi f / d) = sin^2(pi f/d) / (pi f/d)^2, 1 at f = 0. sin^2 has period
 * d in f, so the sine takes f mod d and stays accurate for large f. */
static inline double mcs_ps_sinc2(size_t f, size_t d)
{
    if (f == 0u)
        return 1.0;
    double s = sin(MCS_TWO_PI * 0.5 * (double)(f % d) / (double)d);
    double a = MCS_TWO_PI * 0.5 * (double)f / (double)d;
    return (s * s) / (a * a);
}

/* floor(sqrt(q)) exactly (the double root is corrected by integer steps):
 * the annulus of wave vector f is floor(|f|). */
static inline size_t mcs_ps_isqrt(size_t q)
{
    size_t r = (size_t)sqrt((double)q);
    while (r > 0u && r * r > q)
        --r;
    while ((r + 1u) * (r + 1u) <= q)
        ++r;
    return r;
}

/* The columns ax = lo..hi (none when lo > hi) of row ay >= 0 of the
 * quadrant that lie in annulus r (r^2 <= ax^2 + ay^2 < (r + 1)^2): an
 * annulus is read in O(r) rows of O(1) isqrt each, not over the whole
 * square. r below 2^31 (r^2 fits size_t on 32-bit targets for the caps). */
static inline void mcs_ps_ring_span(size_t r, size_t ay, size_t *lo, size_t *hi)
{
    if (ay > r) {
        *lo = 1u;
        *hi = 0u;
        return;
    }
    const size_t below = r * r - ay * ay; /* ax^2 >= below */
    *lo = below == 0u ? 0u : mcs_ps_isqrt(below - 1u) + 1u;
    *hi = mcs_ps_isqrt((r + 1u) * (r + 1u) - 1u - ay * ay);
}

/* How many whole-plane wave vectors (+-ax, +-ay) the quadrant wave vector
 * (ax, ay) stands for. */
static inline double mcs_ps_ring_mult(size_t ax, size_t ay)
{
    return (ax > 0u ? 2.0 : 1.0) * (ay > 0u ? 2.0 : 1.0);
}

/* Weighted mean and unbiased variance of the values over an annulus, in two
 * passes over them (the variance of values near a large mean would cancel in
 * one): pass 0 sums w p and w, pass 1 the weighted squared deviations. */
typedef struct {
    double sum, n, ss;
} mcs_ps_ring;

static inline void mcs_ps_ring_add(mcs_ps_ring *g, int pass, double w, double p)
{
    if (pass == 0) {
        g->sum += w * p;
        g->n += w;
    } else {
        g->ss += w * (p - g->sum / g->n) * (p - g->sum / g->n);
    }
}

/* psa's anisotropy 10 log10(var / mean^2) of the annulus in dB (divisor
 * n - 1). MCS_ERR_DOMAIN when it is not finite: fewer than two wave vectors,
 * a mean not above mean_min (an empty annulus measured as rounding residue),
 * or a variance not above var_rel_min mean^2 (differences at the rounding
 * level of the mean are no variance). *out_db untouched then. */
static inline mcs_status mcs_ps_ring_db(const mcs_ps_ring *g, double mean_min,
                                        double var_rel_min, double *out_db)
{
    const double mean = g->sum / g->n, var = g->n > 1.0 ? g->ss / (g->n - 1.0) : 0.0;
    if (g->n < 2.0 || !(mean > mean_min) || !(var > var_rel_min * mean * mean))
        return MCS_ERR_DOMAIN;
    *out_db = 10.0 * log10(var / (mean * mean));
    return MCS_OK;
}

/* ---- the cost model of AUTO (pointset_cost.c) ----
 * The faster path for a trial of k points in dims = 1 or 2 at cutoff freq,
 * with a NUFFT grid of n points per axis that takes at most chunk points per
 * transform. */
mcs_pointset_path mcs_ps_auto_path_(int dims, size_t freq, size_t n, size_t chunk, size_t k);

/* The checks of merging src into dst once both passed their own
 * (mcs_check_pair_): MISMATCH unless same_shape, COUNT if the counts would
 * pass MCS_MAX_COUNT, ALIAS for distinct objects whose headers (hdr bytes)
 * or buffers overlap in any way (dst == src is allowed: it doubles). */
static inline mcs_status mcs_ps_check_merge(const void *dst, const void *src, size_t hdr,
                                            const void *dst_mem, size_t dst_bytes,
                                            const void *src_mem, size_t src_bytes,
                                            int same_shape, uint64_t dst_count,
                                            uint64_t src_count)
{
    if (!same_shape)
        return MCS_ERR_MISMATCH;
    mcs_status st = mcs_check_count_(dst_count, src_count);
    if (st == MCS_OK && dst != src &&
        (mcs_overlap_(dst, hdr, src, hdr) || mcs_overlap_(dst_mem, dst_bytes, src_mem, src_bytes) ||
         mcs_overlap_(dst, hdr, src_mem, src_bytes) || mcs_overlap_(src, hdr, dst_mem, dst_bytes)))
        st = MCS_ERR_ALIAS;
    return st;
}

#endif /* MCSPEC_POINTSET_INTERNAL_H */
