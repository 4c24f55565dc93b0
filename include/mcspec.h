/* mcspec: Fourier analysis of Monte Carlo sampling patterns.
 * Umbrella header: one header per module, in data-flow order (patterns, then
 * the estimator and the accumulators that consume them, then the exact
 * moments and closed forms they are checked against). */
#ifndef MCSPEC_H
#define MCSPEC_H

#include "mcspec/config.h"
#include "mcspec/version.h"
#include "mcspec/status.h"
#include "mcspec/rng.h"
#include "mcspec/importance.h"
#include "mcspec/pattern.h"
#include "mcspec/sampler.h"
#include "mcspec/projections.h"
#include "mcspec/bluenoise.h"
#include "mcspec/pattern2d.h"
#include "mcspec/estimate.h"
#include "mcspec/welford.h"
#include "mcspec/dft.h"
#include "mcspec/nufft.h"
#include "mcspec/spectrum.h"
#include "mcspec/moment.h"
#include "mcspec/autocorr.h"
#include "mcspec/pointset.h"
#include "mcspec/pointset2d.h"
#include "mcspec/spectrum2d.h"
#include "mcspec/discrepancy.h"
#include "mcspec/spacing.h"
#include "mcspec/integrand.h"
#include "mcspec/integrate.h"
#include "mcspec/pcf.h"
#include "mcspec/radial.h"
#include "mcspec/theory.h"
#include "mcspec/owen.h"
#include "mcspec/eq.h"
#include "mcspec/io.h"
#include "mcspec/abi.h"

#endif /* MCSPEC_H */
