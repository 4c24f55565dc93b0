/* Point-set and value-list readers of the mcspec command (see input.h). */
#include "input.h"
#include "cli.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* Most columns a line can have: CLI_MAX_DIM coordinates and a weight; one
 * more token is split off so that a longer line is reported, not cut. */
#define MAX_COLUMNS (CLI_MAX_DIM + 2u)

typedef struct {
    const char *cmd;
    const char *name;
    FILE *fp;
    char *buf;
    size_t cap;
    unsigned long line;
} reader;

const char *cli_input_name(const char *path)
{
    return path == NULL || strcmp(path, "-") == 0 ? "<stdin>" : path;
}

static int reader_open(reader *r, const char *cmd, const char *path)
{
    r->cmd = cmd;
    r->name = cli_input_name(path);
    r->buf = NULL;
    r->cap = 0;
    r->line = 0;
    if (path == NULL || strcmp(path, "-") == 0) {
        r->fp = stdin;
        return 0;
    }
    r->fp = fopen(path, "r");
    if (r->fp == NULL)
        return cli_fail(cmd, "cannot read '%s': %s", path, strerror(errno));
    /* fopen succeeds on a directory; the first read would fail less clearly. */
    struct stat st;
    if (fstat(fileno(r->fp), &st) == 0 && S_ISDIR(st.st_mode)) {
        fclose(r->fp);
        r->fp = NULL;
        return cli_fail(cmd, "cannot read '%s': it is a directory", path);
    }
    return 0;
}

static void reader_close(reader *r)
{
    if (r->fp != NULL && r->fp != stdin)
        fclose(r->fp);
    r->fp = NULL;
    free(r->buf);
    r->buf = NULL;
}

/* Next line without its end-of-line characters: 1, or 0 at the end of the
 * input, or -1 after a read error or a NUL byte in the line (reported). */
static int reader_next(reader *r, char **line)
{
    errno = 0;
    ssize_t len = getline(&r->buf, &r->cap, r->fp);
    if (len < 0) {
        if (ferror(r->fp)) {
            cli_fail(r->cmd, "%s: line %lu: read error: %s", r->name, r->line + 1u,
                     strerror(errno != 0 ? errno : EIO));
            return -1;
        }
        return 0;
    }
    ++r->line;
    /* Every later step reads the line as a C string, which a NUL byte would
     * end early: the rest of the line (a point, a digit) would be lost. */
    const char *nul = memchr(r->buf, '\0', (size_t)len);
    if (nul != NULL) {
        cli_fail(r->cmd, "%s: line %lu: a NUL byte at column %zu (not a text line; is this "
                 "a binary file?)", r->name, r->line, (size_t)(nul - r->buf) + 1u);
        return -1;
    }
    while (len > 0 && (r->buf[len - 1] == '\n' || r->buf[len - 1] == '\r'))
        r->buf[--len] = '\0';
    *line = r->buf;
    return 1;
}

