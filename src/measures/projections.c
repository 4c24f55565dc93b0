/* The 2D projections of a d-dimensional point set (projections.h): per pair
 * the periodogram over the half box |fx|, |fy| <= F, tested against what
 * the same two 1D sets paired at random would give. */
#include "mcspec/projections.h"
#include "mcspec/discrepancy.h"
#include "measures_internal.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#define TWO_PI 6.283185307179586476925
/* The two-sided normal tail beyond 5 standard deviations. */
#define ALPHA 5.733031437583878e-7
#define MAX_SETS (UINT64_C(1) << 53)

/* The statistics of one pair, in order, before its mean periodogram. */
enum {
    ST_N,          /* sets */
    ST_RADIAL,     /* Welford of the per-set mean P over the low disc: mean, M2 */
    ST_RADIAL_M2,
    ST_DIFF,       /* Welford of the per-set mean of P - ref over the disc */
    ST_DIFF_M2,
    ST_REF,        /* running mean of the per-set mean ref */
    ST_PEAK,       /* Welford of the per-set largest P / ref off axis */
    ST_PEAK_M2,
    ST_PEAK_MAX,   /* the largest over the sets */
    ST_DISC_N,     /* Welford of the squared WD, sets with it computed */
    ST_DISC,
    ST_DISC_M2,
    ST_WITHIN_RADIAL, /* first set: variance over the disc of P, and of P - ref */
    ST_WITHIN_DIFF,
    ST_N_LOW,      /* wave vectors in the disc */
    ST_N_PEAK,     /* wave vectors the peak is taken over */
    ST_MODEL_VAR   /* running mean of the per-set null variance of the disc mean */
};

static size_t pair_count(size_t d)
{
    return d * (d - 1u) / 2u;
}

static size_t cells(size_t f)
{
    return MCS_PROJECTIONS_CELLS_(f);
}

static size_t pair_stride(size_t f)
{
    return MCS_PROJECTIONS_PAIR_STATS_ + cells(f);
}

/* Index of pair (i, j), i < j, in the order (0,1), (0,2), .., (1,2), .. */
static size_t pair_index(size_t d, size_t i, size_t j)
{
    return i * d - i * (i + 1u) / 2u + (j - i - 1u);
}

static uintptr_t key_of(const mcs_projections *p)
{
    const uintptr_t w[12] = {(uintptr_t)p->dim,        (uintptr_t)p->freq,
                             (uintptr_t)p->radius,     (uintptr_t)p->k_max,
                             (uintptr_t)p->disc_sets,  (uintptr_t)p->sets,
                             (uintptr_t)(p->sets >> 16 >> 16), (uintptr_t)p->k_last,
                             (uintptr_t)p->mem,        (uintptr_t)p->bytes,
                             (uintptr_t)p->pairs,      (uintptr_t)p->scratch};
    uintptr_t h = (uintptr_t)0x9e3779b97f4a7c15u;
    for (int i = 0; i < 12; ++i) {
        h ^= w[i] + (uintptr_t)0x7f4a7c15u + (h << 6) + (h >> 2);
        h *= (uintptr_t)0x2545f491u;
    }
    return h | 1u;
}

mcs_status mcs_projections_size(size_t dim, size_t freq, size_t k_max, size_t *bytes)
{
    if (bytes == NULL)
        return MCS_ERR_NULL;
    if (dim < 2u || dim > MCS_PROJECTIONS_MAX_DIM)
        return MCS_ERR_DOMAIN;
    if (freq < 1u || freq > MCS_PROJECTIONS_MAX_FREQ)
        return MCS_ERR_FREQ_RANGE;
    if (k_max < 1u || (uint64_t)k_max > (UINT64_C(1) << 31))
        return MCS_ERR_K_RANGE;
    *bytes = MCS_PROJECTIONS_SIZE(dim, freq, k_max);
    return MCS_OK;
}

