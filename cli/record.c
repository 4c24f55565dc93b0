/* Saved accumulators for the mcspec command (see record.h): the operations
 * of each kind (new, copy, count, shape, merge, the merge tree); the record
 * files are record_file.c's. */
#include "record.h"
#include "cli.h"
#include "record_ops.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static mcs_status load_spectrum(void *o, size_t l, const void *b) { return mcs_io_load_spectrum(o, l, b); }
static mcs_status load_moment(void *o, size_t l, const void *b) { return mcs_io_load_moment(o, l, b); }
static mcs_status load_autocorr(void *o, size_t l, const void *b) { return mcs_io_load_autocorr(o, l, b); }
static mcs_status load_welford(void *o, size_t l, const void *b) { return mcs_io_load_welford(o, l, b); }
static mcs_status save_spectrum(const void *o, size_t c, void *b, size_t *l) { return mcs_io_save_spectrum(o, c, b, l); }
static mcs_status save_moment(const void *o, size_t c, void *b, size_t *l) { return mcs_io_save_moment(o, c, b, l); }
static mcs_status save_autocorr(const void *o, size_t c, void *b, size_t *l) { return mcs_io_save_autocorr(o, c, b, l); }
static mcs_status save_welford(const void *o, size_t c, void *b, size_t *l) { return mcs_io_save_welford(o, c, b, l); }
static mcs_status merge_spectrum(void *d, const void *s) { return mcs_spectrum_merge(d, s); }
static mcs_status merge_moment(void *d, const void *s) { return mcs_moment_merge(d, s); }
static mcs_status merge_autocorr(void *d, const void *s) { return mcs_autocorr_merge(d, s); }
static mcs_status merge_welford(void *d, const void *s) { return mcs_welford_merge(d, s); }
static mcs_status save_pointset(const void *o, size_t c, void *b, size_t *l) { return mcs_io_save_pointset(o, c, b, l); }
static mcs_status save_pointset2d(const void *o, size_t c, void *b, size_t *l) { return mcs_io_save_pointset2d(o, c, b, l); }
static mcs_status save_spectrum2d(const void *o, size_t c, void *b, size_t *l) { return mcs_io_save_spectrum2d(o, c, b, l); }
static mcs_status merge_pointset(void *d, const void *s) { return mcs_pointset_merge(d, s); }
static mcs_status merge_pointset2d(void *d, const void *s) { return mcs_pointset2d_merge(d, s); }
static mcs_status merge_spectrum2d(void *d, const void *s) { return mcs_spectrum2d_merge(d, s); }
/* Point files: every set is its own unit (batch 1), so the standard errors
 * are the set-to-set spread from two sets on, whatever path AUTO takes. */
static mcs_status init_spectrum(void *o, const size_t *s)
{
    mcs_status st = mcs_spectrum_init(o, s[0]);
    return st == MCS_OK ? mcs_spectrum_set_batch(o, 1u) : st;
}
/* The point sets take the NUFFT's memory too (flags 0): AUTO picks per set. */
static mcs_status size_pointset(const size_t *s, size_t *b) { return mcs_pointset_size(s[0], 0u, b); }
static mcs_status size_pointset2d(const size_t *s, size_t *b) { return mcs_pointset2d_size(s[0], 0u, b); }
static mcs_status size_spectrum2d(const size_t *s, size_t *b) { return mcs_spectrum2d_size(s[0], s[1], b); }
static mcs_status init_pointset(void *o, const size_t *s, void *m, size_t b) { return mcs_pointset_init(o, s[0], 0u, m, b); }
static mcs_status init_pointset2d(void *o, const size_t *s, void *m, size_t b) { return mcs_pointset2d_init(o, s[0], 0u, m, b); }
static mcs_status init_spectrum2d(void *o, const size_t *s, void *m, size_t b) { return mcs_spectrum2d_init(o, s[0], s[1], m, b); }
static mcs_status load_pointset(void *o, void *m, size_t b, size_t l, const void *r) { return mcs_io_load_pointset(o, 0u, m, b, l, r); }
static mcs_status load_pointset2d(void *o, void *m, size_t b, size_t l, const void *r) { return mcs_io_load_pointset2d(o, 0u, m, b, l, r); }
static mcs_status load_spectrum2d(void *o, void *m, size_t b, size_t l, const void *r) { return mcs_io_load_spectrum2d(o, m, b, l, r); }

