/* Private: how a pattern's bins look to the exact theory, shared by the
 * N x N moments (src/theory/theory.c) and the O(N)-memory read-outs at any N
 * (src/theory/theory_spectrum.c, which copies them into its object, and
 * src/theory/theory_cov.c), so both routes see the same bins to the last bit. */
#ifndef MCSPEC_THEORY_INTERNAL_H
#define MCSPEC_THEORY_INTERNAL_H

#include <math.h>
#include <stddef.h>

#include "core/internal.h"
#include "accumulators/readout.h"
#include "patterns/importance_internal.h"
#include "mcspec/importance.h"
#include "mcspec/pattern.h"
#include "mcspec/theory.h"

/* Bin b of the pattern is [edge(b), edge(b + 1)) in t = u K units (its CDF
 * interval with importance, [b/N, (b+1)/N) without); its length in u is the
 * probability one uniform u lands in it; 1/p_b its weight. */
static inline double mcs_theory_edge_(const mcs_pattern *pat, size_t b)
{
    double kd = (double)pat->k;
    if (pat->importance != NULL)
        return pat->importance->cdf[b] * kd;
    return ((double)b * kd) / (double)pat->n; /* exact product, one rounding */
}

/* The rounding of mcs_theory_edge_: edge + edge_lo is the exact edge K
 * cdf[b] (b K / N without importance) to about 2^-106 of it. With
 * importance the product's error is exact (fma); without, b K - edge N is
 * exact (a multiple of the edge's ulp, at most N/2 of them), then divided.
 * The overlaps of a small bin with a stratum, and jitter's pieces of beta,
 * are differences of nearby edges: taken with edge_lo they keep their
 * relative accuracy, where the rounded edges alone left them an absolute
 * error of K 2^-53 (4e-10 of a bin of g = 2.5e-7 at K = 19). */
static inline double mcs_theory_edge_lo_(const mcs_pattern *pat, size_t b)
{
    const double kd = (double)pat->k, e = mcs_theory_edge_(pat, b);
    if (pat->importance != NULL)
        return fma(pat->importance->cdf[b], kd, -e);
    const double nd = (double)pat->n;
    return fma(-e, nd, (double)b * kd) / nd;
}

static inline double mcs_theory_length_(const mcs_pattern *pat, size_t b)
{
    if (pat->importance != NULL)
        return pat->importance->cdf[b + 1u] - pat->importance->cdf[b];
    return 1.0 / (double)pat->n;
}

/* 0 outside the support (p_b = 0): no sample lands there, none weighs. */
static inline double mcs_theory_inv_p_(const mcs_pattern *pat, size_t b)
{
    if (pat->importance == NULL)
        return 1.0;
    const double p = pat->importance->p[b];
    return p > 0.0 ? 1.0 / p : 0.0;
}

/* Bin of the uniform pattern's u_j = (j + 1/2)/K, by the generator's own
 * arithmetic (src/patterns/pattern.c: stratum_point, then place), so a u_j on a bin
 * edge lands in the same bin. Without importance that is the exact
 * floor((2j + 1) N / (2K)); with importance it is the CDF search of the
 * correctly rounded u_j. */
static inline size_t mcs_theory_uniform_bin_(const mcs_pattern *pat, size_t j)
{
    if (pat->importance != NULL) {
        double u = ((double)j + 0.5) / (double)pat->k;
        if (!(u < 1.0))
            u = nextafter(1.0, 0.0);
        size_t bin = 0;
        (void)mcs_importance_warp(pat->importance, u, NULL, &bin);
        return bin;
    }
    size_t b = (size_t)(((double)j + 0.5) * (double)pat->n / (double)pat->k);
    return b < pat->n ? b : pat->n - 1u;
}

/* The uniform pattern's bin counts r[b], b < N, without a walk over the K
 * samples: the bin of u_j never decreases with j (a floor, or a CDF search,
 * of a rounded quotient that grows with j), so the number of samples below
 * bin b + 1 is the first j whose bin passes b, found by bisection on j with
 * mcs_theory_uniform_bin_ itself. O(N log K) (at most 31 steps per bin at
 * MCS_MAX_K), and the counts are those of the walk exactly. */