mcs_status mcs_projections_init(mcs_projections *p, size_t dim, size_t freq, size_t radius,
                                size_t k_max, size_t disc_sets, void *mem, size_t bytes)
{
    size_t need = 0u;
    mcs_status st = p == NULL || mem == NULL ? MCS_ERR_NULL
                                             : mcs_projections_size(dim, freq, k_max, &need);
    if (st != MCS_OK)
        return st;
    if (radius < 1u || radius > freq)
        return MCS_ERR_DOMAIN;
    if (bytes < need)
        return MCS_ERR_SPACE;
    if (mcs_overlap_(mem, bytes, p, sizeof *p))
        return MCS_ERR_ALIAS;
    mcs_projections h;
    memset(&h, 0, sizeof h);
    h.dim = dim;
    h.freq = freq;
    h.radius = radius;
    h.k_max = k_max;
    h.disc_sets = disc_sets;
    h.mem = mem;
    h.bytes = bytes;
    h.pairs = mcs_meas_align_(mem, 8u);
    h.scratch = h.pairs + pair_count(dim) * pair_stride(freq);
    memset(h.pairs, 0, pair_count(dim) * pair_stride(freq) * sizeof(double));
    h.key = key_of(&h);
    *p = h;
    return MCS_OK;
}

static mcs_status check(const mcs_projections *p)
{
    if (p == NULL)
        return MCS_ERR_NULL;
    if (p->dim < 2u || p->dim > MCS_PROJECTIONS_MAX_DIM || p->freq < 1u ||
        p->freq > MCS_PROJECTIONS_MAX_FREQ || p->mem == NULL || p->key != key_of(p))
        return MCS_ERR_UNINIT;
    return MCS_OK;
}

/* Welford update of (mean, M2) at stats[at], n the count after the add. */
static void welford(double *stats, int at, double n, double x)
{
    double delta = x - stats[at];
    stats[at] += delta / n;
    stats[at + 1] += delta * (x - stats[at]);
}

/* 1D periodograms P_a(f), f = 0..F, of every axis: p1[a (F + 1) + f]. The
 * phase e^{-2 pi i f x} by repeated multiplication: F <= 64 steps lose at
 * most ~64 ulp. */
static void periodograms_1d(const mcs_projections *p, size_t k, const double *points, double *p1)
{
    const size_t d = p->dim, f1 = p->freq + 1u;
    for (size_t a = 0; a < d; ++a) {
        double *row = p1 + a * f1;
        for (size_t f = 0; f < f1; ++f)
            row[f] = 0.0;
        for (size_t f = 1; f < f1; ++f) {
            double re = 0.0, im = 0.0;
            for (size_t q = 0; q < k; ++q) {
                double ph = -TWO_PI * (double)f * points[q * d + a];
                re += cos(ph);
                im += sin(ph);
            }
            row[f] = (re * re + im * im) / (double)k;
        }
        row[0] = (double)k;
    }
}

/* S(f) of pair (i, j) for fx = -F..F, fy = 0..F into re, im at
 * [fy (2F + 1) + fx + F]; phase rows from sin and cos at f = 1, then by
 * multiplication. */
static void pair_sums(const mcs_projections *p, size_t k, const double *points, size_t i,
                      size_t j, double *re, double *im, double *phase)
{
    const size_t d = p->dim, F = p->freq, w = 2u * F + 1u, n = cells(F);
    double *xr = phase, *xi = phase + w, *yr = phase + 2u * w, *yi = yr + (F + 1u);
    for (size_t c = 0; c < n; ++c)
        re[c] = im[c] = 0.0;
    for (size_t q = 0; q < k; ++q) {
        const double x = points[q * d + i], y = points[q * d + j];
        const double cx = cos(TWO_PI * x), sx = -sin(TWO_PI * x);
        const double cy = cos(TWO_PI * y), sy = -sin(TWO_PI * y);
        xr[F] = 1.0;
        xi[F] = 0.0;
        yr[0] = 1.0;
        yi[0] = 0.0;
        for (size_t f = 1; f <= F; ++f) {
            xr[F + f] = xr[F + f - 1u] * cx - xi[F + f - 1u] * sx;
            xi[F + f] = xr[F + f - 1u] * sx + xi[F + f - 1u] * cx;
            xr[F - f] = xr[F + f];
            xi[F - f] = -xi[F + f];
            yr[f] = yr[f - 1u] * cy - yi[f - 1u] * sy;
            yi[f] = yr[f - 1u] * sy + yi[f - 1u] * cy;
        }
        for (size_t fy = 0; fy <= F; ++fy) {
            const double ar = yr[fy], ai = yi[fy];
            double *rr = re + fy * w, *ri = im + fy * w;
            for (size_t c = 0; c < w; ++c) {
                rr[c] += xr[c] * ar - xi[c] * ai;
                ri[c] += xr[c] * ai + xi[c] * ar;
            }
        }
    }
}

