/* Type-1 NUFFT: the plan (grid size, kernel and its Fourier transform, the
 * caller's buffer), the argument checks and the two stages' driver. The
 * stages are nufft_spread.c (points to grid) and nufft_modes.c (grid to
 * modes). */
#include "mcspec/nufft.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "nufft_internal.h"
#include "core/internal.h"
#include "kiss_fft.h"

#if MCS_CONFIG_NUFFT /* else the four calls refuse at the end of this file */

/* Every array of the work buffer starts at a multiple of this from the first
 * such address in it (a cache line; KissFFT needs 8). */
#define ALIGN 64u

/* Offsets, from the aligned start, of the arrays of the work buffer, and the
 * bytes asked of the caller (the offsets plus the worst alignment slack). */
typedef struct {
    size_t width, n, fft_len;
    size_t kiss, corr, twiddle, scratch, grid, total;
} layout;

static size_t round_up(size_t bytes)
{
    return (bytes + (ALIGN - 1u)) / ALIGN * ALIGN;
}

static size_t freq_cap(size_t dim)
{
    return dim == 1u ? (size_t)MCS_NUFFT_MAX_FREQ_1D : (size_t)MCS_NUFFT_MAX_FREQ_2D;
}

/* The arguments every call that sets up a plan takes. */
static mcs_status check_shape(size_t dim, size_t freq, double tol)
{
    if (dim != 1u && dim != 2u)
        return MCS_ERR_DOMAIN;
    if (freq == 0u || freq > freq_cap(dim))
        return MCS_ERR_FREQ_RANGE;
    if (!isfinite(tol))
        return MCS_ERR_NOT_FINITE;
    if (!(tol >= MCS_NUFFT_TOL_MIN && tol <= MCS_NUFFT_TOL_MAX))
        return MCS_ERR_DOMAIN;
    return MCS_OK;
}

/* The kernel width: the least w >= 2 with d E(w) <= tol, where
 * E(w) = 10^(1.4 - 0.94 w) bounds the worst error per axis and unit
 * strength of this kernel at upsampling 2 (measured over point offsets and
 * modes up to n/4, F = 40 to 200: 0.025 at w = 3, 5.9e-10 at 11, 1.6e-14 at
 * 16, each at most 0.69 E(w)); a 2D point's error is at most the sum of its
 * two axes'. FINUFFT's ceil(log10(10 / tol)) aims at a relative l2 error
 * near tol and gives up to 5 tol K for a single point or a tight cluster;
 * E adds one or two points per axis (tol = 1e-12: 15 in 1D and 2D, against
 * FINUFFT's 13). */
static size_t width_of(size_t dim, double tol)
{
    const double step = 0.11481536214968828; /* 10^-0.94 */
    double e = 25.118864315095795 * step * step; /* E(2); 10^1.4 = 25.1 */
    size_t w = 2u;
    while ((double)dim * e > tol && w < (size_t)MCS_NUFFT_MAX_WIDTH) {
        e *= step;
        ++w;
    }
    return w;
}

/* The least even 2^a 3^b 5^c (a >= 1) at least m: KissFFT then uses only its
 * radix-2, 3, 4 and 5 butterflies (a larger prime takes the generic one,
 * which allocates scratch), and even n lets 2D pack two real rows into one
 * complex transform. O(log^2 m) candidates; no product can overflow, as each
 * is formed from a value below m, and m < 2^29 within the caps. */
static size_t next_even_smooth(size_t m)
{
    size_t best = SIZE_MAX;
    for (size_t p2 = 2u;; p2 *= 2u) {
        for (size_t p3 = p2;; p3 *= 3u) {
            size_t v = p3;
            while (v < m)
                v *= 5u;
            if (v < best)
                best = v;
            if (p3 >= m)
                break;
        }
        if (p2 >= m)
            break;
    }
    return best;
}

/* Grid points per axis: at least sigma (2F + 1) and 2 w (FINUFFT's floor: a
 * point's kernel then wraps the periodic grid at most once). sigma = 2, but
 * 5/2 in 2D below tol = 1e-13: the rounding of the grid's sums and of its
 * transform, about 10 eps of the largest mode, is divided at the corner
 * k = (F, F) by Psi(F/n)^2, 1/80 of Psi(0)^2 at sigma = 2 (1/16 at 5/2),
 * which held the 2D error near 1.3e-14 K whatever w (measured; 3e-15 K at
 * 5/2). */
