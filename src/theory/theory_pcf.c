/* Exact pair correlation of random points and of the 2D grid patterns
 * (pcf.h: mcs_pcf_exact; derivation in docs/measures.md).
 *
 * For a pattern whose points lie one per cell of an m x n grid, with
 * independent uniform offsets inside their cells, the toroidal difference
 * of two points whose cells are a columns and b rows apart has density
 * f_a(x) h_b(y), f_a the (wrapped) triangle of half-width 1/m centred at
 * a/m. Summed over every column offset the triangles tile the circle:
 * sum_a f_a = m, and likewise sum_b h_b = n. So the expected number of
 * ordered pairs in a ring, K sum_{(a,b) != 0} int_ring f_a h_b, is
 * K (K A - int_ring f_0 h_0): only the same-cell term is left, a
 * two-dimensional integral of a product of triangles over a ring. n-rooks
 * (one point per column and per row of the K x K grid, the column offset
 * of two rows uniform over the K - 1 others) leaves
 * K/(K - 1) int_ring (K - f_0)(K - h_0). The ring integrals are disk
 * integrals D(r1) - D(r0), and D(rho) = 2 int_0^rho f(x) H(sqrt(rho^2 - x^2))
 * dx with H(t) = int_{-t}^t h, in closed form per piece: a one-dimensional
 * quadrature. */
#include "mcspec/pcf.h"
#include "core/internal.h"
#include "measures/pcf_internal.h"

#include <math.h>
#include <stddef.h>

/* Gauss-Legendre points per piece. */
#define GL_N 32

static const double pi = 3.14159265358979323846;

/* 32-point Gauss-Legendre nodes and weights on [0, 1] (numpy's leggauss,
 * mapped to [0, 1]): constants, so the frames stay small and nothing is
 * computed per call. */
static const double gl_x[GL_N] = {
    0.0013680690752592151, 0.0071942442273658092, 0.017618872206246805,
    0.032546962031130167, 0.051839422116973899, 0.075316193133715015,
    0.10275810201602881, 0.13390894062985514, 0.16847786653489238,
    0.20614212137961885, 0.24655004553388532, 0.28932436193468236,
    0.33406569885893617, 0.38035631887393145, 0.42776401920860174,
    0.47584616715613082, 0.52415383284386918, 0.57223598079139826,
    0.61964368112606849, 0.66593430114106389, 0.71067563806531764,
    0.75344995446611462, 0.79385787862038115, 0.83152213346510762,
    0.86609105937014486, 0.89724189798397114, 0.92468380686628504,
    0.9481605778830261, 0.96745303796886983, 0.98238112779375319,
    0.99280575577263419, 0.99863193092474078};
static const double gl_w[GL_N] = {
    0.0035093050047346492, 0.0081371973654529826, 0.012696032654631213,
    0.017136931456510813, 0.021417949011113213, 0.025499029631188122,
    0.029342046739267852, 0.032911111388180876, 0.036172897054424225,
    0.039096947893535156, 0.041655962113473423, 0.043826046502201954,
    0.045586939347881932, 0.046922199540402283, 0.047819360039637417,
    0.048270044257363906, 0.048270044257363906, 0.047819360039637417,
    0.046922199540402283, 0.045586939347881932, 0.043826046502201954,
    0.041655962113473423, 0.039096947893535156, 0.036172897054424225,
    0.032911111388180876, 0.029342046739267852, 0.025499029631188122,
    0.021417949011113213, 0.017136931456510813, 0.012696032654631213,
    0.0081371973654529826, 0.0035093050047346492};

/* One axis' same-cell difference density: a triangle of half-width 1/cells
 * (cells >= 2), the constant 1 with one cell (the wrapped triangle), or
 * the constant 1 also for cells = 0 (the "K minus" terms of n-rooks use
 * it for the uniform factor). */
static double density(size_t cells, double x)
{
    if (cells <= 1u)
        return 1.0;
    const double t = 1.0 - (double)cells * fabs(x);
    return t > 0.0 ? (double)cells * t : 0.0;
}

