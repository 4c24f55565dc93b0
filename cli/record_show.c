/* mcspec show of the measure records (pcf, integrate, discrepancy,
 * spacing): the table and CSV their commands print, rebuilt from the record
 * (see record.h). Columns a record cannot rebuild are empty and said so in
 * mcspec show --help and docs/format.md: the integrate predictions (they
 * need the spectrum and the integrands), the pcf exact column of point files
 * (the record does not keep --exact), and the spectral rows of mcspec stats
 * (the spacing record holds the distances only). */
#include "cli.h"
#include "measure_rows.h"
#include "output.h"
#include "record.h"

#include "mcspec.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* ---- pcf: r,pcf,pcf_stderr,exact ---- */

/* The 2D pattern a record's provenance names (mcspec pcf KIND), or -1. */
static int pattern2d_of(const mcs_io_provenance *prov)
{
    if (prov->source != MCS_IO_SOURCE_PATTERN || prov->dim != 2u)
        return -1;
    for (int i = 0; i < MCS_PATTERN2D_KIND_COUNT; ++i)
        if (strcmp(prov->pattern, mcs_pattern2d_kind_str((mcs_pattern2d_kind)i)) == 0)
            return i;
    return -1;
}

static void show_pcf(int csv, const mcs_pcf *acc, const mcs_io_provenance *prov)
{
    const int kind = pattern2d_of(prov);
    mcs_pattern2d pat;
    /* a 2D pattern's E g; random points' in 1D too (mcs_pcf_exact with no pattern) */
    const int random1d = prov->source == MCS_IO_SOURCE_PATTERN && prov->dim == 1u &&
                         strcmp(prov->pattern, "random") == 0;
    const int exact = random1d || (kind >= 0 && mcs_pattern2d_init(&pat, (mcs_pattern2d_kind)kind,
                                                                   (size_t)prov->k, 0u, 0u) == MCS_OK);
    if (csv) {
        puts("r,pcf,pcf_stderr,exact");
    } else {
        printf("r: bin centre; z = (pcf - exact) / stderr; exact: %s\n\n%9s %13s %13s %13s %8s\n",
               exact ? "E g of the pattern the record names"
                     : "none (a record of point files keeps no --exact)",
               "r", "pcf", "pcf_stderr", "exact", "z");
    }
    for (size_t b = 0; b < acc->bins; ++b) {
        double v[4] = {NAN, NAN, NAN, NAN};
        (void)mcs_pcf_radius_at(acc, b, &v[0]);
        (void)mcs_pcf_mean(acc, b, &v[1]);
        (void)mcs_pcf_stderr(acc, b, &v[2]);
        if (exact && mcs_pcf_exact(acc, random1d ? NULL : &pat, b, &v[3]) != MCS_OK)
            v[3] = NAN;
        cli_pcf_row(csv, v);
    }
}

/* ---- integrate: family,k,mse,mse_stderr,exact,predicted,... ---- */

static void show_integrate(int csv, const mcs_integrate *acc)
{
    double v[10];
    for (int i = 0; i < 10; ++i)
        v[i] = (double)NAN;
    v[0] = cli_or_nan(mcs_integrate_mse(acc, &v[0]), &v[0]);
    v[1] = cli_or_nan(mcs_integrate_mse_stderr(acc, &v[1]), &v[1]);
    v[2] = cli_or_nan(mcs_integrate_exact(acc, &v[2]), &v[2]);
    v[6] = (double)acc->sq.count;
    v[8] = cli_integrate_rate(acc->dim, (int)acc->family, 0);
    v[9] = cli_integrate_rate(acc->dim, (int)acc->family, 1);
    const char *family = mcs_integrand_family_str(acc->family);
    char k[32] = "";
    if (acc->k_min == acc->k_max) /* a merge of records of other K: no one K */
        snprintf(k, sizeof k, "%zu", acc->k_min);
    if (csv) {
        puts("family,k,mse,mse_stderr,exact,predicted,predicted_tail,freq,sets,slope,rate_random,"
             "rate_jittered");
    } else {
        printf("mse: mean over sets of the squared error; z = (mse - exact) / stderr; predicted,\n"
               "tail and F: not in a record (they need the sets' spectrum and integrands)\n\n");
        printf("%-17s %8s %12s %11s %12s %7s %12s %10s %6s\n", "family", "K", "mse", "stderr",
               "exact", "z", "predicted", "tail", "F");
    }
    cli_integrate_row(csv, family, k, v);
}

