/* Point sets as renderers make them (issue 15): the unbinned 2D periodogram
 * of every 2D pattern and low-discrepancy sampler (radial power and psa's
 * anisotropy, measured beside the exact values where they exist), the
 * convergence of the estimator variance with K for a smooth integrand and a
 * disk indicator (fitted log-log slopes beside the published rates), and the
 * note's binned framework on N x N bins (the 2D eq. 13 and 14). */
#include "mcspec/pattern2d.h"
#include "mcspec/pointset2d.h"
#include "mcspec/rng.h"
#include "mcspec/sampler.h"
#include "mcspec/spectrum2d.h"
#include "measure.h"
#include "readout.h"
#include "report.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char help_text[] =
    "Section 6 (issue 15): point sets in 2D as renderers use them.\n"
    "1. Per kind (random, jittered, grid, shifted grid, n-rooks, multi-jittered, cmj,\n"
    "   Halton, Hammersley, Owen-scrambled Sobol, Kronecker R2), T trials of K points:\n"
    "   the radial average of P(f) = |sum_j e^{-2 pi i f.x_j}|^2 / K over the annulus\n"
    "   r <= |f| < r + 1 and psa's anisotropy 10 log10(var / mean^2) of the annulus\n"
    "   (trial noise alone gives about -10 log10 T dB). Exact: mcspec's closed forms\n"
    "   for the patterns; for the rotated or shifted samplers the periodogram of\n"
    "   their unrandomised set (a rotation only changes phases).\n"
    "2. Var[I] of I = (1/K) sum_j f(x_j) for f = e^x (1 + y^2) (smooth) and the\n"
    "   indicator of a disk (centre (0.45, 0.52), radius 0.31) at K = 16, 64, 256,\n"
    "   1024, T trials each, and the weighted least-squares slope of log Var against\n"
    "   log K beside the published rates: random K^-1, jittered K^-2 (smooth) and\n"
    "   K^-1.5 (disk). Exact: Var f / K for random, the per-cell variances for\n"
    "   jittered on the smooth f. The rate is a K -> infinity form: its limit check\n"
    "   compares it with the exact slope over K = 256..16384. A note line states\n"
    "   whether each measured slope is within 0.1 of its rate.\n"
    "3. The binned framework on N x N bins: Var[I] of the bin-centre integrand from\n"
    "   the spectrum, eq. 14 (stationary: closed) and eq. 13 (all k, l: exact),\n"
    "   measured for random, jittered and shifted grid.\n"
    "--k sets K of parts 1 and 3 (at most 4096), --n the bins per side of part 3\n"
    "(at most 64). Part 1's cutoff is F = 2 ceil(sqrt K) (at least 4).\n";

#define MAX_K 4096u
#define MAX_SIDE 64u /* part 3's largest N */
#define N_CONV 5
#define SLOPE_TOL 0.1

enum {
    S_RANDOM, S_JITTERED, S_GRID, S_SHIFTED, S_NROOKS, S_MJ, S_CMJ, S_HALTON, S_HAMMERSLEY,
    S_SOBOL, S_KRONECKER, S_COUNT
};

/* A point source: a 2D pattern or a 2D sampler. */
typedef struct {
    int is_sampler;
    mcs_pattern2d pattern;
    mcs_sampler sampler;
} source;

static const size_t conv_k[N_CONV] = {16u, 64u, 256u, 1024u, 4096u};
static double pts[2u * MAX_K];
static double fgrid[MAX_SIDE * MAX_SIDE], f_re[MAX_SIDE * MAX_SIDE], f_im[MAX_SIDE * MAX_SIDE];
/* The point-set spectra over buffers from their size query (part 1 sets
 * them up for its F); the binned one over a static buffer for the largest
 * N it takes. */
static mcs_pointset2d meas, base;
static void *meas_mem, *base_mem;
static size_t ps_bytes;
static mcs_spectrum2d plan;
static unsigned char plan_mem[MCS_SPECTRUM2D_SIZE(MAX_SIDE, MAX_SIDE)];

/* The samplers' kinds, sources S_HALTON.. in order (the patterns' sources
 * are their mcs_pattern2d_kind values). */
