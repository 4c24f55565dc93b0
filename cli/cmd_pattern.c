/* mcspec pattern: the measured spectrum of a named pattern beside theory. */
#include "cli.h"
#include "input.h"
#include "output.h"
#include "plot.h"
#include "predict.h"
#include "progress.h"
#include "record.h"
#include "source2d.h"
#include "streams.h"
#include "trials.h"

#include "mcspec.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CMD "mcspec pattern"
#define DEFAULT_TRIALS 10000u
#define DEFAULT_SEED 1u

static const char help[] =
    "usage: mcspec pattern KIND --n N --k K [--trials T] [--seed S]\n"
    "                      [--streams P [--stream I]] [--importance FILE]\n"
    "                      [--csv] [--plot FILE [--log]] [--save FILE]\n"
    "       mcspec pattern KIND2 --dim 2 --k K --freq F [--radial] [--trials T]\n"
    "                      [--seed S] [--streams P [--stream I]] [--csv]\n"
    "                      [--plot FILE [--log]] [--save FILE]\n"
    "\n"
    "Draws T trials of K samples over N bins from the pattern KIND and prints\n"
    "its full spectrum, k = 0..N/2, measured beside theory: <S_k> (real and\n"
    "imaginary parts) with its standard error, the power spectrum <|S_k|^2>\n"
    "with its standard error, the exact prediction of <|S_k|^2>, the note's\n"
    "closed form where one exists, and the z-score of the measurement against\n"
    "each, z = (power - prediction) / power_stderr (0 for a deterministic entry\n"
    "that agrees to rounding). S_k = N^(-1/2) sum_n exp(-2 pi i k n / N) s_n\n"
    "(eq. 7), s_n = r_n / p_n (eq. 38).\n"
    "\n"
    "KIND: random      u_j i.i.d. uniform (section 3.1)\n"
    "      stratified  u_j = (j + xi_j) / K (section 3.2)\n"
    "      homogenized stratified, shifted cyclically by a random whole number of\n"
    "                  bins (not defined with --importance)\n"
    "      uniform     u_j = (j + 1/2) / K (section 3.3)\n"
    "      jitter      u_j = (j + beta) / K, one beta per trial (section 3.3)\n"
    "\n"
    "Exact: at every frequency for every N, kind, K and importance function:\n"
    "mcs_theory's exact moments for N <= " CLI_STR(MCS_MAX_COV_N) ", mcs_theory_spectrum's exact\n"
    "spectrum (O(N) memory) above. Closed: the note's form as printed: eq. 23,\n"
    "33 (its N -> infinity sinc form), 37, 45-46 or 50-51; S_0 = K / sqrt(N)\n"
    "(eq. 17) at k = 0 without importance; empty where the note has none.\n"
    "\n";

