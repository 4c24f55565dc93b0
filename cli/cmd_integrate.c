/* mcspec integrate: the integration error of point sets (read from files,
 * or drawn from a named pattern) on families of integrands with exact
 * integrals: per family and point count the mean squared error with its
 * standard error, the exact MSE where it is known, the MSE predicted from
 * the measured spectrum (the point-set eq. 14) and the fitted convergence
 * slope beside the published rates (integrand.h, integrate.h). */
#include "atomic.h"
#include "cli.h"
#include "input.h"
#include "kindsets.h"
#include "measure_rows.h"
#include "output.h"
#include "plot.h"
#include "progress.h"
#include "record.h"
#include "integrate.h"
#include "source2d.h"

#include "mcspec.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define CMD "mcspec integrate"
#define CSV_HEADER "family,k,mse,mse_stderr,exact,predicted"
#define CSV_EXTRA ",predicted_tail,freq,sets,slope,rate_random,rate_jittered"
#define MAX_FREQ_2D 1024 /* --freq caps: the prediction is O(T M F^d) */
#define MAX_FREQ_1D 1048576
#define DEFAULT_FREQ_2D 128 /* the default's caps: a few seconds of prediction at M T = 1024 */
#define DEFAULT_FREQ_1D 65536

static const char help[] =
    "usage: mcspec integrate [options] FILE [FILE ...]\n"
    "       mcspec integrate KIND --k K [--k K2 ...] [--sets T] [--seed S] [options]\n"
    "\n"
    "The integration error of point sets on families of integrands with exact\n"
    "integrals over [0,1)^D, D = 1 or 2. For every set and every family, M fresh\n"
    "integrands are drawn (PCG32 seeded from --seed, so a run is reproducible);\n"
    "the set's squared error is the mean over them of ((1/K) sum_j f(x_j) - I)^2.\n"
    "Per family and point count K: its mean over the sets (mse) and standard\n"
    "error (over sets, integrands included), the exact MSE where theory gives it\n"
    "(random points: Var[f] / K; the jittered grid and 1D stratified: the sum\n"
    "over strata of the variances within them / K^2), and the MSE predicted from\n"
    "the sets' own mean periodogram, (1/K) sum over 0 < |k|_inf <= F of\n"
    "|f^(k)|^2 <P(k)> (the point-set eq. 14, exact for these randomly centred\n"
    "families) for the torus-periodic families, with the bound predicted_tail on\n"
    "what the truncation at F leaves out: the true value lies in [predicted,\n"
    "predicted + tail]. Then the least-squares slope of log mse on log K per\n"
    "family, beside the published rates (random -1; jittered -(1 + 2/D) smooth,\n"
    "-(1 + 1/D) discontinuous).\n"
    "Families: gaussian (a bump on the square, by erf), gaussian_periodic (the\n"
    "same periodised on the torus), heaviside (a half-plane across the square;\n"
    "1D a step), disk (on the torus; 1D an arc), cosine (products of 1 + a cos(2\n"
    "pi m x + phi), integral 1), and utk's blinn_phong (a Blinn-Phong lobe lit by\n"
    "a quad light, 2D only) and gaussian_mixture (Gaussians clipped to random\n"
    "boxes), integrated once per integrand by adaptive quadrature (error below\n"
    "1e-12 relative; no 2D jittered exact value). Definitions: docs/measures.md.\n"
    "\n"
    "Input (FILE, '-' for standard input): one point per line, D coordinates in\n"
    "[0,1); a line starting with '#' ends a set (utk's convention). Sets are\n"
    "grouped by their K, one row per family and K (give files of growing K).\n"
    "KIND: the 2D kinds of mcspec pattern (" CLI_SOURCE2D_NAMES ")\n"
    "or, with --dim 1, its 1D kinds (random, stratified, homogenized, uniform,\n"
    "jitter), and the other kinds of mcspec sample in 1D or 2D (blue noise:\n"
    "dart-throwing, poisson-disk, lloyd, pmj02, pmj02bn; padded, lattice,\n"
    "halton-permuted, halton-owen), which have no exact column.\n"
    "\n"
    "Options:\n"
    "  --k K            points per set (KIND; give it again for more sizes)\n"
    "  --sets T         sets per K (KIND; default 64)\n"
    "  --seed S         seed of the points and integrands (default 1)\n"
    "  --integrands M   integrands per set and family (default 16)\n"
    "  --family LIST    these families only, NAME[,NAME...] (default: all seven;\n"
    "                   all six in 1D)\n"
    "  --dim D          1 or 2 (KIND: default 2; files: the file's)\n"
    "  --freq F         cutoff of the prediction, O(T M F^D) work (default 2 ceil(sqrt K)\n"
    "                   up to " CLI_STR(DEFAULT_FREQ_2D) " in 2D, 4 K up to " CLI_STR(DEFAULT_FREQ_1D) " in 1D; at most " CLI_STR(MAX_FREQ_2D) " in 2D\n"
    "                   and " CLI_STR(MAX_FREQ_1D) " in 1D); 0: no prediction\n"
    "  --wrap           files: take coordinates modulo 1\n"
    "  --exact KIND     files: the exact column for sets of that kind: random, or\n"
    "                   jittered (2D: the most nearly square m x n grid of K cells,\n"
    "                   as mcspec pattern draws it; 1D: K strata, = stratified)\n"
    "  --plot FILE.png  log-log figure of mse against K with the fitted slopes (or .svg)\n"
    "  --save FILE      also save the accumulator of the one row (an integrate record,\n"
    "                   docs/format.md: needs --family and one K, one FILE or KIND)\n"
    "                   for mcspec merge and show, written atomically; show leaves\n"
    "                   predicted, predicted_tail, freq and slope empty\n"
    "  --csv            print CSV only: the header, exactly\n"
    "                   " CSV_HEADER CSV_EXTRA "\n"
    "                   and one row per family and K (an empty field: no value)\n"
    "  --help           this text\n"
    "\n"
    "Exit status: 0 on success, 2 on bad usage or input (one line on stderr).\n";

