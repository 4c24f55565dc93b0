/* The kernels of the spectrum accumulator's three paths (spectrum.h): the
 * block-phase sparse DFT fused with the update, the FFT path, the pair
 * histogram and the batch close, and the weighted Welford update they share.
 *
 * The vectorisable ones (spectrum_simd.h) are compiled twice (simd.h): for
 * the baseline ISA and, on x86-64 with GCC or Clang, for AVX2, which doubles
 * their vector width. mcs_spectrum_init picks the AVX2 copy when the CPU
 * and the OS support it (as its plan found); both copies compute the same
 * bits. */
#include <math.h>
#include <string.h>

#include "dft/dft_internal.h"
#include "spectrum_internal.h"

#define BLOCK MCS_SPECTRUM_BLOCK
#define CHUNK MCS_SPECTRUM_CHUNK

#include "core/simd.h"

/* A unit of weight w joining closed units of total weight w_old moves each
 * mean by f d and adds g |d|^2 to its M2, d = x - old mean, with
 * f = w / (w_old + w) and g = w w_old / (w_old + w) (West 1979; for w = 1
 * this is Welford's step, M2 += d (x - new mean)). g |d|^2 >= 0: M2 never
 * decreases, so no variance can come out negative. */
typedef struct {
    double f, g;
} unit_factors;

static unit_factors factors(double w, double w_old)
{
    const double total = w_old + w;
    unit_factors u = {w / total, w * w_old / total};
    return u;
}

#define MCS_SIMD_BODY "accumulators/spectrum_simd.h"
#include "core/simd_clones.h"

#if MCS_AVX2_CLONES
/* Lanes of a fixed count of four, which the compiler vectorises for AVX2
 * (64-bit compares; 42 against 123 ns at K = 256). The baseline ISA has no
 * 64-bit compare: there the scalar scan (mcs_bins_scan_, acc_internal.h) is
 * the faster one.
 * Lane i keeps an all-ones mask while its bins are below N and its weights
 * >= 0 (NaN fails that, as the sum would), which needs no conversion to 0
 * or 1 (2.4 instead of 3.5 instructions a sample), and sums w[j + i] in
 * index order: the four sums are those of the scalar scan. */
static MCS_ALWAYS_INLINE void scan_group(size_t n, const size_t *restrict b,
                                         const double *restrict w, uint64_t *restrict ok,
                                         double *restrict s)
{
    for (size_t i = 0; i < 4u; ++i) {
        ok[i] &= (uint64_t)0 - (uint64_t)((b[i] < n) & (w[i] >= 0.0));
        s[i] += w[i];
    }
}

MCS_AVX2_BEGIN
int mcs_spectrum_bins_ok_avx2_(size_t n, size_t k, const size_t *restrict b,
                               const double *restrict w, double *sum)
{
    uint64_t ok[4] = {UINT64_MAX, UINT64_MAX, UINT64_MAX, UINT64_MAX};
    double s[4] = {0.0, 0.0, 0.0, 0.0};
    size_t j = 0;
    for (; j + 4u <= k; j += 4u)
        scan_group(n, b + j, w + j, ok, s);
    for (; j < k; ++j) {
        ok[0] &= (uint64_t)0 - (uint64_t)((b[j] < n) & (w[j] >= 0.0));
        s[0] += w[j];
    }
    *sum = (s[0] + s[1]) + (s[2] + s[3]);
    return (ok[0] & ok[1] & ok[2] & ok[3]) == UINT64_MAX;
}
MCS_AVX2_END
#endif

/* The update of every stored frequency from acc->re, acc->im (and the power
 * xp, or |S_k|^2 without it), by the object's kernels. */
static void update_all(mcs_spectrum *acc, const double *xp, unit_factors u)
{
    const size_t blocks = mcs_spectrum_blocks_(acc->n);
#if MCS_AVX2_CLONES
    if (acc->simd) {
        update_range_avx2(acc, 0u, blocks, xp, u);
        return;
    }
#endif
    update_range_generic(acc, 0u, blocks, xp, u);
}

/* Zeroes the pad entries k > N/2 of x, so the pad statistics stay 0. */
static void clear_pad(size_t n, double *x)
{
    for (size_t q = n / 2u + 1u; q < mcs_spectrum_blocks_(n) * BLOCK; ++q)
        x[q] = 0.0;
}