static const mcs_sampler_kind sampler_kinds[4] = {MCS_SAMPLER_HALTON, MCS_SAMPLER_HAMMERSLEY,
                                                  MCS_SAMPLER_SOBOL, MCS_SAMPLER_KRONECKER};

static const char *source_name(int s)
{
    return s < S_HALTON ? mcs_pattern2d_kind_str((mcs_pattern2d_kind)s)
                        : mcs_sampler_kind_str(sampler_kinds[s - S_HALTON]);
}

static mcs_status source_init(source *src, int s, size_t k)
{
    memset(src, 0, sizeof *src);
    src->is_sampler = s >= S_HALTON;
    if (src->is_sampler)
        return mcs_sampler_init(&src->sampler, sampler_kinds[s - S_HALTON], 2u, k);
    return mcs_pattern2d_init(&src->pattern, (mcs_pattern2d_kind)s, k, 0u, 0u);
}

static mcs_status source_draw(const source *src, mcs_rng *rng, size_t k)
{
    return src->is_sampler ? mcs_sampler_draw(&src->sampler, rng, k, pts)
                           : mcs_pattern2d_draw(&src->pattern, rng, k, pts);
}

static ex_row row_of(const char *quantity, const char *equation, const char *pattern, long freq,
                     double closed, double exact, double measured, double se, double floor_)
{
    return ex_row_of("sec6", quantity, equation, pattern, freq, EX_NO_FREQ, closed, exact,
                     measured, se, floor_);
}

/* ---- part 1: radial power and anisotropy ---------------------------------- */

/* Exact radial average and anisotropy of source s at radius r: closed forms
 * for the patterns, the unrandomised set's periodogram (in `base`) for the
 * rotated samplers; EX_NA where neither exists. */
static void exact_radial(const source *src, int s, size_t r, double *power, double *aniso)
{
    double p = 0.0, a = 0.0;
    *power = *aniso = EX_NA;
    if (!src->is_sampler) {
        *power = ex_or_na(mcs_pointset2d_exact_radial(&src->pattern, r, &p), &p);
        *aniso = ex_or_na(mcs_pointset2d_exact_anisotropy(&src->pattern, r, &a), &a);
    } else if (s != S_SOBOL) {
        *power = ex_or_na(mcs_pointset2d_radial(&base, r, &p), &p);
        *aniso = ex_or_na(mcs_pointset2d_anisotropy(&base, r, &a), &a);
    }
}

static int radial_part(const ex_options *opt, size_t fmax, const size_t *radii, size_t nradii)
{
    ex_heading(opt, "radial power (annulus r <= |f| < r+1) and psa anisotropy in dB, "
                    "T trials of K points");
    for (int s = 0; s < S_COUNT; ++s) {
        source src;
        mcs_rng rng;
        mcs_rng_seed(&rng, opt->seed, 0x600u + (uint64_t)s);
        mcs_status st = source_init(&src, s, opt->k);
        if (st == MCS_OK)
            st = mcs_pointset2d_init(&meas, fmax, 0u, meas_mem, ps_bytes);
        for (unsigned long t = 0; st == MCS_OK && t < opt->trials; ++t) {
            st = source_draw(&src, &rng, opt->k);
            if (st == MCS_OK)
                st = mcs_pointset2d_add(&meas, opt->k, pts);
        }
        if (st == MCS_OK && src.is_sampler &&
            mcs_pointset2d_init(&base, fmax, 0u, base_mem, ps_bytes) == MCS_OK &&
            mcs_sampler_base_points(&src.sampler, opt->k, pts) == MCS_OK)
            st = mcs_pointset2d_add(&base, opt->k, pts);
        if (st != MCS_OK) {
            fprintf(stderr, "sec6: %s: %s\n", source_name(s), mcs_status_str(st));
            return 0;
        }
        const double floor_ = 1e-9 * (double)opt->k;
        for (size_t i = 0; i < nradii; ++i) {
            double p = 0.0, se = 0.0, a = 0.0, ep = EX_NA, ea = EX_NA;
            double mp = ex_or_na(mcs_pointset2d_radial(&meas, radii[i], &p), &p);
            double mse = ex_or_na(mcs_pointset2d_radial_stderr(&meas, radii[i], &se), &se);
            double ma = ex_or_na(mcs_pointset2d_anisotropy(&meas, radii[i], &a), &a);
            exact_radial(&src, s, radii[i], &ep, &ea);
            ex_row r = row_of("radial power", "P(r)", source_name(s), (long)radii[i], EX_NA, ep,
                              mp, mse, floor_);
            ex_row_print(opt, &r);
            r = row_of("anisotropy dB", "psa", source_name(s), (long)radii[i], EX_NA, ea, ma,
                       EX_NA, 0.0);
            ex_row_print(opt, &r);
        }
    }
    ex_notef(opt, "an isotropic spectrum measured over T = %lu trials has anisotropy about "
                  "10 log10((1 - 1/K) / T) = %.1f dB (trial noise)",
             opt->trials, 10.0 * log10((1.0 - 1.0 / (double)opt->k) / (double)opt->trials));
    return 1;
}

