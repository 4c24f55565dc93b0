/* The exact discrete moments of a pattern: what the patterns should measure.
 *
 * Two objects. mcs_theory holds <s_n> and the N x N <s_m s_n> for N up to
 * MCS_MAX_COV_N: every read-out of moment.h, cross matrices included.
 * mcs_theory_spectrum (further below) holds O(N) numbers and gives <S_k>,
 * <|S_k|^2>, <S_k S_l*> and Var[I] for every N up to MCS_MAX_N. Where both
 * exist they agree to rounding (1e-12 of the scale of the moments).
 *
 * <s_n> and <s_m s_n> of every pattern kind, with and without importance, for
 * any K and any N up to MCS_MAX_COV_N (K need not divide N). A sample u_j in
 * [0,1) lands in bin n when it falls in the bin's interval I_n of canonical u
 * (its CDF interval [cdf[n], cdf[n+1]) with importance, [n/N, (n+1)/N)
 * without) and then weighs 1/p_n, so the moments are interval overlaps:
 *
 *     <s_n>     = (1/p_n)       sum_j      P(u_j in I_n)
 *     <s_m s_n> = (1/(p_m p_n)) sum_{j,j'} P(u_j in I_m and u_j' in I_n)
 *
 * Per kind (t = u K, so stratum j is [j, j+1) and bin n is [A_n, B_n)):
 * - random: independent u_j, P = lengths, products for j != j'.
 * - stratified: u_j uniform on stratum j; sum_j of the same-stratum overlap
 *   products is removed from the independent K^2 L_m L_n. Strata need not
 *   line up with bins (K not dividing N, or importance).
 * - homogenized: the stratified moments averaged over the N cyclic whole-bin
 *   shifts the generator draws uniformly from [0, N).
 * - uniform: deterministic. u_j is binned by the generator's own arithmetic,
 *   so a u_j exactly on a bin edge (every u_j when N/K is even: not a
 *   measure-zero event for a deterministic pattern) lands where
 *   mcs_pattern_draw puts it: without importance that is the exact
 *   floor((2j + 1) N / (2K)).
 * - jitter (also warped by importance, which the note leaves open): the count
 *   of samples in bin n as a function of the shared beta is
 *   r_n(beta) = ceil(B_n - beta) - ceil(A_n - beta), a step function with at
 *   most two steps in [0,1); <r_m r_n> is the exact integral of the product
 *   of two such step functions.
 * Each kind costs O(N^2) (O(N^3) for homogenized, O(N log K + N^2) for
 * uniform, whose bin counts are found by bisection on j, not by a walk over
 * the K samples): well under a second at every K up to MCS_MAX_K.
 *
 * The read-out is the same, call for call, as that of the measured moments
 * in moment.h (and runs the same code): <S_k> (eq. 15), <S_k S_l*> (eq. 16),
 * Cov(S_k, S_l), and the exact mean and Var[I] = (1/K^2) f^T Cov(s) f of the
 * estimator of a caller's f. The note's closed forms are in eq.h.
 *
 * Exact zeros. Where theory proves a value 0 for every trial, both objects
 * read it as 0 (+0), not as the rounding its sums leave (1e-17 to 1e-32);
 * nowhere else is a value forced, however small:
 * - S_0 and S_{N/2} (N even) are real: the imaginary part of <S_k>, and of
 *   <S_k S_l*> and Cov(S_k, S_l) with both k and l such, is 0;
 * - without importance S_0 = K / sqrt(N) in every trial: Cov(S_0, S_l) = 0,
 *   and Var[I] = Cov(I_f, I_g) = 0 for an f (or g) constant over the bins;
 *   every kind but uniform has <s_n> = K/N: <S_k> = 0 for k != 0;
 * - random, homogenized and jitter without importance are stationary:
 *   Cov(S_k, S_l) = 0 for k != l; stratified without importance is unchanged
 *   by a shift of N/g bins, g = gcd(N, K): Cov(S_k, S_l) = 0 unless g
 *   divides k - l (eq. 30 corrected);
 * - jitter without importance, and uniform whose stored counts repeat every
 *   N/g bins: s repeats every N/g bins in every trial, so S_k = 0 (its
 *   mean, power and every second moment with it) unless g divides k;
 * - uniform, and stratified, homogenized and jitter without importance with
 *   N dividing K: s is the same in every trial, every covariance and Var[I]
 *   is 0;
 * and <S_k S_l*> is 0 where Cov(S_k, S_l) and <S_k> or <S_l> are. A small
 * value theory does not prove 0 is left as computed: jitter's Var[I] of an
 * f whose exact values have no energy at the multiples of K is ~1e-32 for
 * its rounded doubles (their exact variance), which mcs_theory_spectrum_
 * variance gives; mcs_theory_variance gives it only to its absolute
 * rounding (3e-19 for examples/sec1_gradient's f).
 *
 * Conventions: n = N bins, k = K samples per trial, freq a frequency index in
 * [0, N); S_k = N^{-1/2} sum_n e^{-2 pi i k n / N} s_n (eq. 7). Every function
 * validates all inputs before writing anything: on error every output and
 * the theory object are byte-for-byte unchanged. Nothing allocates, and no
 * work arrays live on the stack: transforms are taken one coefficient at a
 * time, at the costs noted per function (all well under a second at N = 64). */
