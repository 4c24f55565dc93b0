/* The sizes and alignments of the public structs as this build of the
 * library lays them out, for callers that hold the objects as opaque bytes
 * (the Python package, python/mcspec, and any other foreign-function
 * binding): they ask here instead of copying a layout that belongs to the C
 * compiler and to the capacities (config.h) the library was built with. */
#ifndef MCSPEC_ABI_H
#define MCSPEC_ABI_H

#include <stddef.h>
#include "status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The public structs, by the header that declares them. */
typedef enum {
    MCS_ABI_RNG = 0,          /* mcs_rng (rng.h) */
    MCS_ABI_IMPORTANCE = 1,   /* mcs_importance (importance.h) */
    MCS_ABI_PATTERN = 2,      /* mcs_pattern (pattern.h) */
    MCS_ABI_PATTERN2D = 3,    /* mcs_pattern2d (pattern2d.h) */
    MCS_ABI_SAMPLER = 4,      /* mcs_sampler (sampler.h) */
    MCS_ABI_WELFORD = 5,      /* mcs_welford (welford.h) */
    MCS_ABI_DFT = 6,          /* mcs_dft (dft.h) */
    MCS_ABI_SPECTRUM = 7,     /* mcs_spectrum (spectrum.h) */
    MCS_ABI_MOMENT = 8,       /* mcs_moment (moment.h) */
    MCS_ABI_AUTOCORR = 9,     /* mcs_autocorr (autocorr.h) */
    MCS_ABI_POINTSET = 10,    /* mcs_pointset, the header only (pointset.h) */
    MCS_ABI_POINTSET2D = 11,  /* mcs_pointset2d, the header only (pointset2d.h) */
    MCS_ABI_SPECTRUM2D = 12,  /* mcs_spectrum2d, the header only (spectrum2d.h) */
    MCS_ABI_THEORY = 13,      /* mcs_theory (theory.h) */
    MCS_ABI_THEORY_SPECTRUM = 14, /* mcs_theory_spectrum (theory.h) */
    MCS_ABI_DISCREPANCY = 15, /* mcs_discrepancy (discrepancy.h) */
    MCS_ABI_SPACING = 16,     /* mcs_spacing (spacing.h) */
    MCS_ABI_PROVENANCE = 17,  /* mcs_io_provenance (io.h) */
    MCS_ABI_PCF = 18,         /* mcs_pcf, the header only (pcf.h) */
    MCS_ABI_INTEGRAND = 19,   /* mcs_integrand (integrand.h) */
    MCS_ABI_INTEGRATE = 20,   /* mcs_integrate, the header only (integrate.h) */
    MCS_ABI_PROJECTIONS = 21, /* mcs_projections, the header only (projections.h) */
    MCS_ABI_PROJECTIONS_PAIR = 22, /* mcs_projections_pair (projections.h) */
    MCS_ABI_BLUENOISE_PARAMS = 23, /* mcs_bluenoise_params (bluenoise.h) */
    MCS_ABI_TYPE_COUNT = 24
} mcs_abi_type;

/* sizeof and _Alignof of the struct type in this build, into *size and
 * *align (either may be NULL when not wanted, not both). MCS_ERR_NULL (both
 * NULL), MCS_ERR_KIND (type not one of the list), MCS_ERR_ALIAS (size and
 * align one object). Outputs untouched on error. */
mcs_status mcs_abi_sizeof(mcs_abi_type type, size_t *size, size_t *align);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_ABI_H */
