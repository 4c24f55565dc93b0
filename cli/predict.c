/* Theory look-up of the mcspec command (see predict.h). */
#include "predict.h"
#include "cli.h"
#include "output.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int divides(size_t k, size_t n)
{
    return k != 0u && n % k == 0u;
}

/* K^2/N: S_0 = K / sqrt(N) for every trial without importance (eq. 17). */
static double power0_plain(const mcs_pattern *pat)
{
    return (double)pat->k * (double)pat->k / (double)pat->n;
}

/* The note's closed form as printed, at freq in [0, N/2]; NaN outside its
 * domain (MCS_ERR_DOMAIN and the like are expected here: the note defines
 * each form on part of the space). */
static double closed_form(const mcs_pattern *pat, size_t freq)
{
    size_t n = pat->n, k = pat->k;
    double v = 0.0;
    if (pat->importance == NULL) {
        if (freq == 0u)
            return power0_plain(pat);
        switch (pat->kind) {
        case MCS_PATTERN_RANDOM:
            return cli_or_nan(mcs_eq23_random_power(n, k, freq, &v), &v);
        case MCS_PATTERN_STRATIFIED:
        case MCS_PATTERN_HOMOGENIZED: /* a cyclic shift leaves |S_k| as it is */
            return cli_or_nan(mcs_eq33_stratified_power_limit(n, k, freq, &v), &v);
        case MCS_PATTERN_UNIFORM:
        case MCS_PATTERN_JITTER:
            return cli_or_nan(mcs_eq37_jitter_power(n, k, freq, &v), &v);
        }
        return (double)NAN;
    }
    const mcs_importance *imp = pat->importance;
    if (pat->kind == MCS_PATTERN_RANDOM)
        return freq == 0u ? cli_or_nan(mcs_eq46_importance_power0(imp, k, &v), &v)
                          : cli_or_nan(mcs_eq45_importance_power(imp, k, freq, &v), &v);
    /* Eq. 51 is eq. 46 (eq.h); the note states it for K dividing N, as eq. 50. */
    if (pat->kind == MCS_PATTERN_STRATIFIED && divides(k, n))
        return freq == 0u ? cli_or_nan(mcs_eq46_importance_power0(imp, k, &v), &v)
                          : cli_or_nan(mcs_eq50_importance_stratified_power(imp, k, freq, &v), &v);
    return (double)NAN;
}

static const char *closed_source(const mcs_pattern *pat)
{
    int whole = divides(pat->k, pat->n);
    if (pat->importance != NULL) {
        if (pat->kind == MCS_PATTERN_RANDOM)
            return "eq. 45 (k = 0: eq. 46)";
        if (pat->kind == MCS_PATTERN_STRATIFIED && whole)
            return "eq. 50 (k = 0: eq. 51)";
        return "";
    }
    switch (pat->kind) {
    case MCS_PATTERN_RANDOM:
        return "eq. 23 (k = 0: eq. 17)";
    case MCS_PATTERN_STRATIFIED:
    case MCS_PATTERN_HOMOGENIZED:
        return whole ? "eq. 33, its N -> infinity form (k = 0: eq. 17)" : "eq. 17 at k = 0 only";
    case MCS_PATTERN_UNIFORM:
    case MCS_PATTERN_JITTER:
        return whole ? "eq. 37" : "eq. 17 at k = 0 only";
    }
    return "";
}

/* The exact engine for a pattern: mcs_theory (exact moments) up to
 * MCS_MAX_COV_N, above it the O(N)-memory mcs_theory_spectrum (every kind,
 * with or without importance: it copies what it needs from pat). */
typedef struct {
    mcs_theory *th;
    mcs_theory_spectrum *ts;
    const char *source;
} exact_engine;

/* Allocates and initialises e's engine for pat: 0 with *st the init's
 * status, or CLI_EXIT_FAIL when out of memory (said). */
