/* Point sets from many files into one point-set spectrum (see psets.h). */
#include "psets.h"
#include "cli.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <stdint.h>
#include <unistd.h>

size_t cli_default_freq(size_t k_max, size_t cap)
{
    /* ceil(5 sqrt(K)) in integers: the least F with F^2 >= 25 K. */
    const double k = (double)k_max;
    size_t f = (size_t)ceil(5.0 * sqrt(k));
    while (f > 1u && (double)(f - 1u) * (double)(f - 1u) >= 25.0 * k)
        --f;
    while ((double)f * (double)f < 25.0 * k)
        ++f;
    if (f < 1u)
        f = 1u;
    return f > cap ? cap : f;
}

int cli_ps_parse_dims(const char *cmd, const char *text, cli_ps_input *in)
{
    char buf[64];
    const size_t len = strlen(text);
    char *comma = len < sizeof buf ? strchr(memcpy(buf, text, len + 1u), ',') : NULL;
    if (comma != NULL)
        *comma = '\0';
    uint64_t a = 0, b = 0;
    const int bad = len >= sizeof buf || cli_parse_u64(buf, 0u, CLI_MAX_DIM - 1u, &a) != 0 ||
                    (comma != NULL && cli_parse_u64(comma + 1, 0u, CLI_MAX_DIM - 1u, &b) != 0);
    if (bad)
        return cli_fail(cmd, "--dims expects one coordinate index or two separated by a comma "
                        "(0-based, 0 to %u: '0,2' reads the first and third), not '%s'",
                        CLI_MAX_DIM - 1u, text);
    if (comma != NULL && a == b)
        return cli_fail(cmd, "--dims %s names coordinate %llu twice: give two different ones",
                        text, (unsigned long long)a);
    in->ndims = comma != NULL ? 2u : 1u;
    in->dims[0] = (size_t)a;
    in->dims[1] = (size_t)b;
    return 0;
}

int cli_ps_parse_format(const char *cmd, const char *format, cli_ps_input *in)
{
    if (format == NULL || strcmp(format, "utk") == 0)
        return 0;
    if (strcmp(format, "psa") == 0) {
        in->psa = 1;
        return 0;
    }
    return cli_fail(cmd, "--format expects utk or psa, not '%s'", format);
}

int cli_ps_parse_path(const char *cmd, const char *text, mcs_pointset_path *path)
{
    static const char *const names[] = {"auto", "direct", "nufft"};
    static const mcs_pointset_path paths[] = {MCS_POINTSET_PATH_AUTO, MCS_POINTSET_PATH_DIRECT,
                                              MCS_POINTSET_PATH_NUFFT};
    for (size_t i = 0; text != NULL && i < 3u; ++i)
        if (strcmp(text, names[i]) == 0) {
            *path = paths[i];
            return 0;
        }
    return text == NULL ? 0 : cli_fail(cmd, "--path expects auto, direct or nufft, not '%s'", text);
}

/* What the reader's callback needs to project a set and pass it on. */
typedef struct {
    const char *cmd;
    const cli_ps_input *in;
    const char *name;
    const cli_pointset_stats *file_stats; /* of the file being read */
    uint64_t first_set;                   /* sets before this file */
    cli_ps_set_fn fn;
    void *ctx;
    double *proj;
    size_t proj_cap;
} read_ctx;

static int project(void *ctx, size_t k, const double *coords, const double *weights)
{
    (void)weights;
    read_ctx *c = ctx;
    const cli_ps_input *in = c->in;
    const size_t fdim = c->file_stats->dim;
    const uint64_t set = c->first_set + c->file_stats->sets;
    if (in->ndims == 0u)
        return c->fn(c->ctx, set, k, coords, c->name);
    for (size_t i = 0; i < in->ndims; ++i)
        if (in->dims[i] >= fdim)
            return cli_fail(c->cmd, "%s: --dims names coordinate %zu (0-based), but the points "
                            "of this file have %zu coordinate%s", c->name, in->dims[i], fdim,
                            fdim == 1u ? "" : "s");
    if (k > c->proj_cap) {
        free(c->proj);
        c->proj = cli_alloc(c->cmd, k, in->ndims * sizeof *c->proj);
        c->proj_cap = c->proj != NULL ? k : 0u;
        if (c->proj == NULL)
            return CLI_EXIT_FAIL;
    }
    for (size_t j = 0; j < k; ++j)
        for (size_t i = 0; i < in->ndims; ++i)
            c->proj[j * in->ndims + i] = coords[j * fdim + in->dims[i]];
    return c->fn(c->ctx, set, k, c->proj, c->name);
}

