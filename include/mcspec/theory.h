/* mcspec theory module: what the patterns should measure.
 *
 * Two halves:
 *
 * 1. The exact discrete moments <s_n> and <s_m s_n> of every pattern kind,
 *    with and without importance, for any K and any N up to MCS_MAX_COV_N
 *    (K need not divide N), from the interval-overlap formula of DESIGN.md:
 *
 *        <s_n>     = (1/p_n)       sum_j      P(u_j in I_n)
 *        <s_m s_n> = (1/(p_m p_n)) sum_{j,j'} P(u_j in I_m and u_j' in I_n)
 *
 *    where I_n is bin n's interval of canonical u (its CDF interval
 *    [cdf[n], cdf[n+1]) with importance, [n/N, (n+1)/N) without). From them,
 *    by linear algebra only: <S_k> (eq. 15), <S_k S_l*> (eq. 16),
 *    Cov(S_k, S_l), and the exact Var[I] of a caller's f, both in the primal
 *    domain (1/K^2) f^T Cov(s) f and through the spectra
 *    (1/K^2) sum_{k,l} F_k* F_l Cov(S_k, S_l) over ALL k, l (they agree to
 *    rounding; the second is the check on the first).
 *
 *    Per kind (t = u K, so stratum j is [j, j+1) and bin n is [A_n, B_n)):
 *    - random: independent u_j, P = lengths, products for j != j'.
 *    - stratified: u_j uniform on stratum j; sum_j of the same-stratum
 *      overlap products is removed from the independent K^2 L_m L_n.
 *      Strata need not line up with bins (K not dividing N, or importance).
 *    - homogenized: the stratified moments averaged over the N cyclic
 *      whole-bin shifts the generator draws uniformly from [0, N).
 *    - uniform: deterministic. u_j is binned by the generator's own
 *      arithmetic, so a u_j exactly on a bin edge (every u_j when N/K is
 *      even: not a measure-zero event for a deterministic pattern) lands
 *      where mcs_pattern_draw puts it: without importance that is the exact
 *      floor((2j + 1) N / (2K)).
 *    - jitter (also warped by importance, which the note leaves open): the
 *      count of samples in bin n as a function of the shared beta is
 *      r_n(beta) = ceil(B_n - beta) - ceil(A_n - beta), a step function with
 *      at most two steps in [0,1); <r_m r_n> is the exact integral of the
 *      product of two such step functions.
 *    Each kind costs O(N^2) (O(N^3) for homogenized, O(K + N^2) for uniform)
 *    whatever K is.
 *
 * 2. Every closed form of the note as a plain function named mcs_eq<number>_...
 *    Each returns MCS_ERR_DOMAIN when asked outside the domain where the note
 *    defines it (K not dividing N for the stratified and uniform forms, a
 *    frequency the formula excludes, an importance formula given no
 *    importance function). Where the note's printed form is wrong, both the
 *    printed and the corrected form exist, named _printed and _corrected, so
 *    the example programs can show the difference from measurements.
 *
 * Conventions: n = N bins, k = K samples per trial, freq a frequency index in
 * [0, n); S_k = N^{-1/2} sum_n e^{-2 pi i k n / N} s_n (eq. 7); F is the same
 * transform of f; Q is the same transform of 1/p_n (eq. 43). Every function
 * validates all inputs before writing anything: on error every output and
 * the theory object are byte-for-byte unchanged. Nothing allocates, and
 * nothing keeps work arrays on the stack: transforms are taken one
 * coefficient at a time, so every frame stays under 300 bytes (the
 * library's `make stack` limit is 1 KiB) at the price of the costs noted
 * per function (all well under a second at N = 64).
 */
#ifndef MCSPEC_THEORY_H
#define MCSPEC_THEORY_H

#include <stddef.h>
#include "config.h"
#include "status.h"
#include "importance.h"
#include "pattern.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Exact first and second moments of one pattern. Caller-owned (static,
 * stack or arena); filled by mcs_theory_init. sizeof(mcs_theory) at the
 * default MCS_MAX_COV_N = 64 is 34,336 bytes on LP64 (the N x N second
 * moment is 32 KiB of it). */