#ifndef MCSPEC_THEORY_H
#define MCSPEC_THEORY_H

#include <stddef.h>
#include "config.h"
#include "estimate.h"
#include "status.h"
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
    double second[MCS_MAX_COV_N * MCS_MAX_COV_N]; /* <s_m s_n> at [bin_m * N + bin_n] (packed
                                                     with stride N, symmetric) */
    double cos_table[MCS_MAX_COV_N]; /* cos(2 pi j / N): twiddles with exact index reduction */
    double sin_table[MCS_MAX_COV_N]; /* sin(2 pi j / N) */
} mcs_theory;

/* Computes the exact <s_n> and <s_m s_n> of pat (any kind, with or without
 * importance, any K in [1, MCS_MAX_K], pat->n <= MCS_MAX_COV_N). pat is read,
 * not kept. MCS_ERR_NULL, MCS_ERR_N_RANGE (pat->n > MCS_MAX_COV_N),
 * MCS_ERR_UNINIT (pat->n == 0, pat->k == 0 or above MCS_MAX_K, unknown kind,
 * or an importance function of the wrong n or not as mcs_importance_init
 * leaves one), MCS_ERR_KIND (homogenized with importance). *th untouched on
 * error. An importance function with bins of g_n = 0 is fine: no sample
 * lands there, s_n = 0 in every trial, and every moment of such a bin is 0. */
mcs_status mcs_theory_init(mcs_theory *th, const mcs_pattern *pat);

/* ---- Read-out: the expectations. Every call returns MCS_ERR_NULL,
 * MCS_ERR_UNINIT, and as stated; outputs are untouched on error, and a
 * complex result's re and im must be two different doubles (MCS_ERR_ALIAS),
 * as for the measured moments (moment.h).
 * Every call returns MCS_ERR_INVARIANT, writing nothing, for a *th whose
 * values mcs_theory_init never writes (overwritten): has_importance not 0
 * or 1 (or 1 for homogenized), a <s_n> outside [0, 2^64] or NaN, a twiddle
 * outside [-1, 1] (these O(N), checked by every call), a <s_n^2> outside
 * [<s_n>^2 (1 - 2^-12), <s_n>^2 + 2^34 <s_n>], an off-diagonal <s_m s_n>
 * above (1 + 2^-12)^(1/2) or below -2^-12 times sqrt(<s_m^2> <s_n^2>)
 * (Cauchy-Schwarz, and s >= 0; checked where read: O(N^2) by each call
 * that reads the matrix, the entry and its two diagonals by
 * mcs_theory_bin_second), and a power or variance below minus its
 * tolerance (its rounding and init's, see mcs_theory_variance). Init's
 * own values are far inside each (its rounding reaches 2^-16 of them). So
 * with MCS_OK every result is finite and no power or variance negative. ---- */

