/* The trial loop of the mcspec command (see trials.h). */
#include "trials.h"
#include "cli.h"

#include <stdlib.h>

static mcs_status one_trial(const mcs_pattern *pat, mcs_rng *rng, size_t *bins, double *weights,
                            cli_sinks *sinks)
{
    mcs_status st = mcs_pattern_draw(pat, rng, pat->k, bins, weights, NULL);
    if (st == MCS_OK && sinks->spectrum != NULL)
        st = mcs_spectrum_add_bins(sinks->spectrum, pat->k, bins, weights);
    if (st == MCS_OK && sinks->estimate != NULL) {
        double value = 0.0;
        st = mcs_estimate_bins(pat->n, pat->k, sinks->f, bins, weights, &value);
        if (st == MCS_OK)
            st = mcs_welford_add(sinks->estimate, value);
    }
    return st;
}

int cli_run_trials(const char *cmd, const mcs_pattern *pat, uint64_t seed, uint64_t stream,
                   uint64_t first, uint64_t last, cli_sinks *sinks, cli_progress *progress)
{
    if ((sinks->f == NULL) != (sinks->estimate == NULL))
        return cli_internal(cmd, "trial loop: integrand and estimate must be given together");
    size_t *bins = cli_alloc(cmd, pat->k, sizeof *bins);
    double *weights = cli_alloc(cmd, pat->k, sizeof *weights);
    if (bins == NULL || weights == NULL) {
        free(bins);
        free(weights);
        return CLI_EXIT_FAIL;
    }
    mcs_rng rng;
    mcs_status st = mcs_rng_seed(&rng, seed, stream);
    for (uint64_t t = first; st == MCS_OK && t < last; ++t) {
        st = one_trial(pat, &rng, bins, weights, sinks);
        if (progress != NULL)
            cli_progress_update(progress, t + 1u);
    }
    free(bins);
    free(weights);
    if (st != MCS_OK)
        return cli_internal(cmd, "a trial failed: %s", mcs_status_str(st));
    return 0;
}
