/* Every closed form of the note, by equation number: mcs_eq<number>_...
 *
 * Each returns MCS_ERR_DOMAIN when asked outside the domain where the note
 * defines it (K not dividing N for the stratified and uniform forms, a
 * frequency the formula excludes, an importance formula given no importance
 * function). Where the note's printed form is wrong, both the printed and the
 * corrected form exist, named _printed and _corrected, so the example
 * programs can show the difference from measurements. The exact moments the
 * forms are checked against are in theory.h.
 *
 * Conventions: n = N bins, k = K samples per trial, freq a frequency index in
 * [0, n); S_k = N^{-1/2} sum_n e^{-2 pi i k n / N} s_n (eq. 7); F is the same
 * transform of f; Q is the same transform of 1/p_n (eq. 43, mcs_importance_q).
 * Every function validates all inputs before writing anything: on error every
 * output is byte-for-byte unchanged. A complex result (re, im) is written
 * last, after every input is read, so re and im may be any two doubles; the
 * same double for both is MCS_ERR_ALIAS (it cannot hold both parts), checked
 * after every other status. Nothing allocates, and no work arrays
 * live on the stack: transforms are taken one coefficient at a time (with
 * trig per term), at the costs noted per function.
 *
 * Magnitudes: an integrand f (and g) takes |f_n| <= MCS_ESTIMATE_MAX_ABS
 * (estimate.h: 2^110, the largest term the estimator takes), a larger finite
 * value is MCS_ERR_MAGNITUDE (after MCS_ERR_NOT_FINITE for NaN or infinity
 * anywhere in it). Within it no square, product or sum inside a form can
 * overflow (they stay below 2^400 with importance weights 1/p_n < 2^32 and
 * K up to MCS_MAX_K), so every result with MCS_OK is finite. */
#ifndef MCSPEC_EQ_H
#define MCSPEC_EQ_H

#include <stddef.h>
#include "config.h"
#include "status.h"
#include "estimate.h"
#include "importance.h"
#include "moment.h"
#include "theory.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- Section 1: gradient variance -------------------------------------- */
/* th: exact moments of the pattern, n == th->n and k == th->k as for
 * mcs_theory_variance, whose statuses these share: MCS_ERR_NULL,
 * MCS_ERR_UNINIT, MCS_ERR_INVARIANT (a *th init never writes, theory.h),
 * MCS_ERR_MISMATCH, MCS_ERR_K_RANGE, MCS_ERR_NOT_FINITE; then
 * MCS_ERR_MAGNITUDE (|f_n| or |g_n| above MCS_ESTIMATE_MAX_ABS), and last
 * MCS_ERR_INVARIANT for a variance below minus its tolerance (each of
 * Var[I_f], Var[I_g] and, for eq. 4, Var[I_f - I_g]; mcs_theory_variance):
 * a variance in [-tolerance, 0) reads 0. */

/* Eq. 2, uncorrelated sampling: the exact Var[I_f] + Var[I_g] when f and g
 * are each estimated from their own independent trial (the covariance is 0).
 * f[n], g[n], each |value| <= MCS_ESTIMATE_MAX_ABS. */
mcs_status mcs_eq2_uncorrelated_variance(const mcs_theory *th, size_t n, size_t k,
                                         const double *f, const double *g, double *out);

/* Eq. 4 (and eq. 6), correlated sampling: the exact Var[I_h] of h = f - g
 * estimated from ONE shared trial; equals Var[f] + Var[g] - 2 Cov[f,g].
 * f[n], g[n], each |value| <= MCS_ESTIMATE_MAX_ABS (so f - g cannot
 * overflow). */
mcs_status mcs_eq4_correlated_variance(const mcs_theory *th, size_t n, size_t k,
                                       const double *f, const double *g, double *out);

/* ---- Section 2: discrete Fourier analysis ------------------------------- */

/* Eq. 11: <I> = (1/N) sum_n f_n, the unbiased mean. f[n], n <= MCS_MAX_N,
 * |f_n| <= MCS_ESTIMATE_MAX_ABS. MCS_ERR_NULL, MCS_ERR_N_RANGE,
 * MCS_ERR_NOT_FINITE, MCS_ERR_MAGNITUDE. */
mcs_status mcs_eq11_unbiased_mean(size_t n, const double *f, double *out);