static mcs_status save_pcf(const void *o, size_t c, void *b, size_t *l) { return mcs_io_save_pcf(o, c, b, l); }
static mcs_status save_integrate(const void *o, size_t c, void *b, size_t *l) { return mcs_io_save_integrate(o, c, b, l); }
static mcs_status save_discrepancy(const void *o, size_t c, void *b, size_t *l) { return mcs_io_save_discrepancy(o, c, b, l); }
static mcs_status save_spacing(const void *o, size_t c, void *b, size_t *l) { return mcs_io_save_spacing(o, c, b, l); }
static mcs_status load_integrate(void *o, size_t l, const void *b) { return mcs_io_load_integrate(o, l, b); }
static mcs_status load_discrepancy(void *o, size_t l, const void *b) { return mcs_io_load_discrepancy(o, l, b); }
static mcs_status load_spacing(void *o, size_t l, const void *b) { return mcs_io_load_spacing(o, l, b); }
static mcs_status load_pcf(void *o, void *m, size_t b, size_t l, const void *r) { return mcs_io_load_pcf(o, m, b, l, r); }
static mcs_status merge_pcf(void *d, const void *s) { return mcs_pcf_merge(d, s); }
static mcs_status merge_integrate(void *d, const void *s) { return mcs_integrate_merge(d, s); }
static mcs_status merge_discrepancy(void *d, const void *s) { return mcs_discrepancy_merge(d, s); }
static mcs_status merge_spacing(void *d, const void *s) { return mcs_spacing_merge(d, s); }

static const kind_ops kinds[] = {
    {MCS_IO_KIND_SPECTRUM, sizeof(mcs_spectrum), init_spectrum, load_spectrum, save_spectrum,
     merge_spectrum, NULL, NULL, NULL},
    {MCS_IO_KIND_MOMENT, sizeof(mcs_moment), NULL, load_moment, save_moment, merge_moment, NULL,
     NULL, NULL},
    {MCS_IO_KIND_AUTOCORR, sizeof(mcs_autocorr), NULL, load_autocorr, save_autocorr,
     merge_autocorr, NULL, NULL, NULL},
    {MCS_IO_KIND_WELFORD, sizeof(mcs_welford), NULL, load_welford, save_welford, merge_welford,
     NULL, NULL, NULL},
    {MCS_IO_KIND_POINTSET, sizeof(mcs_pointset), NULL, NULL, save_pointset, merge_pointset,
     size_pointset, init_pointset, load_pointset},
    {MCS_IO_KIND_POINTSET2D, sizeof(mcs_pointset2d), NULL, NULL, save_pointset2d,
     merge_pointset2d, size_pointset2d, init_pointset2d, load_pointset2d},
    {MCS_IO_KIND_SPECTRUM2D, sizeof(mcs_spectrum2d), NULL, NULL, save_spectrum2d,
     merge_spectrum2d, size_spectrum2d, init_spectrum2d, load_spectrum2d},
    /* The measures: made by their commands, read and merged here. */
    {MCS_IO_KIND_PCF, sizeof(mcs_pcf), NULL, NULL, save_pcf, merge_pcf, NULL, NULL, load_pcf},
    {MCS_IO_KIND_INTEGRATE, sizeof(mcs_integrate), NULL, load_integrate, save_integrate,
     merge_integrate, NULL, NULL, NULL},
    {MCS_IO_KIND_DISCREPANCY, sizeof(mcs_discrepancy), NULL, load_discrepancy, save_discrepancy,
     merge_discrepancy, NULL, NULL, NULL},
    {MCS_IO_KIND_SPACING, sizeof(mcs_spacing), NULL, load_spacing, save_spacing, merge_spacing,
     NULL, NULL, NULL},
};

