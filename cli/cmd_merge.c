/* mcspec merge: several saved accumulators into one, checked by their
 * provenance (docs/format.md) so that no trials count twice and no two
 * patterns mix. Two passes: the first reads every header and provenance
 * (and refuses what cannot merge, before any accumulator is loaded), the
 * second loads the accumulators in the order of their provenance and merges
 * them in the tree order of record.h. */
#include "atomic.h"
#include "cli.h"
#include "record.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define CMD "mcspec merge"
#define MAX_INPUTS 65536u

static const char help[] =
    "usage: mcspec merge FILE... -o OUT [--mix-seeds]\n"
    "\n"
    "Merges the accumulators saved in the FILEs (by --save of mcspec spectrum or\n"
    "pattern, or by mcspec-mpi) into one and writes it to OUT: the same\n"
    "statistics as one run over all their trials (Chan et al.'s merge of means\n"
    "and sums of squared deviations). Every FILE must hold the same kind of\n"
    "record with the same N; a file that is not a valid record (truncated,\n"
    "corrupted, another kind or N) stops the merge with a message naming it,\n"
    "and OUT is not written.\n"
    "\n"
    "A record knows where its trials came from (its provenance): the pattern,\n"
    "N, K, importance function, seed and stream split of a pattern run and the\n"
    "streams it holds, or the checksums of the point files it read. The merge\n"
    "refuses (exit 2, nothing written) the same stream twice or overlapping\n"
    "streams, records of different patterns or runs (kind, N, K, importance\n"
    "function, seed, P or T differ), the same point file twice, the same FILE\n"
    "twice, and an OUT that is one of the FILEs (the same file, by device and\n"
    "inode); OUT's provenance is the union of theirs, so the P streams of a run\n"
    "merge to 'streams 0..P-1 of P' whatever their order. A record of format\n"
    "version 1 has no provenance: it still merges, unchecked, with a note on\n"
    "stderr, and OUT has no provenance then.\n"
    "\n"
    "When every FILE has a provenance they are merged in its order (seed, then\n"
    "stream; point files by checksum), not in the order given, in the tree order\n"
    "(1 + 2), (3 + 4), ((1 + 2) + (3 + 4)), ..., the order mcspec-mpi reduces its\n"
    "ranks in, a merged record counting as the streams it holds: the files of\n"
    "`mcspec pattern ... --streams P --stream I --save FILE_I`, I = 0..P-1, merge\n"
    "in any order, at once or in pieces aligned as the tree is, to the bytes\n"
    "`mcspec pattern ... --streams P --save FILE` writes.\n"
    "\n"
    "Options:\n"
    "  -o, --output OUT   the merged record (required); written atomically: a\n"
    "                     temporary file beside OUT, flushed, then renamed (so OUT\n"
    "                     must be a regular file or a new name)\n"
    "  --mix-seeds        also merge runs of the same pattern, P and T with other\n"
    "                     seeds (more trials for a finished run: run it again with\n"
    "                     another --seed); OUT lists the streams of each seed\n"
    "  --help             this text\n"
    "\n"
    "Prints one line: the kind, N, trials and inputs of the merged record.\n"
    "Exit status: 0 on success, 2 on bad usage or input (one line on stderr).\n";

/* -o OUT is --output OUT: rewrite it before the shared parser sees it. */
static void alias_short_output(int argc, char **argv)
{
    static char output[] = "--output";
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--") == 0)
            break;
        if (strcmp(argv[i], "-o") == 0)
            argv[i] = output;
    }
}

/* What the first pass learns of an input. */
typedef struct {
    const char *path;
    int found;             /* stat succeeded: dev and ino are the file's */
    dev_t dev;
    ino_t ino;
    uint32_t crc;          /* the record's CRC-32, to see the same file in the second pass */
    uint64_t key[2];       /* its place in provenance order */
    uint64_t weight;       /* the streams it holds (1 without a pattern provenance) */
    size_t index;          /* on the command line */
} input;

/* A stream range (pattern) or an input checksum (points, crc in first) of
 * one input, for the overlap check and the union. */
typedef struct {
    uint64_t seed, first, end;
    mcs_io_input in;
    size_t input;
} piece;

