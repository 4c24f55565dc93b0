#include "mcspec/dft.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "dft_internal.h"
#include "core/internal.h"
#include "kiss_fft.h"
#include "core/simd.h"
#if MCS_AVX2_CLONES
#include "dft_kiss_avx2.h"
#endif

#if MCS_AVX2_CLONES
#include <cpuid.h>
#endif

#define MCS_SIMD_BODY "dft/dft_simd.h"
#include "core/simd_clones.h"

int mcs_cpu_avx2_(void)
{
#if MCS_AVX2_CLONES
    unsigned a, b, c, d;
    /* The OS saves YMM state (OSXSAVE, then XCR0 bits 1 and 2), and AVX2
     * (leaf 7, EBX bit 5). */
    if (!__get_cpuid(1u, &a, &b, &c, &d) || !(c & (1u << 27)))
        return 0;
    unsigned xcr0_lo, xcr0_hi;
    __asm__("xgetbv" : "=a"(xcr0_lo), "=d"(xcr0_hi) : "c"(0u));
    (void)xcr0_hi;
    if ((xcr0_lo & 6u) != 6u || !__get_cpuid_count(7u, 0u, &a, &b, &c, &d))
        return 0;
    return (b & (1u << 5)) != 0u;
#else
    return 0;
#endif
}

const char *mcs_dft_backend(void)
{
    return mcs_dft_fftw_name_();
}

/* 1 when every prime factor of n is at most p_max. */
static int is_smooth(size_t n, size_t p_max)
{
    for (size_t p = 2u; p <= p_max && n > 1u; ++p)
        while (n % p == 0u)
            n /= p;
    return n == 1u;
}

/* Only the factors 2, 3 and 5: KissFFT has butterflies for them (radix 2, 3,
 * 4, 5); any other prime sends it to kf_bfly_generic, which asks for scratch. */
static int is_kiss_smooth(size_t n)
{
    return is_smooth(n, 5u);
}

/* The KissFFT-side path for n and its transform length (0 if none). KissFFT
 * of size 1 also reaches the generic butterfly (its factor is 1), so N = 2
 * (half-size 1) and N = 1 are done by hand. */
static mcs_dft_path kiss_path(size_t n, size_t *fft_len)
{
    *fft_len = 0u;
    if (n <= 2u)
        return MCS_DFT_PATH_TRIVIAL;
    if (n % 2u == 0u && is_kiss_smooth(n / 2u)) {
        *fft_len = n / 2u;
        return MCS_DFT_PATH_KISS_REAL;
    }
    if (n % 2u == 1u && is_kiss_smooth(n)) {
        *fft_len = n;
        return MCS_DFT_PATH_KISS_COMPLEX;
    }
    return MCS_DFT_PATH_DIRECT;
}

mcs_status mcs_dft_init(mcs_dft *plan, size_t n)
{
    if (plan == NULL)
        return MCS_ERR_NULL;
    if (n == 0u || n > (size_t)MCS_MAX_N)
        return MCS_ERR_N_RANGE;
    size_t fft_len;
    mcs_dft_path path = kiss_path(n, &fft_len);
    /* First call of the two-call size query: the reserved state must hold it. */
    if (fft_len > 0u) {
        size_t need = 0u;
        (void)kiss_fft_alloc((int)fft_len, 0, NULL, &need);
        if (need > sizeof plan->kiss_state)
            return MCS_ERR_N_RANGE;
    }
    /* FFTW's planner works on its own arrays: nothing of *plan is touched
     * before this point, and nothing can fail after it. */
    if (n >= 3u && mcs_dft_fftw_prepare_(plan, n)) {
        path = MCS_DFT_PATH_FFTW;
        fft_len = 0u;
    }
    plan->n = n;
    plan->fft_len = fft_len;
    plan->path = path;
    plan->simd = mcs_cpu_avx2_();
    mcs_twiddles_(n, plan->cos_table, plan->sin_table);
    if (fft_len > 0u) {
        size_t len = sizeof plan->kiss_state;
        (void)kiss_fft_alloc((int)fft_len, 0, plan->kiss_state, &len);
    }
    return MCS_OK;
}