const kind_ops *cli_ops_of(uint32_t kind)
{
    for (size_t i = 0; i < sizeof kinds / sizeof kinds[0]; ++i)
        if ((uint32_t)kinds[i].kind == kind)
            return &kinds[i];
    return NULL;
}
/* Bytes of memory this machine has, or 0 where it cannot say. */
static uint64_t physical_memory(void)
{
#if defined(_SC_PHYS_PAGES) && defined(_SC_PAGESIZE)
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    if (pages > 0 && page > 0)
        return (uint64_t)pages * (uint64_t)page;
#endif
    return 0u;
}

void *cli_alloc_with_buffer(const char *cmd, const char *what, size_t header, size_t bytes,
                            mcs_status size_status, void **mem)
{
    const size_t head = (header + 63u) / 64u * 64u;
    if (size_status != MCS_OK || bytes > SIZE_MAX - head) {
        (void)cli_fail(cmd, "%s needs more bytes than this machine can address", what);
        return NULL;
    }
    const uint64_t have = physical_memory();
    if (have > 0u && (uint64_t)(head + bytes) > have) {
        (void)cli_fail(cmd, "%s needs %zu bytes, more than the %llu bytes of memory of this "
                       "machine", what, head + bytes, (unsigned long long)have);
        return NULL;
    }
    unsigned char *p = malloc(head + bytes);
    if (p == NULL) {
        (void)cli_fail(cmd, "%s needs %zu bytes, more than this machine can allocate", what,
                       head + bytes);
        return NULL;
    }
    *mem = p + head;
    return p;
}

/* "--freq 4096" or "4096 x 4096 bins": what a new object of kind and shape
 * is made for, as messages name it. */
static void describe_shape(mcs_io_kind kind, const size_t *shape, char *buf, size_t size)
{
    if (kind == MCS_IO_KIND_SPECTRUM2D)
        snprintf(buf, size, "%zu x %zu bins", shape[0], shape[1]);
    else
        snprintf(buf, size, "--freq %zu", shape[0]);
}

int cli_acc_new(const char *cmd, mcs_io_kind kind, const size_t shape[2], cli_acc *acc)
{
    const kind_ops *ops = cli_ops_of(kind);
    if (ops == NULL || (ops->init == NULL && ops->init_mem == NULL))
        return cli_internal(cmd, "cannot make a %s accumulator", mcs_io_kind_str(kind));
    void *obj = NULL, *mem = NULL;
    size_t bytes = 0u;
    if (ops->init_mem != NULL) {
        char what[64];
        describe_shape(kind, shape, what, sizeof what);
        const mcs_status st = ops->mem_size(shape, &bytes);
        obj = cli_alloc_with_buffer(cmd, what, ops->size, bytes, st, &mem);
        if (obj == NULL)
            return CLI_EXIT_USAGE;
    } else {
        obj = cli_alloc(cmd, 1, ops->size);
        if (obj == NULL)
            return CLI_EXIT_FAIL;
    }
    mcs_status st = ops->init_mem != NULL ? ops->init_mem(obj, shape, mem, bytes)
                                          : ops->init(obj, shape);
    if (st != MCS_OK) {
        free(obj);
        return cli_internal(cmd, "setting up a %s accumulator: %s", mcs_io_kind_str(kind),
                            mcs_status_str(st));
    }
    acc->kind = kind;
    acc->obj = obj;
    return 0;
}

int cli_acc_new_spectrum(const char *cmd, size_t n, cli_acc *acc)
{
    const size_t shape[2] = {n, 0u};
    return cli_acc_new(cmd, MCS_IO_KIND_SPECTRUM, shape, acc);
}