int cli_ps_read(const char *cmd, const cli_ps_input *in, const char *const *paths,
                size_t npaths, cli_ps_set_fn fn, void *ctx, cli_pointset_stats *stats,
                cli_progress *progress)
{
    const cli_pointset_format fmt = {in->ndims != 0u ? 0u : in->dim, 0, in->wrap, 0.0, NULL};
    cli_pointset_stats one;
    read_ctx c = {cmd, in, NULL, &one, 0u, fn, ctx, NULL, 0u};
    stats->sets = 0u;
    stats->dim = in->dim;
    stats->k_min = (size_t)-1;
    stats->k_max = 0u;
    stats->lines = 0u;
    int rc = 0;
    for (size_t i = 0; rc == 0 && i < (npaths == 0u ? 1u : npaths); ++i) {
        const char *path = npaths == 0u ? NULL : paths[i];
        c.name = cli_input_name(path);
        c.first_set = stats->sets;
        rc = in->psa ? cli_read_psa(cmd, path, &fmt, project, &c, &one, progress)
                     : cli_read_pointsets(cmd, path, &fmt, project, &c, &one, progress);
        stats->sets += one.sets;
        stats->lines = one.lines;
        if (one.sets > 0u) {
            stats->k_min = one.k_min < stats->k_min ? one.k_min : stats->k_min;
            stats->k_max = one.k_max > stats->k_max ? one.k_max : stats->k_max;
        }
    }
    if (stats->sets == 0u)
        stats->k_min = 0u;
    free(c.proj);
    return rc;
}

size_t cli_ps_bin_count(size_t freq, size_t width)
{
    return (freq + 1u) / width;
}

/* The run's accumulator: it only merges, so it needs no NUFFT memory
 * (MCS_POINTSET_DIRECT_ONLY, about a quarter of the scratch's at large F);
 * header and buffer in one block, as cli_acc_new makes them (cli_acc_free
 * frees both). */
static int new_merge_only(const char *cmd, size_t dim, size_t freq, cli_acc *acc)
{
    const size_t head = ((dim == 2u ? sizeof(mcs_pointset2d) : sizeof(mcs_pointset)) + 63u) /
                        64u * 64u;
    size_t bytes = 0u;
    mcs_status st = dim == 2u ? mcs_pointset2d_size(freq, MCS_POINTSET_DIRECT_ONLY, &bytes)
                              : mcs_pointset_size(freq, MCS_POINTSET_DIRECT_ONLY, &bytes);
    unsigned char *p = st == MCS_OK && bytes <= SIZE_MAX - head ? malloc(head + bytes) : NULL;
    if (p == NULL)
        return cli_fail(cmd, "--freq %zu needs %zu more bytes for the run's statistics, more "
                        "than this machine can allocate", freq, head + bytes);
    st = dim == 2u ? mcs_pointset2d_init((mcs_pointset2d *)(void *)p, freq,
                                         MCS_POINTSET_DIRECT_ONLY, p + head, bytes)
                   : mcs_pointset_init((mcs_pointset *)(void *)p, freq, MCS_POINTSET_DIRECT_ONLY,
                                       p + head, bytes);
    if (st != MCS_OK) {
        free(p);
        return cli_internal(cmd, "setting up the run's accumulator: %s", mcs_status_str(st));
    }
    acc->kind = dim == 2u ? MCS_IO_KIND_POINTSET2D : MCS_IO_KIND_POINTSET;
    acc->obj = p;
    return 0;
}

int cli_ps_sink_init(const char *cmd, size_t dim, size_t freq, size_t width, cli_ps_sink *s)
{
    memset(s, 0, sizeof *s);
    s->cmd = cmd;
    s->dim = dim;
    s->freq = freq;
    s->width = width;
    const mcs_io_kind kind = dim == 2u ? MCS_IO_KIND_POINTSET2D : MCS_IO_KIND_POINTSET;
    const size_t shape[2] = {freq, 0u};
    int rc = cli_acc_new(cmd, kind, shape, &s->one);
    if (rc == 0)
        rc = new_merge_only(cmd, dim, freq, &s->acc);
    if (rc != 0 || dim != 2u || width == 1u)
        return rc;
    s->nbins = cli_ps_bin_count(freq, width);
    s->bin_mean = cli_alloc(cmd, s->nbins, sizeof *s->bin_mean);
    s->bin_m2 = cli_alloc(cmd, s->nbins, sizeof *s->bin_m2);
    s->ring_n = cli_alloc(cmd, freq + 1u, sizeof *s->ring_n);
    if (s->bin_mean == NULL || s->bin_m2 == NULL || s->ring_n == NULL)
        return CLI_EXIT_FAIL;
    for (size_t b = 0; b < s->nbins; ++b)
        s->bin_mean[b] = s->bin_m2[b] = 0.0;
    for (size_t r = 0; r <= freq; ++r) {
        size_t n = 0u;
        if (mcs_pointset2d_ring_size(r, &n) != MCS_OK)
            return cli_internal(cmd, "the size of annulus %zu", r);
        s->ring_n[r] = (double)n;
    }
    return 0;
}

