/* mcspec integrate's state (cmd_integrate.c), shared with its figure
 * (integrate_plot.c). */
#ifndef MCSPEC_CLI_INTEGRATE_H
#define MCSPEC_CLI_INTEGRATE_H

#include <stddef.h>
#include <stdint.h>

#include "input.h"
#include "mcspec.h"

#define CLI_INTEG_FAMILIES MCS_INTEGRAND_FAMILIES
#define CLI_INTEG_MAX_KS 32    /* --k given at most this often */
#define CLI_INTEG_MAX_FILES 64 /* point files on one command line */

typedef struct {
    size_t dim, m, freq, sets_opt, ks[CLI_INTEG_MAX_KS], nks;
    uint64_t seed, sets;
    int wrap, csv, freq_given, dim_given;
    const char *family, *plot, *kind, *exact, *files[CLI_INTEG_MAX_FILES];
    const char *save; /* --save FILE: the record of the one row (cmd_integrate.c) */
    size_t nfiles;
} integ_opts;

/* One point count K: an accumulator per family, the spectrum of its sets
 * and the integrands drawn for them (for the prediction). */
typedef struct {
    size_t k, freq;
    uint64_t sets;
    mcs_integrate acc[CLI_INTEG_FAMILIES];
    mcs_integrand *fs[CLI_INTEG_FAMILIES];
    size_t nfs[CLI_INTEG_FAMILIES], cap[CLI_INTEG_FAMILIES];
    mcs_pointset2d ps2;
    mcs_pointset ps1;
    void *mem;
    double mse[CLI_INTEG_FAMILIES], se[CLI_INTEG_FAMILIES], exact[CLI_INTEG_FAMILIES], pred[CLI_INTEG_FAMILIES], tail[CLI_INTEG_FAMILIES];
} group;

typedef struct {
    const integ_opts *o;
    size_t dim;
    int fam_on[CLI_INTEG_FAMILIES];
    mcs_rng frng[CLI_INTEG_FAMILIES];
    group *g;
    size_t ng;
    mcs_integrate_reference ref;
    size_t strata[2];
    const cli_pointset_stats *stats; /* files: the reader's */
    const char *name;                /* files: the one being read */
    double slope[CLI_INTEG_FAMILIES];
} integ_ctx;

/* The log-log figure of the MSE against K per family, with the fitted
 * lines and (where the rows have it) the exact MSE, into path by gnuplot
 * (plot.h). Returns 0 or an exit status after one line on stderr. */
int cli_integrate_plot(const char *cmd, const char *path, const integ_ctx *c);

#endif /* MCSPEC_CLI_INTEGRATE_H */