/* H(t) = int_{-t}^{t} density(cells, y) dy, t in [0, 1/2]. */
static double mass(size_t cells, double t)
{
    if (cells <= 1u)
        return 2.0 * t;
    const double s = (double)cells * t;
    return s >= 1.0 ? 1.0 : 2.0 * (s - 0.5 * s * s);
}

/* int_a^b density(cx, x) mass(cy, sqrt(rho^2 - x^2)) dx on a piece where
 * both are smooth, through x = a + (b - a)(3u^2 - 2u^3), which turns the
 * square-root ends into smooth ones. */
static double piece(size_t cx, size_t cy, double rho, double a, double b)
{
    if (!(b > a))
        return 0.0;
    double sum = 0.0;
    for (int i = 0; i < GL_N; ++i) {
        const double u = gl_x[i];
        const double x = a + (b - a) * u * u * (3.0 - 2.0 * u);
        const double dx = (b - a) * 6.0 * u * (1.0 - u);
        const double t2 = rho * rho - x * x;
        sum += gl_w[i] * dx * density(cx, x) * mass(cy, t2 > 0.0 ? sqrt(t2) : 0.0);
    }
    return sum;
}

/* D(rho) = int_{|v| < rho} density(cx, x) density(cy, y) dv, rho <= 1/2. */
static double disk(size_t cx, size_t cy, double rho)
{
    if (rho <= 0.0)
        return 0.0;
    double cuts[4];
    size_t nc = 0;
    const double end = cx >= 2u && 1.0 / (double)cx < rho ? 1.0 / (double)cx : rho;
    cuts[nc++] = 0.0;
    if (cy >= 2u && rho > 1.0 / (double)cy) {
        const double xc = sqrt(rho * rho - 1.0 / ((double)cy * (double)cy));
        if (xc < end)
            cuts[nc++] = xc;
    }
    cuts[nc++] = end;
    double sum = 0.0;
    for (size_t i = 0; i + 1u < nc; ++i)
        sum += piece(cx, cy, rho, cuts[i], cuts[i + 1u]);
    return 2.0 * sum;
}

static double ring(size_t cx, size_t cy, double r0, double r1)
{
    return disk(cx, cy, r1) - disk(cx, cy, r0);
}

/* The next column (or row) offset after t of an m-periodic lattice whose
 * toroidal distance min(t, m - t) / m can be below reach: the offsets past
 * reach are skipped, so a bin costs O((reach m) (reach n)), not O(K). */
static size_t next_offset(size_t t, size_t m, double reach)
{
    const double lim = ceil(reach * (double)m);
    const size_t a = lim >= (double)m ? m : (size_t)lim;
    ++t;
    return t > a && t + a < m ? m - a : t;
}

/* The grid's RDF in bin: offsets (a, b) != 0 of the m x n lattice whose
 * toroidal distance falls in the bin, over (K - 1) A. */
static double grid_rdf(const mcs_pcf *acc, size_t m, size_t n, size_t bin, double s, double area)
{
    const double scale = (double)acc->bins / (acc->radius * s);
    const double reach = (double)(bin + 1u) / scale;
    double count = 0.0;
    for (size_t a = 0; a < m; a = next_offset(a, m, reach))
        for (size_t b = 0; b < n; b = next_offset(b, n, reach)) {
            if (a == 0u && b == 0u)
                continue;
            const double dx = (double)(a <= m - a ? a : m - a) / (double)m;
            const double dy = (double)(b <= n - b ? b : n - b) / (double)n;
            const double u = sqrt(dx * dx + dy * dy) * scale;
            if (u < (double)acc->bins && (size_t)u == bin)
                count += 1.0;
        }
    return count / ((double)(m * n - 1u) * area);
}

/* Expected ordered pairs of a jittered (m x n) or n-rooks set closer
 * than d (absolute, d <= 1/2): K (K pi d^2 - D(d)), or
 * K/(K - 1) (K^2 pi d^2 - K (Dx(d) + Dy(d)) + D(d)). */