void cli_acc_copy_to(const cli_acc *acc, void *obj)
{
    /* The kinds over caller memory: obj is set up over its own buffer, which
     * the copy reuses (a byte copy would share acc's). */
    switch (acc->kind) {
    case MCS_IO_KIND_POINTSET: {
        mcs_pointset *d = obj;
        (void)mcs_pointset_copy(d, d->mem, d->bytes, acc->obj);
        break;
    }
    case MCS_IO_KIND_POINTSET2D: {
        mcs_pointset2d *d = obj;
        (void)mcs_pointset2d_copy(d, d->mem, d->bytes, acc->obj);
        break;
    }
    case MCS_IO_KIND_SPECTRUM2D: {
        mcs_spectrum2d *d = obj;
        (void)mcs_spectrum2d_copy(d, d->mem, d->bytes, acc->obj);
        break;
    }
    case MCS_IO_KIND_PCF: { /* the header's fields, the arrays into obj's own buffer */
        mcs_pcf *d = obj;
        const mcs_pcf *s = acc->obj;
        double *mean = d->mean, *m2 = d->m2, *value = d->value;
        void *mem = d->mem;
        memcpy(mean, s->mean, s->bins * sizeof *mean);
        memcpy(m2, s->m2, s->bins * sizeof *m2);
        *d = *s;
        d->mem = mem;
        d->mean = mean;
        d->m2 = m2;
        d->value = value;
        break;
    }
    default: memcpy(obj, acc->obj, cli_ops_of(acc->kind)->size); break;
    }
}

void cli_acc_free(cli_acc *acc)
{
    free(acc->obj);
    acc->obj = NULL;
}

uint64_t cli_acc_count(const cli_acc *acc)
{
    switch (acc->kind) {
    case MCS_IO_KIND_SPECTRUM: return ((const mcs_spectrum *)acc->obj)->count;
    case MCS_IO_KIND_MOMENT: return ((const mcs_moment *)acc->obj)->count;
    case MCS_IO_KIND_AUTOCORR: return ((const mcs_autocorr *)acc->obj)->count;
    case MCS_IO_KIND_POINTSET: return ((const mcs_pointset *)acc->obj)->state->count;
    case MCS_IO_KIND_POINTSET2D: return ((const mcs_pointset2d *)acc->obj)->state->count;
    case MCS_IO_KIND_SPECTRUM2D: return ((const mcs_spectrum2d *)acc->obj)->state->count;
    case MCS_IO_KIND_PCF: return ((const mcs_pcf *)acc->obj)->count;
    case MCS_IO_KIND_INTEGRATE: return ((const mcs_integrate *)acc->obj)->sq.count;
    case MCS_IO_KIND_DISCREPANCY: return ((const mcs_discrepancy *)acc->obj)->inv_k.count;
    case MCS_IO_KIND_SPACING: return ((const mcs_spacing *)acc->obj)->stat[0].count;
    default: return ((const mcs_welford *)acc->obj)->count;
    }
}

void cli_acc_shape(const cli_acc *acc, size_t shape[2])
{
    shape[0] = shape[1] = 0u;
    switch (acc->kind) {
    case MCS_IO_KIND_SPECTRUM: shape[0] = ((const mcs_spectrum *)acc->obj)->n; break;
    case MCS_IO_KIND_MOMENT: shape[0] = ((const mcs_moment *)acc->obj)->n; break;
    case MCS_IO_KIND_AUTOCORR: shape[0] = ((const mcs_autocorr *)acc->obj)->n; break;
    case MCS_IO_KIND_POINTSET: shape[0] = ((const mcs_pointset *)acc->obj)->freq_max; break;
    case MCS_IO_KIND_POINTSET2D: shape[0] = ((const mcs_pointset2d *)acc->obj)->freq_max; break;
    case MCS_IO_KIND_SPECTRUM2D:
        shape[0] = ((const mcs_spectrum2d *)acc->obj)->n_x;
        shape[1] = ((const mcs_spectrum2d *)acc->obj)->n_y;
        break;
    default: break;
    }
}