static int plan_is_valid(const mcs_dft *plan)
{
    if (!(plan->n >= 1u && plan->n <= (size_t)MCS_MAX_N && plan->path >= MCS_DFT_PATH_TRIVIAL &&
          plan->path <= MCS_DFT_PATH_FFTW && (plan->simd == 0 || plan->simd == 1)))
        return 0;
    if (plan->path == MCS_DFT_PATH_FFTW)
        return plan->fft_len == 0u && plan->n >= 3u && mcs_dft_fftw_is_ready_(plan->n);
    if (plan->fft_len == 0u)
        return plan->path == MCS_DFT_PATH_TRIVIAL || plan->path == MCS_DFT_PATH_DIRECT;
    /* KissFFT's state starts with its nfft: a cheap check that it was placed. */
    int nfft;
    memcpy(&nfft, plan->kiss_state, sizeof nfft);
    return plan->fft_len <= (size_t)MCS_MAX_N && nfft == (int)plan->fft_len;
}

/* KissFFT's forward transform, by the plan's copy (dft_kiss_avx2.c). */
static void kiss_forward(const mcs_dft *plan, const kiss_fft_cpx *in, kiss_fft_cpx *out)
{
    kiss_fft_cfg cfg = (kiss_fft_cfg)(uintptr_t)plan->kiss_state;
#if MCS_AVX2_CLONES
    if (plan->simd) {
        mcs_kiss_fft_avx2(cfg, in, out);
        return;
    }
#endif
    kiss_fft(cfg, in, out);
}

/* Even N = 2L: z_j = s_{2j} + i s_{2j+1}, Z = FFT_L(z); then with
 * E_k = (Z_k + Z*_{L-k})/2 (the even samples' DFT),
 * O_k = (Z_k - Z*_{L-k})/(2i) (the odd samples') and T = e^{-2 pi i k/N} O_k,
 * X_k = E_k + T and X_{L-k} = conj(E_k - T): one pass over k <= L/2 gives both. */
static void half_kiss_real(mcs_dft *plan, const double *s, double *re, double *im, double scale)
{
    const size_t len = plan->fft_len;
    kiss_fft_cpx *z = (kiss_fft_cpx *)plan->work;
    kiss_forward(plan, (const kiss_fft_cpx *)s, z);
    /* s is fully read; re or im may alias it from here on. Without im, the
     * imaginary parts go to scratch beyond z, so the loop has no branch. */
    double *imo = im != NULL ? im : plan->work + 2u * len;
    const double z0r = z[0].r, z0i = z[0].i;
    for (size_t k = 1; k <= len / 2u; ++k) {
        const double ar = z[k].r, ai = z[k].i;
        const double br = z[len - k].r, bi = -z[len - k].i;
        const double er = 0.5 * (ar + br), ei = 0.5 * (ai + bi);
        const double or_ = 0.5 * (ai - bi), oi = -0.5 * (ar - br);
        const double c = plan->cos_table[k], sn = plan->sin_table[k];
        /* T = (c - i sn)(or + i oi) */
        const double tr = c * or_ + sn * oi, ti = c * oi - sn * or_;
        re[k] = scale * (er + tr);
        imo[k] = scale * (ei + ti);
        re[len - k] = scale * (er - tr);
        imo[len - k] = scale * (ti - ei);
    }
    re[0] = scale * (z0r + z0i);
    re[len] = scale * (z0r - z0i);
    imo[0] = 0.0;
    imo[len] = 0.0;
}

static void half_kiss_complex(mcs_dft *plan, const double *s, double *re, double *im,
                              double scale)
{
    const size_t n = plan->n, h = n / 2u;
    kiss_fft_cpx *in = (kiss_fft_cpx *)plan->work;
    kiss_fft_cpx *out = in + n;
    for (size_t j = 0; j < n; ++j) {
        in[j].r = s[j];
        in[j].i = 0.0;
    }
    kiss_forward(plan, in, out);
    for (size_t k = 0; k <= h; ++k)
        re[k] = scale * out[k].r;
    if (im != NULL) {
        im[0] = 0.0; /* exactly real, as the other paths give it */
        for (size_t k = 1; k <= h; ++k)
            im[k] = scale * out[k].i;
    }
}

