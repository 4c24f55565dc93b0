#include "mcspec/spectrum.h"
#include "internal.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

/* Per-trial cost model for MCS_SPECTRUM_PATH_AUTO, from the bench on x86-64
 * (gcc -O2): one sparse term (a sample at one of the N/2 + 1 frequencies)
 * costs about 0.8 ns, the FFT path about 0.6 ns per N log2 N. Crossover:
 * K ~ 0.75 N log2 N / (N/2 + 1), about 1.5 log2 N. Only the ratio matters, and
 * only near the crossover, where the two costs are close anyway; both paths
 * give the same numbers. */
#define FFT_COST_PER_NLOGN 3u
#define SPARSE_COST_PER_TERM 4u

static size_t log2_ceil(size_t n)
{
    size_t l = 0u;
    while (((size_t)1u << l) < n)
        ++l;
    return l;
}

/* Largest K for which the sparse sum is expected to be cheaper. For a plan
 * on the direct path (a prime factor above 5) the "FFT" is itself the same sum
 * over the non-zero bins, at most min(K, N) of them: sparse while K <= N. */
static size_t sparse_limit(const mcs_dft *plan)
{
    if (plan->path == MCS_DFT_PATH_DIRECT)
        return plan->n;
    size_t n = plan->n, h1 = n / 2u + 1u;
    size_t fft_cost = FFT_COST_PER_NLOGN * n * log2_ceil(n);
    return fft_cost / (SPARSE_COST_PER_TERM * h1);
}

/* MCS_ERR_NULL without an accumulator, MCS_ERR_UNINIT before mcs_spectrum_init. */
static mcs_status spectrum_check(const mcs_spectrum *acc)
{
    if (acc == NULL)
        return MCS_ERR_NULL;
    if (acc->n >= 1u && acc->n <= (size_t)MCS_MAX_N && acc->plan.n == acc->n &&
        (unsigned)acc->path <= (unsigned)MCS_SPECTRUM_PATH_FFT) /* enum may be unsigned */
        return MCS_OK;
    return MCS_ERR_UNINIT;
}

mcs_status mcs_spectrum_init(mcs_spectrum *acc, size_t n)
{
    if (acc == NULL)
        return MCS_ERR_NULL;
    if (n == 0u || n > (size_t)MCS_MAX_N)
        return MCS_ERR_N_RANGE;
    /* The plan is the only step that can fail; it leaves acc->plan as it was. */
    mcs_status st = mcs_dft_init(&acc->plan, n);
    if (st != MCS_OK)
        return st;
    acc->n = n;
    acc->count = 0u;
    acc->path = MCS_SPECTRUM_PATH_AUTO;
    acc->sparse_max_k = sparse_limit(&acc->plan);
    memset(acc->mean_re, 0, sizeof acc->mean_re);
    memset(acc->mean_im, 0, sizeof acc->mean_im);
    memset(acc->m2_s, 0, sizeof acc->m2_s);
    memset(acc->mean_pow, 0, sizeof acc->mean_pow);
    memset(acc->m2_pow, 0, sizeof acc->m2_pow);
    memset(acc->s, 0, sizeof acc->s);
    memset(acc->re, 0, sizeof acc->re);
    memset(acc->im, 0, sizeof acc->im);
    return MCS_OK;
}

mcs_status mcs_spectrum_set_path(mcs_spectrum *acc, mcs_spectrum_path path)
{
    mcs_status st = spectrum_check(acc);
    if (st == MCS_OK && path != MCS_SPECTRUM_PATH_AUTO && path != MCS_SPECTRUM_PATH_SPARSE &&
        path != MCS_SPECTRUM_PATH_FFT)
        st = MCS_ERR_KIND;
    if (st == MCS_OK)
        acc->path = path;
    return st;
}

static int use_sparse(const mcs_spectrum *acc, size_t k)
{
    if (acc->path == MCS_SPECTRUM_PATH_SPARSE)
        return 1;
    if (acc->path == MCS_SPECTRUM_PATH_FFT)
        return 0;
    return k <= acc->sparse_max_k;
}