static int engine_open(const char *cmd, const mcs_pattern *pat, exact_engine *e, mcs_status *st)
{
    *e = (exact_engine){NULL, NULL, "mcs_theory (exact moments)"};
    if (pat->n <= (size_t)MCS_MAX_COV_N) {
        e->th = cli_alloc(cmd, 1, sizeof *e->th);
        *st = e->th != NULL ? mcs_theory_init(e->th, pat) : MCS_ERR_NULL;
        return e->th != NULL ? 0 : CLI_EXIT_FAIL;
    }
    e->source = "mcs_theory_spectrum (exact, any N)";
    e->ts = cli_alloc(cmd, 1, sizeof *e->ts);
    *st = e->ts != NULL ? mcs_theory_spectrum_init(e->ts, pat) : MCS_ERR_NULL;
    return e->ts != NULL ? 0 : CLI_EXIT_FAIL;
}

/* <|S_k|^2> at k = 0..N/2 from the engine: mcs_theory one frequency at a
 * time, mcs_theory_spectrum all N at once into a scratch array. */
static int engine_power(const char *cmd, const exact_engine *e, const mcs_pattern *pat,
                        cli_prediction *pred, mcs_status *st)
{
    if (e->th != NULL) {
        for (size_t f = 0; *st == MCS_OK && f < pred->nfreq; ++f)
            *st = mcs_theory_power(e->th, f, &pred->exact[f]);
        return 0;
    }
    double *power = cli_alloc(cmd, pat->n, sizeof *power);
    if (power == NULL)
        return CLI_EXIT_FAIL;
    *st = mcs_theory_power_spectrum(e->ts, pat->n, power);
    for (size_t f = 0; *st == MCS_OK && f < pred->nfreq; ++f)
        pred->exact[f] = power[f];
    free(power);
    return 0;
}

static void engine_close(exact_engine *e)
{
    free(e->th);
    free(e->ts);
}

static int theory_power(const char *cmd, const mcs_pattern *pat, cli_prediction *pred)
{
    exact_engine e;
    mcs_status st = MCS_OK;
    int rc = engine_open(cmd, pat, &e, &st);
    if (rc == 0 && st == MCS_OK)
        rc = engine_power(cmd, &e, pat, pred, &st);
    engine_close(&e);
    if (rc != 0)
        return rc;
    if (st != MCS_OK)
        return cli_internal(cmd, "exact theory failed: %s", mcs_status_str(st));
    snprintf(pred->exact_source, sizeof pred->exact_source, "%s", e.source);
    return 0;
}

int cli_predict_power(const char *cmd, const mcs_pattern *pat, cli_prediction *pred)
{
    pred->nfreq = pat->n / 2u + 1u;
    pred->exact_source[0] = '\0';
    snprintf(pred->closed_source, sizeof pred->closed_source, "%s", closed_source(pat));
    for (size_t f = 0; f < pred->nfreq; ++f) {
        pred->closed[f] = closed_form(pat, f);
        pred->exact[f] = (double)NAN;
    }
    return theory_power(cmd, pat, pred);
}

/* Var[I] (bias 0) or the bias (bias 1) of f under pat from whichever exact
 * engine serves pat's N; *source names it. */
static int exact_of_f(const char *cmd, const mcs_pattern *pat, const double *f, int bias,
                      double *out, const char **source)
{
    exact_engine e;
    mcs_status st = MCS_OK;
    *out = (double)NAN;
    *source = "";
    int rc = engine_open(cmd, pat, &e, &st);
    if (rc == 0 && st == MCS_OK && bias)
        st = e.th != NULL ? mcs_theory_bias(e.th, pat->n, pat->k, f, out)
                          : mcs_theory_spectrum_bias(e.ts, pat->n, pat->k, f, out);
    else if (rc == 0 && st == MCS_OK)
        st = e.th != NULL ? mcs_theory_variance(e.th, pat->n, pat->k, f, out)
                          : mcs_theory_spectrum_variance(e.ts, pat->n, pat->k, f, out);
    engine_close(&e);
    if (rc != 0)
        return rc;
    *source = e.source;
    if (st != MCS_OK)
        return cli_internal(cmd, "exact %s failed: %s", bias ? "bias" : "variance",
                            mcs_status_str(st));
    return 0;
}

int cli_predict_variance(const char *cmd, const mcs_pattern *pat, const double *f, double *out,
                         const char **source)
{
    return exact_of_f(cmd, pat, f, 0, out, source);
}

int cli_predict_bias(const char *cmd, const mcs_pattern *pat, const double *f, double *out)
{
    const char *source = NULL;
    return exact_of_f(cmd, pat, f, 1, out, &source);
}