/* ---- part 2: variance against K ------------------------------------------ */

#define DISK_X 0.45
#define DISK_Y 0.52
#define DISK_R 0.31

static double f_smooth(double x, double y)
{
    return exp(x) * (1.0 + y * y);
}

static double f_disk(double x, double y)
{
    double dx = x - DISK_X, dy = y - DISK_Y;
    return dx * dx + dy * dy < DISK_R * DISK_R ? 1.0 : 0.0;
}

/* Means and variances over [0,1)^2 in closed form. */
static double smooth_mean(void)
{
    return (exp(1.0) - 1.0) * (4.0 / 3.0);
}

static double smooth_var(void)
{
    double m = smooth_mean();
    return (exp(2.0) - 1.0) / 2.0 * (28.0 / 15.0) - m * m;
}

static double disk_mean(void)
{
    return 3.14159265358979323846 * DISK_R * DISK_R;
}

/* Exact Var[I] of a jittered m x m grid (K = m^2) for the smooth f: the sum
 * over cells of the variance of f in the cell, over K^2. f = g(x) h(y), so
 * each cell needs the 1D means of g, g^2, h, h^2 over its intervals. */
static double jittered_smooth_var(size_t m)
{
    double total = 0.0, md = (double)m;
    for (size_t i = 0; i < m; ++i) {
        double a = (double)i / md, b = (double)(i + 1u) / md;
        double g1 = md * (exp(b) - exp(a)), g2 = md * (exp(2.0 * b) - exp(2.0 * a)) / 2.0;
        for (size_t j = 0; j < m; ++j) {
            double c = (double)j / md, d = (double)(j + 1u) / md;
            double h1 = md * ((d - c) + (d * d * d - c * c * c) / 3.0);
            double h2 = md * ((d - c) + 2.0 * (d * d * d - c * c * c) / 3.0 +
                              (pow(d, 5.0) - pow(c, 5.0)) / 5.0);
            total += g2 * h2 - g1 * g1 * h1 * h1;
        }
    }
    return total / (md * md * md * md);
}

/* Weighted least-squares slope of log v against log k (weights 1/se_log^2,
 * or equal if se is NULL) and its standard error. */
static double fit_slope(size_t n, const double *k, const double *v, const double *se,
                        double *slope_se)
{
    double sw = 0.0, sx = 0.0, sy = 0.0;
    for (size_t i = 0; i < n; ++i) {
        double w = se ? (v[i] * v[i]) / (se[i] * se[i]) : 1.0;
        sw += w;
        sx += w * log(k[i]);
        sy += w * log(v[i]);
    }
    double sxx = 0.0, sxy = 0.0;
    for (size_t i = 0; i < n; ++i) {
        double w = se ? (v[i] * v[i]) / (se[i] * se[i]) : 1.0;
        double dx = log(k[i]) - sx / sw;
        sxx += w * dx * dx;
        sxy += w * dx * (log(v[i]) - sy / sw);
    }
    if (slope_se != NULL)
        *slope_se = se ? 1.0 / sqrt(sxx) : 0.0;
    return sxy / sxx;
}