/* Sparse path, four samples at once: S_k += sum_q w_q e^{-2 pi i k b_q/N}
 * for k = 0..N/2. Each table index k b_q mod N advances by b_q per step, so
 * every twiddle is an exact table entry (no accumulated phase error); four
 * independent index chains keep the loop from waiting on one of them. */
static void sparse_four(mcs_spectrum *acc, const size_t *b, const double *w)
{
    const size_t n = acc->n, h = n / 2u;
    const double *ct = acc->plan.cos_table, *st = acc->plan.sin_table;
    double *re = acc->re, *im = acc->im;
    const size_t b0 = b[0], b1 = b[1], b2 = b[2], b3 = b[3];
    const double w0 = w[0], w1 = w[1], w2 = w[2], w3 = w[3];
    size_t i0 = 0u, i1 = 0u, i2 = 0u, i3 = 0u;
    for (size_t k = 0; k <= h; ++k) {
        re[k] += (w0 * ct[i0] + w1 * ct[i1]) + (w2 * ct[i2] + w3 * ct[i3]);
        im[k] -= (w0 * st[i0] + w1 * st[i1]) + (w2 * st[i2] + w3 * st[i3]);
        i0 += b0;
        i1 += b1;
        i2 += b2;
        i3 += b3;
        i0 = i0 >= n ? i0 - n : i0;
        i1 = i1 >= n ? i1 - n : i1;
        i2 = i2 >= n ? i2 - n : i2;
        i3 = i3 >= n ? i3 - n : i3;
    }
}

/* Feeds samples to sparse_four in groups; a short last group is padded with
 * weight 0 in bin 0, which adds exactly nothing. */
typedef struct {
    size_t b[4];
    double w[4];
    size_t fill;
} sparse_group;

static void group_push(mcs_spectrum *acc, sparse_group *g, size_t b, double w)
{
    g->b[g->fill] = b;
    g->w[g->fill] = w;
    if (++g->fill == 4u) {
        sparse_four(acc, g->b, g->w);
        g->fill = 0u;
    }
}

static void group_flush(mcs_spectrum *acc, sparse_group *g)
{
    if (g->fill == 0u)
        return;
    for (size_t q = g->fill; q < 4u; ++q) {
        g->b[q] = 0u;
        g->w[q] = 0.0;
    }
    sparse_four(acc, g->b, g->w);
    g->fill = 0u;
}

static void clear_half(mcs_spectrum *acc)
{
    const size_t h1 = acc->n / 2u + 1u;
    memset(acc->re, 0, h1 * sizeof acc->re[0]);
    memset(acc->im, 0, h1 * sizeof acc->im[0]);
}

static void clear_dense(mcs_spectrum *acc)
{
    memset(acc->s, 0, acc->n * sizeof acc->s[0]);
}

/* One Welford step for frequency q from its value x = xr + i xi. */
#define WELFORD_STEP(acc, q, xr, xi, inv)                                        \
    do {                                                                         \
        const double dr_ = (xr) - (acc)->mean_re[q], di_ = (xi) - (acc)->mean_im[q]; \
        const double mr_ = (acc)->mean_re[q] + dr_ * (inv);                      \
        const double mi_ = (acc)->mean_im[q] + di_ * (inv);                      \
        (acc)->mean_re[q] = mr_;                                                 \
        (acc)->mean_im[q] = mi_;                                                 \
        (acc)->m2_s[q] += dr_ * ((xr) - mr_) + di_ * ((xi) - mi_);               \
        const double p_ = (xr) * (xr) + (xi) * (xi);                             \
        const double dp_ = p_ - (acc)->mean_pow[q];                              \
        const double mp_ = (acc)->mean_pow[q] + dp_ * (inv);                     \
        (acc)->mean_pow[q] = mp_;                                                \
        (acc)->m2_pow[q] += dp_ * (p_ - mp_);                                    \
    } while (0)

/* Welford over the half spectrum in acc->re, acc->im, each scaled by
 * `scale` first (1/sqrt(N) for the sparse path, 1 for the FFT path): update
 * the mean first, then M2 with the old and new deviations, so no sum of
 * squares cancels. Two frequencies per step, written out, so the compiler can
 * pair them in one vector register at -O2; with an odd count the pad entry
 * (re = im = 0 always) is updated too and stays 0. */