typedef struct {
    mcs_pattern_kind kind; /* pattern kind the moments are for */
    size_t n;              /* bins N, 1..MCS_MAX_COV_N (0: not initialised) */
    size_t k;              /* samples per trial K, >= 1 */
    int has_importance;    /* 1 if the pattern warps through an importance function */
    double mean_s[MCS_MAX_COV_N]; /* <s_n>, n in [0, N) */
    double second[MCS_MAX_COV_N * MCS_MAX_COV_N]; /* <s_m s_n> at [m * N + n] (packed
                                                     with stride N, symmetric) */
    double cos_table[MCS_MAX_COV_N]; /* cos(2 pi t / N): twiddles with exact index reduction */
    double sin_table[MCS_MAX_COV_N]; /* sin(2 pi t / N) */
} mcs_theory;

/* ---- Exact moments of a pattern ---------------------------------------- */

/* Computes the exact <s_n> and <s_m s_n> of pat (any kind, with or without
 * importance, any K >= 1, pat->n <= MCS_MAX_COV_N). pat is read, not kept.
 * MCS_ERR_NULL, MCS_ERR_N_RANGE (pat->n > MCS_MAX_COV_N), MCS_ERR_UNINIT
 * (pat->n == 0, pat->k == 0, unknown kind, or an importance function of the
 * wrong n), MCS_ERR_KIND (homogenized with importance). *th untouched on error. */
mcs_status mcs_theory_init(mcs_theory *th, const mcs_pattern *pat);

/* <s_bin>. MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_BIN_RANGE (bin >= N). */
mcs_status mcs_theory_mean_s(const mcs_theory *th, size_t bin, double *out);

/* <s_m s_n>. MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_BIN_RANGE. */
mcs_status mcs_theory_second(const mcs_theory *th, size_t m, size_t n, double *out);

/* <S_freq> (eq. 15), complex. MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_FREQ_RANGE. */
mcs_status mcs_theory_spectrum_mean(const mcs_theory *th, size_t freq, double *re, double *im);

/* <S_k S_l*> (eq. 16), complex, for any k, l in [0, N), by separable direct
 * sums (O(N^2) per entry). MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_FREQ_RANGE. */
mcs_status mcs_theory_cross(const mcs_theory *th, size_t freq_k, size_t freq_l, double *re,
                            double *im);

/* Cov(S_k, S_l) = <S_k S_l*> - <S_k><S_l>*. Same statuses as mcs_theory_cross. */
mcs_status mcs_theory_covariance(const mcs_theory *th, size_t freq_k, size_t freq_l, double *re,
                                 double *im);

/* Power spectrum <|S_freq|^2> (the real diagonal of eq. 16; includes freq 0).
 * MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_FREQ_RANGE. */
mcs_status mcs_theory_power(const mcs_theory *th, size_t freq, double *out);

/* <I> = (1/K) sum_n f_n <s_n> (eq. 9 in the primal domain); equals eq. 11
 * for every unbiased kind, not for uniform. f[n], n == th->n.
 * MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_MISMATCH (n != th->n), MCS_ERR_NOT_FINITE. */
mcs_status mcs_theory_estimator_mean(const mcs_theory *th, size_t n, const double *f,
                                     double *out);

/* Exact Var[I] = (1/K^2) f^T Cov(s) f for I = (1/K) sum_n f_n s_n (eq. 8).
 * f[n], n == th->n. MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_MISMATCH,
 * MCS_ERR_NOT_FINITE. */
mcs_status mcs_theory_variance(const mcs_theory *th, size_t n, const double *f, double *out);

/* The same Var[I] through the spectra: (1/K^2) sum over ALL k, l of
 * F_k* F_l Cov(S_k, S_l), each Cov(S_k, S_l) by eq. 16: O(N^4), about
 * 17 M multiply-adds (tens of ms) at N = 64. Agrees with mcs_theory_variance
 * to rounding. Same statuses. */
mcs_status mcs_theory_variance_spectral(const mcs_theory *th, size_t n, const double *f,
                                        double *out);