static double pairs_within(const mcs_pattern2d *pat, double d)
{
    const double kd = (double)pat->k, area = pi * d * d;
    if (pat->kind == MCS_PATTERN2D_JITTERED)
        return kd * (kd * area - disk(pat->strata_x, pat->strata_y, d));
    const size_t k = pat->k;
    return kd / (kd - 1.0) *
           (kd * kd * area - kd * (disk(k, 0u, d) + disk(0u, k, d)) + disk(k, k, d));
}

/* The kernel PCF's E g at bin centre r (absolute), kernel sd sg: the
 * estimator counts k(r - d) for |r - d| <= 8 sg, so
 *   E sum_ordered = int_lo^hi k(r - d) dN(d)
 *                 = [k(r - d) N(d)]_lo^hi + int_lo^hi N(d) k'(r - d) dd,
 * lo = max(0, r - 8 sg), hi = r + 8 sg, k' = -(u / sg^2) k(u); N is smooth
 * between the kinks of its same-cell terms (1/m, 1/n, their hypotenuse),
 * where the range is cut, and each piece is cut again to at most sg wide. */
static double kernel_exact(const mcs_pattern2d *pat, double r, double sg)
{
    const double lo = r - 8.0 * sg > 0.0 ? r - 8.0 * sg : 0.0, hi = r + 8.0 * sg;
    const double norm = 1.0 / (sg * sqrt(2.0 * pi));
    const size_t m = pat->kind == MCS_PATTERN2D_JITTERED ? pat->strata_x : pat->k;
    const size_t n = pat->kind == MCS_PATTERN2D_JITTERED ? pat->strata_y : pat->k;
    double cuts[6];
    size_t nc = 0;
    cuts[nc++] = lo;
    const double kinks[3] = {m >= 2u ? 1.0 / (double)m : -1.0, n >= 2u ? 1.0 / (double)n : -1.0,
                             m >= 2u && n >= 2u ? sqrt(1.0 / ((double)m * (double)m) +
                                                       1.0 / ((double)n * (double)n))
                                                : -1.0};
    for (int i = 0; i < 3; ++i)
        if (kinks[i] > lo && kinks[i] < hi)
            cuts[nc++] = kinks[i];
    cuts[nc++] = hi;
    for (size_t i = 1; i < nc; ++i) /* a few values: insertion sort */
        for (size_t j = i; j > 0u && cuts[j - 1u] > cuts[j]; --j) {
            const double t = cuts[j];
            cuts[j] = cuts[j - 1u];
            cuts[j - 1u] = t;
        }
    const double klo = norm * exp(-0.5 * (r - lo) * (r - lo) / (sg * sg));
    const double khi = norm * exp(-0.5 * (r - hi) * (r - hi) / (sg * sg));
    double sum = khi * pairs_within(pat, hi) - (lo > 0.0 ? klo * pairs_within(pat, lo) : 0.0);
    for (size_t i = 0; i + 1u < nc; ++i) {
        const double a = cuts[i], b = cuts[i + 1u];
        const size_t parts = (size_t)ceil((b - a) / sg);
        for (size_t p = 0; p < parts; ++p) {
            const double pa = a + (b - a) * (double)p / (double)parts;
            const double pb = a + (b - a) * (double)(p + 1u) / (double)parts;
            for (int q = 0; q < GL_N; ++q) {
                const double d = pa + (pb - pa) * gl_x[q], u = r - d;
                const double dk = -(u / (sg * sg)) * norm * exp(-0.5 * u * u / (sg * sg));
                sum += gl_w[q] * (pb - pa) * dk * pairs_within(pat, d);
            }
        }
    }
    const double kd = (double)pat->k;
    return sum / (kd * (kd - 1.0) * 2.0 * pi * r);
}

/* The grid's kernel PCF at r: sum over the lattice offsets within 8 sg of
 * r of k(r - d), over (K - 1) 2 pi r. */