typedef struct {
    input *in;
    size_t n;
    piece *pieces;
    size_t npieces, cap;
    mcs_io_info first_info;
    mcs_io_provenance *ref, *prov, *out; /* the first provenance, the current one, the union */
    size_t ref_at;         /* the input ref came from */
    size_t plain, plain_at[2]; /* inputs without provenance, the first two of them */
    int has_union;         /* every input has a provenance, and out is their union */
    int mix_seeds;
} survey;

static int add_piece(survey *m, const piece *p)
{
    if (m->npieces == m->cap) {
        size_t cap = m->cap == 0u ? 64u : 2u * m->cap;
        piece *q = realloc(m->pieces, cap * sizeof *q);
        if (q == NULL)
            return cli_internal(CMD, "out of memory");
        m->pieces = q;
        m->cap = cap;
    }
    m->pieces[m->npieces++] = *p;
    return 0;
}

/* "stratified", "random (2D)". */
static const char *pattern_name(const mcs_io_provenance *p, char *buf, size_t size)
{
    snprintf(buf, size, "%s%s", p->pattern, p->dim == 2u ? " (2D)" : "");
    return buf;
}

/* m->prov (of input b) against m->ref (of input a): the same pattern and
 * run (and seed, without --mix-seeds), else one line saying what differs. */
static int same_run(const survey *m, const char *a, const char *b)
{
    const mcs_io_provenance *r = m->ref, *p = m->prov;
    char na[48], nb[48];
    if (r->dim != p->dim || strcmp(r->pattern, p->pattern) != 0)
        return cli_fail(CMD, "%s holds trials of %s, %s of %s: different patterns, cannot merge",
                        b, pattern_name(p, nb, sizeof nb), a, pattern_name(r, na, sizeof na));
    if (r->n != p->n || r->k != p->k)
        return cli_fail(CMD, "%s holds trials of N = %llu, K = %llu, %s of N = %llu, K = %llu: "
                        "different patterns, cannot merge", b, (unsigned long long)p->n,
                        (unsigned long long)p->k, a, (unsigned long long)r->n,
                        (unsigned long long)r->k);
    if (r->importance != p->importance)
        return cli_fail(CMD, "%s was drawn %s an importance function, %s %s: different "
                        "patterns, cannot merge", b, p->importance ? "with" : "without", a,
                        r->importance ? "with one" : "without");
    if (r->importance_crc != p->importance_crc)
        return cli_fail(CMD, "%s and %s were drawn with different importance functions (weights "
                        "CRC-32 0x%08lx and 0x%08lx): cannot merge", b, a,
                        (unsigned long)p->importance_crc, (unsigned long)r->importance_crc);
    if (r->streams != p->streams)
        return cli_fail(CMD, "%s is of a run split into %llu streams, %s into %llu: different "
                        "runs, cannot merge", b, (unsigned long long)p->streams, a,
                        (unsigned long long)r->streams);
    if (r->trials != p->trials)
        return cli_fail(CMD, "%s is of a run of %llu trials, %s of %llu: different runs, "
                        "cannot merge", b, (unsigned long long)p->trials, a,
                        (unsigned long long)r->trials);
    for (size_t i = 0; !m->mix_seeds && i < p->nranges; ++i)
        if (p->range[i].seed != r->range[0].seed)
            return cli_fail(CMD, "%s is of seed %llu, %s of seed %llu: different runs, cannot "
                            "merge (--mix-seeds merges runs of one pattern with other seeds)", b,
                            (unsigned long long)p->range[i].seed, a,
                            (unsigned long long)r->range[0].seed);
    return 0;
}

/* The provenance m->prov of input i: checked against the first one, and
 * its pieces, key and weight noted. */