/* The rest of --help (--dim 2, the options), printed after help. */
static const char help_2d[] =
    "--dim 2: T trials of K points in the unit square from the 2D pattern or\n"
    "sampler KIND2, and their point-set spectrum without binning, as mcspec\n"
    "spectrum --dim 2 --freq F prints it: per wave vector |kx|, |ky| <= F (or per\n"
    "annulus with --radial) the mean periodogram <P(k)>, its standard error\n"
    "(--radial: and psa's anisotropy in dB), the exact <P(k)> where exact theory\n"
    "exists and the z-score against it (empty fields elsewhere).\n"
    "KIND2: random, jittered, grid, shifted-grid, n-rooks, multi-jittered, cmj\n"
    "       (m x n strata, the most nearly square with m n = K), and the samplers\n"
    "       halton, hammersley (Cranley-Patterson rotated), sobol-owen (Owen\n"
    "       scrambled), kronecker (R2 lattice, randomly shifted)\n"
    "Exact: the closed forms of mcs_pointset2d_exact_power (random, jittered,\n"
    "grid, shifted-grid, n-rooks); for halton, hammersley and kronecker the\n"
    "periodogram of the unrandomised set, which a rotation or shift changes by a\n"
    "phase only, so every trial has it; none for multi-jittered, cmj, sobol-owen.\n"
    "\n"
    "Options:\n"
    "  --n N              bins N, 1.." CLI_STR(MCS_MAX_N) " (required)\n"
    "  --k K              samples per trial K, 1.." CLI_STR(CLI_MAX_K) " (required; need not\n"
    "                     divide N)\n"
    "  --trials T         trials, at least 2 (default 10000)\n"
    "  --seed S           PCG32 seed (initstate; default 1); the same S (and P)\n"
    "                     gives the same output\n"
    "  --streams P        split the run over P streams, 1.." CLI_STR(CLI_MAX_STREAMS) " (default 1):\n"
    "                     stream i draws from PCG32 seeded (initstate S, initseq i),\n"
    "                     i = 0..P-1, and takes floor(T/P) trials, one more for the\n"
    "                     first T mod P streams; the P accumulators are merged\n"
    "                     pairwise in a fixed tree order, (0+1), (2+3), ((0+1)+(2+3)),\n"
    "                     ... P = 1 is the plain run: stream 0, seeded (S, 0).\n"
    "                     mpirun -np P mcspec-mpi pattern ... runs stream i on rank i\n"
    "                     and gives the same bytes (docs/scaling.md)\n"
    "  --stream I         run stream I of the P alone, I = 0..P-1; `mcspec merge` of\n"
    "                     the P files that --stream 0 .. P-1 --save (in any order)\n"
    "                     equals --streams P --save: a run split over batch jobs\n"
    "  --importance FILE  warp the samples through the importance function whose N\n"
    "                     weights (>= 0, any scale, 0: a bin never drawn; one per line)\n"
    "                     are in FILE\n"
    "  --dim D            1 (default: N bins, the KIND above) or 2 (KIND2, no bins)\n"
    "  --freq F           --dim 2: the cutoff, |kx|, |ky| <= F, 1.." CLI_STR(MCS_POINTSET2D_MAX_FREQ) " (required)\n"
    "  --radial           --dim 2: one row per annulus r <= |k| < r + 1 instead\n"
    "  --csv              print CSV only: the header\n"
    "                     freq,mean_re,mean_im,mean_stderr,power,power_stderr,\n"
    "                     exact,closed,z_exact,z_closed\n"
    "                     (--dim 2: kx,ky,power,power_stderr,exact,z_exact, or\n"
    "                     radius,power,power_stderr,anisotropy_db,exact,z_exact)\n"
    "                     and one row per frequency; an empty field has no value\n"
    "  --plot FILE        also draw the power spectrum (k >= 1) with its standard-\n"
    "                     error band, the exact prediction and the closed form to\n"
    "                     FILE, .svg or .png (needs gnuplot); --dim 2: the image of\n"
    "                     <P(k)> beside its radial profile and the exact one\n"
    "  --log              --plot: the power on a log y axis (--dim 2: the profile's);\n"
    "                     zeros and values below 1e-12 of the highest not drawn\n"
    "  --save FILE        also save the measured accumulator (spectrum, or\n"
    "                     pointset2d with --dim 2) and its provenance to FILE\n"
    "                     (docs/format.md; read by mcspec show and mcspec merge),\n"
    "                     written atomically: a temporary file beside FILE, flushed,\n"
    "                     then renamed, so FILE is never left half-written (FILE:\n"
    "                     a regular file or a new name)\n"
    "  --help             this text\n"
    "\n"
    "Progress goes to stderr when it is a terminal and the run is long (never\n"
    "with --csv). Exit status: 0 on success, 2 on bad usage or input (one line\n"
    "on stderr).\n";

typedef struct {
    const char *kind_name;
    size_t n, k;
    uint64_t trials, seed;
    const char *importance, *plot;
    int csv;
    const char *save;
    uint64_t streams, stream; /* stream == streams: every stream */
    size_t dim, freq;
    int radial;
    int log_y; /* --log */
} pattern_opts;

/* KIND and the options of a 1D run (--n bins). */
static int check_1d(const pattern_opts *o, const cli_opt *opts)
{
    if (cli_pattern_kind(o->kind_name) < 0)
        return cli_fail(CMD, "unknown pattern '%s' (random, stratified, homogenized, uniform, "
                        "jitter; the 2D ones need --dim 2)", o->kind_name);
    if (!opts[0].given || !opts[1].given)
        return cli_fail(CMD, "%s is required (see %s --help)", !opts[0].given ? "--n N" : "--k K",
                        CMD);
    if (o->freq != 0u || o->radial)
        return cli_fail(CMD, "--freq and --radial are for --dim 2");
    return 0;
}

