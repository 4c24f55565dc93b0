/* mcspec sample: T point sets of a named kind, in any dimension it has, to
 * standard output in utk's format; and the kind table the projections
 * command shares (sample.h). */
#include "cli.h"
#include "sample.h"

#include "mcspec.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CMD "mcspec sample"

/* ---- The kinds --------------------------------------------------------- */

static mcs_status init_pattern(cli_sample_source *s)
{
    mcs_status st = mcs_pattern_init(&s->pattern, (mcs_pattern_kind)s->kind->arg, s->n, s->k, NULL);
    if (st != MCS_OK)
        return st;
    s->bins = malloc(s->k * sizeof *s->bins);
    s->weights = malloc(s->k * sizeof *s->weights);
    return s->bins != NULL && s->weights != NULL ? MCS_OK : MCS_ERR_SPACE;
}

static mcs_status draw_pattern(const cli_sample_source *s, mcs_rng *rng, double *points)
{
    return mcs_pattern_draw(&s->pattern, rng, s->k, s->bins, s->weights, points);
}

/* 2D patterns with the most nearly square strata (strata 0, 0). */
static mcs_status init_pattern2d(cli_sample_source *s)
{
    return mcs_pattern2d_init(&s->pattern2d, (mcs_pattern2d_kind)s->kind->arg, s->k, 0u, 0u);
}

static mcs_status draw_pattern2d(const cli_sample_source *s, mcs_rng *rng, double *points)
{
    return mcs_pattern2d_draw(&s->pattern2d, rng, s->k, points);
}

static mcs_status init_sampler(cli_sample_source *s)
{
    return mcs_sampler_init(&s->sampler, (mcs_sampler_kind)s->kind->arg, s->dim, s->k);
}

static mcs_status draw_sampler(const cli_sample_source *s, mcs_rng *rng, double *points)
{
    return mcs_sampler_draw(&s->sampler, rng, s->k, points);
}

/* random in 1D is the 1D pattern, in 2D the 2D pattern; in more dimensions
 * every coordinate is one more uniform double of the generator. */
static mcs_status init_random(cli_sample_source *s)
{
    if (s->dim == 1u)
        return init_pattern(s);
    if (s->dim == 2u)
        return mcs_pattern2d_init(&s->pattern2d, MCS_PATTERN2D_RANDOM, s->k, 0u, 0u);
    return MCS_OK;
}

static mcs_status draw_random(const cli_sample_source *s, mcs_rng *rng, double *points)
{
    if (s->dim == 1u)
        return draw_pattern(s, rng, points);
    if (s->dim == 2u)
        return draw_pattern2d(s, rng, points);
    mcs_status st = MCS_OK;
    for (size_t i = 0; st == MCS_OK && i < s->k * s->dim; ++i)
        st = mcs_rng_double(rng, &points[i]);
    return st;
}

/* Blue noise (bluenoise.h): defaults for every parameter, work memory
 * sized by the library's query. */
static mcs_status init_blue(cli_sample_source *s)
{
    mcs_status st = mcs_bluenoise_work_size((mcs_bluenoise_kind)s->kind->arg, s->dim, s->k,
                                            &s->work_bytes);
    if (st != MCS_OK)
        return st;
    s->work = malloc(s->work_bytes > 0u ? s->work_bytes : 1u);
    return s->work != NULL ? MCS_OK : MCS_ERR_SPACE;
}

static mcs_status draw_blue(const cli_sample_source *s, mcs_rng *rng, double *points)
{
    return mcs_bluenoise_draw((mcs_bluenoise_kind)s->kind->arg, s->dim, s->k, NULL, rng, s->work,
                              s->work_bytes, points);
}

#define PAT1(name, kind) {name, 1, 1, kind, init_pattern, draw_pattern}
#define BLUE(name, lo, hi, kind) {name, lo, hi, kind, init_blue, draw_blue}
#define PAT2(name, kind) {name, 2, 2, kind, init_pattern2d, draw_pattern2d}
#define SMP(name, lo, hi, kind) {name, lo, hi, kind, init_sampler, draw_sampler}