static void welford_update(mcs_spectrum *acc, double scale)
{
    const size_t h1 = acc->n / 2u + 1u;
    acc->count += 1u;
    const double inv = 1.0 / (double)acc->count;
    for (size_t q = 0; q < h1; q += 2u) {
        const double xr0 = scale * acc->re[q], xr1 = scale * acc->re[q + 1u];
        const double xi0 = scale * acc->im[q], xi1 = scale * acc->im[q + 1u];
        WELFORD_STEP(acc, q, xr0, xi0, inv);
        WELFORD_STEP(acc, q + 1u, xr1, xi1, inv);
    }
}

/* The dense s of the current trial is in acc->s (validated, finite, >= 0). */
static void finish_fft(mcs_spectrum *acc)
{
    (void)mcs_dft_real_half(&acc->plan, acc->n, acc->s, acc->re, acc->im);
    welford_update(acc, 1.0);
}

static double sparse_scale(const mcs_spectrum *acc)
{
    return 1.0 / sqrt((double)acc->n); /* eq. 7's normalisation */
}

/* One trial of k samples: bins[j] or, when bins is NULL, the bin of
 * points[j]; weights[j], or 1 when weights is NULL. All checked. */
static void add_samples(mcs_spectrum *acc, size_t k, const size_t *bins, const double *points,
                        const double *weights)
{
    const size_t n = acc->n;
    if (use_sparse(acc, k)) {
        sparse_group g = {{0u}, {0.0}, 0u};
        clear_half(acc);
        for (size_t j = 0; j < k; ++j)
            group_push(acc, &g, bins != NULL ? bins[j] : mcs_point_bin_(points[j], n),
                       weights != NULL ? weights[j] : 1.0);
        group_flush(acc, &g);
        welford_update(acc, sparse_scale(acc));
    } else {
        clear_dense(acc);
        for (size_t j = 0; j < k; ++j)
            acc->s[bins != NULL ? bins[j] : mcs_point_bin_(points[j], n)] +=
                weights != NULL ? weights[j] : 1.0;
        finish_fft(acc);
    }
}

mcs_status mcs_spectrum_add_bins(mcs_spectrum *acc, size_t k, const size_t *bins,
                                 const double *weights)
{
    mcs_status st = bins == NULL || weights == NULL ? MCS_ERR_NULL : spectrum_check(acc);
    if (st == MCS_OK)
        st = mcs_check_sparse_(acc->n, k, bins, weights);
    if (st == MCS_OK)
        add_samples(acc, k, bins, NULL, weights);
    return st;
}

mcs_status mcs_spectrum_add_dense(mcs_spectrum *acc, size_t n, const double *s)
{
    mcs_status st = mcs_check_dense_(spectrum_check(acc), acc != NULL ? acc->n : 0u, n, s);
    if (st != MCS_OK)
        return st;
    memcpy(acc->s, s, n * sizeof s[0]);
    finish_fft(acc);
    return MCS_OK;
}

mcs_status mcs_spectrum_add_points(mcs_spectrum *acc, size_t k, const double *points,
                                   const double *weights)
{
    mcs_status st = points == NULL ? MCS_ERR_NULL : spectrum_check(acc);
    if (st == MCS_OK)
        st = k == 0u ? MCS_ERR_K_RANGE : mcs_check_points_(k, points, weights);
    if (st == MCS_OK)
        add_samples(acc, k, NULL, points, weights);
    return st;
}