/* One per-trial unit (weight 1) from the half spectrum in acc->re, acc->im. */
static void update_trial(mcs_spectrum *acc)
{
    clear_pad(acc->n, acc->re);
    clear_pad(acc->n, acc->im);
    update_all(acc, NULL, factors(1.0, (double)mcs_spectrum_closed_(acc)));
    acc->count += 1u;
    acc->units += 1u;
}

#if defined(MCS_DFT_FFTW) /* the FFTW back end (make FFT=fftw) only */
/* One per-trial unit from acc->s by the FFTW back end: its interleaved
 * output goes straight into the update, which scales it (no split of S_k
 * into acc->re, acc->im and no second pass over them: the fixed cost that
 * decides small N). The same bits as mcs_dft_half_ then update_trial. */
static void update_fftw(mcs_spectrum *acc)
{
    /* frequencies 0..N/2 in whole groups, inside the stored ones */
    const size_t count = (acc->n / 2u + MCS_UPDATE_GROUP_) / MCS_UPDATE_GROUP_ * MCS_UPDATE_GROUP_;
    _Static_assert(MCS_UPDATE_GROUP_ <= MCS_DFT_FFTW_PAD + 1u, "a group's pad fits FFTW's window");
    _Static_assert(BLOCK % MCS_UPDATE_GROUP_ == 0, "groups tile the stored frequencies");
    const double *o = mcs_dft_fftw_out_(&acc->plan, acc->s, count);
    const double scale = 1.0 / sqrt((double)acc->n); /* eq. 7, as mcs_dft_half_ */
    const unit_factors u = factors(1.0, (double)mcs_spectrum_closed_(acc));
#if MCS_AVX2_CLONES
    if (acc->simd)
        update_interleaved_avx2(acc, count, o, scale, u);
    else
#endif
        update_interleaved_generic(acc, count, o, scale, u);
    acc->count += 1u;
    acc->units += 1u;
}
#endif

/* ---------------------------------------------------------------- SPARSE */

void mcs_spectrum_sparse_(mcs_spectrum *acc, const mcs_spectrum_trial_ *t)
{
    const unit_factors u = factors(1.0, (double)mcs_spectrum_closed_(acc));
#if MCS_AVX2_CLONES
    if (acc->simd)
        sparse_trial_avx2(acc, t, u);
    else
#endif
        sparse_trial_generic(acc, t, u);
    acc->count += 1u;
    acc->units += 1u;
}

/* ---------------------------------------------------------- POINT BINS */

/* floor(N x_j) of the points [j0, j1) of t into out[j1 - j0], x_j read as
 * float or double by the constant is_float (widened exactly): each caller's
 * copy of the loop is branch-free. */
static MCS_ALWAYS_INLINE void bin_points_as(const mcs_spectrum_trial_ *t, size_t n, size_t j0,
                                            size_t j1, size_t *restrict out, int is_float)
{
    for (size_t j = j0; j < j1; ++j)
        out[j - j0] = mcs_point_bin_(is_float ? (double)t->points.f[j] : t->points.d[j], n);
}

static void bin_points(const mcs_spectrum_trial_ *t, size_t n, size_t j0, size_t j1,
                       size_t *restrict out)
{
    if (t->points.f != NULL)
        bin_points_as(t, n, j0, j1, out, 1);
    else
        bin_points_as(t, n, j0, j1, out, 0);
}

/* ------------------------------------------------------------------- FFT */

/* s_n += w_j at the bins of t's points (clear: s_n = 0 there again), x_j
 * read as float or double by the constant is_float. */
static MCS_ALWAYS_INLINE void scatter_points_as(mcs_spectrum *acc, const mcs_spectrum_trial_ *t,
                                                int clear, int is_float)
{
    const size_t n = acc->n, k = t->k;
    const double *restrict xd = t->points.d, *restrict w = t->weights;
    const float *restrict xf = t->points.f;
    double *restrict s = acc->s;
    for (size_t j = 0; j < k; ++j) {
        const size_t b = mcs_point_bin_(is_float ? (double)xf[j] : xd[j], n);
        s[b] = clear ? 0.0 : s[b] + (w != NULL ? w[j] : 1.0);
    }
}

