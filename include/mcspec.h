/* mcspec: Fourier analysis of Monte Carlo sampling patterns.
 * Umbrella header: one header per module, in data-flow order. */
#ifndef MCSPEC_H
#define MCSPEC_H

#include "mcspec/config.h"
#include "mcspec/version.h"
#include "mcspec/status.h"
#include "mcspec/rng.h"
#include "mcspec/importance.h"
#include "mcspec/pattern.h"
#include "mcspec/estimate.h"
#include "mcspec/dft.h"
#include "mcspec/spectrum.h"
#include "mcspec/moment.h"
#include "mcspec/theory.h"
#include "mcspec/io.h"

#endif /* MCSPEC_H */