/* <s_bin>. MCS_ERR_BIN_RANGE (bin >= N). */
mcs_status mcs_theory_bin_mean(const mcs_theory *th, size_t bin, double *out);

/* <s_m s_n> for bins bin_m, bin_n (symmetric). MCS_ERR_BIN_RANGE. */
mcs_status mcs_theory_bin_second(const mcs_theory *th, size_t bin_m, size_t bin_n,
                                 double *out);

/* <S_freq> (eq. 15) from <s>. O(N). MCS_ERR_FREQ_RANGE (freq >= N). */
mcs_status mcs_theory_mean(const mcs_theory *th, size_t freq, double *re, double *im);

/* Power spectrum <|S_freq|^2>, the real diagonal of eq. 16 (freq 0 included).
 * O(N^2). MCS_ERR_FREQ_RANGE. Never negative, clamped (or refused) as
 * mcs_theory_variance (b with |e^{-2 pi i k n/N}| = 1 in place of |f_n|,
 * 1/N for 1/K^2, and no <s_m><s_n> term). */
mcs_status mcs_theory_power(const mcs_theory *th, size_t freq, double *out);

/* <S_k S_l*> (eq. 16) for k = freq_k, l = freq_l, by separable direct sums
 * (at k = l the power, clamped as mcs_theory_power). O(N^2).
 * MCS_ERR_FREQ_RANGE. */
mcs_status mcs_theory_cross(const mcs_theory *th, size_t freq_k, size_t freq_l, double *re,
                            double *im);

/* Cov(S_k, S_l) = <S_k S_l*> - <S_k><S_l>*. O(N^2). MCS_ERR_FREQ_RANGE. At
 * k = l a variance, never negative (clamped or refused as the power, with
 * the mean's rounding in b). */
mcs_status mcs_theory_covariance(const mcs_theory *th, size_t freq_k, size_t freq_l,
                                 double *re, double *im);

/* Every <S_k S_l*> at once, O(N^3): re[k * n + l] + i im[k * n + l], caller
 * arrays of n * n (exactly n * n entries are written), n equal to th->n, else
 * MCS_ERR_MISMATCH. re and im must overlap neither each other nor *th (they
 * are written while it is read): MCS_ERR_ALIAS. The diagonal is the power
 * spectrum, never negative (clamped as mcs_theory_power, each checked
 * before anything is written: O(N^3) more). */
mcs_status mcs_theory_cross_matrix(const mcs_theory *th, size_t n, double *re, double *im);

/* Every Cov(S_k, S_l) at once, O(N^3), laid out as mcs_theory_cross_matrix;
 * the diagonal as mcs_theory_covariance(k, k), checked before anything is
 * written. */
mcs_status mcs_theory_covariance_matrix(const mcs_theory *th, size_t n, double *re,
                                        double *im);

/* <I> = (1/K) sum_n f_n <s_n> (eq. 9 in the primal domain); equals eq. 11 for
 * every unbiased kind, not for uniform, and not where an importance function
 * has bins with g_n = 0 (their f_n is never sampled: mcs_theory_bias). f[n], n == th->n, else
 * MCS_ERR_MISMATCH; f finite, else MCS_ERR_NOT_FINITE. k is the K of the
 * pattern, named as for mcs_moment_estimator_mean: MCS_ERR_K_RANGE (k = 0),
 * MCS_ERR_MISMATCH (k != th->k). */
mcs_status mcs_theory_estimator_mean(const mcs_theory *th, size_t n, size_t k, const double *f,
                                     double *out);

