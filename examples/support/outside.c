/* The section of examples/sec4_importance on bins outside the importance
 * function's support (outside.h). */
#include "outside.h"
#include "exact.h"
#include "importance.h"
#include "measure.h"
#include "readout.h"
#include "report.h"

/* g1 with g = 0 on the bins whose centre lies in [0.6, 0.75): never drawn,
 * so the estimator integrates f over the support only. Its runs are apart
 * from the others (their own streams after theirs): random and stratified. */
#define SUPPORT_RUNS 2
static mcs_importance imp_g1z;
static ex_run support_runs[SUPPORT_RUNS];
static ex_exact support_exacts[SUPPORT_RUNS];
static const mcs_pattern_kind support_kinds[SUPPORT_RUNS] = {MCS_PATTERN_RANDOM,
                                                            MCS_PATTERN_STRATIFIED};
static const char *const support_names[SUPPORT_RUNS] = {"random+g1z", "stratified+g1z"};

/* 1 if the band holds a bin and leaves one outside it (else the section
 * has nothing to show: small N), and the runs went. */
static int measure_support(const ex_options *opt, const double *f)
{
    static double w[MCS_MAX_N];
    int zeros = 0, others = 0;
    if (ex_importance_for(EX_G_FOLLOW, opt->n, opt->k, &imp_g1z) != MCS_OK)
        return 0;
    for (size_t b = 0; b < opt->n; ++b) {
        const double x = ((double)b + 0.5) / (double)opt->n;
        const int out = x >= 0.6 && x < 0.75;
        w[b] = out ? 0.0 : imp_g1z.g[b];
        zeros += out;
        others += !out;
    }
    if (zeros == 0 || others == 0 || mcs_importance_init(&imp_g1z, opt->n, w) != MCS_OK)
        return 0;
    for (int r = 0; r < SUPPORT_RUNS; ++r) {
        ex_run *run = &support_runs[r];
        mcs_status st = ex_run_setup(run, &support_exacts[r], NULL, support_kinds[r], opt->n,
                                     opt->k, &imp_g1z, opt->seed, EX_OUTSIDE_STREAM + (uint64_t)r);
        if (st == MCS_OK) {
            ex_run_integrand(run, f);
            st = ex_run_go(run, opt->trials, NULL, NULL);
        }
        if (st != MCS_OK)
            return 0;
    }
    return 1;
}

/* The bias <I> - mean of f: closed, -(1/N) sum of f over the bins with g =
 * 0 (summed here); exact, mcspec's bias read-out; measured, the mean of I
 * less the mean of f, with the mean's standard error. */
void ex_outside_section(const ex_options *opt, const double *f)
{
    if (!measure_support(opt, f))
        return;
    const size_t n_bins = opt->n, k_samples = opt->k;
    ex_heading(opt, "bins outside the support (g = 0 on [0.6, 0.75)): <I> = mean of f less "
                    "(1/N) sum of f there");
    double fbar = 0.0, outside = 0.0;
    for (size_t b = 0; b < n_bins; ++b) {
        fbar += f[b] / (double)n_bins;
        outside += imp_g1z.g[b] == 0.0 ? f[b] : 0.0;
    }
    for (int r = 0; r < SUPPORT_RUNS; ++r) {
        const ex_exact *ex = &support_exacts[r];
        ex_estimator_mean_row(opt, "sec4", support_names[r], ex, &support_runs[r], f);
        double bias = 0.0, se = 0.0;
        const mcs_theory *th = ex_exact_theory(ex);
        const mcs_status st = th != NULL ? mcs_theory_bias(th, n_bins, k_samples, f, &bias)
                                         : mcs_theory_spectrum_bias(&ex->spectrum, n_bins,
                                                                    k_samples, f, &bias);
        const double exact = ex_or_na(st, &bias);
        const double meas = ex_mean(&support_runs[r].estimate[0], &se) - fbar;
        ex_row row = ex_row_of("sec4", "<I> - mean f", "support", support_names[r], EX_NO_FREQ,
                               EX_NO_FREQ, -outside / (double)n_bins, exact, meas, se, 1e-12);
        ex_row_print(opt, &row);
    }
}