static int note_provenance(survey *m, size_t i)
{
    const char *const src_name[3] = {"", "trials drawn from a pattern",
                                     "point sets read from files"};
    input *in = &m->in[i];
    const mcs_io_provenance *p = m->prov;
    if (p->source == MCS_IO_SOURCE_NONE) {
        if (m->plain < 2u)
            m->plain_at[m->plain] = i;
        m->plain += 1u;
        return 0;
    }
    if (m->ref->source == MCS_IO_SOURCE_NONE) {
        memcpy(m->ref, p, sizeof *p);
        m->ref_at = i;
        if (!m->mix_seeds && p->source == MCS_IO_SOURCE_PATTERN &&
            p->range[p->nranges - 1u].seed != p->range[0].seed)
            return cli_fail(CMD, "%s holds runs of several seeds: give --mix-seeds to merge it",
                            in->path);
    } else if (m->ref->source != p->source) {
        return cli_fail(CMD, "%s holds %s, %s %s: cannot merge", in->path, src_name[p->source],
                        m->in[m->ref_at].path, src_name[m->ref->source]);
    } else if (p->source == MCS_IO_SOURCE_PATTERN) {
        int rc = same_run(m, m->in[m->ref_at].path, in->path);
        if (rc != 0)
            return rc;
    }
    in->weight = 0u;
    const size_t count = p->source == MCS_IO_SOURCE_PATTERN ? p->nranges : p->ninputs;
    for (size_t j = 0; j < count; ++j) {
        piece q;
        memset(&q, 0, sizeof q);
        q.input = i;
        if (p->source == MCS_IO_SOURCE_PATTERN) {
            q.seed = p->range[j].seed;
            q.first = p->range[j].first;
            q.end = p->range[j].end;
            in->weight += q.end - q.first;
        } else {
            q.first = p->input[j].crc;
            q.end = q.first + 1u;
            q.in = p->input[j];
        }
        int rc = add_piece(m, &q);
        if (rc != 0)
            return rc;
    }
    in->weight = p->source == MCS_IO_SOURCE_PATTERN ? in->weight : 1u;
    in->key[0] = m->pieces[m->npieces - count].seed;
    in->key[1] = m->pieces[m->npieces - count].first;
    return 0;
}

static int by_file(const void *a, const void *b)
{
    const input *x = a, *y = b;
    if (x->found != y->found)
        return x->found < y->found ? -1 : 1;
    if (x->dev != y->dev)
        return x->dev < y->dev ? -1 : 1;
    if (x->ino != y->ino)
        return x->ino < y->ino ? -1 : 1;
    return x->index < y->index ? -1 : x->index > y->index;
}

static int by_key(const void *a, const void *b)
{
    const input *x = a, *y = b;
    for (int i = 0; i < 2; ++i)
        if (x->key[i] != y->key[i])
            return x->key[i] < y->key[i] ? -1 : 1;
    return x->index < y->index ? -1 : x->index > y->index;
}

static int by_piece(const void *a, const void *b)
{
    const piece *x = a, *y = b;
    if (x->seed != y->seed)
        return x->seed < y->seed ? -1 : 1;
    if (x->first != y->first)
        return x->first < y->first ? -1 : 1;
    return x->input < y->input ? -1 : x->input > y->input;
}

/* No file given twice: sorted by device and inode, equal neighbours. */
static int no_file_twice(const survey *m)
{
    input *sorted = cli_alloc(CMD, m->n, sizeof *sorted);
    if (sorted == NULL)
        return CLI_EXIT_FAIL;
    memcpy(sorted, m->in, m->n * sizeof *sorted);
    qsort(sorted, m->n, sizeof *sorted, by_file);
    int rc = 0;
    for (size_t i = 1; rc == 0 && i < m->n; ++i) {
        const input *a = &sorted[i - 1u], *b = &sorted[i];
        if (!(a->found && b->found && a->dev == b->dev && a->ino == b->ino))
            continue;
        if (strcmp(a->path, b->path) == 0)
            rc = cli_fail(CMD, "%s is given twice: its trials would count twice", b->path);
        else
            rc = cli_fail(CMD, "%s is given twice (the same file as %s): its trials would count "
                          "twice", b->path, a->path);
    }
    free(sorted);
    return rc;
}

/* No stream of a seed (no input checksum) in two inputs; then their union
 * into m->out, when it fits a record. */