static int is_blank(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

/* Splits line in place at blanks; stores up to max tokens, returns how many
 * there are in all (so a caller can report a wrong column count). */
static size_t split(char *line, char **tok, size_t max)
{
    size_t count = 0;
    char *c = line;
    for (;;) {
        while (is_blank(*c))
            ++c;
        if (*c == '\0')
            return count;
        if (count < max)
            tok[count] = c;
        ++count;
        while (*c != '\0' && !is_blank(*c))
            ++c;
        if (*c != '\0')
            *c++ = '\0';
    }
}

/* A finite number filling all of tok. 0, or an exit status (reported). */
static int parse_number(const reader *r, const char *tok, const char *what, double *out)
{
    char *end = NULL;
    errno = 0;
    double v = strtod(tok, &end);
    if (end == tok || *end != '\0') {
        cli_fail(r->cmd, "%s: line %lu: %s '%s' is not a number", r->name, r->line, what, tok);
        return CLI_EXIT_USAGE;
    }
    if (!isfinite(v)) {
        cli_fail(r->cmd, "%s: line %lu: %s '%s' is not a finite number", r->name, r->line, what,
                 tok);
        return CLI_EXIT_USAGE;
    }
    *out = v;
    return 0;
}

/* ---- Point sets -------------------------------------------------------------- */

typedef struct {
    double *coords;
    double *weights;
    size_t k, cap, dim;
    double weight_sum; /* of the set so far, summed in the order the library sums */
} point_buf;

/* Where complete sets go, and the counts kept of them. */
typedef struct {
    cli_pointset_fn fn;
    void *ctx;
    cli_pointset_stats *stats;
    cli_progress *progress;
} set_sink;

static int buf_push(const char *cmd, point_buf *b, const double *coord, double weight)
{
    if (b->k == b->cap) {
        size_t cap = b->cap != 0u ? 2u * b->cap : 1024u;
        double *c = realloc(b->coords, cap * b->dim * sizeof *c);
        if (c == NULL)
            return cli_internal(cmd, "out of memory reading a set of %zu points", b->k);
        b->coords = c;
        double *w = realloc(b->weights, cap * sizeof *w);
        if (w == NULL)
            return cli_internal(cmd, "out of memory reading a set of %zu points", b->k);
        b->weights = w;
        b->cap = cap;
    }
    memcpy(b->coords + b->k * b->dim, coord, b->dim * sizeof *coord);
    b->weights[b->k++] = weight;
    b->weight_sum += weight;
    return 0;
}

/* The set's weights so far against fmt's limit. */
static int check_weight_sum(const reader *r, const cli_pointset_format *fmt, const point_buf *b)
{
    if (!fmt->weights || !(fmt->weight_sum_max > 0.0) || b->weight_sum <= fmt->weight_sum_max)
        return 0;
    int e = 0;
    const double m = frexp(fmt->weight_sum_max, &e);
    char limit[64];
    if (m == 0.5) /* a power of two: say which */
        snprintf(limit, sizeof limit, "%g = 2^%d", fmt->weight_sum_max, e - 1);
    else
        snprintf(limit, sizeof limit, "%g", fmt->weight_sum_max);
    return cli_fail(r->cmd, "%s: line %lu: this set's weights sum to %g by this line, above %s, "
                    "the most a set may sum to (%s): scale the weights down", r->name, r->line,
                    b->weight_sum, limit,
                    fmt->weight_sum_what != NULL ? fmt->weight_sum_what : "the accumulator");
}

/* One point line, tokens already split: coordinates (checked or wrapped),
 * then the weight. */
static int parse_point(const reader *r, const cli_pointset_format *fmt, size_t dim, char **tok,
                       size_t ntok, double *coord, double *weight)
{
    size_t want = dim + (fmt->weights ? 1u : 0u);
    if (ntok != want) {
        const char *hint = fmt->weights ? (dim == 1u ? "a point, then its weight"
                                                     : "the coordinates, then the weight")
                                        : (ntok == dim + 1u && fmt->dim != 0u
                                               ? "a weight column needs --weights"
                                               : fmt->dim == 0u ? "every point has as many "
                                                                  "coordinates as the first"
                                                                : "one point per line");
        return cli_fail(r->cmd, "%s: line %lu: expected %zu column%s, found %zu (%s)", r->name,
                        r->line, want, want == 1u ? "" : "s", ntok, hint);
    }
    for (size_t d = 0; d < dim; ++d) {
        int rc = parse_number(r, tok[d], "coordinate", &coord[d]);
        if (rc != 0)
            return rc;
        if (fmt->wrap) {
            coord[d] -= floor(coord[d]);
            if (coord[d] >= 1.0) /* a tiny negative value rounds up to 1: it is 0 mod 1 */
                coord[d] = 0.0;
        } else if (!(coord[d] >= 0.0 && coord[d] < 1.0)) {
            return cli_fail(r->cmd, "%s: line %lu: coordinate %s is outside [0,1) (--wrap takes it "
                            "modulo 1)", r->name, r->line, tok[d]);
        }
    }
    *weight = 1.0;
    if (fmt->weights) {
        int rc = parse_number(r, tok[dim], "weight", weight);
        if (rc != 0)
            return rc;
        if (*weight < 0.0)
            return cli_fail(r->cmd, "%s: line %lu: weight %s is negative", r->name, r->line,
                            tok[dim]);
    }
    return 0;
}

static int emit_set(const reader *r, const cli_pointset_format *fmt, point_buf *b,
                    const set_sink *out)
{
    cli_pointset_stats *stats = out->stats;
    stats->lines = r->line;
    int rc = out->fn(out->ctx, b->k, b->coords, fmt->weights ? b->weights : NULL);
    if (rc != 0)
        return rc;
    ++stats->sets;
    stats->k_min = b->k < stats->k_min ? b->k : stats->k_min;
    stats->k_max = b->k > stats->k_max ? b->k : stats->k_max;
    b->k = 0;
    b->weight_sum = 0.0;
    if (out->progress != NULL)
        cli_progress_update(out->progress, stats->sets);
    return 0;
}

/* The next line that is not blank, from its first non-blank character on:
 * 1, or 0 at the end of the input, or -1 (reported) as reader_next. */
static int next_text(reader *r, char **text)
{
    char *line = NULL;
    int got;
    while ((got = reader_next(r, &line)) > 0) {
        while (is_blank(*line))
            ++line;
        if (*line != '\0') {
            *text = line;
            return 1;
        }
    }
    return got;
}

/* A point line s of either format (not blank, not '#'): its columns (the
 * first point line fixes the dimension when fmt leaves it open), the point
 * into b, and the set's weights against fmt's limit. */
static int point_line(const reader *r, const cli_pointset_format *fmt, point_buf *b, char *s,
                      cli_pointset_stats *stats)
{
    char *tok[MAX_COLUMNS];
    double coord[MAX_COLUMNS] = {0.0}, weight = 1.0;
    const size_t ntok = split(s, tok, MAX_COLUMNS);
    if (b->dim == 0u) {
        const size_t cols = ntok - (fmt->weights ? 1u : 0u);
        if (ntok == 0u || cols == 0u || cols > CLI_MAX_DIM)
            return cli_fail(r->cmd, "%s: line %lu: %zu column%s: a point has 1 to %u "
                            "coordinates%s", r->name, r->line, ntok, ntok == 1u ? "" : "s",
                            CLI_MAX_DIM, fmt->weights ? ", then its weight" : "");
        b->dim = cols;
        stats->dim = cols;
    }
    int rc = parse_point(r, fmt, b->dim, tok, ntok, coord, &weight);
    if (rc == 0)
        rc = buf_push(r->cmd, b, coord, weight);
    if (rc == 0)
        rc = check_weight_sum(r, fmt, b);
    return rc;
}

/* utk's line loop: rc 0 at the end of the input with every set emitted, one at
 * least. */
static int read_sets(reader *r, const cli_pointset_format *fmt, point_buf *b,
                     const set_sink *out)
{
    cli_pointset_stats *stats = out->stats;
    unsigned long sep_line = 0;
    char *s = NULL;
    int got;
    while ((got = next_text(r, &s)) > 0) {
        if (*s == '#') {
            if (b->k > 0u) {
                int rc = emit_set(r, fmt, b, out);
                if (rc != 0)
                    return rc;
            } else if (stats->sets > 0u) {
                return cli_fail(r->cmd, "%s: line %lu: empty point set (no point since the '#' "
                                "line at line %lu; remove one of them)", r->name, r->line, sep_line);
            }
            sep_line = r->line;
            continue;
        }
        int rc = point_line(r, fmt, b, s, stats);
        if (rc != 0)
            return rc;
    }
    if (got < 0)
        return CLI_EXIT_USAGE;
    if (b->k > 0u)
        return emit_set(r, fmt, b, out);
    if (stats->sets > 0u)
        return 0;
    if (r->line == 0u)
        return cli_fail(r->cmd, "%s: the input is empty (no lines, so no point sets)", r->name);
    return cli_fail(r->cmd, "%s: line %lu: end of input and no point read (one point per line; "
                    "see %s --help)", r->name, r->line, r->cmd);
}

/* The line loop of one file's format. */
typedef int (*line_loop)(reader *r, const cli_pointset_format *fmt, point_buf *b,
                         const set_sink *out);

static void stats_start(cli_pointset_stats *stats, const cli_pointset_format *fmt)
{
    stats->sets = 0;
    stats->dim = fmt->dim;
    stats->k_min = (size_t)-1;
    stats->k_max = 0;
    stats->lines = 0;
}

/* Opens path, runs loop over its lines, closes it (k_min 0 without a set). */
static int read_file(const char *cmd, const char *path, const cli_pointset_format *fmt,
                     line_loop loop, const set_sink *out)
{
    reader r;
    int rc = reader_open(&r, cmd, path);
    if (rc != 0)
        return rc;
    point_buf b = {NULL, NULL, 0, 0, fmt->dim, 0.0};
    rc = loop(&r, fmt, &b, out);
    out->stats->lines = r.line;
    if (out->stats->sets == 0u)
        out->stats->k_min = 0;
    reader_close(&r);
    free(b.coords);
    free(b.weights);
    return rc;
}

int cli_read_pointsets(const char *cmd, const char *path, const cli_pointset_format *fmt,
                       cli_pointset_fn fn, void *ctx, cli_pointset_stats *stats,
                       cli_progress *progress)
{
    const set_sink out = {fn, ctx, stats, progress};
    stats_start(stats, fmt);
    return read_file(cmd, path, fmt, read_sets, &out);
}

/* ---- Value lists ------------------------------------------------------------- */

static int push_value(const char *cmd, double **values, size_t *count, size_t *cap, double v)
{
    if (*count == *cap) {
        size_t c = *cap != 0u ? 2u * *cap : 256u;
        double *p = realloc(*values, c * sizeof *p);
        if (p == NULL)
            return cli_internal(cmd, "out of memory reading %zu values", *count);
        *values = p;
        *cap = c;
    }
    (*values)[(*count)++] = v;
    return 0;
}

static int read_value_lines(reader *r, const char *what, int positive, size_t max,
                            double **values, size_t *count)
{
    size_t cap = 0;
    char *line = NULL;
    int got;
    while ((got = reader_next(r, &line)) > 0) {
        char *tok[2];
        size_t ntok = split(line, tok, 2);
        if (ntok == 0u || tok[0][0] == '#')
            continue;
        if (ntok != 1u)
            return cli_fail(r->cmd, "%s: line %lu: expected one %s per line, found %zu columns",
                            r->name, r->line, what, ntok);
        double v = 0.0;
        int rc = parse_number(r, tok[0], what, &v);
        if (rc != 0)
            return rc;
        /* Importance weights: 0 is a bin that is never drawn (importance.h). */
        if (positive && !(v >= 0.0))
            return cli_fail(r->cmd, "%s: line %lu: %s %s must be >= 0", r->name, r->line, what,
                            tok[0]);
        if (*count == max)
            return cli_fail(r->cmd, "%s: line %lu: more than %zu values (the most this build "
                            "takes, MCS_MAX_N)", r->name, r->line, max);
        rc = push_value(r->cmd, values, count, &cap, v);
        if (rc != 0)
            return rc;
    }
    if (got < 0)
        return CLI_EXIT_USAGE;
    if (*count == 0u && r->line == 0u)
        return cli_fail(r->cmd, "%s: the input is empty (no lines, so no %s)", r->name, what);
    if (*count == 0u)
        return cli_fail(r->cmd, "%s: line %lu: end of input and no %s read", r->name, r->line,
                        what);
    return 0;
}

int cli_read_values(const char *cmd, const char *path, const char *what, int positive,
                    size_t max, double **values, size_t *count)
{
    *values = NULL;
    *count = 0;
    reader r;
    int rc = reader_open(&r, cmd, path);
    if (rc != 0)
        return rc;
    rc = read_value_lines(&r, what, positive, max, values, count);
    reader_close(&r);
    if (rc != 0) {
        free(*values);
        *values = NULL;
        *count = 0;
    }
    return rc;
}

/* ---- psa's point files -------------------------------------------------------- */

/* The count line of a psa file: a whole number >= 1 alone on its line. */
static int psa_count(const reader *r, char *line, size_t *count)
{
    char *tok[2];
    const size_t ntok = split(line, tok, 2);
    uint64_t v = 0;
    if (ntok != 1u || cli_parse_u64(tok[0], 1u, (uint64_t)SIZE_MAX / 2u, &v) != 0)
        return cli_fail(r->cmd, "%s: line %lu: a psa file starts with its point count, a whole "
                        "number >= 1 alone on the line (is this a utk file? drop --format psa)",
                        r->name, r->line);
    *count = (size_t)v;
    return 0;
}

/* psa's line loop over one file: the count, then exactly that many points. */
static int read_psa_lines(reader *r, const cli_pointset_format *fmt, point_buf *b,
                          const set_sink *out)
{
    size_t want = 0u;
    unsigned long count_line = 0;
    char *s = NULL;
    int got;
    while ((got = next_text(r, &s)) > 0) {
        if (*s == '#')
            return cli_fail(r->cmd, "%s: line %lu: a '#' line: psa's files hold one set, its "
                            "count on the first line, and no comments (a utk file? drop --format "
                            "psa)", r->name, r->line);
        if (count_line == 0u) {
            int rc = psa_count(r, s, &want);
            if (rc != 0)
                return rc;
            count_line = r->line;
            continue;
        }
        if (b->k == want)
            return cli_fail(r->cmd, "%s: line %lu: more points than the %zu of line %lu (psa: "
                            "one set per file, its count first)", r->name, r->line, want,
                            count_line);
        int rc = point_line(r, fmt, b, s, out->stats);
        if (rc != 0)
            return rc;
    }
    if (got < 0)
        return CLI_EXIT_USAGE;
    if (count_line == 0u)
        return cli_fail(r->cmd, "%s: %s (a psa file starts with its point count)", r->name,
                        r->line == 0u ? "the input is empty" : "no count line, only blank lines");
    if (b->k < want)
        return cli_fail(r->cmd, "%s: line %lu: the file ends after %zu of the %zu points line "
                        "%lu announces", r->name, r->line, b->k, want, count_line);
    return emit_set(r, fmt, b, out);
}

int cli_read_psa(const char *cmd, const char *path, const cli_pointset_format *fmt,
                 cli_pointset_fn fn, void *ctx, cli_pointset_stats *stats,
                 cli_progress *progress)
{
    const set_sink out = {fn, ctx, stats, progress};
    stats_start(stats, fmt);
    if (fmt->weights)
        return cli_internal(cmd, "psa's point files carry no weights");
    return read_file(cmd, path, fmt, read_psa_lines, &out);
}
