/* Section 4's bins outside the support: an importance function that is 0 on
 * some bins never draws them, so the estimator integrates f over the support
 * only, biased by -(1/N) sum of f there; the section prints that closed
 * form, mcspec's exact bias read-out and the measured bias side by side. */
#ifndef MCSPEC_EXAMPLES_OUTSIDE_H
#define MCSPEC_EXAMPLES_OUTSIDE_H

#include "report.h"

/* The runs' PCG32 streams start here (after sec4's own runs at 0x400 on). */
#define EX_OUTSIDE_STREAM 0x408u

/* Measures and prints the section for opt's N, K, trials and seed and the
 * integrand f[opt->n]; prints nothing when N leaves no bin outside the band
 * [0.6, 0.75) or none inside it. */
void ex_outside_section(const ex_options *opt, const double *f);

#endif /* MCSPEC_EXAMPLES_OUTSIDE_H */