/* KIND2 and the options of a 2D run (--freq, no bins). */
static int check_2d(const pattern_opts *o, const cli_opt *opts)
{
    if (!cli_source2d_known(o->kind_name))
        return cli_fail(CMD, "unknown 2D pattern '%s' (%s)", o->kind_name, CLI_SOURCE2D_NAMES);
    if (!opts[1].given || o->freq == 0u)
        return cli_fail(CMD, "%s is required with --dim 2 (see %s --help)",
                        !opts[1].given ? "--k K" : "--freq F", CMD);
    if (opts[0].given || o->importance != NULL)
        return cli_fail(CMD, "--dim 2 takes no %s: its spectrum is not binned",
                        opts[0].given ? "--n" : "--importance");
    return 0;
}

static int parse(int argc, char **argv, pattern_opts *o)
{
    cli_opt opts[] = {
        {"n", CLI_OPT_SIZE, &o->n, 1, MCS_MAX_N, 0},
        {"k", CLI_OPT_SIZE, &o->k, 1, CLI_MAX_K, 0},
        {"trials", CLI_OPT_U64, &o->trials, 2, UINT64_MAX / 2u, 0},
        {"seed", CLI_OPT_U64, &o->seed, 0, UINT64_MAX, 0},
        {"importance", CLI_OPT_STRING, &o->importance, 0, 0, 0},
        {"csv", CLI_OPT_FLAG, &o->csv, 0, 0, 0},
        {"plot", CLI_OPT_STRING, &o->plot, 0, 0, 0},
        {"save", CLI_OPT_STRING, &o->save, 0, 0, 0},
        {"streams", CLI_OPT_U64, &o->streams, 1, CLI_MAX_STREAMS, 0},
        {"stream", CLI_OPT_U64, &o->stream, 0, CLI_MAX_STREAMS - 1u, 0},
        {"dim", CLI_OPT_SIZE, &o->dim, 1, 2, 0},
        {"freq", CLI_OPT_SIZE, &o->freq, 1, MCS_POINTSET2D_MAX_FREQ, 0},
        {"radial", CLI_OPT_FLAG, &o->radial, 0, 0, 0},
        {"log", CLI_OPT_FLAG, &o->log_y, 0, 0, 0},
    };
    int rc = cli_parse_one(CMD, help, help_2d, opts, CLI_COUNT(opts), argc, argv, &o->kind_name);
    if (rc != CLI_PARSED)
        return rc;
    if (o->kind_name == NULL)
        return cli_fail(CMD, "which pattern? give KIND: random, stratified, homogenized, "
                        "uniform or jitter (with --dim 2: %s)", CLI_SOURCE2D_NAMES);
    rc = o->dim == 2u ? check_2d(o, opts) : check_1d(o, opts);
    if (rc != 0)
        return rc;
    if (!opts[9].given)
        o->stream = o->streams;
    else if (o->stream >= o->streams)
        return cli_fail(CMD, "--stream %llu is not one of the %llu streams (0..%llu; give "
                        "--streams P)", (unsigned long long)o->stream,
                        (unsigned long long)o->streams, (unsigned long long)o->streams - 1u);
    if (o->trials < o->streams)
        return cli_fail(CMD, "--trials %llu is fewer than --streams %llu: every stream needs a "
                        "trial", (unsigned long long)o->trials, (unsigned long long)o->streams);
    rc = cli_plot_check_log(CMD, o->log_y, o->plot);
    return rc != 0 ? rc : cli_check_outputs(CMD, o->save, o->plot);
}

/* The importance function of FILE for n bins into imp, and the checksum of
 * its weights (cli_weights_crc) into *crc. */
static int load_importance(const char *path, size_t n, mcs_importance *imp, uint32_t *crc)
{
    double *w = NULL;
    size_t count = 0;
    int rc = cli_read_values(CMD, path, "importance weight", 1, MCS_MAX_N, &w, &count);
    if (rc != 0)
        return rc;
    if (count != n)
        rc = cli_fail(CMD, "%s holds %zu importance weights, but --n is %zu (one weight per bin)",
                      cli_input_name(path), count, n);
    mcs_status st = rc == 0 ? mcs_importance_init(imp, n, w) : MCS_OK;
    if (rc == 0)
        *crc = cli_weights_crc(n, w);
    free(w);
    if (st != MCS_OK)
        return cli_fail(CMD, "%s: not an importance function: %s", cli_input_name(path),
                        mcs_status_str(st));
    return rc;
}