/* The family named by name[0..len), or -1. */
static int family_of(const char *name, size_t len)
{
    for (int f = 0; f < CLI_INTEG_FAMILIES; ++f) {
        const char *s = mcs_integrand_family_str((mcs_integrand_family)f);
        if (strlen(s) == len && strncmp(name, s, len) == 0)
            return f;
    }
    return -1;
}

/* --family's comma-separated list: the first name that is not a family
 * (its length into *bad_len), or NULL; with on != NULL, marks the ones named. */
static const char *family_list(const char *list, int *on, size_t *bad_len)
{
    for (const char *p = list;;) {
        const size_t len = strcspn(p, ",");
        const int f = family_of(p, len);
        if (f < 0) {
            *bad_len = len;
            return p;
        }
        if (on != NULL)
            on[f] = 1;
        if (p[len] == '\0')
            return NULL;
        p += len + 1;
    }
}

/* Takes every --k out of argv (repeatable, which cli_parse's options are not). */
static int take_ks(int *argc, char **argv, integ_opts *o)
{
    int out = 1;
    for (int i = 1; i < *argc; ++i) {
        const char *a = argv[i], *v = NULL;
        if (strcmp(a, "--") == 0) {
            while (i < *argc)
                argv[out++] = argv[i++];
            break;
        }
        if (strcmp(a, "--k") == 0) {
            if (i + 1 >= *argc)
                return cli_fail(CMD, "--k needs a value");
            v = argv[++i];
        } else if (strncmp(a, "--k=", 4) == 0) {
            v = a + 4;
        } else {
            argv[out++] = argv[i];
            continue;
        }
        uint64_t k = 0;
        if (cli_parse_u64(v, 1u, CLI_MAX_K, &k) != 0)
            return cli_fail(CMD, "--k expects a whole number from 1 to %d, not '%s'", CLI_MAX_K, v);
        if (o->nks == CLI_INTEG_MAX_KS)
            return cli_fail(CMD, "--k given more than %d times", CLI_INTEG_MAX_KS);
        for (size_t j = 0; j < o->nks; ++j)
            if (o->ks[j] == (size_t)k)
                return cli_fail(CMD, "--k %llu given twice", (unsigned long long)k);
        o->ks[o->nks++] = (size_t)k;
    }
    *argc = out;
    return 0;
}