mcs_status mcs_spectrum_merge(mcs_spectrum *dst, const mcs_spectrum *src)
{
    mcs_status st = src == NULL ? MCS_ERR_NULL : spectrum_check(dst);
    if (st == MCS_OK)
        st = spectrum_check(src);
    if (st == MCS_OK && dst->n != src->n)
        st = MCS_ERR_MISMATCH;
    if (st != MCS_OK || src->count == 0u)
        return st;
    const size_t h1 = dst->n / 2u + 1u;
    if (dst->count == 0u) {
        memcpy(dst->mean_re, src->mean_re, h1 * sizeof dst->mean_re[0]);
        memcpy(dst->mean_im, src->mean_im, h1 * sizeof dst->mean_im[0]);
        memcpy(dst->m2_s, src->m2_s, h1 * sizeof dst->m2_s[0]);
        memcpy(dst->mean_pow, src->mean_pow, h1 * sizeof dst->mean_pow[0]);
        memcpy(dst->m2_pow, src->m2_pow, h1 * sizeof dst->m2_pow[0]);
        dst->count = src->count;
        return MCS_OK;
    }
    /* Chan, Golub and LeVeque: shift the mean by the gap times nb/n and add
     * the gap's share na nb/n to M2. Read src before writing dst (dst may be src). */
    const double na = (double)dst->count, nb = (double)src->count, nt = na + nb;
    const double wb = nb / nt, wab = na * nb / nt;
    for (size_t k = 0; k < h1; ++k) {
        const double dr = src->mean_re[k] - dst->mean_re[k];
        const double di = src->mean_im[k] - dst->mean_im[k];
        const double dp = src->mean_pow[k] - dst->mean_pow[k];
        const double m2s = src->m2_s[k], m2p = src->m2_pow[k];
        dst->mean_re[k] += dr * wb;
        dst->mean_im[k] += di * wb;
        dst->m2_s[k] += m2s + (dr * dr + di * di) * wab;
        dst->mean_pow[k] += dp * wb;
        dst->m2_pow[k] += m2p + dp * dp * wab;
    }
    dst->count += src->count;
    return MCS_OK;
}

mcs_status mcs_spectrum_count(const mcs_spectrum *acc, uint64_t *count)
{
    mcs_status st = count == NULL ? MCS_ERR_NULL : spectrum_check(acc);
    if (st == MCS_OK)
        *count = acc->count;
    return st;
}

/* Common read-out checks: outputs given (else NULL), acc initialised, freq in
 * [0, N), at least min_count trials. */
static mcs_status readout(int outputs, const mcs_spectrum *acc, size_t freq, uint64_t min_count)
{
    mcs_status st = outputs ? spectrum_check(acc) : MCS_ERR_NULL;
    if (st == MCS_OK && freq >= acc->n)
        st = MCS_ERR_FREQ_RANGE;
    if (st == MCS_OK && acc->count < min_count)
        st = MCS_ERR_EMPTY;
    return st;
}

/* Where freq is stored: k or N - k (S_{N-k} = conj(S_k), s being real). */
static size_t stored(const mcs_spectrum *acc, size_t freq)
{
    return freq > acc->n / 2u ? acc->n - freq : freq;
}

/* Standard error of a mean over the trials from its Welford M2. */
static double stderr_of(const mcs_spectrum *acc, double m2)
{
    const double t = (double)acc->count;
    return sqrt(m2 / (t - 1.0) / t);
}

mcs_status mcs_spectrum_mean(const mcs_spectrum *acc, size_t freq, double *re, double *im)
{
    mcs_status st = readout(re != NULL && im != NULL, acc, freq, 1u);
    if (st != MCS_OK)
        return st;
    const size_t q = stored(acc, freq);
    *re = acc->mean_re[q];
    *im = q != freq ? -acc->mean_im[q] : acc->mean_im[q];
    return MCS_OK;
}

mcs_status mcs_spectrum_mean_stderr(const mcs_spectrum *acc, size_t freq, double *stderr_out)
{
    mcs_status st = readout(stderr_out != NULL, acc, freq, 2u);
    return st == MCS_OK ? mcs_set_(stderr_out, stderr_of(acc, acc->m2_s[stored(acc, freq)])) : st;
}

mcs_status mcs_spectrum_power(const mcs_spectrum *acc, size_t freq, double *power)
{
    mcs_status st = readout(power != NULL, acc, freq, 1u);
    return st == MCS_OK ? mcs_set_(power, acc->mean_pow[stored(acc, freq)]) : st;
}

mcs_status mcs_spectrum_power_stderr(const mcs_spectrum *acc, size_t freq, double *stderr_out)
{
    mcs_status st = readout(stderr_out != NULL, acc, freq, 2u);
    return st == MCS_OK ? mcs_set_(stderr_out, stderr_of(acc, acc->m2_pow[stored(acc, freq)])) : st;
}
