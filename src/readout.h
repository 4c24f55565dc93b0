/* Private: the one read-out of first and second moments, shared by the
 * measured moments (mcs_moment, sums over trials) and the exact ones
 * (mcs_theory, expectations), so "measured vs exact" is the same code on two
 * objects. Each object is reached through an open function that checks it
 * and describes where its moments are (a view); everything from there on,
 * eq. 15, eq. 16, covariances and Var[I], is written once below. */
#ifndef MCSPEC_READOUT_H
#define MCSPEC_READOUT_H

#include <stddef.h>
#include "mcspec/status.h"

/* Where an object's moments are: <s_bin> = first[bin] * scale and
 * <s_m s_n> = second[m * n + n'] * scale (full, symmetric, stride n). */
typedef struct {
    size_t n;              /* N */
    size_t k;              /* K of exact moments; 0: any K >= 1 the caller names */
    double scale;          /* 1 / trials for sums, 1 for expectations */
    const double *first;   /* [n] */
    const double *second;  /* [n * n] */
    const double *cos_table; /* cos(2 pi j / N), j < N */
    const double *sin_table; /* sin(2 pi j / N), j < N */
} mcs_readout;

/* Checks obj and fills *view: MCS_ERR_UNINIT, MCS_ERR_EMPTY (no trials yet). */
typedef mcs_status (*mcs_readout_open)(const void *obj, mcs_readout *view);

/* The two objects (obj not NULL): a mcs_moment, a mcs_theory. */
mcs_status mcs_readout_open_moment(const void *obj, mcs_readout *view);
mcs_status mcs_readout_open_theory(const void *obj, mcs_readout *view);

/* The public read-outs of moment.h and theory.h, for obj opened by open;
 * arguments and statuses as documented there. */
mcs_status mcs_readout_bin_mean(const void *obj, mcs_readout_open open, size_t bin, double *out);
mcs_status mcs_readout_bin_second(const void *obj, mcs_readout_open open, size_t bin_m,
                                  size_t bin_n, double *out);
mcs_status mcs_readout_mean(const void *obj, mcs_readout_open open, size_t freq, double *re,
                            double *im);
mcs_status mcs_readout_power(const void *obj, mcs_readout_open open, size_t freq, double *out);
mcs_status mcs_readout_cross(const void *obj, mcs_readout_open open, size_t freq_k,
                             size_t freq_l, double *re, double *im);
mcs_status mcs_readout_covariance(const void *obj, mcs_readout_open open, size_t freq_k,
                                  size_t freq_l, double *re, double *im);
mcs_status mcs_readout_cross_matrix(const void *obj, mcs_readout_open open, size_t n,
                                    double *re, double *im);
mcs_status mcs_readout_covariance_matrix(const void *obj, mcs_readout_open open, size_t n,
                                         double *re, double *im);
mcs_status mcs_readout_estimator_mean(const void *obj, mcs_readout_open open, size_t n,
                                      size_t k, const double *f, double *out);
mcs_status mcs_readout_variance(const void *obj, mcs_readout_open open, size_t n, size_t k,
                                const double *f, double *out);
mcs_status mcs_readout_estimator_covariance(const void *obj, mcs_readout_open open, size_t n,
                                            size_t k, const double *f, const double *g,
                                            double *out);

/* For the closed forms built on a read-out (eq. 2, 4, 13). */

/* Opens obj (not NULL) and checks an integrand for it: f[n] finite, n equal
 * to the object's N, k as for mcs_readout_estimator_mean. MCS_ERR_UNINIT,
 * MCS_ERR_EMPTY, MCS_ERR_MISMATCH, MCS_ERR_K_RANGE, MCS_ERR_NOT_FINITE. */
mcs_status mcs_readout_check_integrand(const void *obj, mcs_readout_open open, size_t n,
                                       size_t k, const double *f, mcs_readout *view);

/* (1/K^2) f^T Cov(s) g, K = k, both checked. */
double mcs_readout_form(const mcs_readout *view, size_t k, const double *f, const double *g);

/* Eq. 7 at one frequency, freq < N, of any x[N] from the view's twiddle table. */
void mcs_readout_dft(const mcs_readout *view, const double *x, size_t freq, double *re,
                     double *im);

/* <S_k S_l*> (eq. 16), freq_k and freq_l < N. */
void mcs_readout_cross_at(const mcs_readout *view, size_t freq_k, size_t freq_l, double *re,
                          double *im);

#endif /* MCSPEC_READOUT_H */