/* The measures' shape words as their records hold them (docs/format.md). */
static void measure_words(const cli_acc *acc, uint64_t *w)
{
    switch (acc->kind) {
    case MCS_IO_KIND_PCF: {
        const mcs_pcf *p = acc->obj;
        w[0] = p->dim;
        w[1] = p->estimator == MCS_PCF_GAUSSIAN ? 1u : 0u;
        w[2] = p->bins;
        memcpy(&w[3], &p->radius, sizeof w[3]);
        memcpy(&w[4], &p->sigma, sizeof w[4]);
        break;
    }
    case MCS_IO_KIND_INTEGRATE:
        w[0] = (uint64_t)((const mcs_integrate *)acc->obj)->family;
        w[1] = ((const mcs_integrate *)acc->obj)->dim;
        break;
    case MCS_IO_KIND_DISCREPANCY: w[0] = ((const mcs_discrepancy *)acc->obj)->dim; break;
    case MCS_IO_KIND_SPACING: w[0] = ((const mcs_spacing *)acc->obj)->dim; break;
    default: break;
    }
}

static int is_measure(uint32_t kind)
{
    return kind == MCS_IO_KIND_PCF || kind == MCS_IO_KIND_INTEGRATE ||
           kind == MCS_IO_KIND_DISCREPANCY || kind == MCS_IO_KIND_SPACING;
}

/* "a pcf record (psa's RDF, 2D, 8 bins over [0, 2) mean spacings)" and the like. */
static void describe_measure(uint32_t kind, const uint64_t *w, char *buf, size_t size)
{
    double radius, sigma;
    memcpy(&radius, &w[3], sizeof radius);
    memcpy(&sigma, &w[4], sizeof sigma);
    const unsigned long long d = kind == MCS_IO_KIND_INTEGRATE ? w[1] : w[0];
    if (kind == MCS_IO_KIND_PCF && w[1] == 0u)
        snprintf(buf, size, "a pcf record (psa's RDF, %lluD, %llu bins over [0, %g) mean "
                 "spacings)", d, (unsigned long long)w[2], radius);
    else if (kind == MCS_IO_KIND_PCF)
        snprintf(buf, size, "a pcf record (Gaussian kernel, sigma %g, %lluD, %llu bins over "
                 "[0, %g) mean spacings)", sigma, d, (unsigned long long)w[2], radius);
    else if (kind == MCS_IO_KIND_INTEGRATE)
        snprintf(buf, size, "an integrate record (%s, %lluD)",
                 w[0] < (uint64_t)MCS_INTEGRAND_FAMILIES
                     ? mcs_integrand_family_str((mcs_integrand_family)w[0]) : "unknown", d);
    else
        snprintf(buf, size, "a %s record (%lluD)", mcs_io_kind_str(kind), d);
}

static const char *describe(uint32_t kind_number, const uint64_t *shape, char *buf, size_t size)
{
    const char *kind = mcs_io_kind_str(kind_number);
    const char *a = kind[0] == 'a' ? "an" : "a"; /* "an autocorr record" */
    const unsigned long long s0 = shape[0], s1 = shape[1];
    if (is_measure(kind_number))
        describe_measure(kind_number, shape, buf, size);
    else if (kind_number == MCS_IO_KIND_WELFORD)
        snprintf(buf, size, "%s %s record", a, kind);
    else if (kind_number == MCS_IO_KIND_POINTSET || kind_number == MCS_IO_KIND_POINTSET2D)
        snprintf(buf, size, "%s %s record of F = %llu", a, kind, s0);
    else if (kind_number == MCS_IO_KIND_SPECTRUM2D)
        snprintf(buf, size, "%s %s record of %llu x %llu bins", a, kind, s0, s1);
    else
        snprintf(buf, size, "%s %s record of N = %llu", a, kind, s0);
    return buf;
}