static inline void mcs_theory_uniform_counts_(const mcs_pattern *pat, double *r)
{
    size_t below = 0u; /* samples in bins before b */
    for (size_t b = 0; b < pat->n; ++b) {
        size_t lo = below, hi = pat->k;
        while (lo < hi) {
            const size_t mid = lo + (hi - lo) / 2u;
            if (mcs_theory_uniform_bin_(pat, mid) > b)
                hi = mid;
            else
                lo = mid + 1u;
        }
        r[b] = (double)(lo - below);
        below = lo;
    }
}

/* A pattern the theory can describe, with N up to cap: MCS_ERR_UNINIT
 * (n 0, k 0 or above MCS_MAX_K as mcs_pattern_init allows, unknown kind,
 * importance of another n or not initialised), MCS_ERR_N_RANGE (n > cap),
 * MCS_ERR_KIND (homogenized with importance). */
static inline mcs_status mcs_theory_check_pattern_(const mcs_pattern *pat, size_t cap)
{
    if (pat->n == 0u || pat->k == 0u || pat->k > (size_t)MCS_MAX_K ||
        !mcs_kind_is_valid_(pat->kind))
        return MCS_ERR_UNINIT;
    if (pat->n > cap)
        return MCS_ERR_N_RANGE;
    if (pat->importance != NULL) {
        if (pat->kind == MCS_PATTERN_HOMOGENIZED)
            return MCS_ERR_KIND;
        if (pat->importance->n != pat->n || !mcs_importance_is_valid_(pat->importance) ||
            !mcs_importance_sound_(pat->importance))
            return MCS_ERR_UNINIT;
    }
    return MCS_OK;
}

/* ---- exact zeros: values theory proves 0, read as 0 (not rounding) -------------
 *
 * The read-outs of both objects form their values as sums whose terms
 * cancel where the value is 0 by symmetry, leaving rounding (1e-17 to
 * 1e-32). These rules say where a value is 0 for every trial the pattern
 * can draw, whatever f (so whatever the rounding): there it reads 0.
 * - S_0 and S_{N/2} (N even) are real (their twiddles are +-1): the
 *   imaginary part of <S_k>, and of <S_k S_l*> and Cov(S_k, S_l) with both
 *   k and l such, is 0.
 * - Without importance sum_n s_n = K in every trial: S_0 = K / sqrt(N) is
 *   deterministic, Cov(S_0, S_l) = 0, and an f constant on the bins gives
 *   Var[I] = 0.
 * - Without importance <s_n> = K/N for every kind but uniform: <S_k> = 0 for
 *   k != 0.
 * - Random, homogenized and jitter without importance are stationary (a
 *   shift by one bin is a shift of the uniform draws: of beta by K/N for
 *   jitter): Cov(S_k, S_l) = 0 for k != l. Stratified without importance is
 *   unchanged by a shift of N/g bins, g = gcd(N, K) (it maps strata onto
 *   strata): Cov(S_k, S_l) = 0 unless g divides k - l (eq. 30 corrected,
 *   for K dividing N).
 * - Jitter without importance, and uniform whose s is periodic with period
 *   N/g (checked on its stored <s>: the generator's arithmetic decides its
 *   bins), g = gcd(N, K): s repeats every N/g bins in every trial, so
 *   S_k = 0 unless g divides k.
 * - Uniform, and stratified, homogenized and jitter without importance with
 *   N dividing K (every bin holds K/N samples in every trial): s is
 *   deterministic, every covariance and Var[I] is 0.
 * Anything else is left as computed, even when it is small: an f whose
 * values have no energy at the multiples of K gives jitter a Var[I] of
 * ~1e-32, not 0, because its stored values are rounded (that is the exact
 * variance of the doubles given). */
typedef struct {
    size_t n;       /* N */
    size_t g;       /* S_k = 0 in every trial unless g divides k (1: no such rule) */
    int no_imp;     /* no importance function: sum s = K, S_0 deterministic */
    int mean_const; /* <s_n> = K/N: <S_k> = 0 for k != 0 */
    size_t step;    /* Cov(S_k, S_l) = 0 unless step divides k - l (mod N); step divides N */
    int fixed;      /* s deterministic: every covariance 0 */
} mcs_theory_zeros;

static inline size_t mcs_theory_gcd_(size_t a, size_t b)
{
    while (b != 0u) {
        const size_t t = a % b;
        a = b;
        b = t;
    }
    return a;
}