static void scatter_points(mcs_spectrum *acc, const mcs_spectrum_trial_ *t, int clear)
{
    if (t->points.f != NULL && clear)
        scatter_points_as(acc, t, 1, 1);
    else if (t->points.f != NULL)
        scatter_points_as(acc, t, 0, 1);
    else if (clear)
        scatter_points_as(acc, t, 1, 0);
    else
        scatter_points_as(acc, t, 0, 0);
}

/* s_n += w_j over the trial's (bin, weight) pairs, in index order. A run of
 * samples in one bin (a stratified trial with K > N puts K/N in a row) is
 * summed in a register and stored once: the same additions in the same
 * order as s[b] += w_j each, without each add waiting for the store before
 * it (store-to-load forwarding, ~5 cycles a sample). A loop per run keeps
 * the run's bin in a register: 7 instead of 11 instructions a sample
 * (stratified, N = 64, K = 256). */
static void scatter_bins(double *restrict s, size_t k, const size_t *restrict bins,
                         const double *restrict w)
{
    size_t j = 0;
    while (j < k) { /* one run per pass: its bin read and stored once */
        const size_t b = bins[j];
        double sum = s[b] + w[j];
        for (++j; j < k && bins[j] == b; ++j)
            sum += w[j];
        s[b] = sum;
    }
}

/* s_n += w_j over the trial's (bin, weight) pairs in index order, where a
 * bin seldom comes twice in a row (no test for it). Four samples a pass, in
 * order (a repeated bin reads the store before it), with s in a register:
 * 5 instead of 8 instructions a sample. */
static void scatter_apart(double *restrict s, size_t k, const size_t *restrict bins,
                          const double *restrict w)
{
    size_t j = 0;
    for (; j + 4u <= k; j += 4u) {
        s[bins[j]] += w[j];
        s[bins[j + 1u]] += w[j + 1u];
        s[bins[j + 2u]] += w[j + 2u];
        s[bins[j + 3u]] += w[j + 3u];
    }
    for (; j < k; ++j)
        s[bins[j]] += w[j];
}

void mcs_spectrum_fft_(mcs_spectrum *acc, const mcs_spectrum_trial_ *t)
{
    if (t->bins != NULL && t->k > acc->n) /* weights given with bins, in runs */
        scatter_bins(acc->s, t->k, t->bins, t->weights);
    else if (t->bins != NULL)
        scatter_apart(acc->s, t->k, t->bins, t->weights);
    else
        scatter_points(acc, t, 0);
#if defined(MCS_DFT_FFTW)
    if (acc->plan.path == MCS_DFT_PATH_FFTW)
        update_fftw(acc);
    else
#endif
    {
        mcs_dft_half_(&acc->plan, acc->s, acc->re, acc->im);
        update_trial(acc);
    }
    /* s is 0 again: the touched bins only, or all of it when that is fewer
     * stores */
    if (t->k >= acc->n / 4u)
        memset(acc->s, 0, acc->n * sizeof acc->s[0]);
    else if (t->bins != NULL)
        for (size_t j = 0; j < t->k; ++j)
            acc->s[t->bins[j]] = 0.0;
    else
        scatter_points(acc, t, 1);
}

void mcs_spectrum_dense_(mcs_spectrum *acc, const double *s)
{
    mcs_dft_half_(&acc->plan, s, acc->re, acc->im);
    update_trial(acc);
}

/* ------------------------------------------------------------------ PAIR */

/* Adds w_j w_q for the pair (j, q), j < q, at open_pairs[N + n_q - n_j]:
 * the signed difference, offset so that no index wraps. hj = open_pairs + N
 * - n_j, so the add is hj[n_q]. */
#define MCS_PAIR_(hj, wj, bq, wq) ((hj)[bq] += (wj) * (wq))

/* Every pair of a trial given as arrays. Four rows share each column's
 * loads, which halves the memory traffic per pair; the triangle inside a
 * group of four is written out. */