/* The kind a pattern record names (mcspec discrepancy KIND --save, mcspec
 * stats KIND --save), or NULL for point files: the exact columns follow it. */
static const char *drawn_kind(const mcs_io_provenance *prov)
{
    return prov->source == MCS_IO_SOURCE_PATTERN ? prov->pattern : NULL;
}

/* ---- discrepancy: the rows of mcspec discrepancy ---- */

static void show_discrepancy(int csv, const mcs_discrepancy *acc, const mcs_io_provenance *prov)
{
    double exact[MCS_DISCREPANCY_MEASURES];
    cli_discrepancy_exact(drawn_kind(prov), acc->dim, (size_t)prov->k, exact);
    uint64_t star = 0u, sets = 0u;
    (void)mcs_discrepancy_count(acc, MCS_DISCREPANCY_STAR, &star);
    (void)mcs_discrepancy_count(acc, MCS_DISCREPANCY_L2_STAR, &sets);
    if (!csv) {
        printf("value: mean over the sets of D^2; root = sqrt(value); exact_random: E[D^2] of "
               "independent uniform points; exact: E[D^2] of the sets' kind (- where not "
               "known); z = (value - exact, else exact_random) / stderr\n");
        if (acc->dim == 2u && star != sets)
            printf("star: not computed (a set has more than %d points)\n",
                   MCS_DISCREPANCY_STAR_MAX_K);
    }
    cli_discrepancy_rows(csv, acc, exact);
}

/* ---- spacing: the distance rows of mcspec stats ---- */

static void show_spacing(int csv, const mcs_spacing *acc, const mcs_io_provenance *prov)
{
    double exact[MCS_SPACING_STATISTICS];
    cli_spacing_exact(drawn_kind(prov), acc->dim, (size_t)prov->k, exact);
    if (!csv)
        printf("toroidal distances as fractions of the maximal packing distance; value: mean "
               "over the sets\n(the spectral rows of mcspec stats are not in a spacing "
               "record)\nexact: the expectation for independent uniform points (- where not "
               "known); z = (value - exact) / stderr\n");
    cli_spacing_rows(csv, acc, exact);
}

int cli_show_measure(int csv, const cli_acc *acc, const mcs_io_provenance *prov,
                     const char *title, const char *origin)
{
    if (!csv) {
        const mcs_pcf *p = acc->obj;
        printf("%s\n%s\n", title, origin);
        if (acc->kind == MCS_IO_KIND_PCF)
            printf("K = %zu to %zu points per set\n", p->k_min, p->k_max);
        else if (acc->kind == MCS_IO_KIND_DISCREPANCY)
            printf("K = %zu to %zu points per set\n", ((const mcs_discrepancy *)acc->obj)->k_min,
                   ((const mcs_discrepancy *)acc->obj)->k_max);
        else if (acc->kind == MCS_IO_KIND_SPACING)
            printf("K = %zu to %zu points per set\n", ((const mcs_spacing *)acc->obj)->k_min,
                   ((const mcs_spacing *)acc->obj)->k_max);
    }
    switch (acc->kind) {
    case MCS_IO_KIND_PCF: show_pcf(csv, acc->obj, prov); break;
    case MCS_IO_KIND_INTEGRATE: show_integrate(csv, acc->obj); break;
    case MCS_IO_KIND_DISCREPANCY: show_discrepancy(csv, acc->obj, prov); break;
    default: show_spacing(csv, acc->obj, prov); break;
    }
    return 0;
}