static int parse(int argc, char **argv, integ_opts *o)
{
    int rc = take_ks(&argc, argv, o);
    if (rc != 0)
        return rc;
    cli_opt opts[] = {
        {"sets", CLI_OPT_U64, &o->sets, 1, 1u << 24, 0},
        {"seed", CLI_OPT_U64, &o->seed, 0, UINT64_MAX, 0},
        {"integrands", CLI_OPT_SIZE, &o->m, 1, 65536, 0},
        {"family", CLI_OPT_STRING, &o->family, 0, 0, 0},
        {"dim", CLI_OPT_SIZE, &o->dim, 1, 2, 0},
        {"freq", CLI_OPT_SIZE, &o->freq, 0, MAX_FREQ_1D, 0},
        {"wrap", CLI_OPT_FLAG, &o->wrap, 0, 0, 0},
        {"plot", CLI_OPT_STRING, &o->plot, 0, 0, 0},
        {"csv", CLI_OPT_FLAG, &o->csv, 0, 0, 0},
        {"exact", CLI_OPT_STRING, &o->exact, 0, 0, 0},
        {"save", CLI_OPT_STRING, &o->save, 0, 0, 0},
    };
    cli_parser p = {CMD, help, opts, CLI_COUNT(opts), o->files, CLI_INTEG_MAX_FILES, 0u, NULL};
    rc = cli_parse(&p, argc, argv);
    if (rc != CLI_PARSED)
        return rc;
    o->nfiles = p.nargs;
    o->dim_given = opts[4].given;
    o->freq_given = opts[5].given;
    size_t bad_len = 0;
    const char *bad = o->family != NULL ? family_list(o->family, NULL, &bad_len) : NULL;
    if (bad != NULL)
        return cli_fail(CMD, "unknown family '%.*s' (gaussian, gaussian_periodic, heaviside, disk, "
                        "cosine, blinn_phong, gaussian_mixture)", (int)bad_len, bad);
    if (o->nks > 0u) { /* a named pattern */
        if (o->nfiles != 1u)
            return cli_fail(CMD, o->nfiles == 0u ? "--k needs a KIND to draw from"
                                                 : "give one KIND with --k, not files");
        o->kind = o->files[0];
        o->nfiles = 0;
        if (o->wrap)
            return cli_fail(CMD, "--wrap is for point files, not a named pattern");
        if (o->exact != NULL)
            return cli_fail(CMD, "--exact is for point files: a named pattern has its own");
        if (!o->dim_given)
            o->dim = 2u;
    } else {
        if (opts[0].given)
            return cli_fail(CMD, "--sets is for a named pattern (give --k K too)");
        if (o->nfiles == 0u && isatty(STDIN_FILENO))
            return cli_fail(CMD, "no input: give point files, or a KIND with --k K");
        if (o->nfiles == 1u && (cli_source2d_known(o->files[0]) || cli_pattern_kind(o->files[0]) >= 0) &&
            access(o->files[0], F_OK) != 0)
            return cli_fail(CMD, "'%s' is a pattern: give --k K to draw from it", o->files[0]);
        if (o->nfiles == 0u)
            o->files[o->nfiles++] = "-";
    }
    if (o->exact != NULL && strcmp(o->exact, "random") != 0 && strcmp(o->exact, "jittered") != 0 &&
        strcmp(o->exact, "stratified") != 0)
        return cli_fail(CMD, "--exact takes random, jittered or stratified, not '%s'", o->exact);
    if (o->freq_given && o->freq > (size_t)(o->dim == 2u ? MAX_FREQ_2D : MAX_FREQ_1D))
        return cli_fail(CMD, "--freq: at most %d in 2D", MAX_FREQ_2D);
    /* A record holds one accumulator: one family, one K, one input. */
    if (o->save != NULL &&
        (o->family == NULL || strchr(o->family, ',') != NULL || o->nks > 1u || o->nfiles > 1u))
        return cli_fail(CMD, "--save holds one row: give --family NAME (one family) and one --k "
                             "(or one FILE)");
    return o->plot != NULL ? cli_plot_check(CMD, o->plot) : 0;
}

/* ---- Accumulation ------------------------------------------------------------ */

static size_t default_freq(size_t dim, size_t k)
{
    if (dim == 1u)
        return k * 4u < (size_t)DEFAULT_FREQ_1D ? k * 4u : (size_t)DEFAULT_FREQ_1D;
    const size_t f = 2u * (size_t)ceil(sqrt((double)k));
    return f < (size_t)DEFAULT_FREQ_2D ? f : (size_t)DEFAULT_FREQ_2D;
}