/* What identifies the run of o (its importance checksum set by make_pattern). */
static cli_run run_of(const pattern_opts *o)
{
    const cli_run run = {o->dim == 2u ? 2u : 1u, o->kind_name, o->dim == 2u ? 0u : o->n, o->k,
                         0, 0u, o->seed, o->streams, o->trials};
    return run;
}

/* The provenance of what o runs: stream I, or all P streams. */
static void provenance(const pattern_opts *o, const cli_run *run, mcs_io_provenance *prov)
{
    const int one = o->stream < o->streams;
    cli_run_provenance(run, one ? o->stream : 0u, one ? o->stream + 1u : o->streams, prov);
}

static int make_pattern(const pattern_opts *o, mcs_importance *imp, mcs_pattern *pat,
                        cli_run *run)
{
    const mcs_importance *g = NULL;
    if (o->importance != NULL) {
        int rc = load_importance(o->importance, o->n, imp, &run->importance_crc);
        if (rc != 0)
            return rc;
        run->importance = 1;
        g = imp;
    }
    mcs_status st = mcs_pattern_init(pat, (mcs_pattern_kind)cli_pattern_kind(o->kind_name), o->n, o->k, g);
    if (st == MCS_ERR_KIND)
        return cli_fail(CMD, "%s is not defined with an importance function; drop --importance",
                        o->kind_name);
    if (st != MCS_OK)
        return cli_fail(CMD, "cannot set up the pattern: %s", mcs_status_str(st));
    return 0;
}

static int plot(const pattern_opts *o, const mcs_pattern *pat, const cli_prediction *pred,
                const cli_spectrum_row *rows, size_t nrows)
{
    char title[256], sub[512], exact[160], closed[160];
    snprintf(title, sizeof title, "%s: power spectrum, N = %zu bins, K = %zu samples, "
             "%llu trials (seed %llu)", o->kind_name, o->n, o->k,
             (unsigned long long)o->trials, (unsigned long long)o->seed);
    if (pat->importance != NULL)
        snprintf(sub, sizeof sub, "warped by the importance function of %s (harmonic mean "
                 "H = %.4f); k = 0 not drawn", cli_input_name(o->importance),
                 pat->importance->harmonic_mean);
    else
        snprintf(sub, sizeof sub, "k = 0 not drawn (S_0 = K / sqrt N = %.4g in every trial)",
                 (double)o->k / sqrt((double)o->n));
    snprintf(exact, sizeof exact, "exact: %s", pred->exact_source);
    snprintf(closed, sizeof closed, "closed form: %s", pred->closed_source);
    cli_plot_info info = {title, sub, pred->exact_source[0] != '\0' ? exact : NULL,
                          pred->closed_source[0] != '\0' ? closed : NULL, NULL, o->log_y};
    return cli_plot_spectrum(CMD, o->plot, &info, rows, nrows);
}

/* The first note: the kind, its shape ("N = 16 bins, K = 4 samples"), and
 * the trials, seed and streams of the run. */
static void run_line(const pattern_opts *o, const char *shape, char *buf, size_t size)
{
    uint64_t first = 0u, count = o->trials;
    if (o->stream < o->streams) {
        cli_stream_share(o->trials, o->streams, o->stream, &first, &count);
        snprintf(buf, size, "%s %s: %s, seed %llu, stream %llu of %llu: trials %llu..%llu of %llu",
                 CMD, o->kind_name, shape, (unsigned long long)o->seed,
                 (unsigned long long)o->stream, (unsigned long long)o->streams,
                 (unsigned long long)first, (unsigned long long)(first + count - 1u),
                 (unsigned long long)o->trials);
    } else {
        snprintf(buf, size, "%s %s: %s, %llu trials, seed %llu (%llu stream%s)", CMD,
                 o->kind_name, shape, (unsigned long long)o->trials, (unsigned long long)o->seed,
                 (unsigned long long)o->streams, o->streams == 1u ? "" : "s");
    }
}

