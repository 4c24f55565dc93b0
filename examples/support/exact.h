/* Shared by the section examples: the exact moments of one pattern at any N.
 * Up to MCS_MAX_COV_N they come from the N x N moments of mcs_theory, so
 * every row reads what it always read; above, from mcs_theory_spectrum (O(N)
 * memory, every N up to MCS_MAX_N). The power at every k is computed once.
 * Rows that need the N x N moments themselves (eq. 13, the primal moment
 * accumulator) ask ex_exact_theory, which is NULL above MCS_MAX_COV_N. Every
 * read-out is EX_NA where the library call fails. */
#ifndef MCSPEC_EXAMPLE_EXACT_H
#define MCSPEC_EXAMPLE_EXACT_H

#include <stddef.h>

#include "mcspec.h"
#include "report.h"

typedef struct {
    size_t n, k;
    int full;                       /* 1: N <= MCS_MAX_COV_N, theory holds the N x N moments */
    mcs_theory theory;              /* when full */
    mcs_theory_spectrum spectrum;   /* when not full */
    double power[MCS_MAX_N];        /* <|S_k|^2>, every k */
} ex_exact;

/* The exact moments of pat (mcs_theory_init or mcs_theory_spectrum_init's
 * status). */
mcs_status ex_exact_init(ex_exact *ex, const mcs_pattern *pat);

/* The same from mcs_theory_spectrum at every N (ex_exact_theory is NULL):
 * variances formed without cancellation, for tables that have no earlier
 * output to keep. */
mcs_status ex_exact_init_spectrum(ex_exact *ex, const mcs_pattern *pat);

/* The N x N moments, or NULL above MCS_MAX_COV_N. */
const mcs_theory *ex_exact_theory(const ex_exact *ex);

/* <|S_freq|^2>, <S_freq>, <S_k S_l*>. */
double ex_exact_power(const ex_exact *ex, size_t freq);
ex_complex ex_exact_mean(const ex_exact *ex, size_t freq);
ex_complex ex_exact_cross(const ex_exact *ex, size_t freq_k, size_t freq_l);
/* Cov(S_k, S_l) = <S_k S_l*> - <S_k><S_l>*. */
ex_complex ex_exact_covariance(const ex_exact *ex, size_t freq_k, size_t freq_l);

/* Mean over k >= 1 of <|S_k|^2> (EX_NA for N = 1). */
double ex_exact_mean_power(const ex_exact *ex);

/* <I>, Var[I] and Cov(I_f, I_g) of integrands f[N], g[N] (K of the pattern). */
double ex_exact_estimator_mean(const ex_exact *ex, const double *f);
double ex_exact_variance(const ex_exact *ex, const double *f);
double ex_exact_estimator_covariance(const ex_exact *ex, const double *f, const double *g);

/* The larger N at which an N -> infinity form's limit check compares it
 * with the exact value: EX_LARGE_N_FACTOR N, or the largest multiple of N
 * within MCS_MAX_N if that is smaller; 0 when no multiple above N fits. */
size_t ex_large_n(size_t n);

#endif /* MCSPEC_EXAMPLE_EXACT_H */