/* Once the dimension is known: the families that have it (blinn_phong is
 * 2D only), or exit 2 if the one asked for does not. */
static int families_for_dim(integ_ctx *c)
{
    for (int f = 0; f < CLI_INTEG_FAMILIES; ++f) {
        const int has = mcs_integrand_has_dim((mcs_integrand_family)f, c->dim);
        if (c->fam_on[f] && !has && c->o->family != NULL)
            return cli_fail(CMD, "family %s has no %zuD integrands (give 2D points)",
                            mcs_integrand_family_str((mcs_integrand_family)f), c->dim);
        c->fam_on[f] = c->fam_on[f] && has;
    }
    return 0;
}

static int any_periodic(const integ_ctx *c)
{
    for (int f = 0; f < CLI_INTEG_FAMILIES; ++f)
        if (c->fam_on[f] && mcs_integrand_is_periodic((mcs_integrand_family)f))
            return 1;
    return 0;
}

static group *group_for(integ_ctx *c, size_t k)
{
    for (size_t i = 0; i < c->ng; ++i)
        if (c->g[i].k == k)
            return &c->g[i];
    group *ng = realloc(c->g, (c->ng + 1u) * sizeof *ng);
    if (ng == NULL) {
        cli_internal(CMD, "out of memory");
        return NULL;
    }
    c->g = ng;
    group *g = &c->g[c->ng++];
    memset(g, 0, sizeof *g);
    g->k = k;
    for (int f = 0; f < CLI_INTEG_FAMILIES; ++f)
        (void)mcs_integrate_init(&g->acc[f], (mcs_integrand_family)f, c->dim);
    g->freq = c->o->freq_given ? c->o->freq : default_freq(c->dim, k);
    if (g->freq == 0u || !any_periodic(c))
        return g;
    size_t bytes = 0;
    mcs_status st = c->dim == 2u ? mcs_pointset2d_size(g->freq, 0u, &bytes)
                                 : mcs_pointset_size(g->freq, 0u, &bytes);
    g->mem = st == MCS_OK ? malloc(bytes) : NULL;
    if (g->mem == NULL) {
        cli_internal(CMD, "cannot set up the spectrum at F = %zu", g->freq);
        return NULL;
    }
    st = c->dim == 2u ? mcs_pointset2d_init(&g->ps2, g->freq, 0u, g->mem, bytes)
                      : mcs_pointset_init(&g->ps1, g->freq, 0u, g->mem, bytes);
    if (st != MCS_OK) {
        cli_internal(CMD, "spectrum init: %s", mcs_status_str(st));
        return NULL;
    }
    return g;
}

/* One set: fresh integrands of every family, their errors, its spectrum. */
static int add_set(void *ctx, size_t k, const double *coords, const double *weights)
{
    (void)weights;
    integ_ctx *c = ctx;
    if (c->dim == 0u) {
        if (c->stats->dim > 2u)
            return cli_fail(CMD, "%s: the points have %zu coordinates; the integrands take 1 or 2",
                            c->name, c->stats->dim);
        c->dim = c->stats->dim;
        if (c->dim == 2u && c->o->freq_given && c->o->freq > (size_t)MAX_FREQ_2D)
            return cli_fail(CMD, "--freq: at most %d in 2D", MAX_FREQ_2D);
        const int rc = families_for_dim(c);
        if (rc != 0)
            return rc;
    }
    group *g = group_for(c, k);
    if (g == NULL)
        return CLI_EXIT_FAIL;
    if (c->o->exact != NULL) { /* files: the pattern the user says they are */
        mcs_pattern2d grid;
        c->ref = strcmp(c->o->exact, "random") == 0 ? MCS_INTEGRATE_RANDOM : MCS_INTEGRATE_JITTERED;
        c->strata[0] = k;
        c->strata[1] = 1u;
        if (c->dim == 2u && mcs_pattern2d_init(&grid, MCS_PATTERN2D_JITTERED, k, 0u, 0u) == MCS_OK) {
            c->strata[0] = grid.strata_x; /* the most nearly square grid, as mcspec pattern's */
            c->strata[1] = grid.strata_y;
        }
    }
    const size_t m = c->o->m;
    for (int f = 0; f < CLI_INTEG_FAMILIES; ++f) {
        if (!c->fam_on[f])
            continue;
        if (g->nfs[f] + m > g->cap[f]) {
            const size_t cap = 2u * (g->nfs[f] + m);
            mcs_integrand *p = realloc(g->fs[f], cap * sizeof *p);
            if (p == NULL)
                return cli_internal(CMD, "out of memory for the integrands");
            g->fs[f] = p;
            g->cap[f] = cap;
        }
        mcs_integrand *fs = g->fs[f] + g->nfs[f];
        mcs_status st = MCS_OK;
        for (size_t i = 0; i < m && st == MCS_OK; ++i)
            st = mcs_integrand_draw(&fs[i], (mcs_integrand_family)f, c->dim, &c->frng[f]);
        if (st == MCS_OK)
            st = mcs_integrate_add(&g->acc[f], m, fs, k, coords, c->ref, c->strata[0], c->strata[1]);
        if (st != MCS_OK)
            return cli_internal(CMD, "adding a set failed: %s", mcs_status_str(st));
        if (mcs_integrand_is_periodic((mcs_integrand_family)f))
            g->nfs[f] += m; /* kept for the prediction */
    }
    if (g->mem != NULL) {
        mcs_status st = c->dim == 2u ? mcs_pointset2d_add(&g->ps2, k, coords)
                                     : mcs_pointset_add(&g->ps1, k, coords);
        if (st != MCS_OK)
            return cli_internal(CMD, "spectrum of a set: %s", mcs_status_str(st));
    }
    ++g->sets;
    return 0;
}