static double grid_kernel(size_t m, size_t n, double r, double sg)
{
    const double norm = 1.0 / (sg * sqrt(2.0 * pi)), reach = r + 8.0 * sg;
    double sum = 0.0;
    for (size_t a = 0; a < m; a = next_offset(a, m, reach))
        for (size_t b = 0; b < n; b = next_offset(b, n, reach)) {
            if (a == 0u && b == 0u)
                continue;
            const double dx = (double)(a <= m - a ? a : m - a) / (double)m;
            const double dy = (double)(b <= n - b ? b : n - b) / (double)n;
            const double u = r - sqrt(dx * dx + dy * dy);
            if (fabs(u) <= 8.0 * sg)
                sum += norm * exp(-0.5 * u * u / (sg * sg));
        }
    return sum / ((double)(m * n - 1u) * 2.0 * pi * r);
}

static double normal_cdf(double x)
{
    return 0.5 * erfc(-x / sqrt(2.0));
}

mcs_status mcs_pcf_exact(const mcs_pcf *acc, const mcs_pattern2d *pat, size_t bin, double *out)
{
    mcs_status st = out == NULL ? MCS_ERR_NULL : mcs_pcf_check_(acc);
    if (st == MCS_OK && bin >= acc->bins)
        st = MCS_ERR_BIN_RANGE;
    if (st != MCS_OK)
        return st;
    const int random = pat == NULL || pat->kind == MCS_PATTERN2D_RANDOM;
    if (pat != NULL) {
        if (pat->k < 1u || pat->strata_x * pat->strata_y != pat->k || pat->strata_x == 0u ||
            (unsigned)pat->kind >= (unsigned)MCS_PATTERN2D_KIND_COUNT)
            return MCS_ERR_UNINIT;
        if (acc->dim != 2u)
            return MCS_ERR_MISMATCH;
        if (pat->k < 2u || !(mcs_pcf_cutoff_(acc) * mcs_pcf_spacing_(2u, pat->k) <= 0.5))
            return MCS_ERR_K_RANGE;
    }
    if (random) {
        if (acc->estimator == MCS_PCF_RDF)
            return mcs_set_(out, 1.0);
        /* E g(r) = int_0^inf k(r - d) S(d) dd / S(r), scale-free in mean spacings. */
        const double r = ((double)bin + 0.5) * acc->radius / (double)acc->bins, z = r / acc->sigma;
        const double phi = exp(-0.5 * z * z) / sqrt(2.0 * pi);
        return mcs_set_(out, acc->dim == 1u ? normal_cdf(z) : normal_cdf(z) + phi / z);
    }
    const size_t k = pat->k, m = pat->strata_x, n = pat->strata_y;
    const double s = mcs_pcf_spacing_(2u, k), w = acc->radius / (double)acc->bins * s;
    if (acc->estimator == MCS_PCF_GAUSSIAN) {
        const double r = ((double)bin + 0.5) * w, sg = acc->sigma * s;
        switch (pat->kind) {
        case MCS_PATTERN2D_GRID:
        case MCS_PATTERN2D_SHIFTED_GRID: return mcs_set_(out, grid_kernel(m, n, r, sg));
        case MCS_PATTERN2D_JITTERED:
        case MCS_PATTERN2D_NROOKS: return mcs_set_(out, kernel_exact(pat, r, sg));
        default: return MCS_ERR_KIND;
        }
    }
    const double r0 = (double)bin * w, r1 = (double)(bin + 1u) * w;
    const double area = mcs_pcf_ring_(2u, r0, r1), kd = (double)k;
    switch (pat->kind) {
    case MCS_PATTERN2D_GRID:
    case MCS_PATTERN2D_SHIFTED_GRID: return mcs_set_(out, grid_rdf(acc, m, n, bin, s, area));
    case MCS_PATTERN2D_JITTERED:
        return mcs_set_(out, (kd * area - ring(m, n, r0, r1)) / ((kd - 1.0) * area));
    case MCS_PATTERN2D_NROOKS: {
        const double ix = ring(k, 0u, r0, r1), iy = ring(0u, k, r0, r1);
        const double i2 = ring(k, k, r0, r1);
        return mcs_set_(out, (kd * kd * area - kd * (ix + iy) + i2) /
                                 ((kd - 1.0) * (kd - 1.0) * area));
    }
    default: return MCS_ERR_KIND;
    }
}