/* int s(u) du with s(u) = sqrt(r^2 - u^2), u in [-r, r]. */
static double arc_integral(double u)
{
    double r = DISK_R, s = sqrt(fmax(r * r - u * u, 0.0));
    return 0.5 * (u * s + r * r * asin(fmax(-1.0, fmin(1.0, u / r))));
}

/* Area of the disk (centred at the origin) with X < x and Y < y: the
 * integral over X of the overlap of (-s(X), s(X)) with (-inf, y). */
static double quadrant_area(double x, double y)
{
    const double r = DISK_R;
    x = fmin(fmax(x, -r), r);
    if (y <= -r)
        return 0.0;
    if (y >= r)
        return 2.0 * (arc_integral(x) + 0.25 * 3.14159265358979323846 * r * r);
    double c = sqrt(r * r - y * y); /* s(X) = |y| at X = +-c */
    double lo = -c, hi = c, area = 0.0;
    if (y >= 0.0) { /* s < y outside [-c, c]: the whole chord counts there */
        area += 2.0 * (arc_integral(fmin(x, -c)) - arc_integral(-r));
        if (x > c)
            area += 2.0 * (arc_integral(x) - arc_integral(c));
    }
    double a = lo, b = fmin(x, hi); /* inside [-c, c]: from -s to y */
    if (b > a)
        area += y * (b - a) + arc_integral(b) - arc_integral(a);
    return area;
}

/* Exact Var[I] of a jittered m x m grid for the disk: sum over cells of
 * a (1 - a), a the cell's area fraction inside the disk, over K^2. */
static double jittered_disk_var(size_t m)
{
    double total = 0.0, md = (double)m;
    for (size_t i = 0; i < m; ++i)
        for (size_t j = 0; j < m; ++j) {
            double x0 = (double)i / md - DISK_X, x1 = (double)(i + 1u) / md - DISK_X;
            double y0 = (double)j / md - DISK_Y, y1 = (double)(j + 1u) / md - DISK_Y;
            double a = (quadrant_area(x1, y1) - quadrant_area(x0, y1) - quadrant_area(x1, y0) +
                        quadrant_area(x0, y0)) * md * md;
            total += a * (1.0 - a);
        }
    return total / (md * md * md * md);
}

/* Exact variance where it is known in closed form (random: Var f / K;
 * jittered: per-cell variances), else EX_NA. */
static double exact_var(int s, int smooth, size_t k)
{
    if (s == S_RANDOM)
        return (smooth ? smooth_var() : disk_mean() * (1.0 - disk_mean())) / (double)k;
    size_t m = (size_t)sqrt((double)k);
    if (s == S_JITTERED && m * m == k)
        return smooth ? jittered_smooth_var(m) : jittered_disk_var(m);
    return EX_NA;
}

/* Published rate, or EX_NA. */
static double published_rate(int s, int smooth)
{
    if (s == S_RANDOM)
        return -1.0;
    if (s == S_JITTERED)
        return smooth ? -2.0 : -1.5;
    return EX_NA;
}

/* Measured <(I - mu)^2> over the trials for both integrands (every kind
 * here is unbiased, so mu is the exact mean), with standard errors from
 * the 4th central moment. */
static mcs_status measure_var(const ex_options *opt, int s, size_t k, double *var, double *se)
{
    source src;
    mcs_rng rng;
    mcs_rng_seed(&rng, opt->seed, 0x61000000u + ((uint64_t)s << 16) + (uint64_t)k);
    mcs_status st = source_init(&src, s, k);
    double c2[2] = {0.0, 0.0}, c4[2] = {0.0, 0.0}, mu[2] = {smooth_mean(), disk_mean()};
    const double t = (double)opt->trials;
    for (unsigned long i = 0; st == MCS_OK && i < opt->trials; ++i) {
        st = source_draw(&src, &rng, k);
        double est[2] = {0.0, 0.0};
        for (size_t j = 0; st == MCS_OK && j < k; ++j) {
            est[0] += f_smooth(pts[2 * j], pts[2 * j + 1]);
            est[1] += f_disk(pts[2 * j], pts[2 * j + 1]);
        }
        for (int f = 0; f < 2; ++f) {
            double d2 = (est[f] / (double)k - mu[f]) * (est[f] / (double)k - mu[f]);
            c2[f] += d2 / t;
            c4[f] += d2 * d2 / t;
        }
    }
    for (int f = 0; f < 2; ++f) {
        var[f] = c2[f];
        se[f] = sqrt(fmax(c4[f] - c2[f] * c2[f], 0.0) / t);
    }
    return st;
}

