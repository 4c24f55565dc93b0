/* Type-1 NUFFT, second stage: the grid's transform by KissFFT (complex,
 * forward, out of place, lengths with factors 2, 3, 5 only: no allocation),
 * read out at |k| <= F and divided by the kernel's transform. The grid is
 * real, so its transform is Hermitian: only k_x >= 0 is computed and
 * c_{-k} = conj(c_k) is written exactly. Grid index 0 is x = 0, so a mode
 * needs no phase factor beyond the transform's own e^{-2 pi i k l / n}. */
#include <stddef.h>

#include "nufft_internal.h"
#include "kiss_fft.h"

#if MCS_CONFIG_NUFFT /* else nothing here (config.h) */

static kiss_fft_cfg cfg_of(const mcs_nufft *plan)
{
    return (kiss_fft_cfg)plan->fft;
}

/* out(kx, ky) and out(-kx, -ky) = conj: complex index (ky + F)(2F+1) + kx + F
 * from centre = out + 2 ((2F+1) F + F). */
static void put_pair(double *centre, ptrdiff_t side, ptrdiff_t kx, ptrdiff_t ky, double re,
                     double im)
{
    const ptrdiff_t at = 2 * (ky * side + kx);
    centre[at] = re;
    centre[at + 1] = im;
    centre[-at] = re;
    centre[-at + 1] = -im;
}

/* 1D: the n real grid values g as L = n/2 complex z_j = g_{2j} + i g_{2j+1},
 * Z = FFT_L(z); the even points' transform is E_k = (Z_k + conj Z_{L-k})/2,
 * the odd points' O_k = (Z_k - conj Z_{L-k})/(2i), and the grid's
 * G_k = E_k + e^{-2 pi i k/n} O_k (F < L). */
static void modes_1d(const mcs_nufft *plan, double *out)
{
    const size_t len = plan->fft_len, f = plan->freq;
    kiss_fft_cpx *z = (kiss_fft_cpx *)(void *)plan->scratch;
    kiss_fft(cfg_of(plan), (const kiss_fft_cpx *)(const void *)plan->grid, z);
    const double *tw = plan->twiddle, *corr = plan->corr;
    double *centre = out + 2u * f;
    for (size_t k = 0; k <= f; ++k) {
        const size_t kr = k == 0u ? 0u : len - k;
        const double ar = z[k].r, ai = z[k].i, br = z[kr].r, bi = -z[kr].i;
        const double er = 0.5 * (ar + br), ei = 0.5 * (ai + bi);
        const double or_ = 0.5 * (ai - bi), oi = -0.5 * (ar - br);
        const double c = tw[2u * k], s = tw[2u * k + 1u];
        const double g = corr[k];
        put_pair(centre, 0, (ptrdiff_t)k, 0, g * (er + c * or_ - s * oi),
                 g * (ei + c * oi + s * or_));
    }
    centre[1] = 0.0; /* c_0 = K is real */
}

/* 2D, rows: complex row r holds real rows 2r (re) and 2r + 1 (im); with
 * X = FFT_n(row r), their transforms are A_k = (X_k + conj X_{n-k})/2 and
 * B_k = (X_k - conj X_{n-k})/(2i). A and B for k_x = 0..F go to rows 2r and
 * 2r + 1 of H, (F + 1) complex per row from the grid's start: they end at
 * complex index (2r + 2)(F + 1) <= (r + 1) n, before the rows not yet
 * transformed. */
static void rows_2d(const mcs_nufft *plan)
{
    const size_t n = plan->n, m1 = plan->freq + 1u;
    kiss_fft_cpx *h = (kiss_fft_cpx *)(void *)plan->grid;
    kiss_fft_cpx *x = (kiss_fft_cpx *)(void *)plan->scratch;
    kiss_fft_cfg cfg = cfg_of(plan);
    for (size_t r = 0; r < n / 2u; ++r) {
        kiss_fft(cfg, h + r * n, x);
        kiss_fft_cpx *a = h + 2u * r * m1, *b = a + m1;
        for (size_t k = 0; k < m1; ++k) {
            const size_t kr = k == 0u ? 0u : n - k;
            const double xr = x[k].r, xi = x[k].i, yr = x[kr].r, yi = x[kr].i;
            a[k].r = 0.5 * (xr + yr);
            a[k].i = 0.5 * (xi - yi);
            b[k].r = 0.5 * (xi + yi);
            b[k].i = -0.5 * (xr - yr);
        }
    }
}

/* 2D, columns: column k_x of H (stride F + 1) through FFT_n gives the modes
 * (k_x, k_y) at k_y mod n. Column 0 gives k_y >= 0 only (its negative half is
 * their conjugate). */
static void columns_2d(const mcs_nufft *plan, double *out)
{
    const size_t n = plan->n, f = plan->freq, m1 = f + 1u;
    const kiss_fft_cpx *h = (const kiss_fft_cpx *)(const void *)plan->grid;
    kiss_fft_cpx *y = (kiss_fft_cpx *)(void *)plan->scratch;
    kiss_fft_cfg cfg = cfg_of(plan);
    const double *corr = plan->corr;
    const ptrdiff_t side = (ptrdiff_t)(2u * f + 1u);
    double *centre = out + 2u * ((2u * f + 1u) * f + f);
    for (size_t kx = 0; kx <= f; ++kx) {
        kiss_fft_stride(cfg, h + kx, y, (int)m1);
        const double gx = corr[kx];
        for (size_t ky = 0; ky <= f; ++ky) {
            const double g = gx * corr[ky];
            put_pair(centre, side, (ptrdiff_t)kx, (ptrdiff_t)ky, g * y[ky].r, g * y[ky].i);
        }
        if (kx == 0u)
            continue;
        for (size_t ky = 1; ky <= f; ++ky) {
            const double g = gx * corr[ky];
            put_pair(centre, side, (ptrdiff_t)kx, -(ptrdiff_t)ky, g * y[n - ky].r,
                     g * y[n - ky].i);
        }
    }
    centre[1] = 0.0; /* c_0 = K is real */
}

void mcs_nufft_modes_(const mcs_nufft *plan, double *out)
{
    if (plan->dim == 1u) {
        modes_1d(plan, out);
        return;
    }
    rows_2d(plan);
    columns_2d(plan, out);
}

#else
/* ISO C wants a declaration in every translation unit. */
typedef int mcs_nufft_left_out_;
#endif /* MCS_CONFIG_NUFFT */
