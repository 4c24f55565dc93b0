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

static inline double mcs_theory_length_(const mcs_pattern *pat, size_t b)
{
    if (pat->importance != NULL)
        return pat->importance->cdf[b + 1u] - pat->importance->cdf[b];
    return 1.0 / (double)pat->n;
}

static inline double mcs_theory_inv_p_(const mcs_pattern *pat, size_t b)
{
    return pat->importance != NULL ? 1.0 / pat->importance->p[b] : 1.0;
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
        if (pat->importance->n != pat->n || !mcs_importance_is_valid_(pat->importance))
            return MCS_ERR_UNINIT;
    }
    return MCS_OK;
}

/* ---- src/theory/theory.c: the rounding exact moments carry ------------------ */

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