/* Eq. 13: (1/K^2) sum_{m,n >= 1} F_m* F_n <S_m S_n*>, the full double sum
 * from the exact moments of th (second moments, not covariances, and no
 * k = 0 terms, as printed; it is the variance when <S_{k>0}> = 0 and S_0 is
 * deterministic, i.e. unbiased kinds without importance). O(N^4), about
 * 17 M multiply-adds (tens of ms) at N = 64. f[n], |f_n| <=
 * MCS_ESTIMATE_MAX_ABS; statuses as section 1. It is (1/K^2)
 * <(sum_n (f_n - fbar) s_n)^2>, never negative: a sum in [-b, 0) reads 0,
 * b = (N^2 + 4N + 16) DBL_EPSILON (sum |f_n|)^2 (sum |<s_m s_n>|) / K^2
 * plus init's rounding (as mcs_theory_variance, of |f_n| + |fbar|); one
 * below -b is MCS_ERR_INVARIANT. */
mcs_status mcs_eq13_variance(const mcs_theory *th, size_t n, size_t k, const double *f,
                             double *out);

/* Largest |power[b]| mcs_eq14_variance takes: MCS_MOMENT_MAX_TRIAL squared,
 * 2^440, the most |S_k|^2 (<= (sum_n s_n)^2 / N) of any trial an accumulator
 * takes. With |F_k|^2 <= sum_n f_n^2 < 2^232 the sum stays below 2^672. */
#define MCS_EQ_MAX_POWER (MCS_MOMENT_MAX_TRIAL * MCS_MOMENT_MAX_TRIAL)

/* Eq. 14: (1/K^2) sum_{n >= 1} |F_n|^2 power[n], the diagonal (stationary)
 * approximation, for any power spectrum the caller holds: measured, from
 * mcs_theory_power, or a closed form below. f[n] (|f_n| <=
 * MCS_ESTIMATE_MAX_ABS), power[n] (power[0] unused, the others within
 * +-MCS_EQ_MAX_POWER), n <= MCS_MAX_N (direct DFT of f, O(N^2) trig: about
 * 0.3 s at 4096). MCS_ERR_NULL, MCS_ERR_N_RANGE, MCS_ERR_K_RANGE (k = 0),
 * MCS_ERR_NOT_FINITE, MCS_ERR_MAGNITUDE (f or power beyond its bound). */
mcs_status mcs_eq14_variance(size_t n, size_t k, const double *f, const double *power,
                             double *out);

/* ---- Section 3: random, stratified, uniform, jitter --------------------- */
/* Shared statuses: MCS_ERR_NULL, MCS_ERR_N_RANGE (n = 0 or > MCS_MAX_N),
 * MCS_ERR_K_RANGE (k = 0), MCS_ERR_FREQ_RANGE
 * (freq >= n), MCS_ERR_DOMAIN as stated per function, MCS_ERR_NOT_FINITE (f),
 * MCS_ERR_MAGNITUDE (|f_n| above MCS_ESTIMATE_MAX_ABS), MCS_ERR_ALIAS
 * (re == im, where the result is complex). */

/* Eq. 23: random power spectrum <|S_freq|^2> = K/N, freq in [1, N) (exact at
 * finite N). freq 0: MCS_ERR_DOMAIN. */
mcs_status mcs_eq23_random_power(size_t n, size_t k, size_t freq, double *out);

/* Eq. 24: random Var[I] = (1/K)(1/N) sum_{n >= 1} |F_n|^2. f[n] (|f_n| <=
 * MCS_ESTIMATE_MAX_ABS), n <= MCS_MAX_N:
 * the sum term by term up to MCS_MAX_COV_N, above it its Parseval equal
 * sum_n (f_n - fbar)^2 (O(N)). */
mcs_status mcs_eq24_random_variance(size_t n, size_t k, const double *f, double *out);

/* Eq. 25: random Var[I] = (1/K) (1/N) sum_n (f_n - fbar)^2, the population
 * variance of f over K. f[n] (|f_n| <= MCS_ESTIMATE_MAX_ABS), n <= MCS_MAX_N. */
mcs_status mcs_eq25_random_variance(size_t n, size_t k, const double *f, double *out);

/* Eq. 30 as printed: the stratified correction
 * Delta_kl = -(K/N)^3 [(1 - e^{-2 pi i k/K}) / (1 - e^{-2 pi i k/N})]
 *                     [(1 - e^{+2 pi i l/K}) / (1 - e^{+2 pi i l/N})],
 * K dividing N, freq_k and freq_l in [1, N) (the ratios are 0/0 at 0):
 * otherwise MCS_ERR_DOMAIN. The printed form misses the phase sum over the
 * K strata, sum_q e^{-2 pi i (k - l) q / K}, which is K only when
 * k = l (mod K) and 0 otherwise: see the _corrected form. */