static void pair_arrays(mcs_spectrum *acc, size_t k, const size_t *restrict b,
                        const double *restrict w)
{
    const size_t n = acc->n;
    double *restrict hist = acc->open_pairs;
    size_t j = 0;
    for (; j + 4u <= k; j += 4u) {
        const size_t b1 = b[j + 1u], b2 = b[j + 2u], b3 = b[j + 3u];
        const double w0 = w[j], w1 = w[j + 1u], w2 = w[j + 2u], w3 = w[j + 3u];
        double *h0 = hist + n - b[j], *h1 = hist + n - b1, *h2 = hist + n - b2, *h3 = hist + n - b3;
        MCS_PAIR_(h0, w0, b1, w1);
        MCS_PAIR_(h0, w0, b2, w2);
        MCS_PAIR_(h0, w0, b3, w3);
        MCS_PAIR_(h1, w1, b2, w2);
        MCS_PAIR_(h1, w1, b3, w3);
        MCS_PAIR_(h2, w2, b3, w3);
        for (size_t q = j + 4u; q < k; ++q) {
            const size_t bq = b[q];
            const double wq = w[q];
            MCS_PAIR_(h0, w0, bq, wq);
            MCS_PAIR_(h1, w1, bq, wq);
            MCS_PAIR_(h2, w2, bq, wq);
            MCS_PAIR_(h3, w3, bq, wq);
        }
    }
    for (; j + 1u < k; ++j) {
        double *hj = hist + n - b[j];
        for (size_t q = j + 1u; q < k; ++q)
            MCS_PAIR_(hj, w[j], b[q], w[q]);
    }
}

/* Pairs (j, q), j < q, for the columns q in [c0, c1), whose bins and
 * weights are cb[q - c0], cw[q - c0] (binned points); the rows j < c0 come
 * from t, four at a time as in pair_arrays, the rows in the chunk from cb, cw. */
static void pair_columns(mcs_spectrum *acc, const mcs_spectrum_trial_ *t, size_t c0, size_t c1,
                         const size_t *restrict cb, const double *restrict cw)
{
    const size_t n = acc->n;
    double *restrict hist = acc->open_pairs;
    size_t j = 0;
    for (; j + 4u <= c0; j += 4u) { /* rows before the chunk: every column is later */
        double *h[4];
        double wr[4];
        for (size_t r = 0; r < 4u; ++r) {
            h[r] = hist + n - mcs_spectrum_trial_bin_(t, n, j + r);
            wr[r] = mcs_spectrum_trial_weight_(t, j + r);
        }
        for (size_t q = 0; q < c1 - c0; ++q) {
            MCS_PAIR_(h[0], wr[0], cb[q], cw[q]);
            MCS_PAIR_(h[1], wr[1], cb[q], cw[q]);
            MCS_PAIR_(h[2], wr[2], cb[q], cw[q]);
            MCS_PAIR_(h[3], wr[3], cb[q], cw[q]);
        }
    }
    /* c0 is a whole number of chunks (of a multiple of 4), so j = c0 here:
     * the rows left are the chunk's own, binned already. */
    _Static_assert(CHUNK % 4 == 0, "the rows before a chunk come in fours");
    for (; j + 1u < c1; ++j) {
        double *hj = hist + n - cb[j - c0];
        const double wj = cw[j - c0];
        for (size_t q = j + 1u; q < c1; ++q)
            MCS_PAIR_(hj, wj, cb[q - c0], cw[q - c0]);
    }
}

/* Each sample once: s_n into the open sums, and half of w^2 at lag 0
 * (open_pairs[N]), so that h(0) + h(-0) counts w^2 once. Two partial sums
 * keep the adds from waiting on each other. */
static void pair_singles(mcs_spectrum *acc, size_t count, const size_t *b, const double *w)
{
    double self0 = 0.0, self1 = 0.0;
    size_t j = 0;
    for (; j + 2u <= count; j += 2u) {
        acc->open_sum[b[j]] += w[j];
        acc->open_sum[b[j + 1u]] += w[j + 1u];
        self0 += w[j] * w[j];
        self1 += w[j + 1u] * w[j + 1u];
    }
    if (j < count) {
        acc->open_sum[b[j]] += w[j];
        self0 += w[j] * w[j];
    }
    acc->open_pairs[acc->n] += 0.5 * (self0 + self1);
}

