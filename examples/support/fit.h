/* Shared by the section examples: power laws fitted on a log-log scale. */
#ifndef MCSPEC_EXAMPLE_FIT_H
#define MCSPEC_EXAMPLE_FIT_H

#include <stddef.h>

/* Slope of log y against log x by least squares over the count points with
 * x > 0 and y > 0 (EX_NA if fewer than 2). With se (standard errors of the
 * y, or NULL) each point weighs (y / se)^2, the inverse variance of log y,
 * and *slope_se (if not NULL) is the slope's standard error; without se, or
 * where an se is 0, the points weigh alike and *slope_se is EX_NA. */
double ex_loglog_slope(size_t count, const double *x, const double *y, const double *se,
                       double *slope_se);

#endif /* MCSPEC_EXAMPLE_FIT_H */