/* A prime factor above 5. Bluestein would need scratch several times N; this
 * instead sums over the non-zero s_n only (dft_simd.h), with exact twiddle
 * indices: O(N * nnz), cheap for the sparse patterns this library
 * transforms and for small N. Without im only the real parts are summed.
 * The sums go to the work area, padded to whole blocks of 8 frequencies. */
static void half_direct(mcs_dft *plan, const double *s, double *re, double *im, double scale)
{
    const size_t n = plan->n, h = n / 2u, padded = (n / 2u + 8u) / 8u * 8u;
    double *acc_re = plan->work, *acc_im = plan->work + padded;
    memset(plan->work, 0, 2u * padded * sizeof plan->work[0]);
#if MCS_AVX2_CLONES
    if (plan->simd)
        direct_sums_avx2(plan, s, acc_re, im != NULL ? acc_im : NULL);
    else
#endif
        direct_sums_generic(plan, s, acc_re, im != NULL ? acc_im : NULL);
    for (size_t k = 0; k <= h; ++k)
        re[k] = scale * acc_re[k];
    if (im != NULL) {
        im[0] = 0.0;
        for (size_t k = 1; k <= h; ++k)
            im[k] = scale * acc_im[k];
        if (n % 2u == 0u)
            im[h] = 0.0; /* Nyquist: exactly real */
    }
}

static void half_trivial(size_t n, const double *s, double *re, double *im)
{
    if (n == 1u) {
        re[0] = s[0];
        if (im != NULL)
            im[0] = 0.0;
        return;
    }
    const double a = s[0], b = s[1], r = 0.70710678118654752440084436210485;
    re[0] = r * (a + b);
    re[1] = r * (a - b);
    if (im != NULL) {
        im[0] = 0.0;
        im[1] = 0.0;
    }
}

void mcs_dft_half_(mcs_dft *plan, const double *s, double *re, double *im)
{
    const double scale = 1.0 / sqrt((double)plan->n); /* eq. 7's normalisation */
    switch (plan->path) {
    case MCS_DFT_PATH_KISS_REAL: half_kiss_real(plan, s, re, im, scale); break;
    case MCS_DFT_PATH_KISS_COMPLEX: half_kiss_complex(plan, s, re, im, scale); break;
    case MCS_DFT_PATH_DIRECT: half_direct(plan, s, re, im, scale); break;
    case MCS_DFT_PATH_FFTW: mcs_dft_fftw_half_(plan, s, re, im, scale); break;
    default: half_trivial(plan->n, s, re, im); break;
    }
}

/* Per-call time in nanoseconds, fitted to build/bench/spectrum_costs (see
 * src/accumulators/spectrum_cost.c) on the bench machine, gcc 12 -O2: KissFFT costs about
 * 0.42 ns per N log2 N on the packed real path and 0.84 on the odd complex
 * one, 0.37 and 0.74 for its AVX2 copy (1024: 3.5 against 4.0 us; 3375:
 * 28.3 against 31.9); the direct sum C_DIRECT ns per (non-zero bin, frequency) pair for its
 * block-phase kernel (half that without im, which the model leaves to its
 * caller); FFTW's r2c 0.11 ns per N log2 N plus its copy in and out when
 * every prime factor of N has a codelet (up to 13), and 17 times that
 * otherwise: at N = 4093 (prime, Rader's algorithm) make bench measured
 * 94 us where the smooth-size figure gives 5.5 (FFTW 3.3.10, FFTW_MEASURE).
 * Without that factor AUTO put N = 4093, K = 256 on the FFT path at a
 * quarter of the PAIR path's speed. */
static double cost_of(size_t n_bins, mcs_dft_path path, int simd, size_t nnz)
{
    /* baseline, AVX2 */
    static const double c_direct[2] = {0.36, 0.24}, c_real[2] = {0.42, 0.37},
                        c_complex[2] = {0.84, 0.74};
    const size_t half = n_bins / 2u + 1u; /* the frequencies computed */
    const double n = (double)n_bins, nlog = n * log2(n > 2.0 ? n : 2.0), h1 = (double)half;
    const double used = (double)(nnz < n_bins ? nnz : n_bins);
    switch (path) {
    case MCS_DFT_PATH_KISS_REAL: return 40.0 + c_real[simd != 0] * nlog;
    case MCS_DFT_PATH_KISS_COMPLEX: return 40.0 + c_complex[simd != 0] * nlog;
    case MCS_DFT_PATH_DIRECT: return 40.0 + 0.5 * n + c_direct[simd != 0] * used * h1;
    case MCS_DFT_PATH_FFTW:
        return 40.0 + 0.11 * nlog * (is_smooth(n_bins, 13u) ? 1.0 : 17.0) + 0.3 * n;
    default: return 5.0;
    }
}