static void slope_rows(const ex_options *opt, int s, const double kd[N_CONV],
                       double var[2][N_CONV], double se[2][N_CONV])
{
    for (int f = 0; f < 2; ++f) {
        double slope_se = 0.0, ex[N_CONV], ex_big[N_CONV], kbig[N_CONV];
        double slope = fit_slope(N_CONV, kd, var[f], se[f], &slope_se);
        double rate = published_rate(s, f == 0), exact_slope = EX_NA, gap_big = EX_NA;
        int have_exact = !isnan(exact_var(s, f == 0, conv_k[0]));
        if (have_exact) {
            for (int i = 0; i < N_CONV; ++i) {
                ex[i] = exact_var(s, f == 0, conv_k[i]);
                kbig[i] = kd[i] * 16.0;
                ex_big[i] = exact_var(s, f == 0, conv_k[i] * 16u);
            }
            exact_slope = fit_slope(N_CONV, kd, ex, NULL, NULL);
            double big = fit_slope(N_CONV, kbig, ex_big, NULL, NULL);
            gap_big = ex_rel_gap(rate, big, 1e-12);
        }
        ex_row r = row_of(f == 0 ? "slope smooth" : "slope disk", "K^rate", source_name(s),
                          EX_NO_FREQ, rate, exact_slope, slope, slope_se, 1e-12);
        r.limit_gap = gap_big;
        ex_row_print(opt, &r);
        if (!isnan(rate))
            ex_notef(opt, "  %s %s: measured slope %.3f +- %.3f, rate %.1f: |diff| = %.3f %s 0.1",
                     source_name(s), f == 0 ? "smooth" : "disk", slope, slope_se, rate,
                     fabs(slope - rate), fabs(slope - rate) <= SLOPE_TOL ? "<=" : ">");
    }
}

static int convergence_part(const ex_options *opt)
{
    ex_heading(opt, "Var[I] against K (smooth f = e^x (1 + y^2), disk indicator) and the "
                    "log-log slope beside the published rate");
    double kd[N_CONV];
    for (int i = 0; i < N_CONV; ++i)
        kd[i] = (double)conv_k[i];
    for (int s = 0; s < S_COUNT; ++s) {
        if (s == S_GRID)
            continue; /* deterministic: no variance (and biased) */
        double var[2][N_CONV], se[2][N_CONV];
        for (int i = 0; i < N_CONV; ++i) {
            double v[2], e[2];
            mcs_status st = measure_var(opt, s, conv_k[i], v, e);
            if (st != MCS_OK) {
                fprintf(stderr, "sec6: %s K = %zu: %s\n", source_name(s), conv_k[i],
                        mcs_status_str(st));
                return 0;
            }
            for (int f = 0; f < 2; ++f) {
                var[f][i] = v[f];
                se[f][i] = e[f];
                char q[40];
                snprintf(q, sizeof q, "Var[I] %s K=%zu", f == 0 ? "smooth" : "disk", conv_k[i]);
                ex_row r = row_of(q, "", source_name(s), EX_NO_FREQ, EX_NA,
                                  exact_var(s, f == 0, conv_k[i]), v[f], e[f], 1e-14);
                ex_row_print(opt, &r);
            }
        }
        slope_rows(opt, s, kd, var, se);
    }
    return 1;
}

/* ---- part 3: the binned framework ----------------------------------------- */