mcs_status mcs_eq30_stratified_delta_printed(size_t n, size_t k, size_t freq_k, size_t freq_l,
                                             double *re, double *im);

/* Eq. 30 corrected: Delta_kl times [k = l (mod K)], for every k, l in [0, N)
 * (the geometric sums are taken directly, so k or l = 0 is fine). With it
 * the exact stratified cross spectrum (K dividing N, no importance) is
 * <S_k S_l*> = (K/N) delta_kl + (K^2/N) delta_k0 delta_l0 + Delta_kl.
 * K not dividing N: MCS_ERR_DOMAIN. */
mcs_status mcs_eq30_stratified_delta_corrected(size_t n, size_t k, size_t freq_k,
                                               size_t freq_l, double *re, double *im);

/* Eq. 30 corrected, assembled: the exact stratified <S_k S_l*> above, all
 * k, l in [0, N), K dividing N (else MCS_ERR_DOMAIN). */
mcs_status mcs_eq30_stratified_cross(size_t n, size_t k, size_t freq_k, size_t freq_l,
                                     double *re, double *im);

/* Eq. 31 as printed: -(K/N)^3 [(1 - cos(2 pi k/K)) / (1 - cos(2 pi k/N))]^2.
 * Wrong: the bracket should not be squared (it is |ratio|^2 already).
 * K dividing N, freq in [1, N), else MCS_ERR_DOMAIN. */
mcs_status mcs_eq31_stratified_delta_printed(size_t n, size_t k, size_t freq, double *out);

/* Eq. 32 (first, exact form): Delta_kk = -(K/N)^3 sin^2(pi k/K) / sin^2(pi k/N),
 * = -(K/N) sinc^2(pi k/K) / sinc^2(pi k/N). K dividing N, freq in [1, N). */
mcs_status mcs_eq32_stratified_delta(size_t n, size_t k, size_t freq, double *out);

/* Eq. 33, exact finite-N form (eq. 23 plus eq. 32):
 * <|S_k|^2> = K/N - (K/N)^3 sin^2(pi k/K) / sin^2(pi k/N).
 * K dividing N, freq in [1, N), else MCS_ERR_DOMAIN. */
mcs_status mcs_eq33_stratified_power_exact(size_t n, size_t k, size_t freq, double *out);

/* Eq. 33 as printed, the N -> infinity limit: (K/N)(1 - sinc^2(pi k/K)),
 * sinc x = sin x / x, read at the signed frequency (index freq > N/2 is
 * freq - N). K dividing N, freq in [1, N), else MCS_ERR_DOMAIN. */
mcs_status mcs_eq33_stratified_power_limit(size_t n, size_t k, size_t freq, double *out);

/* Eq. 34 with beta = 1/2 (uniform): S_k = (K/sqrt N) e^{-pi i mu} at
 * k = mu K, 0 elsewhere; deterministic, so it is also <S_k>, and |S_{mu K}|
 * = K/sqrt N is the bias. The note puts sample alpha at bin (alpha + 1/2) N/K,
 * a whole bin only when N/K is even: K not dividing N or N/K odd is
 * MCS_ERR_DOMAIN (the generator's bin is floor((alpha + 1/2) N/K); use
 * mcs_theory_mean for that case). */
mcs_status mcs_eq34_uniform_spectrum(size_t n, size_t k, size_t freq, double *re, double *im);

/* Eq. 35: uniform jitter <S_k> = (K/sqrt N) delta_k0, freq in [0, N).
 * K dividing N, else MCS_ERR_DOMAIN. */
mcs_status mcs_eq35_jitter_mean(size_t n, size_t k, size_t freq, double *re, double *im);

/* Eq. 37: uniform jitter (and uniform) power spectrum: K^2/N at k = mu K, and
 * 0 elsewhere (eq. 34), freq in [0, N). K dividing N, else MCS_ERR_DOMAIN. */
mcs_status mcs_eq37_jitter_power(size_t n, size_t k, size_t freq, double *out);

