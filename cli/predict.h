/* What a pattern should measure: the one place the mcspec command looks up
 * theory, so a better source (exact theory at every N) is a change here only.
 *
 * Power spectrum <|S_k|^2>, k = 0..N/2:
 *  - exact: at every N, for every kind, K and importance function:
 *    mcs_theory's exact moments where N <= MCS_MAX_COV_N, the O(N)-memory
 *    mcs_theory_spectrum above;
 *  - closed: the note's closed form as printed, where one exists (eq. 17 or
 *    46/51 at k = 0; eq. 23, 33, 37, 45, 50 at k > 0).
 * Var[I]: exact from the same two engines at every N. */
#ifndef MCSPEC_CLI_PREDICT_H
#define MCSPEC_CLI_PREDICT_H

#include <stddef.h>

#include "mcspec.h"

/* Frequencies k = 0..N/2 of the largest N. */
#define CLI_HALF_MAX ((MCS_MAX_N) / 2 + 1)

typedef struct {
    size_t nfreq;                /* N/2 + 1 */
    double exact[CLI_HALF_MAX];  /* NaN where no exact value is available */
    double closed[CLI_HALF_MAX]; /* NaN where the note has no closed form */
    char exact_source[96];       /* where the exact values come from ("" if none) */
    char closed_source[96];      /* which equation the closed form is ("" if none) */
} cli_prediction;

/* Fills pred for the power spectrum of pat (initialised by mcs_pattern_init).
 * Returns 0, or CLI_EXIT_FAIL after a message (a library call failed). */
int cli_predict_power(const char *cmd, const mcs_pattern *pat, cli_prediction *pred);

/* Exact Var[I] of I = (1/K) sum_n f_n s_n under pat, f[pat->n]: *out, or NaN
 * where none is available; *source names it ("" if none). Returns 0 or
 * CLI_EXIT_FAIL after a message. */
int cli_predict_variance(const char *cmd, const mcs_pattern *pat, const double *f, double *out,
                         const char **source);

/* The estimator's exact bias <I> - (1/N) sum_n f_n under pat, f[pat->n]
 * (mcs_theory_bias: 0 for the unbiased kinds but for the bins an importance
 * function never draws; the uniform pattern's counts): *out. Returns 0 or
 * CLI_EXIT_FAIL after a message. */
int cli_predict_bias(const char *cmd, const mcs_pattern *pat, const double *f, double *out);

#endif /* MCSPEC_CLI_PREDICT_H */