/* E[P(f) | the two 1D sets] under a random pairing. */
static double reference(size_t k, double pi, double pj)
{
    return k == 1u ? 1.0 : 1.0 + (pi - 1.0) * (pj - 1.0) / (double)(k - 1u);
}

static void add_pair(mcs_projections *p, size_t k, const double *points, size_t i, size_t j,
                     const double *p1, double *scratch_pts)
{
    const size_t F = p->freq, w = 2u * F + 1u, f1 = F + 1u;
    double *stats = p->pairs + pair_index(p->dim, i, j) * pair_stride(F);
    double *mean = stats + MCS_PROJECTIONS_PAIR_STATS_;
    double *re = p->scratch, *im = re + cells(F);
    double *phase = p->scratch + 2u * cells(F) + p->dim * f1;
    pair_sums(p, k, points, i, j, re, im, phase);
    const double n = stats[ST_N] + 1.0;
    const long R2 = (long)(p->radius * p->radius);
    double sum_p = 0.0, sum_d = 0.0, sum_pp = 0.0, sum_dd = 0.0, sum_ref = 0.0, peak = 0.0;
    double sum_rr = 0.0;
    double n_low = 0.0, n_peak = 0.0;
    for (size_t fy = 0; fy <= F; ++fy)
        for (size_t c = 0; c < w; ++c) {
            const size_t cell = fy * w + c;
            const double pw = (re[cell] * re[cell] + im[cell] * im[cell]) / (double)k;
            mean[cell] += (pw - mean[cell]) / n;
            const long fx = (long)c - (long)F;
            if (fy == 0u || fx == 0)
                continue; /* axis wave vectors: the 1D spectra alone */
            const double ref = reference(k, p1[i * f1 + (size_t)(fx < 0 ? -fx : fx)], p1[j * f1 + fy]);
            const double ratio = ref > 1e-9 ? pw / ref : 0.0;
            peak = ratio > peak ? ratio : peak;
            n_peak += 1.0;
            if (fx * fx + (long)(fy * fy) <= R2) {
                sum_p += pw;
                sum_pp += pw * pw;
                sum_d += pw - ref;
                sum_dd += (pw - ref) * (pw - ref);
                sum_ref += ref;
                sum_rr += ref * ref;
                n_low += 1.0;
            }
        }
    const double mp = sum_p / n_low, md = sum_d / n_low;
    if (stats[ST_N] == 0.0) {
        stats[ST_WITHIN_RADIAL] = n_low > 1.0 ? (sum_pp - n_low * mp * mp) / (n_low - 1.0) : 0.0;
        stats[ST_WITHIN_DIFF] = n_low > 1.0 ? (sum_dd - n_low * md * md) / (n_low - 1.0) : 0.0;
        stats[ST_N_LOW] = n_low;
        stats[ST_N_PEAK] = n_peak;
    }
    stats[ST_N] = n;
    welford(stats, ST_RADIAL, n, mp);
    welford(stats, ST_DIFF, n, md);
    stats[ST_REF] += (sum_ref / n_low - stats[ST_REF]) / n;
    /* independent dimensions: each P(f) about an exponential of mean ref(f),
     * independent across the disc, so the disc mean has variance
     * sum ref^2 / n_low^2 */
    stats[ST_MODEL_VAR] += (sum_rr / (n_low * n_low) - stats[ST_MODEL_VAR]) / n;
    welford(stats, ST_PEAK, n, peak);
    stats[ST_PEAK_MAX] = peak > stats[ST_PEAK_MAX] ? peak : stats[ST_PEAK_MAX];
    if (p->sets < (uint64_t)p->disc_sets) {
        double d2[MCS_DISCREPANCY_L2_COUNT];
        for (size_t q = 0; q < k; ++q) {
            scratch_pts[2u * q] = points[q * p->dim + i];
            scratch_pts[2u * q + 1u] = points[q * p->dim + j];
        }
        if (mcs_discrepancy_l2(k, 2u, scratch_pts, d2) == MCS_OK) {
            stats[ST_DISC_N] += 1.0;
            welford(stats, ST_DISC, stats[ST_DISC_N], d2[MCS_DISCREPANCY_L2_WRAPAROUND]);
        }
    }
}

