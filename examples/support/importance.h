/* Shared by the section examples: the importance functions they sample
 * with, and the note's power spectra under importance sampling evaluated at
 * any number of bins m (at N for the tables, at a larger N for the limit
 * checks of section 4). */
#ifndef MCSPEC_EXAMPLE_IMPORTANCE_H
#define MCSPEC_EXAMPLE_IMPORTANCE_H

#include <stddef.h>

#include "mcspec.h"

/* The importance functions (weights at the bin centres, normalised):
 *   EX_G_FOLLOW   g1 = 0.45 + 0.3 sin(2 pi x) + 0.3 [x >= 0.35], roughly
 *                 following ex_integrand;
 *   EX_G_MISMATCH g2 = 0.2 + (1 - x)^2, high where ex_integrand is low
 *                 (smooth, not periodic);
 *   EX_G_FLAT     the uniform g (p_n = 1);
 *   EX_G_BALANCED g1 with every block of m/K bins rescaled to mass 1/K, so
 *                 each stratum of the warped pattern is m/K whole bins (when
 *                 K divides m; otherwise it is g1);
 *   EX_G_UNRELATED 1 + 0.6 sin(10 pi x + 1), five bumps that ignore f;
 *   EX_G_PROPORTIONAL ex_integrand itself: f / p is the same in every bin
 *                 (the note's "perfect importance sampling");
 *   EX_G_SMOOTH   0.45 + 0.3 sin(2 pi x), smooth and periodic.
 * EX_G_NONE stands for sampling without importance. */
enum {
    EX_G_NONE,
    EX_G_FOLLOW,
    EX_G_MISMATCH,
    EX_G_FLAT,
    EX_G_BALANCED,
    EX_G_UNRELATED,
    EX_G_PROPORTIONAL,
    EX_G_SMOOTH,
    EX_G_COUNT
};

/* The continuous limit of 1/H = (1/N) sum_n 1/p_n: the integral over [0, 1)
 * of 1/p(x), p = g / (integral of g), in closed form for EX_G_MISMATCH
 * (0.2 + 1/3) atan(1/sqrt 0.2) / sqrt 0.2 and EX_G_SMOOTH a / sqrt(a^2 - b^2)
 * (a = 0.45, b = 0.3); EX_NA for the others. */
double ex_g_inverse_integral(int g);

/* Importance function g over m bins for K = k samples into imp
 * (mcs_importance_init's status). */
mcs_status ex_importance_for(int g, size_t m, size_t k, mcs_importance *imp);

/* The note's power <|S_q|^2> at m bins and DFT index q for k samples of
 * random sampling (eq. 23, or eq. 45 with importance) or stratified sampling
 * (eq. 33's sinc^2 form, or eq. 50 with importance; these at the signed
 * frequency min(q, m - q), see ex_fold), through the importance function imp
 * over m bins (NULL without importance). EX_NA where undefined. */
double ex_closed_power_at(mcs_pattern_kind kind, const mcs_importance *imp, size_t m, size_t k,
                          size_t q);

/* Mean over the K - 1 inner stratum edges of a stratified pattern warped
 * through imp (the CDF levels j/K) of the distance to the nearest bin edge,
 * in bins: 0 when every stratum is whole bins, 0.5 at most. */
double ex_strata_misalignment(const mcs_importance *imp, size_t k);

/* A pattern of the section 4 tables for the limit checks: kind, importance
 * function g (EX_G_*), the tables' N and K. */
typedef struct {
    mcs_pattern_kind kind;
    int g;
    size_t n, k;
} ex_imp_run;

/* The note's power of run r at m bins and DFT index q: ex_closed_power_at
 * with g discretised over m bins. */
double ex_imp_closed_power(const ex_imp_run *r, size_t m, size_t q);

/* The exact power of run r at m bins where it is known in closed form,
 * stratified sampling whose strata are m/K whole bins (no g, flat g, g1b
 * with K dividing m): ex_whole_bin_power_at with the harmonic mean of g
 * (over N bins for the flat g, whose H is 1 but for rounding). EX_NA
 * otherwise. */
double ex_imp_exact_power(const ex_imp_run *r, size_t m, size_t q);

/* Mean over q in [1, m) of ex_imp_closed_power (exact = 0) or of
 * ex_imp_exact_power (exact = 1). */
double ex_imp_mean_power(const ex_imp_run *r, size_t m, int exact);

/* Relative gap of the closed form to the exact value at the larger N of the
 * limit checks (ex_large_n(N)), at index q, or of their means over k >= 1 if
 * q == 0; floor_ is the rounding scale at N (it shrinks with 1/N). EX_NA
 * where either is undefined or no larger N fits in MCS_MAX_N. */
double ex_imp_limit_gap(const ex_imp_run *r, size_t q, double floor_);

/* The exact power of stratified sampling whose strata are m/k whole bins,
 * through an importance function of harmonic mean h (1 without):
 * (k/m)/h + eq. 32 = eq. 33's exact form + (k/m)(1/h - 1) (mcspec's theory
 * tests check this). EX_NA where eq. 33's exact form is undefined. */
double ex_whole_bin_power_at(size_t m, size_t k, double h, size_t q);

#endif /* MCSPEC_EXAMPLE_IMPORTANCE_H */