/* T sets of a kind of mcspec sample that mcspec pattern does not draw (blue
 * noise, the any-dimension samplers): no exact column. */
static int draw_sample_kind(integ_ctx *c, size_t k, uint64_t stream)
{
    const integ_opts *o = c->o;
    cli_sample_source src;
    int rc = cli_sample_init(CMD, o->kind, c->dim, k, MCS_MAX_N, &src);
    if (rc != 0)
        return rc;
    double *pts = cli_alloc(CMD, k * c->dim, sizeof *pts);
    rc = pts == NULL ? CLI_EXIT_FAIL : 0;
    c->ref = MCS_INTEGRATE_NONE;
    mcs_rng rng;
    mcs_rng_seed(&rng, o->seed, stream);
    for (uint64_t t = 0; rc == 0 && t < o->sets; ++t) {
        rc = cli_sample_draw(CMD, &src, &rng, pts);
        if (rc == 0)
            rc = add_set(c, k, pts, NULL);
    }
    free(pts);
    cli_sample_free(&src);
    return rc;
}

/* Whether mcspec pattern draws kind in dim dimensions (else mcspec sample's
 * table does). */
static int pattern_draws(const char *kind, size_t dim)
{
    return dim == 2u ? cli_source2d_known(kind) : cli_pattern_kind(kind) >= 0;
}

/* T sets of a named pattern with k points. */
static int draw_pattern(integ_ctx *c, size_t k, uint64_t stream)
{
    if (!pattern_draws(c->o->kind, c->dim))
        return draw_sample_kind(c, k, stream);
    const integ_opts *o = c->o;
    double *pts = cli_alloc(CMD, k * c->dim, sizeof *pts);
    size_t *bins = c->dim == 1u ? cli_alloc(CMD, k, sizeof *bins) : NULL;
    double *w = c->dim == 1u ? cli_alloc(CMD, k, sizeof *w) : NULL;
    cli_source2d src;
    mcs_pattern pat;
    int rc = pts == NULL || (c->dim == 1u && (bins == NULL || w == NULL)) ? CLI_EXIT_FAIL : 0;
    memset(&src, 0, sizeof src);
    if (rc == 0 && c->dim == 2u) {
        rc = cli_source2d_init(CMD, o->kind, k, 1u, &src);
        if (rc == 0 && !src.is_sampler) {
            const mcs_pattern2d_kind pk = src.pattern.kind;
            c->ref = pk == MCS_PATTERN2D_RANDOM     ? MCS_INTEGRATE_RANDOM
                     : pk == MCS_PATTERN2D_JITTERED ? MCS_INTEGRATE_JITTERED
                                                    : MCS_INTEGRATE_NONE;
            c->strata[0] = src.pattern.strata_x;
            c->strata[1] = src.pattern.strata_y;
        }
    } else if (rc == 0) {
        const mcs_pattern_kind pk = (mcs_pattern_kind)cli_pattern_kind(o->kind);
        if (mcs_pattern_init(&pat, pk, MCS_MAX_N, k, NULL) != MCS_OK)
            rc = cli_fail(CMD, "cannot set up %s with K = %zu", o->kind, k);
        c->ref = pk == MCS_PATTERN_RANDOM       ? MCS_INTEGRATE_RANDOM
                 : pk == MCS_PATTERN_STRATIFIED ? MCS_INTEGRATE_JITTERED
                                                : MCS_INTEGRATE_NONE;
        c->strata[0] = k;
        c->strata[1] = 1u;
    }
    mcs_rng rng;
    mcs_rng_seed(&rng, o->seed, stream);
    for (uint64_t t = 0; rc == 0 && t < o->sets; ++t) {
        mcs_status st = c->dim == 1u      ? mcs_pattern_draw(&pat, &rng, k, bins, w, pts)
                        : src.is_sampler ? mcs_sampler_draw(&src.sampler, &rng, k, pts)
                                         : mcs_pattern2d_draw(&src.pattern, &rng, k, pts);
        rc = st != MCS_OK ? cli_internal(CMD, "a set failed: %s", mcs_status_str(st))
                          : add_set(c, k, pts, NULL);
    }
    cli_source2d_free(&src);
    free(pts);
    free(bins);
    free(w);
    return rc;
}