/* One row per kind. */
static const cli_sample_kind kinds[] = {
    {"random", 1, MCS_SAMPLER_MAX_DIM, MCS_PATTERN_RANDOM, init_random, draw_random},
    PAT1("stratified", MCS_PATTERN_STRATIFIED),
    PAT1("homogenized", MCS_PATTERN_HOMOGENIZED),
    PAT1("uniform", MCS_PATTERN_UNIFORM),
    PAT1("jitter", MCS_PATTERN_JITTER),
    PAT2("jittered", MCS_PATTERN2D_JITTERED),
    PAT2("grid", MCS_PATTERN2D_GRID),
    PAT2("shifted-grid", MCS_PATTERN2D_SHIFTED_GRID),
    PAT2("n-rooks", MCS_PATTERN2D_NROOKS),
    PAT2("multi-jittered", MCS_PATTERN2D_MULTI_JITTERED),
    PAT2("cmj", MCS_PATTERN2D_CMJ),
    SMP("van-der-corput", 1, 1, MCS_SAMPLER_VAN_DER_CORPUT),
    SMP("halton", 2, 2, MCS_SAMPLER_HALTON),
    SMP("hammersley", 2, 2, MCS_SAMPLER_HAMMERSLEY),
    SMP("kronecker", 1, 2, MCS_SAMPLER_KRONECKER),
    SMP("sobol-owen", 1, MCS_SAMPLER_MAX_DIM, MCS_SAMPLER_SOBOL_ND),
    SMP("halton-permuted", 1, MCS_SAMPLER_MAX_DIM, MCS_SAMPLER_HALTON_PERMUTED),
    SMP("halton-owen", 1, MCS_SAMPLER_MAX_DIM, MCS_SAMPLER_HALTON_OWEN),
    SMP("lattice", 1, MCS_SAMPLER_MAX_DIM, MCS_SAMPLER_LATTICE),
    SMP("padded", 2, MCS_SAMPLER_MAX_DIM, MCS_SAMPLER_PADDED),
    BLUE("dart-throwing", 1, 3, MCS_BLUENOISE_DART_THROWING),
    BLUE("poisson-disk", 1, 3, MCS_BLUENOISE_POISSON_DISK),
    BLUE("lloyd", 2, 2, MCS_BLUENOISE_LLOYD),
    BLUE("pmj02", 2, 2, MCS_BLUENOISE_PMJ02),
    BLUE("pmj02bn", 2, 2, MCS_BLUENOISE_PMJ02BN),
};

#define KIND_COUNT (sizeof kinds / sizeof kinds[0])

void cli_sample_names(char *buf, size_t size)
{
    size_t used = 0;
    buf[0] = '\0';
    for (size_t i = 0; i < KIND_COUNT && used < size; ++i) {
        int w = snprintf(buf + used, size - used, "%s%s", i > 0u ? ", " : "", kinds[i].name);
        used += w > 0 ? (size_t)w : 0u;
    }
}

static void dims_text(const cli_sample_kind *k, char *buf, size_t size)
{
    if (k->dim_min == k->dim_max)
        snprintf(buf, size, "%zu only", k->dim_min);
    else
        snprintf(buf, size, "%zu to %zu", k->dim_min, k->dim_max);
}

int cli_sample_init(const char *cmd, const char *name, size_t dim, size_t k, size_t n,
                    cli_sample_source *src)
{
    memset(src, 0, sizeof *src);
    const cli_sample_kind *kind = NULL;
    for (size_t i = 0; i < KIND_COUNT && kind == NULL; ++i)
        if (strcmp(name, kinds[i].name) == 0)
            kind = &kinds[i];
    if (kind == NULL) {
        char names[512];
        cli_sample_names(names, sizeof names);
        return cli_fail(cmd, "unknown kind '%s' (one of %s)", name, names);
    }
    if (dim < kind->dim_min || dim > kind->dim_max) {
        char dims[40];
        dims_text(kind, dims, sizeof dims);
        return cli_fail(cmd, "%s has dimensions %s, not %zu: give --dim in that range", name, dims,
                        dim);
    }
    src->kind = kind;
    src->dim = dim;
    src->k = k;
    src->n = n;
    mcs_status st = kind->init(src);
    if (st == MCS_ERR_SPACE)
        return cli_internal(cmd, "out of memory");
    if (st != MCS_OK)
        return cli_fail(cmd, "cannot set up %s with K = %zu in %zu dimensions: %s", name, k, dim,
                        mcs_status_str(st));
    return 0;
}

void cli_sample_free(cli_sample_source *src)
{
    free(src->bins);
    free(src->weights);
    free(src->work);
    src->bins = NULL;
    src->weights = NULL;
    src->work = NULL;
}

int cli_sample_draw(const char *cmd, const cli_sample_source *src, mcs_rng *rng, double *points)
{
    mcs_status st = src->kind->draw(src, rng, points);
    if (st == MCS_ERR_EMPTY) /* a Poisson kind placed fewer than K points: the user's choice of K */
        return cli_fail(cmd, "%s could not place %zu points at its default radius (its set "
                        "saturated): ask for fewer points", src->kind->name, src->k);
    return st == MCS_OK ? 0 : cli_internal(cmd, "a draw failed: %s", mcs_status_str(st));
}

/* ---- The command ------------------------------------------------------- */