/* ---- Section 4: importance sampling ------------------------------------- */
/* imp: the importance function, N = imp->n bins, H = imp->harmonic_mean
 * (eq. 44: N^{-1/2} Q_0 = 1/H). imp NULL means "no importance function" and
 * gives MCS_ERR_DOMAIN; imp not initialised (n out of range) gives
 * MCS_ERR_UNINIT. Also MCS_ERR_NULL (outputs), MCS_ERR_K_RANGE (k = 0),
 * MCS_ERR_FREQ_RANGE (freq >= N), MCS_ERR_NOT_FINITE (f), MCS_ERR_MAGNITUDE
 * (|f_n| above MCS_ESTIMATE_MAX_ABS), MCS_ERR_ALIAS (re == im, where the
 * result is complex), and last MCS_ERR_INVARIANT when imp holds values
 * mcs_importance_init never makes (a p_n zeroed on a bin that is drawn,
 * negative or NaN, an empty support, a zeroed H: checked, O(N)) or the
 * result would not be finite: for every object init makes it is
 * (1/p_n < 2^32).
 *
 * Over the support. A bin with g_n = 0 (importance.h) is never drawn and
 * s_n = 0 there, so every form below reads 1/p_n and f_n as 0 on such a bin
 * and nothing divides by p_n = 0: Q_k, H (1/H = (1/N) sum over the support
 * of 1/p_n), F_k (the transform of f on the support) and the sums. The
 * statements of exactness below are for an importance function with every
 * g_n > 0 unless they say otherwise; with bins outside the support the
 * random pattern's <s_m s_n> gains the indicator of the support on both
 * bins, so <S_k S_l*> gains (K^2 - K)/N^3 X_k X_l* (X the transform of the
 * support's indicator) and eq. 43, 45 and 46 miss that term; eq. 41, eq. 52
 * corrected (with fbar the mean of f on the support, the estimator's <I>)
 * and the bound of eq. 58 corrected (its 1/N read as N_s / N^2, N_s the
 * bins of the support) stay exact. */

/* Eq. 41: random with importance, <s_m s_n> = (K^2 - K)/N^2 + (K/N) delta_mn / p_n
 * (exact) for bins bin_m, bin_n of imp: MCS_ERR_BIN_RANGE. 0, exactly, when
 * either bin is outside the support (s = 0 there in every trial). */
mcs_status mcs_eq41_importance_second(const mcs_importance *imp, size_t k, size_t bin_m,
                                      size_t bin_n, double *out);

/* Eq. 43: random with importance, <S_k S_l*> = (K/N) N^{-1/2} Q_{k-l}; exact
 * for every (k, l) except k = l = 0 (MCS_ERR_DOMAIN; see eq. 46). */
mcs_status mcs_eq43_importance_cross(const mcs_importance *imp, size_t k, size_t freq_k,
                                     size_t freq_l, double *re, double *im);

/* Eq. 45: random with importance, <|S_k|^2> = (K/N)/H for freq in [1, N)
 * (freq 0: MCS_ERR_DOMAIN, see eq. 46). */
mcs_status mcs_eq45_importance_power(const mcs_importance *imp, size_t k, size_t freq,
                                     double *out);

/* Eq. 46: random with importance, <|S_0|^2> = K^2/N + (K/N)(1/H - 1).
 * Eq. 51 (stratified with importance) is the same expression: exact when
 * every stratum is N/K whole bins (uniform g, or any g whose blocks of N/K
 * bins have mass 1/K); otherwise stratification also removes variance from
 * S_0 and the exact value is lower. */
mcs_status mcs_eq46_importance_power0(const mcs_importance *imp, size_t k, double *out);

/* Eq. 49 as printed: stratified with importance, <S_k S_l*> =
 * (K/N) N^{-1/2} Q_{k-l} + Delta_kl (eq. 30 as printed). K dividing imp->n,
 * freq_k and freq_l in [1, N), else MCS_ERR_DOMAIN. Exact only when every
 * stratum is N/K whole bins (each block of N/K bins has mass 1/K: uniform g,
 * or any g so balanced), and then only for k = l (mod K): it inherits
 * eq. 30's missing strata phase (elsewhere the exact value is its Q term). */
mcs_status mcs_eq49_importance_stratified_cross(const mcs_importance *imp, size_t k,
                                                size_t freq_k, size_t freq_l, double *re,
                                                double *im);

/* Eq. 50: stratified with importance, <|S_k|^2> = (K/N)(1/H - sinc^2(pi k/K)),
 * freq in [1, N), K dividing N, else MCS_ERR_DOMAIN; sinc read at the signed
 * frequency as in eq. 33. The note's claim; its finite-N form (K/N)/H +
 * eq. 32 is exact only when every stratum is N/K whole bins (uniform g, or
 * any g whose blocks of N/K bins have mass 1/K), and the sinc form only as
 * N -> infinity. */