/* kind, N, K, importance and the stored <s> (read for uniform) of an object. */
static inline mcs_theory_zeros mcs_theory_zeros_of_(mcs_pattern_kind kind, size_t n, size_t k,
                                                    int has_importance, const double *mean_s)
{
    mcs_theory_zeros z = {n, 1u, !has_importance, 0, 1u, 0};
    const size_t g = mcs_theory_gcd_(n, k);
    z.mean_const = z.no_imp && kind != MCS_PATTERN_UNIFORM;
    if (z.no_imp && (kind == MCS_PATTERN_RANDOM || kind == MCS_PATTERN_HOMOGENIZED ||
                     kind == MCS_PATTERN_JITTER))
        z.step = n;
    else if (z.no_imp && kind == MCS_PATTERN_STRATIFIED)
        z.step = g;
    z.fixed = kind == MCS_PATTERN_UNIFORM || (z.no_imp && kind != MCS_PATTERN_RANDOM && k % n == 0u);
    if (z.no_imp && kind == MCS_PATTERN_JITTER) {
        z.g = g;
    } else if (kind == MCS_PATTERN_UNIFORM && g > 1u) {
        int periodic = 1;
        for (size_t b = 0; b + n / g < n; ++b)
            periodic &= mean_s[b] == mean_s[b + n / g];
        z.g = periodic ? g : 1u;
    }
    return z;
}

/* S_q = 0 in every trial. */
static inline int mcs_theory_s_zero_(const mcs_theory_zeros *z, size_t q)
{
    return q % z->g != 0u || (q != 0u && z->fixed && z->mean_const);
}

static inline int mcs_theory_real_freq_(const mcs_theory_zeros *z, size_t q)
{
    return q == 0u || 2u * q == z->n;
}

/* <S_q> = 0. */
static inline int mcs_theory_mean_zero_(const mcs_theory_zeros *z, size_t q)
{
    return mcs_theory_s_zero_(z, q) || (q != 0u && z->mean_const);
}

/* Cov(S_k, S_l) = 0. */
static inline int mcs_theory_cov_zero_(const mcs_theory_zeros *z, size_t k, size_t l)
{
    return z->fixed || mcs_theory_s_zero_(z, k) || mcs_theory_s_zero_(z, l) ||
           (z->no_imp && (k == 0u || l == 0u)) || (k + z->n - l) % z->step != 0u;
}

/* <S_k S_l*> = Cov(S_k, S_l) + <S_k><S_l>* = 0. */
static inline int mcs_theory_cross_zero_(const mcs_theory_zeros *z, size_t k, size_t l)
{
    return mcs_theory_s_zero_(z, k) || mcs_theory_s_zero_(z, l) ||
           (mcs_theory_cov_zero_(z, k, l) &&
            (mcs_theory_mean_zero_(z, k) || mcs_theory_mean_zero_(z, l)));
}

/* The imaginary part of a second moment of S_k and S_l is 0. */
static inline int mcs_theory_im_zero_(const mcs_theory_zeros *z, size_t k, size_t l)
{
    return k == l || (mcs_theory_real_freq_(z, k) && mcs_theory_real_freq_(z, l));
}

/* f[n] the same value on every bin. */
static inline int mcs_theory_constant_(size_t n, const double *f)
{
    int same = 1;
    for (size_t b = 1; b < n; ++b)
        same &= f[b] == f[0];
    return same;
}

/* Cov(I_f, I_g) = 0 (g == f for Var[I]). */
static inline int mcs_theory_estimator_zero_(const mcs_theory_zeros *z, size_t n, const double *f,
                                             const double *g)
{
    return z->fixed || (z->no_imp && (mcs_theory_constant_(n, f) || mcs_theory_constant_(n, g)));
}

/* ---- the bias of the estimator ------------------------------------------------ */

/* <I> - (1/N) sum_n f_n, from the stored <s>: random, stratified, homogenized
 * and jitter have <s_n> = K/N on the importance function's support (p_n and
 * the sampled interval lengths agree) and 0 outside it (<s_n> = 0 there, and
 * only there), so the bias is -(1/N) sum over those bins of f_n, one sum and
 * no difference of nearby values; uniform's <s_n> are its weighted counts,
 * and its bias (1/(K N)) sum_n f_n (N <s_n> - K), each N <s_n> - K with one
 * rounding (exact without importance: integer counts). */