static int binned_part(const ex_options *opt)
{
    const size_t n = opt->n, k = opt->k;
    ex_heading(opt, "binned framework on N x N bins: Var[I] from the spectrum, eq. 14 "
                    "(closed) against eq. 13 (exact)");
    double mu = 0.0;
    for (size_t b2 = 0; b2 < n; ++b2)
        for (size_t b1 = 0; b1 < n; ++b1) {
            double x = ((double)b1 + 0.5) / (double)n, y = ((double)b2 + 0.5) / (double)n;
            fgrid[b2 * n + b1] = f_smooth(x, y) + f_disk(x, y);
            mu += fgrid[b2 * n + b1] / (double)(n * n);
        }
    if (mcs_spectrum2d_init(&plan, n, n, plan_mem, sizeof plan_mem) != MCS_OK ||
        mcs_spectrum2d_transform(&plan, fgrid, f_re, f_im) != MCS_OK)
        return 0;
    const int kinds[3] = {S_RANDOM, S_JITTERED, S_SHIFTED};
    for (int i = 0; i < 3; ++i) {
        source src;
        mcs_rng rng;
        mcs_rng_seed(&rng, opt->seed, 0x6200u + (uint64_t)kinds[i]);
        mcs_status st = source_init(&src, kinds[i], k);
        double c2 = 0.0, c4 = 0.0, v13 = 0.0, v14 = 0.0;
        const double t = (double)opt->trials;
        for (unsigned long tr = 0; st == MCS_OK && tr < opt->trials; ++tr) {
            st = source_draw(&src, &rng, k);
            double est = 0.0;
            for (size_t j = 0; st == MCS_OK && j < k; ++j) {
                size_t b1 = (size_t)(pts[2 * j] * (double)n), b2 = (size_t)(pts[2 * j + 1] * (double)n);
                est += fgrid[b2 * n + b1] / (double)k;
            }
            c2 += (est - mu) * (est - mu) / t;
            c4 += (est - mu) * (est - mu) * (est - mu) * (est - mu) / t;
        }
        if (st != MCS_OK)
            return 0;
        double closed = ex_or_na(
            mcs_spectrum2d_exact_variance14(&src.pattern, n, n, f_re, f_im, &v14), &v14);
        double exact = ex_or_na(
            mcs_spectrum2d_exact_variance(&src.pattern, n, n, f_re, f_im, &v13), &v13);
        ex_row r = row_of("Var[I] binned", "eq. 13/14", source_name(kinds[i]), EX_NO_FREQ,
                          closed, exact, c2, sqrt(fmax(c4 - c2 * c2, 0.0) / t), 1e-12 * c2);
        ex_row_print(opt, &r);
    }
    return 1;
}

int main(int argc, char **argv)
{
    ex_options opt = {16u, 64u, 1000ul, 1u, 0};
    int rc = ex_parse_options(argc, argv, &opt, MAX_SIDE, MAX_K, help_text);
    if (rc != EX_PARSE_OK)
        return rc == EX_PARSE_HELP ? 0 : 2;
    /* Cutoff: twice the grid frequency sqrt(K) (128 at most, K <= 4096). */
    size_t fmax = 2u * (size_t)ceil(sqrt((double)opt.k));
    fmax = fmax < 4u ? 4u : fmax;
    /* The two-call size query, then the caller's memory. */
    if (mcs_pointset2d_size(fmax, 0u, &ps_bytes) != MCS_OK ||
        (meas_mem = malloc(ps_bytes)) == NULL || (base_mem = malloc(ps_bytes)) == NULL) {
        fprintf(stderr, "sec6: no memory for the point-set spectra of F = %zu\n", fmax);
        free(meas_mem);
        return 1;
    }
    double root = sqrt((double)opt.k);
    const size_t cand[5] = {(size_t)lround(root / 4.0), (size_t)lround(root / 2.0),
                            (size_t)lround(root), (size_t)lround(1.5 * root),
                            (size_t)lround(2.0 * root)};
    size_t radii[5];
    size_t nradii = ex_pick_freqs(fmax + 1u, cand, 5u, radii);

    ex_begin(&opt, "Section 6: point sets, low-discrepancy samplers and 2D spectra (issue 15)");
    ex_notef(&opt, "per-axis frequency cutoff F = %zu; N is the bins per side of the binned part",
             fmax);
    rc = radial_part(&opt, fmax, radii, nradii) && convergence_part(&opt) && binned_part(&opt);
    free(meas_mem);
    free(base_mem);
    if (!rc)
        return 1;
    ex_end(&opt);
    return 0;
}