double mcs_dft_cost_(const mcs_dft *plan, size_t nnz)
{
    return cost_of(plan->n, plan->path, plan->simd, nnz);
}

double mcs_dft_reference_cost_(size_t n, size_t nnz)
{
    size_t fft_len;
    return cost_of(n, kiss_path(n, &fft_len), 1, nnz);
}

mcs_status mcs_dft_check(const mcs_dft *plan, size_t n)
{
    if (plan == NULL)
        return MCS_ERR_NULL;
    if (!plan_is_valid(plan))
        return MCS_ERR_UNINIT;
    if (n != plan->n)
        return MCS_ERR_MISMATCH;
    return MCS_OK;
}

/* MCS_OK when the sum of |x_j| is at most MCS_DFT_MAX_ABS_SUM, so that the
 * transform's partial sums stay below overflow; MCS_ERR_NOT_FINITE for a NaN
 * or infinity (they poison the sum), MCS_ERR_MAGNITUDE for finite values
 * too large. Four partial sums keep the adds from waiting on each other. */
static mcs_status abs_sum_status(size_t n, const double *x)
{
    double z0 = 0.0, z1 = 0.0, z2 = 0.0, z3 = 0.0;
    size_t j = 0;
    for (; j + 4u <= n; j += 4u) {
        z0 += fabs(x[j]);
        z1 += fabs(x[j + 1u]);
        z2 += fabs(x[j + 2u]);
        z3 += fabs(x[j + 3u]);
    }
    for (; j < n; ++j)
        z0 += fabs(x[j]);
    if ((z0 + z1) + (z2 + z3) <= MCS_DFT_MAX_ABS_SUM)
        return MCS_OK;
    return mcs_all_finite_(n, x) ? MCS_ERR_MAGNITUDE : MCS_ERR_NOT_FINITE;
}

/* Arguments of mcs_dft_real(_half) with outputs of `len` entries each. */
static mcs_status check(const mcs_dft *plan, size_t n, const double *s, const double *re,
                        const double *im, size_t len)
{
    if (plan == NULL || s == NULL || re == NULL)
        return MCS_ERR_NULL;
    mcs_status st = mcs_dft_check(plan, n);
    if (st != MCS_OK)
        return st;
    const size_t bytes = len * sizeof(double);
    if (mcs_overlap_(s, n * sizeof(double), plan, sizeof *plan) ||
        mcs_overlap_(re, bytes, plan, sizeof *plan) ||
        (im != NULL && (mcs_overlap_(im, bytes, plan, sizeof *plan) ||
                        mcs_overlap_(re, bytes, im, bytes))))
        return MCS_ERR_ALIAS;
    return abs_sum_status(n, s);
}

mcs_status mcs_dft_real_half(mcs_dft *plan, size_t n, const double *s, double *re, double *im)
{
    mcs_status st = check(plan, n, s, re, im, n / 2u + 1u);
    if (st != MCS_OK)
        return st;
    mcs_dft_half_(plan, s, re, im);
    return MCS_OK;
}

mcs_status mcs_dft_real(mcs_dft *plan, size_t n, const double *s, double *re, double *im)
{
    mcs_status st = check(plan, n, s, re, im, n);
    if (st != MCS_OK)
        return st;
    mcs_dft_half_(plan, s, re, im);
    /* s is real: S_{N-k} = conj(S_k). */
    const size_t h = n / 2u;
    for (size_t k = h + 1u; k < n; ++k)
        re[k] = re[n - k];
    if (im != NULL)
        for (size_t k = h + 1u; k < n; ++k)
            im[k] = -im[n - k];
    return MCS_OK;
}