mcs_status mcs_projections_add(mcs_projections *p, size_t k, const double *points)
{
    mcs_status st = check(p);
    if (st != MCS_OK)
        return st;
    if (points == NULL)
        return MCS_ERR_NULL;
    if (k < 1u || k > p->k_max)
        return MCS_ERR_K_RANGE;
    const size_t d = p->dim, nb = k * d * sizeof(double);
    if (mcs_overlap_(points, nb, p, sizeof *p) || mcs_overlap_(points, nb, p->mem, p->bytes))
        return MCS_ERR_ALIAS;
    for (size_t q = 0; q < k * d; ++q)
        if (!(points[q] >= 0.0 && points[q] < 1.0))
            return MCS_ERR_POINT_RANGE;
    if (p->sets >= MAX_SETS)
        return MCS_ERR_COUNT;
    const size_t f1 = p->freq + 1u;
    double *p1 = p->scratch + 2u * cells(p->freq);
    double *scratch_pts = p1 + d * f1 + 6u * p->freq + 6u;
    periodograms_1d(p, k, points, p1);
    for (size_t i = 0; i < d; ++i)
        for (size_t j = i + 1u; j < d; ++j)
            add_pair(p, k, points, i, j, p1, scratch_pts);
    p->sets += 1u;
    p->k_last = k;
    p->key = key_of(p);
    return MCS_OK;
}

/* psa's anisotropy of each annulus r = 1..F of the mean periodogram, the
 * whole plane counted (P(-f) = P(f)), averaged in dB where finite. */
static double anisotropy(const double *mean, size_t F)
{
    const long w = 2 * (long)F + 1;
    double total = 0.0;
    int used = 0;
    for (size_t r = 1; r <= F; ++r) {
        double s = 0.0, ss = 0.0, cnt = 0.0;
        const double lo = (double)r * (double)r, hi = ((double)r + 1.0) * ((double)r + 1.0);
        for (long fy = -(long)F; fy <= (long)F; ++fy)
            for (long fx = -(long)F; fx <= (long)F; ++fx) {
                double rr = (double)(fx * fx + fy * fy);
                if (rr < lo || rr >= hi)
                    continue;
                long sx = fy >= 0 ? fx : -fx, sy = fy >= 0 ? fy : -fy;
                double v = mean[sy * w + sx + (long)F];
                s += v;
                ss += v * v;
                cnt += 1.0;
            }
        double m = s / cnt, var = cnt > 1.0 ? (ss - cnt * m * m) / (cnt - 1.0) : 0.0;
        if (m > 1e-20 && var > 0.0) {
            total += 10.0 * log10(var / (m * m));
            ++used;
        }
    }
    return used > 0 ? total / used : (double)NAN;
}

static double welford_se(const double *stats, int at, double n)
{
    return n >= 2.0 ? sqrt(stats[at + 1] / (n - 1.0) / n) : (double)NAN;
}

/* z of a mean against 0 with standard error se; a deterministic difference
 * (se 0) is infinite unless it is rounding. */