static const char help[] =
    "usage: mcspec sample KIND --dim D --k K [--sets T] [--seed S] [--n N]\n"
    "\n"
    "Writes T point sets of K points of KIND in D dimensions to standard output\n"
    "in utk's format: one point per line, its D coordinates in [0,1) separated by\n"
    "spaces (%.17g, so they read back bit for bit), a line '#' between sets. The\n"
    "output is read by mcspec spectrum, discrepancy, stats and projections.\n"
    "\n"
    "KIND and its dimensions:\n"
    "  random                      1 to 64 (1D: the pattern; 2D: the 2D pattern;\n"
    "                              more: every coordinate uniform, independent)\n"
    "  stratified, homogenized, uniform, jitter   1 (the 1D patterns, over N bins)\n"
    "  jittered, grid, shifted-grid, n-rooks, multi-jittered, cmj   2 (the 2D\n"
    "                              patterns; strata the most nearly square m n = K)\n"
    "  van-der-corput 1; halton, hammersley 2; kronecker 1 or 2 (the samplers of\n"
    "                              mcspec pattern --dim 2, randomly rotated or shifted)\n"
    "  sobol-owen                  1 to 64: Owen-scrambled Sobol, Joe and Kuo's\n"
    "                              direction numbers (1D and 2D: mcspec pattern's)\n"
    "  halton-permuted             1 to 64: Halton, random digit permutations per\n"
    "                              base and digit position\n"
    "  halton-owen                 1 to 64: Halton, Owen-scrambled in each base\n"
    "  lattice                     1 to 64: Korobov rank-1 lattice, random shift\n"
    "  padded                      2 to 64: independent Owen-scrambled Sobol pairs,\n"
    "                              each in its own random order (pbrt's padding)\n"
    "  dart-throwing, poisson-disk 1 to 3: blue noise on the torus, dart throwing\n"
    "                              and Bridson's method at their default radius\n"
    "  lloyd                       2: Lloyd's relaxation of random points on the torus\n"
    "  pmj02, pmj02bn              2: progressive multi-jittered (0,2) sequences, and\n"
    "                              their best-candidate blue-noise variant\n"
    "docs/samplers-nd.md and docs/samplers.md define each.\n"
    "\n"
    "Options:\n"
    "  --dim D    dimensions, 1 to 64 as KIND has them (required)\n"
    "  --k K      points per set, 1.." CLI_STR(CLI_MAX_K) " (required)\n"
    "  --sets T   sets, 1..1000000 (default 1)\n"
    "  --seed S   PCG32 seed (initstate; initseq 0; default 1): the same S gives\n"
    "             the same sets\n"
    "  --n N      bins of the 1D patterns, 1.." CLI_STR(MCS_MAX_N) " (default " CLI_STR(MCS_MAX_N) ";\n"
    "             homogenized shifts by whole bins)\n"
    "  --help     this text\n"
    "\n"
    "Exit status: 0 on success, 2 on bad usage (one line on stderr).\n";

int cli_cmd_sample(int argc, char **argv)
{
    size_t dim = 0, k = 0, sets = 1, n = MCS_MAX_N;
    uint64_t seed = 1;
    cli_opt opts[] = {
        {"dim", CLI_OPT_SIZE, &dim, 1, MCS_SAMPLER_MAX_DIM, 0},
        {"k", CLI_OPT_SIZE, &k, 1, CLI_MAX_K, 0},
        {"sets", CLI_OPT_SIZE, &sets, 1, 1000000, 0},
        {"seed", CLI_OPT_U64, &seed, 0, UINT64_MAX, 0},
        {"n", CLI_OPT_SIZE, &n, 1, MCS_MAX_N, 0},
    };
    const char *kind = NULL;
    int rc = cli_parse_one(CMD, help, NULL, opts, CLI_COUNT(opts), argc, argv, &kind);
    if (rc != CLI_PARSED)
        return rc < 0 ? CLI_EXIT_OK : rc;
    if (kind == NULL)
        return cli_fail(CMD, "which kind? give KIND (see %s --help)", CMD);
    if (!opts[0].given)
        return cli_fail(CMD, "give --dim D, the number of dimensions");
    if (!opts[1].given)
        return cli_fail(CMD, "give --k K, the points per set");
    cli_sample_source src;
    rc = cli_sample_init(CMD, kind, dim, k, n, &src);
    if (rc != 0) {
        cli_sample_free(&src);
        return rc;
    }
    double *pts = cli_alloc(CMD, k * dim, sizeof *pts);
    mcs_rng rng;
    if (pts == NULL || mcs_rng_seed(&rng, seed, 0u) != MCS_OK) {
        free(pts);
        cli_sample_free(&src);
        return CLI_EXIT_FAIL;
    }
    for (size_t t = 0; rc == 0 && t < sets; ++t) {
        rc = cli_sample_draw(CMD, &src, &rng, pts);
        if (t > 0u && rc == 0)
            fputs("#\n", stdout);
        for (size_t j = 0; rc == 0 && j < k; ++j)
            for (size_t a = 0; a < dim; ++a)
                printf(a + 1u < dim ? "%.17g " : "%.17g\n", pts[j * dim + a]);
    }
    free(pts);
    cli_sample_free(&src);
    return rc;
}
