/* Shared helpers for the exact-moment and closed-form tests (theory, eq). */
#ifndef THEORY_REF_H
#define THEORY_REF_H

#include <stddef.h>

#include "mcspec.h"

#define THEORY_PI 3.14159265358979323846

/* Fails the test unless |expected - actual| <= rel * max(1, |expected|). */
void theory_assert_close(double expected, double actual, double rel, const char *what);

/* Pattern (kind, n, k, im) and its exact moments into *t; fails the test on error. */
void theory_init(mcs_theory *t, mcs_pattern_kind kind, size_t n, size_t k,
                 const mcs_importance *im);

/* A fixed, lumpy test integrand f[n]; phase picks one of a family. */
void theory_make_f(size_t n, double *f, double phase);

/* Normalised DFT (eq. 7) of x[n] into re[n], im[n], O(N^2), independent of
 * the library. */
void theory_ref_dft(size_t n, const double *x, double *re, double *im);

/* A lumpy importance function over n bins into *imp; fails the test on error. */
void theory_lumpy_importance(mcs_importance *imp, size_t n);

/* Every outcome of one trial of the pattern (kind, n, k, im), enumerated by a
 * route independent of the theory's overlap formulas: all interval endpoints
 * in u (bin edges or CDF values, strata) are multiples of 1/grid, so a
 * sample's bin is constant on each grid cell; the cell midpoint goes through
 * the library's warp (or floor(u N)), and each trial's dense s is weighted
 * by its cell probability. Random and stratified enumerate grid^k and
 * (grid/k)^k outcomes (grid a multiple of k for stratified), homogenized
 * adds the n shifts, jitter the grid values of beta, uniform draws its one
 * outcome from the generator. mean[n] = <s_n>, second[n * n] = <s_m s_n>;
 * n <= MCS_MAX_COV_N, k <= THEORY_BF_KMAX. */
#define THEORY_BF_KMAX 64
void theory_brute_force(mcs_pattern_kind kind, size_t n, size_t k, const mcs_importance *im,
                        size_t grid, double *mean, double *second);

/* Least common multiple. */
size_t theory_lcm(size_t a, size_t b);

/* The read-outs of integrands on exact moments, mcs_theory_variance and the
 * closed forms built on it, share one argument list and one set of bad-input
 * statuses. Exactly one of one, two is not NULL. th: initialised, th->n <= 63.
 * Each bad call (NULL, UNINIT, MISMATCH for n or k, K_RANGE, NOT_FINITE in f
 * or g) must return its status and leave *th and the output untouched. */
typedef mcs_status (*theory_one_fn)(const mcs_theory *, size_t, size_t, const double *,
                                    double *);
typedef mcs_status (*theory_two_fn)(const mcs_theory *, size_t, size_t, const double *,
                                    const double *, double *);
void theory_check_bad_integrands(const mcs_theory *th, theory_one_fn one, theory_two_fn two);

#endif /* THEORY_REF_H */