/* Cov(I_f, I_g) = (1/K^2) f^T Cov(s) g for two integrands estimated from the
 * SAME trial (correlated sampling, the Cov[f,g] of eq. 2 and 5). f[n], g[n].
 * Same statuses as mcs_theory_variance. */
mcs_status mcs_theory_estimator_covariance(const mcs_theory *th, size_t n, const double *f,
                                           const double *g, double *out);

/* Q_freq = N^{-1/2} sum_n e^{-2 pi i freq n / N} / p_n: the eq. 7 transform of
 * 1/p (eq. 43). imp NULL means no importance: MCS_ERR_DOMAIN.
 * MCS_ERR_NULL (outputs), MCS_ERR_DOMAIN, MCS_ERR_UNINIT (imp->n out of range),
 * MCS_ERR_FREQ_RANGE (freq >= imp->n). */
mcs_status mcs_theory_q(const mcs_importance *imp, size_t freq, double *re, double *im);

/* ---- Section 1: gradient variance -------------------------------------- */

/* Eq. 2, uncorrelated sampling of f and g: Var[I] = Var[f] + Var[g] (the
 * covariance is 0). var_f, var_g finite and >= 0.
 * MCS_ERR_NULL, MCS_ERR_NOT_FINITE, MCS_ERR_NEGATIVE. */
mcs_status mcs_eq2_uncorrelated_variance(double var_f, double var_g, double *out);

/* Eq. 2 from integrands: the exact Var[I_f] + Var[I_g] when f and g are each
 * estimated from their own independent trial of the pattern th. f[n], g[n].
 * Same statuses as mcs_theory_variance. */
mcs_status mcs_eq2_uncorrelated_variance_fg(const mcs_theory *th, size_t n, const double *f,
                                            const double *g, double *out);

/* Eq. 4 (and eq. 6), correlated sampling: the exact Var[I_h] of h = f - g
 * estimated from ONE shared trial; equals Var[f] + Var[g] - 2 Cov[f,g].
 * f[n], g[n]. Same statuses as mcs_theory_variance. */
mcs_status mcs_eq4_correlated_variance(const mcs_theory *th, size_t n, const double *f,
                                       const double *g, double *out);

/* ---- Section 2: discrete Fourier analysis ------------------------------- */

/* Eq. 11: <I> = (1/N) sum_n f_n, the unbiased mean. f[n], n <= MCS_MAX_N.
 * MCS_ERR_NULL, MCS_ERR_N_RANGE, MCS_ERR_NOT_FINITE. */
mcs_status mcs_eq11_unbiased_mean(size_t n, const double *f, double *out);

/* Eq. 13: (1/K^2) sum_{m,n >= 1} F_m* F_n <S_m S_n*>, the full double sum
 * from the exact moments of th (second moments, not covariances, and no
 * k = 0 terms, as printed; it is the variance when <S_{k>0}> = 0 and S_0 is
 * deterministic, i.e. unbiased kinds without importance). O(N^4) like
 * mcs_theory_variance_spectral. f[n], n == th->n. Same statuses as
 * mcs_theory_variance. */
mcs_status mcs_eq13_variance(const mcs_theory *th, size_t n, const double *f, double *out);

/* Eq. 14: (1/K^2) sum_{n >= 1} |F_n|^2 power[n], the diagonal (stationary)
 * approximation, for any power spectrum the caller holds: measured, from
 * mcs_theory_power, or a closed form below. f[n], power[n] (power[0]
 * unused), n <= MCS_MAX_COV_N (direct DFT of f).
 * MCS_ERR_NULL, MCS_ERR_N_RANGE, MCS_ERR_K_RANGE (k = 0), MCS_ERR_NOT_FINITE. */
mcs_status mcs_eq14_variance(size_t n, size_t k, const double *f, const double *power,
                             double *out);

/* ---- Section 3: random, stratified, uniform, jitter --------------------- */
/* Shared statuses: MCS_ERR_NULL, MCS_ERR_N_RANGE (n = 0 or > MCS_MAX_N; > MCS_MAX_COV_N
 * where f is transformed), MCS_ERR_K_RANGE (k = 0), MCS_ERR_FREQ_RANGE
 * (freq >= n), MCS_ERR_DOMAIN as stated per function, MCS_ERR_NOT_FINITE (f). */

