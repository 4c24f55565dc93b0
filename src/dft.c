#include "mcspec/dft.h"

#include <math.h>
#include <string.h>

#include "internal.h"
#include "kiss_fft.h"

/* Only the factors 2, 3 and 5: KissFFT has butterflies for them (radix 2, 3,
 * 4, 5); any other prime sends it to kf_bfly_generic, which asks for scratch. */
static int is_kiss_smooth(size_t n)
{
    while (n % 2u == 0u)
        n /= 2u;
    while (n % 3u == 0u)
        n /= 3u;
    while (n % 5u == 0u)
        n /= 5u;
    return n == 1u;
}

mcs_status mcs_dft_init(mcs_dft *plan, size_t n)
{
    if (plan == NULL)
        return MCS_ERR_NULL;
    if (n == 0u || n > (size_t)MCS_MAX_N)
        return MCS_ERR_N_RANGE;

    /* KissFFT of size 1 also reaches the generic butterfly (its factor is 1),
     * so N = 2 (half-size 1) and N = 1 are done by hand. */
    mcs_dft_path path;
    size_t fft_len = 0u;
    if (n <= 2u) {
        path = MCS_DFT_PATH_TRIVIAL;
    } else if (n % 2u == 0u && is_kiss_smooth(n / 2u)) {
        path = MCS_DFT_PATH_KISS_REAL;
        fft_len = n / 2u;
    } else if (n % 2u == 1u && is_kiss_smooth(n)) {
        path = MCS_DFT_PATH_KISS_COMPLEX;
        fft_len = n;
    } else {
        path = MCS_DFT_PATH_DIRECT;
    }

    /* First call of the two-call size query: the reserved state must hold it. */
    if (fft_len > 0u) {
        size_t need = 0u;
        (void)kiss_fft_alloc((int)fft_len, 0, NULL, &need);
        if (need > sizeof plan->kiss_state)
            return MCS_ERR_N_RANGE;
    }

    plan->n = n;
    plan->fft_len = fft_len;
    plan->path = path;
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
          plan->path <= MCS_DFT_PATH_DIRECT))
        return 0;
    if (plan->fft_len == 0u)
        return plan->path == MCS_DFT_PATH_TRIVIAL || plan->path == MCS_DFT_PATH_DIRECT;
    /* KissFFT's state starts with its nfft: a cheap check that it was placed. */
    int nfft;
    memcpy(&nfft, plan->kiss_state, sizeof nfft);
    return plan->fft_len <= (size_t)MCS_MAX_N && nfft == (int)plan->fft_len;
}

/* Even N = 2L: z_j = s_{2j} + i s_{2j+1}, Z = FFT_L(z); then with
 * E_k = (Z_k + Z*_{L-k})/2 (the even samples' DFT),
 * O_k = (Z_k - Z*_{L-k})/(2i) (the odd samples') and T = e^{-2 pi i k/N} O_k,
 * X_k = E_k + T and X_{L-k} = conj(E_k - T): one pass over k <= L/2 gives both. */
static void half_kiss_real(mcs_dft *plan, const double *s, double *re, double *im, double scale)
{
    const size_t len = plan->fft_len;
    kiss_fft_cpx *z = (kiss_fft_cpx *)plan->work;
    kiss_fft((kiss_fft_cfg)plan->kiss_state, (const kiss_fft_cpx *)s, z);
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
    kiss_fft((kiss_fft_cfg)plan->kiss_state, in, out);
    for (size_t k = 0; k <= h; ++k)
        re[k] = scale * out[k].r;
    if (im != NULL) {
        im[0] = 0.0; /* exactly real, as the other paths give it */
        for (size_t k = 1; k <= h; ++k)
            im[k] = scale * out[k].i;
    }
}

/* A prime factor above 5. Bluestein would need scratch several times N; this
 * instead sums over the non-zero s_n only, stepping the twiddle index by n
 * (mod N) so every root is an exact table entry: O(N * nnz), cheap for the
 * sparse patterns this library transforms and for small N. */
static void half_direct(mcs_dft *plan, const double *s, double *re, double *im, double scale)
{
    const size_t n = plan->n, h = n / 2u;
    double *acc_re = plan->work, *acc_im = plan->work + (h + 1u);
    for (size_t k = 0; k <= h; ++k) {
        acc_re[k] = 0.0;
        acc_im[k] = 0.0;
    }
    for (size_t b = 0; b < n; ++b) {
        const double w = s[b];
        if (w == 0.0)
            continue;
        size_t idx = 0u;
        for (size_t k = 0; k <= h; ++k) {
            acc_re[k] += w * plan->cos_table[idx];
            acc_im[k] -= w * plan->sin_table[idx];
            idx += b;
            if (idx >= n)
                idx -= n;
        }
    }
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

static mcs_status check(const mcs_dft *plan, size_t n, const double *s, const double *re)
{
    if (plan == NULL || s == NULL || re == NULL)
        return MCS_ERR_NULL;
    mcs_status st = mcs_dft_check(plan, n);
    if (st != MCS_OK)
        return st;
    if (!mcs_all_finite_(n, s))
        return MCS_ERR_NOT_FINITE;
    return MCS_OK;
}

static void transform_half(mcs_dft *plan, const double *s, double *re, double *im)
{
    const double scale = 1.0 / sqrt((double)plan->n); /* eq. 7's normalisation */
    switch (plan->path) {
    case MCS_DFT_PATH_KISS_REAL: half_kiss_real(plan, s, re, im, scale); break;
    case MCS_DFT_PATH_KISS_COMPLEX: half_kiss_complex(plan, s, re, im, scale); break;
    case MCS_DFT_PATH_DIRECT: half_direct(plan, s, re, im, scale); break;
    default: half_trivial(plan->n, s, re, im); break;
    }
}

mcs_status mcs_dft_real_half(mcs_dft *plan, size_t n, const double *s, double *re, double *im)
{
    mcs_status st = check(plan, n, s, re);
    if (st != MCS_OK)
        return st;
    transform_half(plan, s, re, im);
    return MCS_OK;
}

mcs_status mcs_dft_real(mcs_dft *plan, size_t n, const double *s, double *re, double *im)
{
    mcs_status st = check(plan, n, s, re);
    if (st != MCS_OK)
        return st;
    transform_half(plan, s, re, im);
    /* s is real: S_{N-k} = conj(S_k). */
    const size_t h = n / 2u;
    for (size_t k = h + 1u; k < n; ++k)
        re[k] = re[n - k];
    if (im != NULL)
        for (size_t k = h + 1u; k < n; ++k)
            im[k] = -im[n - k];
    return MCS_OK;
}