static void print_notes(const pattern_opts *o, const mcs_pattern *pat, const cli_prediction *pred)
{
    char shape[96], line[512];
    snprintf(shape, sizeof shape, "N = %zu bins, K = %zu samples", o->n, o->k);
    run_line(o, shape, line, sizeof line);
    cli_note(o->csv, "%s", line);
    if (pat->importance != NULL)
        cli_note(o->csv, "importance function: %s, harmonic mean H = %.6g",
                 cli_input_name(o->importance), pat->importance->harmonic_mean);
    cli_note(o->csv, "exact: %s; closed: %s; z = (power - prediction) / power_stderr",
             pred->exact_source[0] != '\0' ? pred->exact_source : "none at this N",
             pred->closed_source[0] != '\0' ? pred->closed_source : "none in the note");
    cli_note(o->csv, "%s", "");
}

/* Progress of the run: all T trials, or with --stream I that stream's share. */
static void progress_start(const pattern_opts *o, cli_progress *progress, char *label,
                           size_t size)
{
    snprintf(label, size, "%s %s", CMD, o->kind_name);
    cli_progress_init(progress, !o->csv, label, "trials", o->trials);
    if (o->stream < o->streams) {
        uint64_t first = 0u, count = 0u;
        cli_stream_share(o->trials, o->streams, o->stream, &first, &count);
        cli_progress_span(progress, first, first + count);
    }
}

/* Measures, then plots (if asked) and prints: nothing reaches stdout when
 * the plot fails. */
static int measure_and_report(const pattern_opts *o, const mcs_pattern *pat,
                              const cli_prediction *pred, const cli_run *run, mcs_spectrum *acc,
                              cli_spectrum_row *rows)
{
    char label[128];
    cli_progress progress;
    progress_start(o, &progress, label, sizeof label);
    int rc = cli_run_streams(CMD, pat, o->seed, o->trials, o->streams, o->stream, acc, &progress);
    cli_progress_end(&progress);
    size_t nrows = 0;
    if (rc == 0)
        rc = cli_spectrum_rows(CMD, acc, pred, (double)o->k / (double)o->n, rows, &nrows);
    if (rc == 0 && o->plot != NULL)
        rc = plot(o, pat, pred, rows, nrows);
    if (rc == 0) {
        print_notes(o, pat, pred);
        cli_print_spectrum(o->csv, 1, rows, nrows);
    }
    if (rc == 0 && o->save != NULL) {
        cli_acc saved = {MCS_IO_KIND_SPECTRUM, acc};
        mcs_io_provenance *prov = cli_alloc(CMD, 1, sizeof *prov);
        rc = prov != NULL ? 0 : CLI_EXIT_FAIL;
        if (rc == 0) {
            provenance(o, run, prov);
            rc = cli_acc_write_with(CMD, o->save, &saved, prov);
        }
        free(prov);
    }
    return rc;
}

/* "jittered (2D, 8 x 8 strata), K = 64 points, F = 16" and the like. */
static void shape_2d(const pattern_opts *o, const cli_source2d *src, char *buf, size_t size)
{
    if (cli_source2d_uses_strata(src))
        snprintf(buf, size, "2D, %zu x %zu strata, K = %zu points, F = %zu",
                 src->pattern.strata_x, src->pattern.strata_y, o->k, o->freq);
    else
        snprintf(buf, size, "2D%s, K = %zu points, F = %zu", src->is_sampler ? " sampler" : "",
                 o->k, o->freq);
}

