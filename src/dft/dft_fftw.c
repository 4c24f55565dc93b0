/* The FFTW back end of the dft module (dft.h), compiled in with
 * -DMCS_DFT_FFTW (make FFT=fftw; CMake -DMCSPEC_FFT=fftw) and linked with
 * -lfftw3. Without that define this file only provides the stubs that make
 * every plan a KissFFT one, so the default build neither includes nor links
 * FFTW.
 *
 * An mcs_dft holds no pointers, so FFTW's plans cannot live in it. They live
 * here instead, one r2c plan per N, made on the first mcs_dft_init for that N
 * and kept for the life of the process: FFTW allocates then, and never when a
 * trial is transformed (fftw_execute_dft_r2c on the new-array interface does
 * not allocate). The plans are made on 64-byte aligned arrays, and the
 * transform runs on the 64-byte aligned window of the plan's work area, so the
 * alignment FFTW planned for always holds, whatever address a (copied) mcs_dft
 * has. This table is the one piece of global state of the library, and exists
 * only in FFTW builds. */
#include "dft_internal.h"

#if defined(MCS_DFT_FFTW)

#include <fftw3.h>
#include <stdint.h>
#include <string.h>
#include <threads.h>

static fftw_plan plans[MCS_MAX_N + 1];
static once_flag lock_once = ONCE_FLAG_INIT;
static mtx_t lock;
static int lock_ok;

static void lock_init(void)
{
    lock_ok = mtx_init(&lock, mtx_plain) == thrd_success;
}

/* The window: in[n] from the first 64-byte boundary of plan->work, the
 * n/2 + 1 complex outputs and MCS_DFT_FFTW_PAD more (zeros for a caller's
 * whole blocks, mcs_dft_fftw_out_) from the next one after it. */
static double *aligned(double *p)
{
    const uintptr_t a = (uintptr_t)p, mis = a % 64u;
    return mis == 0u ? p : p + (64u - mis) / sizeof(double);
}

/* Doubles of the window: in, then out, each after up to 7 pad doubles. */
static size_t window_doubles(size_t n)
{
    return (n + 7u) + (2u * (n / 2u + 1u + MCS_DFT_FFTW_PAD) + 7u);
}

int mcs_dft_fftw_is_ready_(size_t n)
{
    return n >= 3u && n <= (size_t)MCS_MAX_N && plans[n] != NULL;
}

/* Plans on FFTW's own (SIMD-aligned) arrays with FFTW_MEASURE, then frees
 * them: the plan is for any arrays of the same alignment. */
static fftw_plan make_plan(size_t n)
{
    double *in = fftw_alloc_real(n);
    fftw_complex *out = fftw_alloc_complex(n / 2u + 1u);
    fftw_plan p = NULL;
    if (in != NULL && out != NULL)
        p = fftw_plan_dft_r2c_1d((int)n, in, out, FFTW_MEASURE);
    fftw_free(in);
    fftw_free(out);
    return p;
}

int mcs_dft_fftw_prepare_(mcs_dft *plan, size_t n)
{
    (void)plan;
    if (n < 3u || n > (size_t)MCS_MAX_N || window_doubles(n) > 4u * (size_t)MCS_MAX_N)
        return 0;
    call_once(&lock_once, lock_init);
    if (!lock_ok || mtx_lock(&lock) != thrd_success)
        return 0;
    if (plans[n] == NULL)
        plans[n] = make_plan(n);
    const int ready = plans[n] != NULL;
    (void)mtx_unlock(&lock);
    return ready;
}

/* re[k], im[k] = scale times the parts of FFTW's interleaved out[2k],
 * out[2k + 1], k < count: groups of four with a fixed count, which the
 * compiler vectorises at -O2 (the loop with a variable count it left scalar:
 * about 13 instructions a frequency); then the rest. */
static void split_scaled(size_t count, const double *restrict out, double scale,
                         double *restrict re, double *restrict im)
{
    size_t k = 0;
    for (; k + 4u <= count; k += 4u)
        for (size_t i = 0; i < 4u; ++i) {
            re[k + i] = scale * out[2u * (k + i)];
            im[k + i] = scale * out[2u * (k + i) + 1u];
        }
    for (; k < count; ++k) {
        re[k] = scale * out[2u * k];
        im[k] = scale * out[2u * k + 1u];
    }
}

/* The r2c of s into the output window; returns the window. */
static double *transform(mcs_dft *plan, const double *s)
{
    const size_t n = plan->n;
    double *in = aligned(plan->work);
    double *out = aligned(in + n);
    /* FFTW runs a plan on other arrays of the planned arrays' alignment (its
     * fftw_malloc'd ones: 0): s itself when it has that alignment, a copy
     * otherwise. r2c out of place leaves its input as it was, and s is read
     * in full before re or im (which may alias it) are written. */
    const double *src = s;
    if (fftw_alignment_of((double *)(uintptr_t)s) != 0) {
        memcpy(in, s, n * sizeof in[0]);
        src = in;
    }
    fftw_execute_dft_r2c(plans[n], (double *)(uintptr_t)src, (fftw_complex *)out);
    return out;
}

const double *mcs_dft_fftw_out_(mcs_dft *plan, const double *s, size_t count)
{
    const size_t n = plan->n, h = n / 2u;
    double *out = transform(plan, s);
    out[1] = 0.0; /* exactly real, as on the KissFFT paths */
    if (n % 2u == 0u)
        out[2u * h + 1u] = 0.0;
    for (size_t k = h + 1u; k < count; ++k)
        out[2u * k] = out[2u * k + 1u] = 0.0;
    return out;
}

void mcs_dft_fftw_half_(mcs_dft *plan, const double *s, double *re, double *im, double scale)
{
    const size_t n = plan->n, h = n / 2u;
    const double *out = transform(plan, s);
    if (im != NULL) {
        split_scaled(h + 1u, out, scale, re, im);
        im[0] = 0.0; /* exactly real, as on the KissFFT paths */
        if (n % 2u == 0u)
            im[h] = 0.0;
    } else {
        for (size_t k = 0; k <= h; ++k)
            re[k] = scale * out[2u * k];
    }
}

const char *mcs_dft_fftw_name_(void)
{
    return "fftw3";
}

#else /* the default build: KissFFT only */

int mcs_dft_fftw_prepare_(mcs_dft *plan, size_t n)
{
    (void)plan;
    (void)n;
    return 0;
}

void mcs_dft_fftw_half_(mcs_dft *plan, const double *s, double *re, double *im, double scale)
{
    (void)plan;
    (void)s;
    (void)re;
    (void)im;
    (void)scale;
}

int mcs_dft_fftw_is_ready_(size_t n)
{
    (void)n;
    return 0;
}

const char *mcs_dft_fftw_name_(void)
{
    return "kissfft";
}

#endif