void cli_ps_sink_free(cli_ps_sink *s)
{
    cli_acc_free(&s->acc);
    cli_acc_free(&s->one);
    free(s->bin_mean);
    free(s->bin_m2);
    free(s->ring_n);
    s->bin_mean = s->bin_m2 = s->ring_n = NULL;
}

int cli_ps_sink_transform(cli_ps_sink *s, size_t k, const double *pts)
{
    mcs_status st;
    if (s->dim == 2u) {
        mcs_pointset2d *o = s->one.obj;
        st = mcs_pointset2d_init(o, s->freq, 0u, o->mem, o->bytes);
        if (st == MCS_OK)
            st = mcs_pointset2d_set_path(o, s->path);
        if (st == MCS_OK)
            st = mcs_pointset2d_add(o, k, pts);
    } else {
        mcs_pointset *o = s->one.obj;
        st = mcs_pointset_init(o, s->freq, 0u, o->mem, o->bytes);
        if (st == MCS_OK)
            st = mcs_pointset_set_path(o, s->path);
        if (st == MCS_OK)
            st = mcs_pointset_add(o, k, pts);
    }
    if (st != MCS_OK)
        return cli_internal(s->cmd, "adding a point set failed: %s", mcs_status_str(st));
    return 0;
}

/* The set's average over each annulus of width W, into the Welford sums. */
static int absorb_bins(cli_ps_sink *s, const mcs_pointset2d *one)
{
    const double t = (double)(s->sets + 1u);
    for (size_t b = 0; b < s->nbins; ++b) {
        double sum = 0.0, n = 0.0;
        for (size_t r = b * s->width; r < (b + 1u) * s->width; ++r) {
            double avg = 0.0;
            if (mcs_pointset2d_radial(one, r, &avg) != MCS_OK)
                return cli_internal(s->cmd, "reading annulus %zu of a set", r);
            sum += s->ring_n[r] * avg;
            n += s->ring_n[r];
        }
        const double v = sum / n, d = v - s->bin_mean[b];
        s->bin_mean[b] += d / t;
        s->bin_m2[b] += d * (v - s->bin_mean[b]);
    }
    return 0;
}

int cli_ps_sink_absorb(cli_ps_sink *s, const void *one)
{
    int rc = s->nbins > 0u ? absorb_bins(s, one) : 0;
    if (rc != 0)
        return rc;
    const mcs_status st = s->dim == 2u ? mcs_pointset2d_merge(s->acc.obj, one)
                                       : mcs_pointset_merge(s->acc.obj, one);
    if (st != MCS_OK)
        return cli_internal(s->cmd, "merging a point set failed: %s", mcs_status_str(st));
    ++s->sets;
    return 0;
}

/* floor(sqrt(v)) for a whole v < 2^52. */
static size_t isqrt(size_t v)
{
    size_t r = (size_t)sqrt((double)v);
    while (r * r > v)
        --r;
    while ((r + 1u) * (r + 1u) <= v)
        ++r;
    return r;
}

/* Sum (pass 0) or squared deviations from mean (pass 1) of the mean
 * periodogram over the wave vectors lo <= |k| < hi, |kx|, |ky| <= F, the
 * whole plane counted; *n counts them. Row by row over ky, the two runs of
 * kx with lo^2 - ky^2 <= kx^2 < hi^2 - ky^2. */
static void annulus_pass(const mcs_pointset2d *acc, size_t lo, size_t hi, int pass, double mean,
                         double *acc_out, double *n)
{
    const long f = (long)acc->freq_max, h = (long)hi;
    for (long ky = -h + 1; ky < h; ++ky) {
        if (labs(ky) > f)
            continue;
        const size_t y2 = (size_t)(ky * ky);
        const size_t lo2 = lo * lo > y2 ? lo * lo - y2 : 0u;
        const long xmax = (long)isqrt(hi * hi - y2 - 1u);
        long xmin = (long)isqrt(lo2);
        if ((size_t)(xmin * xmin) < lo2)
            ++xmin;
        for (long ax = xmin; ax <= xmax && ax <= f; ++ax)
            for (int sign = 0; sign < (ax == 0 ? 1 : 2); ++sign) {
                double p = 0.0;
                if (mcs_pointset2d_power(acc, sign ? -ax : ax, ky, &p) != MCS_OK)
                    continue;
                *acc_out += pass == 0 ? p : (p - mean) * (p - mean);
                *n += pass == 0 ? 1.0 : 0.0;
            }
    }
}

/* psa's anisotropy over annulus b of width W of the mean periodogram:
 * 10 log10(unbiased variance / mean^2) over its wave vectors, by two passes
 * (mean, then squared deviations), as mcs_pointset2d_anisotropy does for
 * W = 1; NaN where it is not defined. */