/* Eq. 23: random power spectrum <|S_freq|^2> = K/N, freq in [1, N) (exact at
 * finite N). freq 0: MCS_ERR_DOMAIN. */
mcs_status mcs_eq23_random_power(size_t n, size_t k, size_t freq, double *out);

/* Eq. 24: random Var[I] = (1/K)(1/N) sum_{n >= 1} |F_n|^2. f[n], n <= MCS_MAX_COV_N. */
mcs_status mcs_eq24_random_variance(size_t n, size_t k, const double *f, double *out);

/* Eq. 25: random Var[I] = (1/K) (1/N) sum_n (f_n - fbar)^2, the population
 * variance of f over K. f[n], n <= MCS_MAX_N. */
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
 * sinc x = sin x / x. K dividing N, freq in [1, N), else MCS_ERR_DOMAIN. */
mcs_status mcs_eq33_stratified_power_limit(size_t n, size_t k, size_t freq, double *out);

/* Eq. 34 with beta = 1/2 (uniform): S_k = (K/sqrt N) e^{-pi i mu} at
 * k = mu K, 0 elsewhere; deterministic, so it is also <S_k>, and |S_{mu K}|
 * = K/sqrt N is the bias. The note puts sample alpha at bin (alpha + 1/2) N/K,
 * a whole bin only when N/K is even: K not dividing N or N/K odd is
 * MCS_ERR_DOMAIN (the generator's bin is floor((alpha + 1/2) N/K); use
 * mcs_theory_spectrum_mean for that case). */
mcs_status mcs_eq34_uniform_spectrum(size_t n, size_t k, size_t freq, double *re, double *im);

/* Eq. 35: uniform jitter <S_k> = (K/sqrt N) delta_k0, freq in [0, N).
 * K dividing N, else MCS_ERR_DOMAIN. */
mcs_status mcs_eq35_jitter_mean(size_t n, size_t k, size_t freq, double *re, double *im);

/* Eq. 37: uniform jitter (and uniform) power spectrum: K^2/N at k = mu K, and
 * 0 elsewhere (eq. 34), freq in [0, N). K dividing N, else MCS_ERR_DOMAIN. */
mcs_status mcs_eq37_jitter_power(size_t n, size_t k, size_t freq, double *out);

/* ---- Section 4: importance sampling ------------------------------------- */
/* imp NULL means "no importance function" and gives MCS_ERR_DOMAIN; imp
 * with n out of range gives MCS_ERR_UNINIT. h is the harmonic mean H of p
 * (imp->harmonic_mean); h must be finite (MCS_ERR_NOT_FINITE) and in
 * (0, 1] up to rounding (MCS_ERR_DOMAIN), since the mean of p is 1. */

/* Eq. 41: random with importance, <s_m s_n> = (K^2 - K)/N^2 + (K/N) delta_mn / p_n
 * (exact). m, n bins of imp: MCS_ERR_BIN_RANGE. MCS_ERR_K_RANGE (k = 0). */
mcs_status mcs_eq41_importance_second(const mcs_importance *imp, size_t k, size_t m, size_t n,
                                      double *out);

/* Eq. 43: random with importance, <S_k S_l*> = (K/N) N^{-1/2} Q_{k-l}; exact
 * for every (k, l) except k = l = 0 (MCS_ERR_DOMAIN; see eq. 46).
 * MCS_ERR_K_RANGE, MCS_ERR_FREQ_RANGE (freq >= imp->n). */
mcs_status mcs_eq43_importance_cross(const mcs_importance *imp, size_t k, size_t freq_k,
                                     size_t freq_l, double *re, double *im);

/* Eq. 44: N^{-1/2} Q_0 = (1/N) sum_n 1/p_n = 1/H. */
mcs_status mcs_eq44_inverse_harmonic_mean(const mcs_importance *imp, double *out);