/* The estimator's bias <I> - (1/N) sum_n f_n (eq. 11's integral). Random,
 * stratified, homogenized and jitter are unbiased on the importance
 * function's support, so it is -(1/N) sum over the bins with g_n = 0 of
 * f_n, exactly (one sum, no difference of <I> and the integral; 0 without
 * importance or with every g_n > 0); uniform's is that of its
 * deterministic counts, (1/(K N)) sum_n f_n (N <s_n> - K). Arguments and
 * statuses as mcs_theory_estimator_mean, and MCS_ERR_MAGNITUDE (|f_n| above
 * MCS_ESTIMATE_MAX_ABS). O(N). */
mcs_status mcs_theory_bias(const mcs_theory *th, size_t n, size_t k, const double *f,
                           double *out);

/* Exact Var[I] = (1/K^2) f^T Cov(s) f for I = (1/K) sum_n f_n s_n (eq. 8).
 * Arguments and statuses as mcs_theory_estimator_mean. Never negative: the
 * form is a difference of second moments, and a result in [-b, 0) is
 * rounding and reads 0, b = (2N + 16) DBL_EPSILON (1/K^2) sum_{m,n} |f_m|
 * |f_n| (|<s_m s_n>| + |<s_m>| |<s_n>|) bounding the rounding of that sum,
 * plus what init's rounding adds to the form, 64 DBL_EPSILON (1/K^2)
 * ((sum |f_n| <s_n>)^2 + K (sum |f_n| u_n)^2), u_n = min(max(<s_n^2> /
 * <s_n>, <s_n>), 2^33) bounding 1/p_n (the bin edges are rounded in units
 * of 1/K of u, so a small bin's moments err far more than the read-out
 * does). A result below -b comes from no object init writes:
 * MCS_ERR_INVARIANT. The absolute error is of the order of b, so for a
 * variance far below (mean I)^2 prefer mcs_theory_spectrum_variance, which
 * never forms the difference. */
mcs_status mcs_theory_variance(const mcs_theory *th, size_t n, size_t k, const double *f,
                               double *out);

/* Cov(I_f, I_g) = (1/K^2) f^T Cov(s) g for two integrands estimated from the
 * SAME trial (correlated sampling, the Cov[f,g] of eq. 2 and 5). f[n], g[n];
 * statuses as mcs_theory_estimator_mean. */
mcs_status mcs_theory_estimator_covariance(const mcs_theory *th, size_t n, size_t k,
                                           const double *f, const double *g, double *out);