static size_t grid_points(size_t dim, size_t freq, size_t width, double tol)
{
    const size_t side = 2u * freq + 1u;
    size_t m = dim == 2u && tol < 1e-13 ? (5u * side + 1u) / 2u : 2u * side;
    if (m < 2u * width)
        m = 2u * width;
    return next_even_smooth(m);
}

/* The buffer's layout for checked arguments. Within the caps of nufft.h no
 * size below can overflow size_t (the caps are chosen so). */
static void layout_of(size_t dim, size_t freq, double tol, layout *lay)
{
    lay->width = width_of(dim, tol);
    lay->n = grid_points(dim, freq, lay->width, tol);
    /* 1D: the n real grid values as n/2 complex (even and odd points);
     * 2D: n/2 complex rows of n, each two real rows. */
    lay->fft_len = dim == 1u ? lay->n / 2u : lay->n;
    size_t kiss = 0u;
    (void)kiss_fft_alloc((int)lay->fft_len, 0, NULL, &kiss); /* size query: no allocation */
    const size_t d = sizeof(double);
    lay->kiss = 0u;
    lay->corr = round_up(kiss);
    lay->twiddle = lay->corr + round_up((freq + 1u) * d);
    lay->scratch = lay->twiddle + (dim == 1u ? round_up(2u * (freq + 1u) * d) : 0u);
    lay->grid = lay->scratch + round_up(2u * lay->fft_len * d);
    const size_t grid = dim == 1u ? lay->n : lay->n * lay->n;
    lay->total = (ALIGN - 1u) + lay->grid + grid * d;
}

