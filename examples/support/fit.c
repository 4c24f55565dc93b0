#include "fit.h"
#include "report.h"

#include <math.h>

/* Weight of point i: the inverse variance of log y_i, or 1 (weighted = 0). */
static double weight_of(const double *y, const double *se, size_t i, int weighted)
{
    return weighted ? (y[i] / se[i]) * (y[i] / se[i]) : 1.0;
}

double ex_loglog_slope(size_t count, const double *x, const double *y, const double *se,
                       double *slope_se)
{
    int weighted = se != NULL;
    size_t used = 0;
    for (size_t i = 0; i < count; ++i)
        if (x[i] > 0.0 && y[i] > 0.0) {
            ++used;
            weighted = weighted && se[i] > 0.0;
        }
    if (slope_se != NULL)
        *slope_se = EX_NA;
    if (used < 2u)
        return EX_NA;
    double sw = 0.0, sx = 0.0, sy = 0.0;
    for (size_t i = 0; i < count; ++i)
        if (x[i] > 0.0 && y[i] > 0.0) {
            const double w = weight_of(y, se, i, weighted);
            sw += w;
            sx += w * log(x[i]);
            sy += w * log(y[i]);
        }
    const double mx = sx / sw, my = sy / sw;
    double sxx = 0.0, sxy = 0.0;
    for (size_t i = 0; i < count; ++i)
        if (x[i] > 0.0 && y[i] > 0.0) {
            const double w = weight_of(y, se, i, weighted), dx = log(x[i]) - mx;
            sxx += w * dx * dx;
            sxy += w * dx * (log(y[i]) - my);
        }
    if (!(sxx > 0.0))
        return EX_NA;
    if (weighted && slope_se != NULL)
        *slope_se = 1.0 / sqrt(sxx);
    return sxy / sxx;
}