/* ==== Exact spectra at any N: mcs_theory_spectrum ============================
 *
 * Usage. Set up the pattern, then the object once (O(N) memory, no N x N
 * array), then read what you need; every N from 1 to MCS_MAX_N, every kind,
 * with and without importance, any K. The object copies what it needs, so
 * the pattern and its importance function may go away after the init:
 *
 *     static mcs_theory_spectrum ts;         (about 256 KiB: not on a small stack)
 *     mcs_pattern_init(&pat, MCS_PATTERN_JITTER, n, k, &imp);
 *     mcs_theory_spectrum_init(&ts, &pat);              O(N log N)
 *     mcs_theory_power_spectrum(&ts, n, power);         power[n] = <|S_k|^2>, all k, O(N^2)
 *     mcs_theory_spectrum_power(&ts, freq, &p);         one k, O(N)
 *     mcs_theory_spectrum_mean(&ts, freq, &re, &im);    <S_k>, O(N)
 *     mcs_theory_spectrum_variance(&ts, n, k, f, &v);   Var[I] of f[n], O(N)
 *
 * The all-k power spectrum takes about 0.1 s (random, stratified) to 0.5 s
 * (jitter with importance) at N = 4096 on a desktop core.
 *
 * How. Every quantity is E[(X - <X>)(Y - <Y>)*] + <X><Y>* for two linear
 * functionals X = sum_n x_n s_n of one trial (x_n = e^{-2 pi i k n/N}/sqrt N
 * for S_k, f_n/K for I), and that covariance is taken per kind over what is
 * independent in the pattern: the bin probabilities of one sample (random,
 * times K), each stratum that holds more than one bin (stratified: the other
 * strata contribute nothing), the pieces of the shared beta between the
 * sorted fractional bin edges (jitter), and the average over the N whole-bin
 * shifts (homogenized; |S_k|^2 does not see a shift, so its power is the
 * stratified one). Each is a weighted sum of squared deviations from the
 * mean (two passes, or a weighted Welford update for the jitter pieces), so
 * variances and powers are never negative, and nothing cancels
 * against <X><X>*: a variance far below (mean I)^2 keeps its relative
 * accuracy. The bins, edges and weights are those of mcs_theory (the same
 * arithmetic), so where N <= MCS_MAX_COV_N the two objects agree to 1e-12 of
 * the scale of the moments (tested for every kind, with and without
 * importance, K dividing N or not, K > N), and so do both with the exact
 * values (edges taken as exact integers, long double sums) under an extreme
 * importance function: weights 1e6 and 1 (N = 39, K = 19, g ~ 2.5e-7 in
 * the small bins, which weigh 1/p ~ 1e5). That needs each bin's edge with
 * its rounding (edge_lo): a small bin's overlap with a stratum, or its
 * piece of jitter's beta, is a difference of nearby edges, and from the
 * rounded edges alone it erred by K 2^-53, 1.6e-11 of the scale there.
 *
 * Every read-out validates all inputs first and writes nothing on error:
 * MCS_ERR_NULL, MCS_ERR_UNINIT (ts not set up), and as stated. Nothing
 * allocates; every call uses a few hundred bytes of stack. ================== */

/* Exact first moments of one pattern and the per-bin numbers its
 * covariances are formed from, for N up to MCS_MAX_N. Caller-owned; filled by
 * mcs_theory_spectrum_init, which copies everything it needs (the pattern's
 * importance function need not outlive it). sizeof at the default
 * MCS_MAX_N = 4096 is 262,192 bytes on LP64 (8 arrays of N). */
typedef struct {
    mcs_pattern_kind kind;        /* pattern kind */
    size_t n;                     /* bins N, 1..MCS_MAX_N (0: not set up) */
    size_t k;                     /* samples per trial K, >= 1 */
    int has_importance;           /* 1 if the pattern warps through an importance function */
    double mean_s[MCS_MAX_N];     /* <s_n>, n in [0, N) */
    double edge[MCS_MAX_N + 1];   /* bin b is [edge[b], edge[b+1]) in t = u K units (the
                                     CDF interval times K), edge[0] = 0, edge[N] = K */
    double edge_lo[MCS_MAX_N + 1]; /* the rounding of edge[b]: edge + edge_lo is the exact
                                      K cdf[b] (to ~2^-106 of it); a small bin's overlaps
                                      are differences of nearby edges, taken with it */
    double length[MCS_MAX_N];     /* P(one uniform u lands in bin b) */
    double inv_p[MCS_MAX_N];      /* the weight 1/p_b of a sample in bin b */
    size_t order[MCS_MAX_N];      /* jitter: bins 1..N-1 ordered by the fractional part of
                                     edge[b] (where the shared beta moves a sample on) */
    double cos_table[MCS_MAX_N];  /* cos(2 pi j / N), j < N */
    double sin_table[MCS_MAX_N];  /* sin(2 pi j / N) */
} mcs_theory_spectrum;

/* Sets up ts for pat (any kind, with or without importance, any K in
 * [1, MCS_MAX_K], 1 <= pat->n <= MCS_MAX_N): <s_n> and the bins (O(N),
 * O(N log K) for uniform) and, for jitter, the sorted bin edges
 * (O(N log N)). pat is read, not kept. MCS_ERR_NULL,
 * MCS_ERR_UNINIT (pat->n == 0, pat->k == 0 or above MCS_MAX_K, unknown kind,
 * an importance function not initialised, overwritten or of another n;
 * bins with g_n = 0 are fine, as for mcs_theory_init), MCS_ERR_N_RANGE (pat->n >
 * MCS_MAX_N), MCS_ERR_KIND (homogenized with importance). *ts untouched on
 * error. */
