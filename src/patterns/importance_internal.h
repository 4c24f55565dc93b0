/* Private: the unchecked parts of the importance module shared with pattern.c
 * (the warp) and the closed forms (Q_k). */
#ifndef MCSPEC_IMPORTANCE_INTERNAL_H
#define MCSPEC_IMPORTANCE_INTERNAL_H

#include <stddef.h>
#include "mcspec/importance.h"

/* imp valid, u in [0,1): bin whose CDF interval holds u, and the warped x. */
void mcs_importance_warp_unchecked(const mcs_importance *imp, double u, double *x, size_t *bin);

/* Largest x in bin b of n (floor(n x) = b) close to (b + t)/n, t in [0,1). */
double mcs_importance_point_in_bin(size_t n, size_t b, double t);

/* imp valid, freq < imp->n: Q_freq of eq. 43 (see mcs_importance_q). */
void mcs_importance_q_unchecked(const mcs_importance *imp, size_t freq, double *re, double *im);

#endif /* MCSPEC_IMPORTANCE_INTERNAL_H */