static int no_trials_twice(survey *m)
{
    qsort(m->pieces, m->npieces, sizeof *m->pieces, by_piece);
    const int points = m->ref->source == MCS_IO_SOURCE_POINTS;
    size_t reach = 0u; /* the piece reaching furthest among those of this seed so far */
    for (size_t i = 1; i < m->npieces; ++i) {
        const piece *a = &m->pieces[reach], *b = &m->pieces[i];
        if (a->seed == b->seed && b->first < a->end) {
            if (points)
                return cli_fail(CMD, "%s and %s both hold the point sets of %s (CRC-32 "
                                "0x%08lx): they would count twice", m->in[a->input].path,
                                m->in[b->input].path, b->in.name, (unsigned long)b->in.crc);
            return cli_fail(CMD, "%s and %s both hold stream %llu of seed %llu: its trials "
                            "would count twice", m->in[a->input].path, m->in[b->input].path,
                            (unsigned long long)b->first, (unsigned long long)b->seed);
        }
        if (a->seed != b->seed || b->end > a->end)
            reach = i;
    }
    /* The union: pieces of one seed that touch are one range. */
    mcs_io_provenance *out = m->out;
    memcpy(out, m->ref, sizeof *out);
    memset(out->range, 0, sizeof out->range);
    memset(out->input, 0, sizeof out->input);
    size_t count = 0u;
    for (size_t i = 0; i < m->npieces; ++i) {
        const piece *b = &m->pieces[i];
        if (!points && count > 0u && out->range[count - 1u].seed == b->seed &&
            out->range[count - 1u].end == b->first) {
            out->range[count - 1u].end = b->end;
            continue;
        }
        if (count == (points ? MCS_IO_PROV_MAX_INPUTS : MCS_IO_PROV_MAX_RANGES)) {
            count += 1u; /* too many: no union */
            break;
        }
        if (points)
            out->input[count] = b->in;
        else
            out->range[count] = (mcs_io_streams){b->seed, b->first, b->end};
        count += 1u;
    }
    const size_t cap = points ? MCS_IO_PROV_MAX_INPUTS : MCS_IO_PROV_MAX_RANGES;
    m->has_union = count <= cap;
    if (points)
        out->ninputs = (uint32_t)count;
    else
        out->nranges = (uint32_t)count;
    return 0;
}

/* The first pass: every input's header and provenance. */
static int survey_inputs(survey *m, const char **files, const char *output)
{
    struct stat out_st;
    const int out_found = stat(output, &out_st) == 0;
    int rc = 0;
    for (size_t i = 0; rc == 0 && i < m->n; ++i) {
        input *in = &m->in[i];
        struct stat st;
        memset(in, 0, sizeof *in);
        in->path = files[i];
        in->index = i;
        in->weight = 1u;
        in->found = stat(files[i], &st) == 0;
        in->dev = in->found ? st.st_dev : 0;
        in->ino = in->found ? st.st_ino : 0;
        if (in->found && out_found && st.st_dev == out_st.st_dev && st.st_ino == out_st.st_ino)
            return cli_fail(CMD, "OUT %s is the input %s%s: write the merge to another file",
                            output, files[i], strcmp(output, files[i]) == 0 ? "" : " (the same file)");
        mcs_io_info info;
        rc = cli_record_peek(CMD, files[i], &info, m->prov, &in->crc);
        if (rc != 0)
            return rc;
        char da[96], db[96];
        if (i == 0u)
            m->first_info = info;
        else if (info.kind != m->first_info.kind || info.shape_len != m->first_info.shape_len ||
                 memcmp(info.shape, m->first_info.shape, sizeof info.shape) != 0)
            return cli_fail(CMD, "%s holds %s, %s %s: cannot merge", files[i],
                            cli_record_describe(&info, da, sizeof da), files[0],
                            cli_record_describe(&m->first_info, db, sizeof db));
        rc = note_provenance(m, i);
    }
    if (rc == 0)
        rc = no_file_twice(m);
    /* Among the inputs that have a provenance, even if others have none. */
    if (rc == 0 && m->ref->source != MCS_IO_SOURCE_NONE)
        rc = no_trials_twice(m);
    return rc;
}

/* The second pass: every accumulator, in provenance order when all have
 * one, through the merge tree. */
static int merge_all(const survey *m, cli_acc *out)
{
    cli_merge_tree *tree = cli_alloc(CMD, 1, sizeof *tree);
    input *order = cli_alloc(CMD, m->n, sizeof *order);
    if (tree == NULL || order == NULL) {
        free(tree);
        free(order);
        return CLI_EXIT_FAIL;
    }
    memset(tree, 0, sizeof *tree);
    memcpy(order, m->in, m->n * sizeof *order);
    if (m->plain == 0u)
        qsort(order, m->n, sizeof *order, by_key);
    int rc = 0;
    for (size_t i = 0; rc == 0 && i < m->n; ++i) {
        cli_acc acc = {MCS_IO_KIND_SPECTRUM, NULL};
        uint32_t crc = 0u;
        rc = cli_acc_read_with(CMD, order[i].path, &acc, NULL, &crc);
        if (rc == 0 && crc != order[i].crc) {
            cli_acc_free(&acc);
            rc = cli_fail(CMD, "%s changed during the merge: run it again", order[i].path);
        }
        if (rc == 0)
            rc = cli_tree_push_weighted(CMD, tree, &acc, m->plain == 0u ? order[i].weight : 1u,
                                        order[i].path);
    }
    if (rc == 0)
        rc = cli_tree_finish(CMD, tree, out);
    cli_tree_free(tree);
    free(tree);
    free(order);
    return rc;
}