/* Eq. 45: random with importance, <|S_k|^2> = (K/N)/H for freq in [1, N)
 * (freq 0: MCS_ERR_DOMAIN, see eq. 46). */
mcs_status mcs_eq45_importance_power(size_t n, size_t k, double h, size_t freq, double *out);

/* Eq. 46: random with importance, <|S_0|^2> = K^2/N + (K/N)(1/H - 1). */
mcs_status mcs_eq46_importance_power0(size_t n, size_t k, double h, double *out);

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
 * freq in [1, N), K dividing N, else MCS_ERR_DOMAIN. The note's claim; its
 * finite-N form (K/N)/H + eq. 32 is exact only when every stratum is N/K
 * whole bins (uniform g, or any g whose blocks of N/K bins have mass 1/K),
 * and the sinc form only as N -> infinity. */
mcs_status mcs_eq50_importance_stratified_power(size_t n, size_t k, double h, size_t freq,
                                                double *out);

/* Eq. 51: stratified with importance, <|S_0|^2> = K^2/N + (K/N)(1/H - 1),
 * K dividing N, else MCS_ERR_DOMAIN. Exact under the same whole-bin-strata
 * condition as eq. 50; otherwise stratification also removes variance from
 * S_0 and the exact value is lower. */
mcs_status mcs_eq51_importance_stratified_power0(size_t n, size_t k, double h, double *out);

/* Eq. 52 as printed: (1/K) N^{-3/2} sum_{k,l >= 1} F_k* F_l Q_{k-l}.
 * Not the variance under importance sampling (S_0 is random there).
 * f[imp->n], imp->n <= MCS_MAX_COV_N (else MCS_ERR_N_RANGE); O(N^3) trig
 * (eq. 52 corrected and eq. 55 too). */
mcs_status mcs_eq52_variance_printed(const mcs_importance *imp, size_t k, const double *f,
                                     double *out);

/* Eq. 52 corrected: (1/K) [N^{-3/2} sum_{all k,l} F_k* F_l Q_{k-l} - |F_0|^2/N],
 * the exact Var[I] of random sampling with importance. Same arguments. */
mcs_status mcs_eq52_variance_corrected(const mcs_importance *imp, size_t k, const double *f,
                                       double *out);

/* Eq. 52 corrected, primal form: (1/K) [(1/N) sum_n f_n^2 / p_n - fbar^2]
 * (equal to the above by Parseval). f[imp->n], imp->n <= MCS_MAX_N. */
mcs_status mcs_eq52_variance_corrected_primal(const mcs_importance *imp, size_t k,
                                              const double *f, double *out);

/* Eq. 55 as printed: (1/K) N^{-3/2} sum_{k >= 1} F_k* (F (x) Q)_k with the full
 * cyclic convolution (F (x) Q)_k = sum_{l=0}^{N-1} F_l Q_{k-l}. By Parseval it
 * equals (1/K)[(1/N) sum f^2/p - fbar * mean(f/p)]: zero when f/p is constant
 * (the note's remark) but the exact variance only when mean(f/p) = fbar.
 * f[imp->n], imp->n <= MCS_MAX_COV_N. */
mcs_status mcs_eq55_variance_convolution(const mcs_importance *imp, size_t k, const double *f,
                                         double *out);

/* Eq. 58 as printed: (1/K) (sum_{n >= 1} |F_n|^2) / H. Not a bound under
 * importance sampling (constant f: 0, while the variance is not).
 * f[n], n <= MCS_MAX_COV_N. */
mcs_status mcs_eq58_bound_printed(size_t n, size_t k, double h, const double *f, double *out);

/* Eq. 58 corrected: (1/K) (sum_{all n} |F_n|^2) (1/H - 1/N), the
 * Cauchy-Schwarz step applied over every k (sum_k Var S_k = K/H - K/N); a
 * valid upper bound on the random-with-importance Var[I]. f[n], n <= MCS_MAX_N
 * (sum |F_n|^2 = sum f_n^2 by Parseval). */
mcs_status mcs_eq58_bound_corrected(size_t n, size_t k, double h, const double *f, double *out);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_THEORY_H */