mcs_status mcs_eq50_importance_stratified_power(const mcs_importance *imp, size_t k, size_t freq,
                                                double *out);

/* Eq. 52 as printed: (1/K) N^{-3/2} sum_{k,l >= 1} F_k* F_l Q_{k-l}.
 * Not the variance under importance sampling (S_0 is random there).
 * f[imp->n], |f_n| <= MCS_ESTIMATE_MAX_ABS, any N up to MCS_MAX_N. Up to MCS_MAX_COV_N the double sum is
 * taken term by term, O(N^3) trig (eq. 52 corrected and eq. 55 too); above,
 * its equal by Parseval in O(N), (1/K)(1/N) sum_n (f_n - fbar)^2 / p_n
 * (eq. 52 corrected: (1/K)(1/N) sum_n p_n (f_n/p_n - fbar)^2; eq. 55:
 * (1/K)(1/N) sum_n (f_n/p_n)(f_n - fbar)). The two agree to 1e-12. */
mcs_status mcs_eq52_variance_printed(const mcs_importance *imp, size_t k, const double *f,
                                     double *out);

/* Eq. 52 corrected: (1/K) [N^{-3/2} sum_{all k,l} F_k* F_l Q_{k-l} - |F_0|^2/N],
 * the exact Var[I] of random sampling with importance, equal by Parseval to
 * the primal (1/K) [(1/N) sum_n f_n^2 / p_n - fbar^2]; with bins outside the
 * support, F of f on the support and fbar its mean (the sums over the
 * support), still the exact variance. Same arguments.
 * Never negative, nor is eq. 52 as printed (both are sums of squares by
 * Parseval): a term-by-term sum in [-b, 0) is rounding and reads 0, b =
 * (N^2 + 4N + 16) DBL_EPSILON (sum_n |f_n|)^2 / (H K) bounding it; one
 * below -b comes from no p_n init gives (an overwritten object):
 * MCS_ERR_INVARIANT, nothing written. */
mcs_status mcs_eq52_variance_corrected(const mcs_importance *imp, size_t k, const double *f,
                                       double *out);

/* Eq. 55 as printed: (1/K) N^{-3/2} sum_{k >= 1} F_k* (F (x) Q)_k with the full
 * cyclic convolution (F (x) Q)_k = sum_{l=0}^{N-1} F_l Q_{k-l}. By Parseval it
 * equals (1/K)[(1/N) sum f^2/p - fbar * mean(f/p)]: zero when f/p is constant
 * (the note's remark) but the exact variance only when mean(f/p) = fbar.
 * f[imp->n], |f_n| <= MCS_ESTIMATE_MAX_ABS, any N up to MCS_MAX_N (as
 * eq. 52). */
mcs_status mcs_eq55_variance_convolution(const mcs_importance *imp, size_t k, const double *f,
                                         double *out);

/* Eq. 58 as printed: (1/K) (sum_{n >= 1} |F_n|^2) / H. Not a bound under
 * importance sampling (constant f: 0, while the variance is not).
 * f[imp->n], |f_n| <= MCS_ESTIMATE_MAX_ABS, any N up to MCS_MAX_N (the sum
 * as for eq. 24). */
mcs_status mcs_eq58_bound_printed(const mcs_importance *imp, size_t k, const double *f,
                                  double *out);

/* Eq. 58 corrected: (1/K) (sum_{all n} |F_n|^2) (1/H - 1/N), the
 * Cauchy-Schwarz step applied over every k (sum_k Var S_k = K/H - K/N); a
 * valid upper bound on the random-with-importance Var[I]. With N_s < N bins
 * in the support sum_k Var S_k = K/H - K N_s / N^2, and the bound is
 * (1/K) (sum over the support of f_n^2) (1/H - N_s / N^2): with 1/N in its
 * place it is no bound (g = (1, 1, 0, 0)/2, f = (1, 0, 0, 0): 0 against
 * Var[I] = 1/(16 K)). f[imp->n],
 * |f_n| <= MCS_ESTIMATE_MAX_ABS (sum |F_n|^2 = sum f_n^2 by Parseval, so
 * any N). */
mcs_status mcs_eq58_bound_corrected(const mcs_importance *imp, size_t k, const double *f,
                                    double *out);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_EQ_H */