/* The note of a merge of records without provenance, or of a union too
 * large for a record. */
static void note(const survey *m, const char *output)
{
    if (m->plain > 0u) {
        char names[256] = "";
        if (m->plain == 2u)
            snprintf(names, sizeof names, " and %s", m->in[m->plain_at[1]].path);
        else if (m->plain > 2u)
            snprintf(names, sizeof names, ", %s and %zu more", m->in[m->plain_at[1]].path,
                     m->plain - 2u);
        fprintf(stderr, "%s: note: %s%s %s version 1 record%s, with no provenance: merged "
                "without the checks for the same trials twice or another pattern, and %s has "
                "none\n", CMD, m->in[m->plain_at[0]].path, names,
                m->plain == 1u ? "is a" : "are", m->plain == 1u ? "" : "s", output);
    } else if (!m->has_union) {
        const int points = m->ref->source == MCS_IO_SOURCE_POINTS;
        fprintf(stderr, "%s: note: the inputs hold more %s than a record lists (%u): %s has no "
                "provenance\n", CMD, points ? "point files" : "separate stream ranges",
                points ? MCS_IO_PROV_MAX_INPUTS : MCS_IO_PROV_MAX_RANGES, output);
    }
}

static int run(const char **files, size_t nfiles, const char *output, int mix_seeds)
{
    survey m;
    memset(&m, 0, sizeof m);
    m.n = nfiles;
    m.mix_seeds = mix_seeds;
    m.in = cli_alloc(CMD, nfiles, sizeof *m.in);
    m.ref = cli_alloc(CMD, 3, sizeof *m.ref);
    int rc = m.in != NULL && m.ref != NULL ? 0 : CLI_EXIT_FAIL;
    if (rc == 0) {
        memset(m.ref, 0, 3u * sizeof *m.ref);
        m.prov = m.ref + 1;
        m.out = m.ref + 2;
        rc = survey_inputs(&m, files, output);
    }
    cli_acc merged = {MCS_IO_KIND_SPECTRUM, NULL};
    if (rc == 0)
        rc = merge_all(&m, &merged);
    if (rc == 0)
        rc = cli_acc_write_with(CMD, output, &merged,
                                m.plain == 0u && m.has_union ? m.out : NULL);
    char what[96];
    if (rc == 0) {
        note(&m, output);
        printf("%s: %s, %llu trials from %zu file%s\n", output,
               cli_acc_describe(&merged, what, sizeof what),
               (unsigned long long)cli_acc_count(&merged), nfiles, nfiles == 1u ? "" : "s");
    }
    cli_acc_free(&merged);
    free(m.pieces);
    free(m.ref);
    free(m.in);
    return rc;
}

int cli_cmd_merge(int argc, char **argv)
{
    const char *output = NULL;
    int mix_seeds = 0;
    cli_opt opts[] = {{"output", CLI_OPT_STRING, &output, 0, 0, 0},
                      {"mix-seeds", CLI_OPT_FLAG, &mix_seeds, 0, 0, 0}};
    const char **files = cli_alloc(CMD, MAX_INPUTS, sizeof *files);
    if (files == NULL)
        return CLI_EXIT_FAIL;
    alias_short_output(argc, argv);
    cli_parser p = {CMD, help, opts, CLI_COUNT(opts), files, MAX_INPUTS, 0, NULL};
    int rc = cli_parse(&p, argc, argv);
    if (rc != CLI_PARSED) {
        free(files);
        return rc == CLI_HELP ? CLI_EXIT_OK : rc;
    }
    if (output == NULL)
        rc = cli_fail(CMD, "where to? give -o OUT (see %s --help)", CMD);
    else if (p.nargs == 0u)
        rc = cli_fail(CMD, "which records? give one or more FILEs");
    if (rc == 0)
        rc = cli_write_check(CMD, output);
    if (rc == 0)
        rc = run(files, p.nargs, output, mix_seeds);
    free(files);
    return rc;
}
