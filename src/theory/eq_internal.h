/* Private: checks and transforms shared by the closed forms of sections 1-3
 * (src/theory/eq.c) and section 4 (src/theory/eq_importance.c); defined in src/theory/eq.c. */
#ifndef MCSPEC_EQ_INTERNAL_H
#define MCSPEC_EQ_INTERNAL_H

#include <stddef.h>
#include "core/internal.h"
#include "mcspec/status.h"

#define MCS_PI 3.14159265358979323846

/* n in [1, cap] (else N_RANGE), k >= 1 (else K_RANGE). */
mcs_status mcs_eq_check_n_k(size_t n, size_t cap, size_t k);

/* The stratified forms of the note put N/K whole bins in each stratum. */
int mcs_eq_k_divides_n(size_t n, size_t k);

/* A pair of frequencies for a stratified form: outputs given (else NULL),
 * check_n_k at MCS_MAX_N, both frequencies < n (FREQ_RANGE), K dividing N
 * (DOMAIN). */
mcs_status mcs_eq_check_pair(int outputs, size_t n, size_t k, size_t freq_k, size_t freq_l);

/* A complex result's last check: st if it is an error, else MCS_ERR_ALIAS
 * when re and im overlap (one double cannot hold both parts), else MCS_OK.
 * Inline, so the static analyser sees that an error st covers NULL outputs. */
static inline mcs_status mcs_eq_check_complex(mcs_status st, const double *re, const double *im)
{
    if (st == MCS_OK && mcs_overlap_(re, sizeof *re, im, sizeof *im))
        return MCS_ERR_ALIAS;
    return st;
}

/* Eq. 7 at one frequency with the twiddle computed per term from the reduced
 * index (freq t mod N): no table, so any N. support (an importance
 * function's p, or NULL for every bin): x_t read as 0 where support[t] is
 * not > 0, the bins an importance function never draws. */
void mcs_eq_dft_at(size_t n, const double *x, const double *support, size_t freq, double *re,
                   double *im);

/* x_t on the support (as mcs_eq_dft_at reads it). */
static inline double mcs_eq_on_support(const double *x, const double *support, size_t t)
{
    return support == NULL || support[t] > 0.0 ? x[t] : 0.0;
}

/* sum_{k >= 1} |F_k|^2 of f on the support (as mcs_eq_dft_at): by direct
 * DFTs, O(N^2) trig, for N <= MCS_MAX_COV_N; above, its equal by Parseval,
 * sum_n (f_n - fbar)^2, O(N). */
double mcs_eq_ac_energy(size_t n, const double *f, const double *support);

/* Delta_kl of eq. 30 as printed, unchecked: K dividing N, freq_k and freq_l
 * in [1, N) (the caller checks). */
void mcs_eq_delta_printed(size_t n, size_t k, size_t freq_k, size_t freq_l, double *re,
                          double *im);

/* sinc^2(pi freq / K) at the signed frequency min(freq, N - freq), freq in
 * [1, N), K dividing N. */
double mcs_eq_sinc2(size_t n, size_t k, size_t freq);

#endif /* MCSPEC_EQ_INTERNAL_H */