mcs_status mcs_theory_spectrum_init(mcs_theory_spectrum *ts, const mcs_pattern *pat);

/* The three calls with a complex result (re, im) below compute it first and
 * write it last, so re and im may be any two doubles, even inside ts; the
 * same double for both is MCS_ERR_ALIAS (it cannot hold both parts).
 * On any *ts mcs_theory_spectrum_init wrote, powers and variances are >= 0
 * exactly (sums of non-negative terms: nothing to clamp) and every result is
 * finite; every read-out below returns MCS_ERR_INVARIANT, writing nothing,
 * where a corrupted *ts would give a non-finite result, a negative power or
 * variance, or an index outside the object. */

/* <S_freq> (eq. 15). O(N). MCS_ERR_FREQ_RANGE (freq >= N), MCS_ERR_ALIAS. */
mcs_status mcs_theory_spectrum_mean(const mcs_theory_spectrum *ts, size_t freq, double *re,
                                    double *im);

/* <|S_freq|^2> = Var(S_freq) + |<S_freq>|^2, freq 0 included. O(N) (O(N) for
 * homogenized too: its power is the stratified one). MCS_ERR_FREQ_RANGE. */
mcs_status mcs_theory_spectrum_power(const mcs_theory_spectrum *ts, size_t freq, double *out);

/* <|S_k|^2> for every k in [0, n): power[n], exactly n entries written, n
 * equal to the pattern's N (else MCS_ERR_MISMATCH). O(N^2). */
mcs_status mcs_theory_power_spectrum(const mcs_theory_spectrum *ts, size_t n, double *power);

/* Every stored frequency k = 0..N/2 at once (the exact counterpart of
 * mcs_spectrum_read_all, spectrum.h): mean_re[k] + i mean_im[k] = <S_k>,
 * variance[k] = Var(S_k) = E|S_k - <S_k>|^2 (the exact counterpart of T
 * times a measured mean_stderr^2 over T trials) and power[k] = <|S_k|^2>,
 * each bit for bit what mcs_theory_spectrum_mean, mcs_theory_spectrum_
 * covariance(k, k) and mcs_theory_spectrum_power return. Exact values
 * have no standard errors, so there are no arrays for them. Caller arrays
 * of n_out doubles, n_out equal to N/2 + 1 (else MCS_ERR_MISMATCH); exactly
 * n_out entries written to each array given. Any array may be NULL when
 * not wanted, not all of them (MCS_ERR_NULL); the arrays must overlap
 * neither one another nor *ts (MCS_ERR_ALIAS). MCS_ERR_INVARIANT (a body
 * init does not write, checked before anything is written). O(N^2). */
mcs_status mcs_theory_spectrum_read_all(const mcs_theory_spectrum *ts, size_t n_out,
                                        double *mean_re, double *mean_im, double *variance,
                                        double *power);

/* <S_k S_l*> (eq. 16) for k = freq_k, l = freq_l; at k = l the power
 * read-out bit for bit, imaginary part 0. O(N) (homogenized: its
 * covariance is circulant, so Cov(S_k, S_l) = 0 for k != l).
 * MCS_ERR_FREQ_RANGE, MCS_ERR_ALIAS. */
mcs_status mcs_theory_spectrum_cross(const mcs_theory_spectrum *ts, size_t freq_k,
                                     size_t freq_l, double *re, double *im);

/* Cov(S_k, S_l) = <S_k S_l*> - <S_k><S_l>*, formed directly (no difference).
 * O(N). MCS_ERR_FREQ_RANGE, MCS_ERR_ALIAS. */
mcs_status mcs_theory_spectrum_covariance(const mcs_theory_spectrum *ts, size_t freq_k,
                                          size_t freq_l, double *re, double *im);

