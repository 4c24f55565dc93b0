/* Helpers of the pair correlation (pcf.c, pcf_power.c) that the exact
 * values (theory/theory_pcf.c) share; private header. */
#ifndef MCSPEC_PCF_INTERNAL_H
#define MCSPEC_PCF_INTERNAL_H

#include <stddef.h>

#include "mcspec/pcf.h"

/* The mean spacing of k points in dim dimensions: 1/k, 1/sqrt(k). */
double mcs_pcf_spacing_(size_t dim, size_t k);

/* The pairs' cutoff in mean spacings: R, plus 8 sigma for the kernel. */
double mcs_pcf_cutoff_(const mcs_pcf *acc);

/* The measure of the toroidal ring [r0, r1), absolute units. */
double mcs_pcf_ring_(size_t dim, double r0, double r1);

/* MCS_OK for a header init made that holds values adds make
 * (MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_INVARIANT otherwise). */
mcs_status mcs_pcf_check_(const mcs_pcf *acc);

/* Whether a set of k points fits acc (MCS_ERR_K_RANGE if not), its grid
 * side (0: all pairs) and the work it needs. */
mcs_status mcs_pcf_set_check_(const mcs_pcf *acc, size_t k, size_t *side, size_t *bytes);

/* One checked set's g per bin into g[acc->bins]. */
void mcs_pcf_values_(const mcs_pcf *acc, size_t k, const double *points, size_t side, void *work,
                     double *g);

/* J1(x), the Bessel function of the first kind, to rounding (pcf_power.c). */
double mcs_pcf_bessel_j1_(double x);

#endif /* MCSPEC_PCF_INTERNAL_H */