/* ---- Results ----------------------------------------------------------------- */

static int cmp_group(const void *a, const void *b)
{
    const size_t x = ((const group *)a)->k, y = ((const group *)b)->k;
    return x < y ? -1 : x > y;
}

double cli_integrate_rate(size_t dim, int f, int jittered)
{
    const int smooth = f != MCS_INTEGRAND_HEAVISIDE && f != MCS_INTEGRAND_DISK &&
                       f != MCS_INTEGRAND_GAUSSIAN_MIXTURE; /* blinn_phong: continuous, a kink */
    return !jittered ? -1.0 : -(1.0 + (smooth ? 2.0 : 1.0) / (double)dim);
}

void cli_integrate_row(int csv, const char *family, const char *k, const double *v)
{
    if (csv) {
        printf("%s,%s", family, k);
        cli_print_values(1, v, 10);
        return;
    }
    char b[6][40];
    cli_table_double(b[0], 40, 12, v[0]);
    cli_table_double(b[1], 40, 11, v[1]);
    cli_table_double(b[2], 40, 12, v[2]);
    cli_table_double(b[3], 40, 12, v[3]);
    cli_table_double(b[4], 40, 10, v[4]);
    const double z = cli_z(v[0], v[2], v[1], 1e-12 * fabs(v[2]));
    if (isnan(z))
        snprintf(b[5], 40, "%7s", "-");
    else
        snprintf(b[5], 40, "%7.2f", z);
    printf("%-17s %8s %s %s %s %s %s %s ", family, k[0] != '\0' ? k : "-", b[0], b[1], b[2], b[5],
           b[3], b[4]);
    if (isnan(v[5]))
        printf("%6s\n", "-");
    else
        printf("%6.0f\n", v[5]);
}

static int results(integ_ctx *c)
{
    qsort(c->g, c->ng, sizeof *c->g, cmp_group);
    for (size_t i = 0; i < c->ng; ++i) {
        group *g = &c->g[i];
        for (int f = 0; f < CLI_INTEG_FAMILIES; ++f) {
            g->mse[f] = cli_or_nan(mcs_integrate_mse(&g->acc[f], &g->mse[f]), &g->mse[f]);
            g->se[f] = cli_or_nan(mcs_integrate_mse_stderr(&g->acc[f], &g->se[f]), &g->se[f]);
            g->exact[f] = cli_or_nan(mcs_integrate_exact(&g->acc[f], &g->exact[f]), &g->exact[f]);
            g->pred[f] = g->tail[f] = (double)NAN;
            if (g->mem == NULL || g->nfs[f] == 0u)
                continue;
            mcs_status st = c->dim == 2u
                                ? mcs_integrand_predict(g->fs[f], g->nfs[f], &g->ps2, g->k,
                                                        &g->pred[f], &g->tail[f])
                                : mcs_integrand_predict_1d(g->fs[f], g->nfs[f], &g->ps1, g->k,
                                                           &g->pred[f], &g->tail[f]);
            if (st != MCS_OK)
                return cli_internal(CMD, "prediction failed: %s", mcs_status_str(st));
        }
    }
    for (int f = 0; f < CLI_INTEG_FAMILIES; ++f) { /* least squares of log mse on log K */
        double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
        for (size_t i = 0; i < c->ng; ++i)
            if (c->g[i].mse[f] > 0.0) {
                const double x = log((double)c->g[i].k), y = log(c->g[i].mse[f]);
                n += 1.0;
                sx += x;
                sy += y;
                sxx += x * x;
                sxy += x * y;
            }
        const double den = n * sxx - sx * sx;
        c->slope[f] = n >= 2.0 && den > 0.0 ? (n * sxy - sx * sy) / den : (double)NAN;
    }
    return 0;
}