/* <I> = (1/K) sum_n f_n <s_n>. f[n], n equal to the pattern's N, else
 * MCS_ERR_MISMATCH; k the pattern's K: MCS_ERR_K_RANGE (k = 0),
 * MCS_ERR_MISMATCH (k != K); f finite, else MCS_ERR_NOT_FINITE, and |f_n| <=
 * MCS_ESTIMATE_MAX_ABS (estimate.h: 2^110, the largest term the estimator
 * takes), else MCS_ERR_MAGNITUDE: within it no square or product of f with
 * the moments (below 2^124 at K <= MCS_MAX_K, 1/p_n < 2^32) can overflow,
 * so this and the two calls below return finite values. O(N). */
mcs_status mcs_theory_spectrum_estimator_mean(const mcs_theory_spectrum *ts, size_t n,
                                              size_t k, const double *f, double *out);

/* The bias <I> - (1/N) sum_n f_n, as mcs_theory_bias (the same arithmetic):
 * -(1/N) sum over the bins outside the support of f_n but for uniform.
 * Arguments and statuses as mcs_theory_spectrum_estimator_mean. O(N). */
mcs_status mcs_theory_spectrum_bias(const mcs_theory_spectrum *ts, size_t n, size_t k,
                                    const double *f, double *out);

/* Var[I] of I = (1/K) sum_n f_n s_n (eq. 8), never negative. Arguments and
 * statuses as mcs_theory_spectrum_estimator_mean. O(N) (homogenized
 * O(N^2)). */
mcs_status mcs_theory_spectrum_variance(const mcs_theory_spectrum *ts, size_t n, size_t k,
                                        const double *f, double *out);

/* Cov(I_f, I_g) for two integrands estimated from the same trial. f[n], g[n];
 * statuses as mcs_theory_spectrum_estimator_mean. O(N) (homogenized O(N^2)). */
mcs_status mcs_theory_spectrum_estimator_covariance(const mcs_theory_spectrum *ts, size_t n,
                                                    size_t k, const double *f, const double *g,
                                                    double *out);

/* ==== The rotation average of a fixed point set: mcs_theory_rotation ======
 *
 * A renderer's Cranley-Patterson rotation: a fixed set of K points a_j in
 * [0, 1), the same for every pixel, moved by one uniform beta per pixel,
 * x_j = a_j + beta mod 1, and binned over N bins. Its exact binned <S_k>,
 * <|S_k|^2> and Var[I] (averaged over beta) for any set, not only the
 * ones that reduce to a pattern kind (K = 2^m van der Corput points rotated
 * are uniform jitter; Halton base 3 points are no pattern kind):
 *
 *     static double work[MCS_THEORY_ROTATION_LEN(64)];
 *     mcs_theory_rotation rot;
 *     mcs_theory_rotation_init(&rot, n, k, points, work, 64);   O(K^2)
 *     mcs_theory_rotation_power(&rot, freq, &p);                O(N)
 *     mcs_theory_rotation_variance(&rot, n, k, f, &v);          O(N^2)
 *
 * How. With A_j = N a_j the bin offset n_j - n_j' (mod N) of two rotated
 * points is floor(D) or floor(D) + 1, D = A_j - A_j', the latter with
 * probability frac(D), and the bin of a rotated point is uniform on [0, N)
 * and independent of that offset. So the rotation-averaged histogram h(d)
 * of the bin offsets of the K^2 ordered pairs (init: O(K^2), about 16 M
 * pair steps at K = 4096) carries every read-out:
 *     <|S_q|^2> = (1/N) sum_d h(d) cos(2 pi q d / N),
 *     Var[I]    = (1/K^2) sum_d h(d) R(d) - fbar^2,  R(d) = (1/N) sum_n f_n f_{n+d},
 * and <S_k> = (K / sqrt N) delta_k0 exactly (the rotation is stationary, and
 * S_0 = K / sqrt N in every trial). h lives in the caller's work array,
 * which must stay as init left it while the object is read.
 *
 * Every call validates its inputs before writing: on error nothing
 * changes. Nothing allocates. ============================================== */