mcs_status mcs_nufft_size(size_t dim, size_t freq, double tol, size_t *bytes)
{
    if (bytes == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_shape(dim, freq, tol);
    if (st != MCS_OK)
        return st;
    layout lay;
    layout_of(dim, freq, tol, &lay);
    *bytes = lay.total;
    return MCS_OK;
}

/* Legendre P_m(z) and P_m'(z) by the three-term recurrence (|z| < 1). */
static void legendre(size_t m, double z, double *p, double *dp)
{
    double p0 = 1.0, p1 = z;
    for (size_t j = 2u; j <= m; ++j) {
        const double jd = (double)j, p2 = ((2.0 * jd - 1.0) * z * p1 - (jd - 1.0) * p0) / jd;
        p0 = p1;
        p1 = p2;
    }
    *p = p1;
    *dp = (double)m * (z * p1 - p0) / (z * z - 1.0);
}

/* The i-th positive node (i = 1..m/2, m even) of the m-point Gauss-Legendre
 * rule and its weight: Newton's iteration on P_m from Tricomi's first-order
 * guess, until the step is below 1e-14, then two more steps (quadratic
 * convergence takes it to rounding). */
static void gauss_legendre(size_t m, size_t i, double *node, double *weight)
{
    double z = cos(0.5 * MCS_TWO_PI * ((double)i - 0.25) / ((double)m + 0.5));
    double p, dp;
    int extra = 2;
    for (int it = 0; it < 100 && extra > 0; ++it) {
        legendre(m, z, &p, &dp);
        const double dz = p / dp;
        z -= dz;
        if (fabs(dz) < 1e-14)
            --extra;
    }
    legendre(m, z, &p, &dp);
    *node = z;
    *weight = 2.0 / ((1.0 - z * z) * dp * dp);
}

/* corr[k] = 1 / Psi(k / n), k = 0..F, where Psi is the Fourier transform of
 * the kernel in grid units, psi(t) = phi(2 t / w):
 *   Psi(xi) = (w/2) int_{-1}^{1} phi(z) cos(pi w xi z) dz
 *           = w sum_{z_i > 0} W_i phi(z_i) cos(pi w xi z_i)
 * by the 2q-point Gauss-Legendre rule, q = 2 + 3w/2 as FINUFFT's
 * onedim_fseries_kernel takes it (the integrand is even). Per node the
 * cosines over k advance by a rotation, recomputed every 32 frequencies. A
 * point x spread at t = n x has grid transform e^{-2 pi i k x} Psi(k/n) plus
 * the aliases (Poisson summation), so dividing by Psi gives c_k. */
static void kernel_transform(size_t width, double beta, size_t n, size_t freq, double *corr)
{
    const size_t q = 2u + 3u * width / 2u, m = 2u * q;
    const double wd = (double)width;
    for (size_t k = 0; k <= freq; ++k)
        corr[k] = 0.0;
    for (size_t i = 1u; i <= q; ++i) {
        double z, weight;
        gauss_legendre(m, i, &z, &weight);
        const double a = weight * mcs_nufft_kernel_(z, beta);
        const double theta = 0.5 * MCS_TWO_PI * wd * z / (double)n;
        const double step_c = cos(theta), step_s = sin(theta);
        for (size_t k0 = 0; k0 <= freq; k0 += 32u) {
            const size_t end = freq + 1u - k0 < 32u ? freq + 1u : k0 + 32u;
            double c = cos(theta * (double)k0), s = sin(theta * (double)k0);
            for (size_t k = k0; k < end; ++k) {
                corr[k] += a * c;
                const double c2 = c * step_c - s * step_s;
                s = s * step_c + c * step_s;
                c = c2;
            }
        }
    }
    for (size_t k = 0; k <= freq; ++k)
        corr[k] = 1.0 / (wd * corr[k]);
}

/* A hash of the plan's fields: a header not set by init (zeroed, garbage,
 * edited) fails it before any of its pointers is followed. */
static uintptr_t key_of(const mcs_nufft *p)
{
    const uintptr_t words[] = {(uintptr_t)p->dim,     (uintptr_t)p->freq,    (uintptr_t)p->n,
                               (uintptr_t)p->width,   (uintptr_t)p->fft_len, (uintptr_t)p->bytes,
                               (uintptr_t)p->mem,     (uintptr_t)p->grid,    (uintptr_t)p->scratch,
                               (uintptr_t)p->corr,    (uintptr_t)p->twiddle, (uintptr_t)p->fft};
    uintptr_t h = (uintptr_t)0x6e75666674u; /* "nufft" */
    for (size_t j = 0; j < sizeof words / sizeof words[0]; ++j) {
        h ^= words[j];
        h *= (uintptr_t)0x9e3779b1u;
        h ^= h >> 15;
    }
    return h;
}

mcs_status mcs_nufft_init(mcs_nufft *plan, size_t dim, size_t freq, double tol, void *mem,
                          size_t bytes)
{
    if (plan == NULL || mem == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_shape(dim, freq, tol);
    if (st != MCS_OK)
        return st;
    layout lay;
    layout_of(dim, freq, tol, &lay);
    if (bytes < lay.total)
        return MCS_ERR_SPACE;
    if (mcs_overlap_(mem, lay.total, plan, sizeof *plan))
        return MCS_ERR_ALIAS;
    const uintptr_t start = (uintptr_t)mem;
    unsigned char *base = (unsigned char *)mem + ((ALIGN - start % ALIGN) % ALIGN);

    mcs_nufft p;
    memset(&p, 0, sizeof p);
    p.dim = dim;
    p.freq = freq;
    p.n = lay.n;
    p.width = lay.width;
    p.beta = 2.30 * (double)lay.width;
    p.tol = tol;
    p.fft_len = lay.fft_len;
    p.bytes = lay.total;
    p.mem = mem;
    p.fft = base + lay.kiss;
    p.corr = (double *)(void *)(base + lay.corr);
    p.twiddle = dim == 1u ? (double *)(void *)(base + lay.twiddle) : NULL;
    p.scratch = (double *)(void *)(base + lay.scratch);
    p.grid = (double *)(void *)(base + lay.grid);

    size_t kiss = lay.corr - lay.kiss;
    (void)kiss_fft_alloc((int)lay.fft_len, 0, p.fft, &kiss);
    kernel_transform(p.width, p.beta, p.n, freq, p.corr);
    if (dim == 1u)
        for (size_t k = 0; k <= freq; ++k) {
            const double a = mcs_twiddle_angle_(k, p.n);
            p.twiddle[2u * k] = cos(a);
            p.twiddle[2u * k + 1u] = -sin(a);
        }
    p.key = key_of(&p);
    *plan = p;
    return MCS_OK;
}

/* Set up by mcs_nufft_init: the fields agree with each other and the key. */
static int plan_is_valid(const mcs_nufft *p)
{
    if (!(p->dim == 1u || p->dim == 2u) || p->freq == 0u || p->freq > freq_cap(p->dim) ||
        !(p->tol >= MCS_NUFFT_TOL_MIN && p->tol <= MCS_NUFFT_TOL_MAX))
        return 0;
    if (p->key != key_of(p) || p->n != grid_points(p->dim, p->freq, p->width, p->tol) ||
        p->width != width_of(p->dim, p->tol) ||
        p->fft_len != (p->dim == 1u ? p->n / 2u : p->n) || p->beta != 2.30 * (double)p->width)
        return 0;
    return p->mem != NULL && p->grid != NULL && p->scratch != NULL && p->corr != NULL &&
           p->fft != NULL && (p->twiddle != NULL) == (p->dim == 1u);
}

/* The checks of a transform before its points are read: elem is the bytes
 * of one coordinate. */
static mcs_status check_call(const mcs_nufft *plan, const void *points, size_t elem, size_t k,
                             const double *out)
{
    if (plan == NULL || points == NULL || out == NULL)
        return MCS_ERR_NULL;
    if (!plan_is_valid(plan))
        return MCS_ERR_UNINIT;
    if (k == 0u || k > SIZE_MAX / (plan->dim * elem))
        return MCS_ERR_K_RANGE;
    const size_t side = 2u * plan->freq + 1u, modes = plan->dim == 1u ? side : side * side;
    const size_t in_bytes = k * plan->dim * elem, out_bytes = 2u * modes * sizeof(double);
    if (mcs_overlap_(points, in_bytes, plan, sizeof *plan) ||
        mcs_overlap_(points, in_bytes, plan->mem, plan->bytes) ||
        mcs_overlap_(out, out_bytes, plan, sizeof *plan) ||
        mcs_overlap_(out, out_bytes, plan->mem, plan->bytes))
        return MCS_ERR_ALIAS;
    return MCS_OK;
}

mcs_status mcs_nufft_type1(mcs_nufft *plan, const double *points, size_t k, double *out)
{
    mcs_status st = check_call(plan, points, sizeof *points, k, out);
    if (st != MCS_OK)
        return st;
    const size_t count = k * plan->dim;
    for (size_t j = 0; j < count; ++j)
        if (!(points[j] >= 0.0 && points[j] < 1.0))
            return MCS_ERR_POINT_RANGE;
    mcs_nufft_spread_(plan, points, k);
    mcs_nufft_modes_(plan, out);
    return MCS_OK;
}

mcs_status mcs_nufft_type1_f(mcs_nufft *plan, const float *points, size_t k, double *out)
{
    mcs_status st = check_call(plan, points, sizeof *points, k, out);
    if (st != MCS_OK)
        return st;
    const size_t count = k * plan->dim;
    for (size_t j = 0; j < count; ++j)
        if (!((double)points[j] >= 0.0 && (double)points[j] < 1.0))
            return MCS_ERR_POINT_RANGE;
    mcs_nufft_spread_f_(plan, points, k);
    mcs_nufft_modes_(plan, out);
    return MCS_OK;
}

#else /* MCS_CONFIG_NUFFT 0 (config.h): built without the NUFFT */

mcs_status mcs_nufft_size(size_t dim, size_t freq, double tol, size_t *bytes)
{
    (void)dim, (void)freq, (void)tol, (void)bytes;
    return MCS_ERR_DOMAIN;
}

mcs_status mcs_nufft_init(mcs_nufft *plan, size_t dim, size_t freq, double tol, void *mem,
                          size_t bytes)
{
    (void)plan, (void)dim, (void)freq, (void)tol, (void)mem, (void)bytes;
    return MCS_ERR_DOMAIN;
}

mcs_status mcs_nufft_type1(mcs_nufft *plan, const double *points, size_t k, double *out)
{
    (void)plan, (void)points, (void)k, (void)out;
    return MCS_ERR_DOMAIN;
}

mcs_status mcs_nufft_type1_f(mcs_nufft *plan, const float *points, size_t k, double *out)
{
    (void)plan, (void)points, (void)k, (void)out;
    return MCS_ERR_DOMAIN;
}

#endif /* MCS_CONFIG_NUFFT */