static void report(const integ_ctx *c)
{
    const integ_opts *o = c->o;
    if (o->csv) {
        puts(CSV_HEADER CSV_EXTRA);
    } else {
        if (o->kind != NULL)
            printf("%s: %s (%zuD), %llu sets per K, %zu integrands per set and family (seed %llu)\n",
                   CMD, o->kind, c->dim, (unsigned long long)o->sets, o->m,
                   (unsigned long long)o->seed);
        else
            printf("%s: %zu file(s), %llu point sets in %zuD, %zu integrands per set and family "
                   "(seed %llu)\n", CMD, o->nfiles, (unsigned long long)c->stats->sets, c->dim,
                   o->m, (unsigned long long)o->seed);
        printf("mse: mean over sets of the squared error; exact: %s; z = (mse - exact) / stderr;\n"
               "predicted: eq. 14 from the sets' mean periodogram over 0 < |k|_inf <= F, the\n"
               "true value in [predicted, predicted + tail] (periodic families only)\n\n",
               c->ref == MCS_INTEGRATE_RANDOM     ? "Var[f] / K (independent uniform points)"
               : c->ref == MCS_INTEGRATE_JITTERED ? "the jittered grid's, from its strata"
                                                  : "none for this input");
        printf("%-17s %8s %12s %11s %12s %7s %12s %10s %6s\n", "family", "K", "mse", "stderr",
               "exact", "z", "predicted", "tail", "F");
    }
    for (int f = 0; f < CLI_INTEG_FAMILIES; ++f) {
        if (!c->fam_on[f])
            continue;
        for (size_t i = 0; i < c->ng; ++i) {
            const group *g = &c->g[i];
            const int pr = !isnan(g->pred[f]);
            const double v[10] = {g->mse[f], g->se[f], g->exact[f], g->pred[f], g->tail[f],
                                  pr ? (double)g->freq : (double)NAN, (double)g->sets,
                                  c->slope[f], cli_integrate_rate(c->dim, f, 0), cli_integrate_rate(c->dim, f, 1)};
            char k[32];
            snprintf(k, sizeof k, "%zu", g->k);
            cli_integrate_row(o->csv, mcs_integrand_family_str((mcs_integrand_family)f), k, v);
        }
    }
    if (o->csv)
        return;
    printf("\nconvergence (least squares of log mse on log K over the rows above)\n");
    printf("%-17s %8s %14s %16s\n", "family", "slope", "random rate", "jittered rate");
    for (int f = 0; f < CLI_INTEG_FAMILIES; ++f) {
        if (!c->fam_on[f])
            continue;
        char b[40];
        cli_table_double(b, sizeof b, 8, c->slope[f]);
        printf("%-17s %s %14.3g %16.3g\n", mcs_integrand_family_str((mcs_integrand_family)f), b,
               cli_integrate_rate(c->dim, f, 0), cli_integrate_rate(c->dim, f, 1));
    }
}

/* ---- Entry point ------------------------------------------------------------- */

static void free_groups(integ_ctx *c)
{
    for (size_t i = 0; i < c->ng; ++i) {
        for (int f = 0; f < CLI_INTEG_FAMILIES; ++f)
            free(c->g[i].fs[f]);
        free(c->g[i].mem);
    }
    free(c->g);
}