/* Doubles of work memory the rotation of a set over n bins needs (a
 * constant expression, for a static array): h(d), d < n. */
#define MCS_THEORY_ROTATION_LEN(n) ((size_t)(n))

/* Set up by mcs_theory_rotation_init; read-only to the caller. */
typedef struct {
    size_t n;        /* bins N, 1..MCS_MAX_N (0: not set up) */
    size_t k;        /* points K, 1..MCS_MAX_K */
    double *offsets; /* h(d), d < N, in the caller's work array: the rotation-averaged
                        number of ordered pairs (j, j') whose bins lie d apart (mod N);
                        they sum to K^2 */
} mcs_theory_rotation;

/* Sets up *rot for the k points points[k] in [0, 1) over n bins, h(d) into
 * work[len], len >= MCS_THEORY_ROTATION_LEN(n) (exactly n entries
 * written). O(K^2). points is read, not kept. MCS_ERR_NULL, MCS_ERR_N_RANGE
 * (n = 0 or above MCS_MAX_N), MCS_ERR_K_RANGE (k = 0 or above MCS_MAX_K),
 * MCS_ERR_SPACE (len too small), MCS_ERR_ALIAS (any two of work, points and
 * *rot overlapping), MCS_ERR_POINT_RANGE (a point outside [0, 1) or NaN).
 * On error neither *rot nor work changes. */
mcs_status mcs_theory_rotation_init(mcs_theory_rotation *rot, size_t n, size_t k,
                                    const double *points, double *work, size_t len);

/* The read-outs: MCS_ERR_NULL, MCS_ERR_UNINIT (rot not set up), and
 * MCS_ERR_INVARIANT where an offset is negative, above 2^61 or NaN (the
 * work array was written since init), as stated; outputs untouched on
 * error. */

/* <S_freq>: K / sqrt(N) at freq 0, 0 elsewhere, exactly. MCS_ERR_FREQ_RANGE
 * (freq >= N), MCS_ERR_ALIAS (re and im one double). */
mcs_status mcs_theory_rotation_mean(const mcs_theory_rotation *rot, size_t freq, double *re,
                                    double *im);

/* <|S_freq|^2> averaged over the rotation (above). O(N). MCS_ERR_FREQ_RANGE.
 * Never negative: the sum has terms of both signs, and one in [-b, 0) is
 * rounding and reads 0, b = (2 K^2 + N + 16) DBL_EPSILON K^2 / N (init adds
 * each h(d) from up to 2 K^2 terms; a rotated van der Corput set, which is
 * jitter, has exact zeros the sum leaves near -1e-16); below -b comes from
 * no work array init writes: MCS_ERR_INVARIANT. */
mcs_status mcs_theory_rotation_power(const mcs_theory_rotation *rot, size_t freq, double *out);

/* Var[I] of I = (1/K) sum_j f[n_j] (eq. 8) averaged over the rotation, f[n]
 * as for mcs_theory_spectrum_variance: n equal to the set's N, k to its K
 * (MCS_ERR_MISMATCH; k = 0 MCS_ERR_K_RANGE), f finite (MCS_ERR_NOT_FINITE)
 * with |f_n| <= MCS_ESTIMATE_MAX_ABS (MCS_ERR_MAGNITUDE). <I> is the mean
 * of f (eq. 11): every rotated point's bin is uniform. O(N^2). Never
 * negative, as the power: a value in [-b, 0) reads 0, b = 2 (2 K^2 + N + 16)
 * DBL_EPSILON (1/N) sum_n (f_n - fbar)^2; below -b MCS_ERR_INVARIANT. */
mcs_status mcs_theory_rotation_variance(const mcs_theory_rotation *rot, size_t n, size_t k,
                                        const double *f, double *out);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_THEORY_H */