static double bin_anisotropy(const cli_ps_sink *s, size_t b)
{
    const size_t lo = b * s->width, hi = lo + s->width;
    double sum = 0.0, dev = 0.0, n = 0.0;
    annulus_pass(s->acc.obj, lo, hi, 0, 0.0, &sum, &n);
    const double mean = sum / n;
    annulus_pass(s->acc.obj, lo, hi, 1, mean, &dev, &n);
    const double var = dev / (n - 1.0);
    if (!(n > 1.0) || !(fabs(mean) > 1e-20) || !(var > 0.0))
        return (double)NAN;
    return 10.0 * log10(var / (mean * mean));
}

void cli_ps_sink_bin(const void *sink, size_t b, double *mean, double *se, double *aniso)
{
    const cli_ps_sink *s = sink;
    const double t = (double)s->sets;
    *mean = s->sets > 0u ? s->bin_mean[b] : (double)NAN;
    *se = s->sets > 1u ? sqrt(fmax(s->bin_m2[b], 0.0) / (t - 1.0) / t) : (double)NAN;
    *aniso = b == 0u && s->width == 1u ? (double)NAN : bin_anisotropy(s, b);
}

/* ---- Provenance of the inputs --------------------------------------------- */

/* The CRC-32 and length of the bytes of fp, copied to copy when not NULL. */
static int checksum(FILE *fp, FILE *copy, uint32_t *crc, uint64_t *bytes)
{
    static unsigned char buf[1u << 16];
    size_t got;
    *crc = 0u;
    *bytes = 0u;
    while ((got = fread(buf, 1u, sizeof buf, fp)) > 0u) {
        *crc = cli_crc32_update(*crc, buf, got);
        *bytes += got;
        if (copy != NULL && fwrite(buf, 1u, got, copy) != got)
            return -1;
    }
    return ferror(fp) ? -1 : 0;
}

/* --save of standard input: its bytes go to an unnamed temporary file that
 * becomes standard input, so the reader reads what was checksummed (and
 * names it <stdin> as ever). */
int cli_ps_checksum_stdin(const char *cmd, uint32_t *crc, uint64_t *bytes)
{
    FILE *copy = tmpfile();
    if (copy == NULL)
        return cli_fail(cmd, "<stdin>: cannot keep a copy to checksum: %s", strerror(errno));
    int bad = checksum(stdin, copy, crc, bytes) != 0 || fflush(copy) != 0;
    const int err = errno;
    if (!bad && dup2(fileno(copy), STDIN_FILENO) < 0)
        bad = 1;
    fclose(copy);
    if (bad)
        return cli_fail(cmd, "<stdin>: cannot read it to checksum: %s", strerror(err));
    clearerr(stdin);
    rewind(stdin);
    return 0;
}

/* The CRC-32 and length of the file path, read again after the point sets. */
int cli_ps_checksum_path(const char *cmd, const char *path, uint32_t *crc, uint64_t *bytes)
{
    FILE *fp = fopen(path, "rb");
    int bad = fp == NULL || checksum(fp, NULL, crc, bytes) != 0;
    const int err = errno;
    if (fp != NULL)
        fclose(fp);
    return bad ? cli_fail(cmd, "cannot read '%s' to checksum it: %s", path, strerror(err)) : 0;
}

/* The --save provenance of the inputs: each file's CRC-32 and length (of
 * standard input, what checksum_stdin kept), merged (mcs_io_provenance_merge
 * sorts them and drops a file given twice). */
int cli_ps_provenance(const char *cmd, const char *const *paths, size_t npaths,
                      uint32_t stdin_crc, uint64_t stdin_bytes, mcs_io_provenance *prov)
{
    mcs_io_provenance *one = cli_alloc(cmd, 1, sizeof *one);
    if (one == NULL)
        return CLI_EXIT_FAIL;
    int rc = 0;
    for (size_t i = 0; rc == 0 && i < (npaths > 0u ? npaths : 1u); ++i) {
        const char *path = npaths > 0u ? paths[i] : NULL;
        uint32_t crc = stdin_crc;
        uint64_t bytes = stdin_bytes;
        if (path != NULL && strcmp(path, "-") != 0)
            rc = cli_ps_checksum_path(cmd, path, &crc, &bytes);
        if (rc != 0)
            break;
        cli_input_provenance(cli_input_name(path), crc, bytes, i == 0u ? prov : one);
        const mcs_status st = i == 0u ? MCS_OK : mcs_io_provenance_merge(prov, one);
        if (st != MCS_OK)
            rc = cli_internal(cmd, "the provenance of %s: %s", path, mcs_status_str(st));
    }
    free(one);
    return rc;
}