void mcs_spectrum_pairs_(mcs_spectrum *acc, const mcs_spectrum_trial_ *t)
{
    if (t->bins != NULL) { /* bins and weights as given */
        pair_singles(acc, t->k, t->bins, t->weights);
        pair_arrays(acc, t->k, t->bins, t->weights);
    } else { /* bin the points chunk by chunk into the column scratch */
        for (size_t c0 = 0; c0 < t->k; c0 += CHUNK) {
            const size_t c1 = t->k - c0 > CHUNK ? c0 + CHUNK : t->k;
            bin_points(t, acc->n, c0, c1, acc->chunk_bins);
            for (size_t q = c0; q < c1; ++q)
                acc->chunk_weights[q - c0] = mcs_spectrum_trial_weight_(t, q);
            pair_singles(acc, c1 - c0, acc->chunk_bins, acc->chunk_weights);
            pair_columns(acc, t, c0, c1, acc->chunk_bins, acc->chunk_weights);
        }
    }
    acc->count += 1u;
    acc->open_count += 1u;
    acc->open_work += mcs_spectrum_pair_count_(t->k);
}

/* Closes the open batch of B trials. Folding the two halves of open_pairs
 * gives h(d), d in [0, N); the batch's sum of |S_k|^2 is
 * (1/N) sum_d (h(d) + h(-d)) e^{-2 pi i k d/N} = 2 N^{-1/2} Re DFT(h)_k
 * (Wiener-Khinchin with eq. 7), and its sum of S_k is DFT(open_sum)_k. */
void mcs_spectrum_close_(mcs_spectrum *acc)
{
    const size_t n = acc->n, hpad = mcs_spectrum_blocks_(n) * BLOCK;
    const double b = (double)acc->open_count;
    double *hist = acc->open_pairs;
    for (size_t d = 0; d < n; ++d)
        hist[d] += hist[n + d];
    /* Lags d and N - d have the same cosine: fold them onto d < N/2, which
     * halves the non-zero entries the direct sum (prime factors above 5)
     * goes through, and changes nothing else. */
    for (size_t d = 1; 2u * d < n; ++d) {
        hist[d] += hist[n - d];
        hist[n - d] = 0.0;
    }
    mcs_dft_half_(&acc->plan, hist, acc->pw, NULL);
    mcs_dft_half_(&acc->plan, acc->open_sum, acc->re, acc->im);
    /* Means over the batch. A mean of |S_k|^2 is >= 0; where it is 0 the
     * cosine sum may round to -1e-17, so it is clamped (a change within
     * rounding). */
    const double pscale = 2.0 / (sqrt((double)n) * b);
    for (size_t q = 0; q <= n / 2u; ++q) {
        acc->pw[q] = fmax(0.0, pscale * acc->pw[q]);
        acc->re[q] /= b;
        acc->im[q] /= b;
    }
    for (size_t q = n / 2u + 1u; q < hpad; ++q)
        acc->pw[q] = acc->re[q] = acc->im[q] = 0.0;
    update_all(acc, acc->pw, factors(b, (double)mcs_spectrum_closed_(acc)));
    memset(acc->open_pairs, 0, 2u * n * sizeof acc->open_pairs[0]);
    memset(acc->open_sum, 0, n * sizeof acc->open_sum[0]);
    acc->units += 1u;
    acc->open_count = 0u;
    acc->open_work = 0.0;
}

/* The same two sums for one frequency q straight from the open sums, with
 * exact twiddle indices (q d mod N). h(d) is the sum of the two halves of
 * open_pairs (entry i < N stands for d = i - N, which is d = i mod N). */
void mcs_spectrum_open_values_(const mcs_spectrum *acc, size_t q, double *re, double *im,
                               double *power)
{
    const size_t n = acc->n;
    const double *ct = acc->plan.cos_table, *st = acc->plan.sin_table;
    const double b = (double)acc->open_count;
    double sr = 0.0, si = 0.0, p = 0.0;
    size_t i = 0u;
    for (size_t d = 0; d < n; ++d) {
        sr += acc->open_sum[d] * ct[i];
        si -= acc->open_sum[d] * st[i];
        p += (acc->open_pairs[d] + acc->open_pairs[n + d]) * ct[i];
        i += q;
        i = i >= n ? i - n : i;
    }
    const double scale = 1.0 / sqrt((double)n);
    *re = scale * sr / b;
    *im = (q == 0u || 2u * q == n) ? 0.0 : scale * si / b;
    *power = fmax(0.0, 2.0 * p / ((double)n * b)); /* >= 0, as in mcs_spectrum_close_ */
}