/* acc's shape as its record's words (the rest 0). */
static void acc_words(const cli_acc *acc, uint64_t *words)
{
    size_t shape[2];
    memset(words, 0, MCS_IO_MAX_SHAPE * sizeof *words);
    cli_acc_shape(acc, shape);
    words[0] = shape[0];
    words[1] = shape[1];
    measure_words(acc, words);
}

const char *cli_acc_describe(const cli_acc *acc, char *buf, size_t size)
{
    uint64_t words[MCS_IO_MAX_SHAPE];
    acc_words(acc, words);
    return describe(acc->kind, words, buf, size);
}

const char *cli_record_describe(const mcs_io_info *info, char *buf, size_t size)
{
    return describe(info->kind, info->shape, buf, size);
}

int cli_acc_same(const cli_acc *a, const cli_acc *b)
{
    uint64_t wa[MCS_IO_MAX_SHAPE], wb[MCS_IO_MAX_SHAPE];
    acc_words(a, wa);
    acc_words(b, wb);
    return a->kind == b->kind && memcmp(wa, wb, sizeof wa) == 0;
}

int cli_acc_merge(const char *cmd, cli_acc *dst, const cli_acc *src, const char *what)
{
    char da[96], db[96];
    if (!cli_acc_same(dst, src))
        return cli_fail(cmd, "%s holds %s, the others %s: cannot merge", what,
                        cli_acc_describe(src, da, sizeof da), cli_acc_describe(dst, db, sizeof db));
    if (cli_acc_count(dst) + cli_acc_count(src) > MCS_IO_MAX_COUNT)
        return cli_fail(cmd, "merging %s would pass 2^53 trials", what);
    mcs_status st = cli_ops_of(dst->kind)->merge(dst->obj, src->obj);
    if (st != MCS_OK)
        return cli_internal(cmd, "merging %s failed: %s", what, mcs_status_str(st));
    return 0;
}

int cli_tree_push(const char *cmd, cli_merge_tree *tree, cli_acc *acc, const char *what)
{
    return cli_tree_push_weighted(cmd, tree, acc, 1u, what);
}

int cli_tree_push_weighted(const char *cmd, cli_merge_tree *tree, cli_acc *acc, uint64_t weight,
                           const char *what)
{
    if (tree->depth == sizeof tree->level / sizeof tree->level[0]) {
        cli_acc_free(acc);
        return cli_internal(cmd, "merge tree full");
    }
    tree->level[tree->depth] = *acc;
    tree->leaves[tree->depth] = weight;
    tree->depth += 1u;
    acc->obj = NULL;
    /* Carry: two equal subtrees side by side become one, left absorbs right. */
    while (tree->depth >= 2u && tree->leaves[tree->depth - 1u] == tree->leaves[tree->depth - 2u]) {
        cli_acc *left = &tree->level[tree->depth - 2u], *right = &tree->level[tree->depth - 1u];
        int rc = cli_acc_merge(cmd, left, right, what);
        cli_acc_free(right);
        tree->depth -= 1u;
        if (rc != 0)
            return rc;
        tree->leaves[tree->depth - 1u] *= 2u;
    }
    return 0;
}

int cli_tree_finish(const char *cmd, cli_merge_tree *tree, cli_acc *out)
{
    int rc = tree->depth == 0u ? cli_internal(cmd, "nothing to merge") : 0;
    while (rc == 0 && tree->depth >= 2u) {
        cli_acc *left = &tree->level[tree->depth - 2u], *right = &tree->level[tree->depth - 1u];
        rc = cli_acc_merge(cmd, left, right, "the last inputs");
        cli_acc_free(right);
        tree->depth -= 1u;
    }
    if (rc != 0) {
        cli_tree_free(tree);
        out->obj = NULL;
        return rc;
    }
    *out = tree->level[0];
    tree->level[0].obj = NULL;
    tree->depth = 0u;
    return 0;
}

void cli_tree_free(cli_merge_tree *tree)
{
    for (size_t i = 0; i < tree->depth; ++i)
        cli_acc_free(&tree->level[i]);
    tree->depth = 0u;
}