static inline double mcs_theory_bias_of_(mcs_pattern_kind kind, size_t n, size_t k,
                                         const double *mean_s, const double *f)
{
    const double kd = (double)k, nd = (double)n;
    double sum = 0.0;
    if (kind == MCS_PATTERN_UNIFORM) {
        for (size_t b = 0; b < n; ++b)
            sum += f[b] * fma(nd, mean_s[b], -kd);
        return sum / (kd * nd);
    }
    for (size_t b = 0; b < n; ++b)
        if (mean_s[b] == 0.0)
            sum += f[b];
    return 0.0 - sum / nd; /* +0, not -0, for no such bin */
}

/* ---- src/theory/theory.c: the rounding exact moments carry ------------------ */

/* The checks of an object mcs_theory_init wrote (theory.c), for its
 * read-outs (theory_readout.c): 1 when th is set up (N, K, kind); when the
 * first moments, every second moment, the diagonal <s_b^2> or entry (a, b)
 * keep the bounds init's bodies keep. */
int mcs_theory_valid_(const mcs_theory *th);
int mcs_theory_first_sound_(const mcs_theory *th);
int mcs_theory_second_sound_(const mcs_theory *th);
int mcs_theory_diagonal_sound_(const mcs_theory *th, size_t b);
int mcs_theory_entry_sound_(const mcs_theory *th, size_t a, size_t b);

/* What mcs_theory_init's rounding can add to a form sum_{m,n} x_m x_n
 * <s_m s_n> (or to the same form of <s_m><s_n>), |x_b| <= |x[b]| + c (x
 * NULL: 1 + c): 64 DBL_EPSILON ((sum w_b <s_b>)^2 + K (sum w_b u_b)^2), u_b
 * the largest 1/p_b the moments of bin b allow. The edges in t = u K units
 * are rounded to K 2^-53, so an entry errs by up to about 16 DBL_EPSILON K
 * / (p_m p_n) besides its relative rounding: far more than the read-out's
 * own rounding when a bin is small (an importance weight near 2^-32). */
double mcs_theory_init_rounding_(const mcs_theory *th, const double *x, double c);

/* The tolerance of Var[I] = (1/K^2) f^T Cov(s) f read from th (view opened
 * on it): the read-out's rounding bound (mcs_readout_form_bound) plus init's
 * (above); a variance below minus it comes from no object init writes. */
double mcs_theory_form_tolerance_(const mcs_theory *th, const mcs_readout *view,
                                  const double *f);

/* ---- src/theory/theory_cov.c: covariances of linear functionals of s ----------- */

/* A complex weight per bin: w_b = f_i, or scale e^{-2 pi i freq i/N}, at
 * i = (b + shift) mod N, so that X = sum_b w_b s_b is K I (f given) or S_freq
 * (f NULL, scale 1/sqrt N), and shift moves the weights as the homogenizing
 * shift moves the samples. */
typedef struct {
    const double *f;     /* real weights f[N], or NULL for the twiddle */
    size_t freq;         /* frequency of the twiddle, < N */
    double scale;        /* factor of the twiddle */
    size_t shift;        /* < N */
} mcs_theory_weight;

/* E[(X - <X>)(Y - <Y>)*] for X, Y of weights x, y over one trial of the
 * pattern of ts, into *re, *im; x == y (the same pointer) for a variance.
 * Formed per kind over what is independent in the pattern as weighted sums
 * of (x - mean)(y - mean)* (two passes, or a weighted Welford update over the
 * jitter pieces), so a variance is a sum of non-negative terms and no mean
 * is subtracted after squaring:
 * random O(N), stratified O(N), jitter O(N) (its breakpoints are sorted at
 * init), homogenized O(N^2), uniform 0. */
void mcs_theory_cov_(const mcs_theory_spectrum *ts, const mcs_theory_weight *x,
                     const mcs_theory_weight *y, double *re, double *im);

/* The same for the stratified pattern of ts's bins (the homogenized pattern
 * before its shift). */
void mcs_theory_strat_cov_(const mcs_theory_spectrum *ts, const mcs_theory_weight *x,
                           const mcs_theory_weight *y, double *re, double *im);

/* Sorts the jitter breakpoints of ts (bins 1..N-1 by the fractional part of
 * edge[b]) into ts->order. O(N log N), in place. */
void mcs_theory_sort_breakpoints_(mcs_theory_spectrum *ts);

#endif /* MCSPEC_THEORY_INTERNAL_H */