/* Notes, figure and rows of a 2D run in acc. */
static int report_2d(const pattern_opts *o, const cli_source2d *src, const mcs_pointset2d *acc)
{
    char shape[128], line[512], exact[160], title[512], sub[256], label[192];
    const char *source = cli_source2d_exact_source(src);
    shape_2d(o, src, shape, sizeof shape);
    run_line(o, shape, line, sizeof line);
    snprintf(exact, sizeof exact, "exact: %s; z = (power - exact) / power_stderr",
             source[0] != '\0' ? source
                                : "none for this kind (no closed form; not a rotated set)");
    const char *const notes[] = {line, exact, "", NULL};
    snprintf(title, sizeof title, "%s: 2D point-set spectrum, K = %zu points, %llu trials "
             "(seed %llu)", o->kind_name, o->k, (unsigned long long)acc->state->count,
             (unsigned long long)o->seed);
    if (cli_source2d_uses_strata(src))
        snprintf(sub, sizeof sub, "%zu x %zu strata; |kx|, |ky| <= F = %zu",
                 src->pattern.strata_x, src->pattern.strata_y, o->freq);
    else
        snprintf(sub, sizeof sub, "|kx|, |ky| <= F = %zu", o->freq);
    snprintf(label, sizeof label, "exact: %s", source);
    cli_exact2d ex;
    cli_source2d_exact(src, &ex);
    const cli_ps_report rep = {o->csv, o->radial, o->plot, o->log_y, title, sub, label, &ex, notes};
    return cli_report_pointset2d(CMD, &rep, acc);
}

/* --dim 2: the trials of a 2D pattern or sampler into a point-set spectrum. */
static int run_2d(const pattern_opts *o)
{
    cli_source2d src;
    int rc = cli_source2d_init(CMD, o->kind_name, o->k, o->freq, &src);
    const cli_stream_job job = {MCS_IO_KIND_POINTSET2D, {o->freq, 0u}, cli_source2d_run, &src};
    cli_acc acc = {MCS_IO_KIND_POINTSET2D, NULL};
    if (rc == 0)
        rc = cli_acc_new(CMD, job.kind, job.shape, &acc);
    if (rc == 0) {
        char label[128];
        cli_progress progress;
        progress_start(o, &progress, label, sizeof label);
        rc = cli_run_job(CMD, &job, o->seed, o->trials, o->streams, o->stream, acc.obj, &progress);
        cli_progress_end(&progress);
    }
    if (rc == 0)
        rc = report_2d(o, &src, acc.obj);
    mcs_io_provenance *prov = rc == 0 && o->save != NULL ? cli_alloc(CMD, 1, sizeof *prov) : NULL;
    if (rc == 0 && o->save != NULL && prov == NULL)
        rc = CLI_EXIT_FAIL;
    if (rc == 0 && o->save != NULL) {
        const cli_run run = run_of(o);
        provenance(o, &run, prov);
        rc = cli_acc_write_with(CMD, o->save, &acc, prov);
    }
    free(prov);
    cli_acc_free(&acc);
    cli_source2d_free(&src);
    return rc;
}

int cli_cmd_pattern(int argc, char **argv)
{
    pattern_opts o = {NULL, 0, 0, DEFAULT_TRIALS, DEFAULT_SEED, NULL, NULL, 0, NULL, 1u, 1u,
                      1u, 0u, 0, 0};
    int rc = parse(argc, argv, &o);
    if (rc != 0)
        return rc < 0 ? CLI_EXIT_OK : rc;
    if (o.dim == 2u)
        return run_2d(&o);
    mcs_importance *imp = cli_alloc(CMD, 1, sizeof *imp);
    mcs_spectrum *acc = cli_alloc(CMD, 1, sizeof *acc);
    cli_prediction *pred = cli_alloc(CMD, 1, sizeof *pred);
    cli_spectrum_row *rows = cli_alloc(CMD, CLI_HALF_MAX, sizeof *rows);
    mcs_pattern pat;
    cli_run run = run_of(&o);
    rc = imp != NULL && acc != NULL && pred != NULL && rows != NULL ? 0 : CLI_EXIT_FAIL;
    if (rc == 0)
        rc = make_pattern(&o, imp, &pat, &run);
    if (rc == 0)
        rc = cli_predict_power(CMD, &pat, pred);
    /* Batch 1 (every trial its own unit): per-trial standard errors that a
     * split into streams, files or ranks reproduces exactly on merge. */
    if (rc == 0 && (mcs_spectrum_init(acc, o.n) != MCS_OK || mcs_spectrum_set_batch(acc, 1u) != MCS_OK))
        rc = cli_internal(CMD, "mcs_spectrum_init failed");
    if (rc == 0)
        rc = measure_and_report(&o, &pat, pred, &run, acc, rows);
    free(rows);
    free(pred);
    free(acc);
    free(imp);
    return rc;
}