static int check_kind(const integ_opts *o)
{
    if (!cli_source2d_known(o->kind) && cli_pattern_kind(o->kind) < 0 && cli_kind_known(o->kind))
        return 0; /* mcspec sample's kinds: cli_sample_init says if it lacks the dimension */
    if (o->dim == 2u && !cli_source2d_known(o->kind))
        return cli_fail(CMD, cli_pattern_kind(o->kind) >= 0
                                 ? "'%s' is a 1D pattern: give --dim 1"
                                 : "unknown pattern '%s' (see mcspec integrate --help)", o->kind);
    if (o->dim == 1u && cli_pattern_kind(o->kind) < 0)
        return cli_fail(CMD, cli_source2d_known(o->kind)
                                 ? "'%s' is a 2D pattern: give --dim 2"
                                 : "unknown pattern '%s' (see mcspec integrate --help)", o->kind);
    return 0;
}

int cli_cmd_integrate(int argc, char **argv)
{
    integ_opts o;
    memset(&o, 0, sizeof o);
    o.seed = 1u;
    o.sets = 64u;
    o.m = 16u;
    int rc = parse(argc, argv, &o);
    if (rc != 0)
        return rc < 0 ? CLI_EXIT_OK : rc;
    if (o.kind != NULL && (rc = check_kind(&o)) != 0)
        return rc;
    integ_ctx c;
    memset(&c, 0, sizeof c);
    c.o = &o;
    c.dim = o.kind != NULL || o.dim_given ? o.dim : 0u;
    for (int f = 0; f < CLI_INTEG_FAMILIES; ++f) {
        c.fam_on[f] = o.family == NULL;
        mcs_rng_seed(&c.frng[f], o.seed, 1000u + (uint64_t)f);
    }
    size_t unused = 0;
    if (o.family != NULL)
        (void)family_list(o.family, c.fam_on, &unused);
    if (c.dim != 0u && (rc = families_for_dim(&c)) != 0)
        return rc;
    cli_pointset_stats stats;
    memset(&stats, 0, sizeof stats);
    c.stats = &stats;
    cli_save_target save = {o.save, o.nfiles > 0u ? o.files[0] : NULL, 0u, 0u};
    if (o.kind != NULL)
        rc = o.save != NULL ? cli_write_check(CMD, o.save) : 0;
    else
        rc = cli_save_begin(CMD, &save);
    if (rc != 0)
        return rc;
    cli_progress progress;
    cli_progress_init(&progress, !o.csv, CMD, "sets", 0);
    if (o.kind != NULL) {
        for (size_t i = 0; rc == 0 && i < o.nks; ++i)
            rc = draw_pattern(&c, o.ks[i], 1u + i);
    } else {
        cli_pointset_format fmt = {.dim = o.dim_given ? o.dim : 0u, .weights = 0, .wrap = o.wrap};
        for (size_t i = 0; rc == 0 && i < o.nfiles; ++i) {
            cli_pointset_stats s;
            memset(&s, 0, sizeof s);
            c.stats = &s;
            c.name = cli_input_name(o.files[i]);
            rc = cli_read_pointsets(CMD, o.files[i], &fmt, add_set, &c, &s, &progress);
            if (rc == 0 && fmt.dim == 0u)
                fmt.dim = s.dim; /* every file as the first */
            stats.sets += s.sets;
            stats.dim = s.dim;
        }
        c.stats = &stats;
    }
    cli_progress_end(&progress);
    if (rc == 0 && c.ng == 0u)
        rc = cli_fail(CMD, "no point sets in the input");
    if (rc == 0 && o.save != NULL && c.ng != 1u)
        rc = cli_fail(CMD, "--save holds one row: the sets have %zu sizes K (give sets of one K)",
                      c.ng);
    if (rc == 0)
        rc = results(&c);
    if (rc == 0)
        report(&c);
    if (rc == 0 && o.plot != NULL)
        rc = cli_integrate_plot(CMD, o.plot, &c);
    if (rc == 0 && o.save != NULL) {
        mcs_integrate *acc = &c.g[0].acc[family_of(o.family, strlen(o.family))];
        const cli_run run = {(unsigned)c.dim, o.kind, c.dim == 1u ? (uint64_t)MCS_MAX_N : 0u,
                             c.g[0].k, 0, 0u, o.seed, 1u, o.sets};
        rc = o.kind != NULL ? cli_save_drawn(CMD, o.save, &run, MCS_IO_KIND_INTEGRATE, acc)
                            : cli_save_points(CMD, &save, MCS_IO_KIND_INTEGRATE, acc);
    }
    free_groups(&c);
    return rc;
}