static double z_of(double mean, double se, double scale)
{
    if (se > 0.0)
        return mean / se;
    if (fabs(mean) <= 1e-9 * scale)
        return 0.0;
    return mean > 0.0 ? (double)INFINITY : -(double)INFINITY;
}

mcs_status mcs_projections_pair_stats(const mcs_projections *p, size_t i, size_t j,
                                      mcs_projections_pair *out)
{
    mcs_status st = check(p);
    if (st != MCS_OK)
        return st;
    if (out == NULL)
        return MCS_ERR_NULL;
    if (i >= p->dim || j >= p->dim || i == j)
        return MCS_ERR_DOMAIN;
    if (p->sets == 0u)
        return MCS_ERR_EMPTY;
    if (i > j) {
        size_t t = i;
        i = j;
        j = t;
    }
    const double *stats = p->pairs + pair_index(p->dim, i, j) * pair_stride(p->freq);
    const double n = stats[ST_N];
    mcs_projections_pair r;
    r.radial_low = stats[ST_RADIAL];
    r.radial_low_ref = stats[ST_REF];
    double se_r = welford_se(stats, ST_RADIAL, n), se_d = welford_se(stats, ST_DIFF, n);
    if (n < 2.0) { /* one set: the spread over the disc, wave vectors as independent */
        se_r = sqrt(stats[ST_WITHIN_RADIAL] / stats[ST_N_LOW]);
        se_d = sqrt(stats[ST_WITHIN_DIFF] / stats[ST_N_LOW]);
    }
    r.radial_low_stderr = se_r;
    /* The test's standard error is never below the one independent
     * dimensions have: with few sets their spread is itself uncertain (3
     * sets would give a Student t of 2 degrees of freedom, whose tail
     * beyond 5 is 2 %, not 3e-7). */
    const double se_null = sqrt(stats[ST_MODEL_VAR] / n);
    r.radial_low_z = z_of(stats[ST_DIFF], se_d > se_null ? se_d : se_null,
                          1.0 + fabs(r.radial_low_ref));
    r.anisotropy_db = anisotropy(stats + MCS_PROJECTIONS_PAIR_STATS_, p->freq);
    r.discrepancy = stats[ST_DISC_N] > 0.0 ? stats[ST_DISC] : (double)NAN;
    r.discrepancy_stderr = welford_se(stats, ST_DISC, stats[ST_DISC_N]);
    r.discrepancy_random = (double)NAN;
    double e = 0.0;
    if (mcs_discrepancy_l2_exact_random(MCS_DISCREPANCY_L2_WRAPAROUND, p->k_last, 2u, &e) ==
        MCS_OK)
        r.discrepancy_random = e;
    const double np = stats[ST_N_PEAK];
    double v = 0.0; /* variance of the max of np unit exponentials: sum 1/i^2 */
    for (size_t q = 1u; (double)q <= np; ++q)
        v += 1.0 / ((double)q * (double)q);
    r.peak = stats[ST_PEAK];
    r.peak_stderr = n >= 2.0 ? welford_se(stats, ST_PEAK, n) : sqrt(v);
    r.peak_max = stats[ST_PEAK_MAX];
    r.peak_threshold = log(np * n * (double)pair_count(p->dim) / ALPHA);
    r.flagged = r.radial_low_z > 5.0 || r.peak_max > r.peak_threshold;
    *out = r;
    return MCS_OK;
}

mcs_status mcs_projections_flagged(const mcs_projections *p, size_t *count)
{
    mcs_status st = check(p);
    if (st != MCS_OK)
        return st;
    if (count == NULL)
        return MCS_ERR_NULL;
    if (p->sets == 0u)
        return MCS_ERR_EMPTY;
    size_t c = 0u;
    for (size_t i = 0; i < p->dim; ++i)
        for (size_t j = i + 1u; j < p->dim; ++j) {
            mcs_projections_pair r;
            if (mcs_projections_pair_stats(p, i, j, &r) == MCS_OK)
                c += (size_t)r.flagged;
        }
    *count = c;
    return MCS_OK;
}
