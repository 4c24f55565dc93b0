/* Saved accumulators for the mcspec command (see record.h). */
#include "record.h"
#include "atomic.h"
#include "cli.h"
#include "streams.h"

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* Largest record file read: above any kind of a usable size (a spectrum at
 * MCS_MAX_N = 4096 is 82 KB, a pointset2d record 32 (F + 1)^2 bytes, 134 MB
 * at F = 2048), small enough to refuse a wrong file early. */
#define RECORD_FILE_MAX ((size_t)1 << 30)

typedef struct {
    mcs_io_kind kind;
    size_t size; /* the object; for the kinds over caller memory, its header */
    mcs_status (*init)(void *obj, const size_t *shape); /* NULL: not made here */
    mcs_status (*load)(void *obj, size_t len, const void *buf);
    mcs_status (*save)(const void *obj, size_t cap, void *buf, size_t *len);
    mcs_status (*merge)(void *dst, const void *src);
    /* The kinds whose arrays live in caller memory (pointset.h,
     * pointset2d.h, spectrum2d.h), NULL for the others: the buffer's size
     * for a shape, and init and load over a buffer. */
    mcs_status (*mem_size)(const size_t *shape, size_t *bytes);
    mcs_status (*init_mem)(void *obj, const size_t *shape, void *mem, size_t bytes);
    mcs_status (*load_mem)(void *obj, void *mem, size_t bytes, size_t len, const void *buf);
} kind_ops;

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
};

static const kind_ops *ops_of(uint32_t kind)
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

/* One block for an object over caller memory: its header, then its buffer
 * of `bytes` (*mem). NULL, after one line naming `what` (e.g. "--freq 4096")
 * and the bytes, where the size cannot be held: more than size_t counts,
 * than the machine's memory, or than malloc gives. */
static void *alloc_with_buffer(const char *cmd, const char *what, size_t header, size_t bytes,
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
    const kind_ops *ops = ops_of(kind);
    if (ops == NULL || (ops->init == NULL && ops->init_mem == NULL))
        return cli_internal(cmd, "cannot make a %s accumulator", mcs_io_kind_str(kind));
    void *obj = NULL, *mem = NULL;
    size_t bytes = 0u;
    if (ops->init_mem != NULL) {
        char what[64];
        describe_shape(kind, shape, what, sizeof what);
        const mcs_status st = ops->mem_size(shape, &bytes);
        obj = alloc_with_buffer(cmd, what, ops->size, bytes, st, &mem);
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
    default: memcpy(obj, acc->obj, ops_of(acc->kind)->size); break;
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

static const char *describe(uint32_t kind_number, const uint64_t shape[2], char *buf, size_t size)
{
    const char *kind = mcs_io_kind_str(kind_number);
    const char *a = kind[0] == 'a' ? "an" : "a"; /* "an autocorr record" */
    const unsigned long long s0 = shape[0], s1 = shape[1];
    if (kind_number == MCS_IO_KIND_WELFORD)
        snprintf(buf, size, "%s %s record", a, kind);
    else if (kind_number == MCS_IO_KIND_POINTSET || kind_number == MCS_IO_KIND_POINTSET2D)
        snprintf(buf, size, "%s %s record of F = %llu", a, kind, s0);
    else if (kind_number == MCS_IO_KIND_SPECTRUM2D)
        snprintf(buf, size, "%s %s record of %llu x %llu bins", a, kind, s0, s1);
    else
        snprintf(buf, size, "%s %s record of N = %llu", a, kind, s0);
    return buf;
}

const char *cli_acc_describe(const cli_acc *acc, char *buf, size_t size)
{
    size_t shape[2];
    cli_acc_shape(acc, shape);
    const uint64_t words[2] = {shape[0], shape[1]};
    return describe(acc->kind, words, buf, size);
}

const char *cli_record_describe(const mcs_io_info *info, char *buf, size_t size)
{
    const uint64_t words[2] = {info->shape[0], info->shape_len > 1u ? info->shape[1] : 0u};
    return describe(info->kind, words, buf, size);
}

/* The whole file into a new buffer. */
static int read_file(const char *cmd, const char *path, unsigned char **buf, size_t *len)
{
    FILE *fp = fopen(path, "rb");
    if (fp == NULL)
        return cli_fail(cmd, "cannot read %s: %s", path, strerror(errno));
    size_t cap = 1u << 16, used = 0u;
    unsigned char *p = malloc(cap);
    while (p != NULL) {
        used += fread(p + used, 1u, cap - used, fp);
        if (used < cap || cap >= RECORD_FILE_MAX)
            break;
        unsigned char *q = realloc(p, cap * 2u);
        if (q == NULL)
            free(p);
        p = q;
        cap *= 2u;
    }
    int bad = p == NULL || ferror(fp) || (used == cap && cap >= RECORD_FILE_MAX);
    int err = errno;
    fclose(fp);
    if (bad) {
        free(p);
        if (p == NULL)
            return cli_internal(cmd, "out of memory reading %s", path);
        return cli_fail(cmd, "cannot read %s: %s", path,
                        used == cap ? "larger than any record" : strerror(err));
    }
    *buf = p;
    *len = used;
    return 0;
}

/* One line saying what is wrong with the record of path. */
static int record_error(const char *cmd, const char *path, mcs_status st, const mcs_io_info *info)
{
    switch (st) {
    case MCS_ERR_MAGIC: return cli_fail(cmd, "%s: not an mcspec record", path);
    case MCS_ERR_TRUNCATED:
        return cli_fail(cmd, "%s: truncated (shorter than its header says)", path);
    case MCS_ERR_VERSION:
        return cli_fail(cmd, "%s: a record of another format version; this build reads "
                        "versions 1 to %u", path, (unsigned)MCS_IO_VERSION);
    case MCS_ERR_FORMAT:
        return cli_fail(cmd, "%s: malformed record (its lengths do not fit its kind, or its "
                        "provenance block breaks the format)", path);
    case MCS_ERR_CHECKSUM: return cli_fail(cmd, "%s: checksum mismatch (corrupted)", path);
    case MCS_ERR_KIND:
        return cli_fail(cmd, "%s: record kind %u, unknown to this build", path,
                        (unsigned)info->kind);
    case MCS_ERR_N_RANGE:
    case MCS_ERR_FREQ_RANGE:
        return cli_fail(cmd, "%s: a %s record of size %llu%s, beyond this build's capacity "
                        "(docs/format.md)", path, mcs_io_kind_str(info->kind),
                        (unsigned long long)info->shape[0], info->shape_len > 1u ? " x ..." : "");
    case MCS_ERR_NOT_FINITE: return cli_fail(cmd, "%s: holds a NaN or infinite value", path);
    case MCS_ERR_INVARIANT:
        return cli_fail(cmd, "%s: holds values no accumulation produces (negative spread, data "
                        "with no trials, a count above 2^53 or a value above 2^500)", path);
    default: return cli_fail(cmd, "%s: cannot load: %s", path, mcs_status_str(st));
    }
}

/* The record file path into *buf (the caller frees it), its framing checked
 * and its header, provenance and kind's operations read. */
static int read_record(const char *cmd, const char *path, unsigned char **buf, size_t *len,
                       mcs_io_info *info, mcs_io_provenance *prov, const kind_ops **ops)
{
    int rc = read_file(cmd, path, buf, len);
    if (rc != 0)
        return rc;
    memset(info, 0, sizeof *info);
    mcs_status st = mcs_io_peek(*len, *buf, info);
    if (st == MCS_OK)
        st = mcs_io_peek_provenance(*len, *buf, prov);
    *ops = st == MCS_OK ? ops_of(info->kind) : NULL;
    if (st == MCS_OK && *ops == NULL)
        st = MCS_ERR_KIND;
    if (st != MCS_OK) {
        free(*buf);
        *buf = NULL;
        return record_error(cmd, path, st, info);
    }
    return 0;
}

/* The CRC-32 a record of len >= MCS_IO_CRC_BYTES bytes ends with. */
static uint32_t record_crc(const unsigned char *buf, size_t len)
{
    uint32_t crc = 0u;
    for (size_t i = 0; i < MCS_IO_CRC_BYTES; ++i)
        crc |= (uint32_t)buf[len - MCS_IO_CRC_BYTES + i] << (8u * i);
    return crc;
}

int cli_record_peek(const char *cmd, const char *path, mcs_io_info *info,
                    mcs_io_provenance *prov, uint32_t *crc)
{
    unsigned char *buf = NULL;
    size_t len = 0u;
    const kind_ops *ops = NULL;
    int rc = read_record(cmd, path, &buf, &len, info, prov, &ops);
    if (rc != 0)
        return rc;
    *crc = record_crc(buf, len);
    free(buf);
    return 0;
}

int cli_acc_read_with(const char *cmd, const char *path, cli_acc *acc, mcs_io_provenance *prov,
                      uint32_t *crc)
{
    unsigned char *buf = NULL;
    size_t len = 0u;
    mcs_io_info info;
    const kind_ops *ops = NULL;
    mcs_io_provenance *p = cli_alloc(cmd, 1, sizeof *p);
    if (p == NULL)
        return CLI_EXIT_FAIL;
    int rc = read_record(cmd, path, &buf, &len, &info, p, &ops);
    /* The kinds over caller memory: the record says how much (an error in
     * the record itself is the load's to name, below). */
    size_t bytes = 0u;
    void *obj = NULL, *mem = NULL;
    mcs_status st = rc == 0 && ops->load_mem != NULL ? mcs_io_load_size(len, buf, 0u, &bytes)
                                                      : MCS_OK;
    if (rc == 0 && ops->load_mem != NULL && st == MCS_OK) {
        char what[320];
        if (info.kind == MCS_IO_KIND_SPECTRUM2D)
            snprintf(what, sizeof what, "%s: a spectrum2d record of %llu x %llu bins", path,
                     (unsigned long long)info.shape[0], (unsigned long long)info.shape[1]);
        else
            snprintf(what, sizeof what, "%s: a %s record of F = %llu", path,
                     mcs_io_kind_str(info.kind), (unsigned long long)info.shape[0]);
        obj = alloc_with_buffer(cmd, what, ops->size, bytes, MCS_OK, &mem);
        if (obj == NULL)
            rc = CLI_EXIT_USAGE;
    } else if (rc == 0 && ops->load_mem == NULL) {
        obj = cli_alloc(cmd, 1, ops->size);
        if (obj == NULL)
            rc = CLI_EXIT_FAIL;
    }
    if (rc == 0 && st == MCS_OK)
        st = ops->load_mem != NULL ? ops->load_mem(obj, mem, bytes, len, buf)
                                   : ops->load(obj, len, buf);
    if (rc == 0 && crc != NULL)
        *crc = record_crc(buf, len);
    free(buf);
    if (rc == 0 && st != MCS_OK)
        rc = record_error(cmd, path, st, &info);
    if (rc == 0) {
        acc->kind = ops->kind;
        acc->obj = obj;
        if (prov != NULL)
            memcpy(prov, p, sizeof *p);
    } else {
        free(obj);
    }
    free(p);
    return rc;
}

int cli_acc_read(const char *cmd, const char *path, cli_acc *acc)
{
    return cli_acc_read_with(cmd, path, acc, NULL, NULL);
}

int cli_acc_save(const char *cmd, const cli_acc *acc, unsigned char **buf, size_t *len)
{
    return cli_acc_save_with(cmd, acc, NULL, buf, len);
}

int cli_acc_save_with(const char *cmd, const cli_acc *acc, const mcs_io_provenance *prov,
                      unsigned char **buf, size_t *len)
{
    const kind_ops *ops = ops_of(acc->kind);
    size_t need = 0u, block = 0u;
    mcs_status st = ops != NULL ? ops->save(acc->obj, 0u, NULL, &need) : MCS_ERR_KIND;
    if (st == MCS_ERR_NOT_FINITE || st == MCS_ERR_INVARIANT)
        return cli_fail(cmd, "cannot save: the accumulator overflowed (%s)", mcs_status_str(st));
    if (st == MCS_OK && prov != NULL)
        st = mcs_io_provenance_bytes(prov, &block);
    if (st != MCS_OK)
        return cli_internal(cmd, "saving the accumulator failed: %s", mcs_status_str(st));
    unsigned char *p = cli_alloc(cmd, 1, need + block);
    if (p == NULL)
        return CLI_EXIT_FAIL;
    st = ops->save(acc->obj, need, p, len);
    if (st == MCS_OK && block != 0u)
        st = mcs_io_set_provenance(prov, need + block, p, len);
    if (st != MCS_OK) {
        free(p);
        return cli_internal(cmd, "saving the accumulator failed: %s", mcs_status_str(st));
    }
    *buf = p;
    return 0;
}

int cli_acc_write(const char *cmd, const char *path, const cli_acc *acc)
{
    return cli_acc_write_with(cmd, path, acc, NULL);
}

int cli_acc_write_with(const char *cmd, const char *path, const cli_acc *acc,
                       const mcs_io_provenance *prov)
{
    unsigned char *buf = NULL;
    size_t len = 0u;
    int rc = cli_acc_save_with(cmd, acc, prov, &buf, &len);
    if (rc == 0)
        rc = cli_write_atomic(cmd, path, buf, len);
    free(buf);
    return rc;
}

int cli_acc_same(const cli_acc *a, const cli_acc *b)
{
    size_t sa[2], sb[2];
    cli_acc_shape(a, sa);
    cli_acc_shape(b, sb);
    return a->kind == b->kind && sa[0] == sb[0] && sa[1] == sb[1];
}

int cli_acc_merge(const char *cmd, cli_acc *dst, const cli_acc *src, const char *what)
{
    char da[96], db[96];
    if (!cli_acc_same(dst, src))
        return cli_fail(cmd, "%s holds %s, the others %s: cannot merge", what,
                        cli_acc_describe(src, da, sizeof da), cli_acc_describe(dst, db, sizeof db));
    if (cli_acc_count(dst) + cli_acc_count(src) > MCS_IO_MAX_COUNT)
        return cli_fail(cmd, "merging %s would pass 2^53 trials", what);
    mcs_status st = ops_of(dst->kind)->merge(dst->obj, src->obj);
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

/* ---- provenance ---- */

void cli_run_provenance(const cli_run *run, uint64_t first, uint64_t end,
                        mcs_io_provenance *prov)
{
    memset(prov, 0, sizeof *prov);
    prov->source = MCS_IO_SOURCE_PATTERN;
    prov->dim = run->dim;
    snprintf(prov->pattern, sizeof prov->pattern, "%s", run->pattern);
    prov->n = run->n;
    prov->k = run->k;
    prov->importance = run->importance != 0;
    prov->importance_crc = run->importance != 0 ? run->importance_crc : 0u;
    prov->streams = run->streams;
    prov->trials = run->trials;
    prov->nranges = 1u;
    prov->range[0].seed = run->seed;
    prov->range[0].first = first;
    prov->range[0].end = end;
}

uint32_t cli_weights_crc(size_t n, const double *weights)
{
    /* Byte by byte, as the records are: the checksum of the same weights is
     * the same on every host. */
    unsigned char *bytes = malloc(n > 0u ? 8u * n : 1u);
    uint32_t crc = 0u;
    if (bytes == NULL) /* a checksum nobody matches; the mismatch is then said */
        return 0xffffffffu;
    for (size_t i = 0; i < n; ++i) {
        uint64_t bits;
        memcpy(&bits, &weights[i], sizeof bits);
        for (size_t b = 0; b < 8u; ++b)
            bytes[8u * i + b] = (unsigned char)(bits >> (8u * b));
    }
    (void)mcs_io_crc32(8u * n, bytes, &crc);
    free(bytes);
    return crc;
}

uint32_t cli_crc32_update(uint32_t crc, const void *data, size_t len)
{
    /* The reflected polynomial of mcs_io_crc32, a byte per step. */
    static uint32_t table[256];
    static int ready;
    if (!ready) {
        for (uint32_t i = 0; i < 256u; ++i) {
            uint32_t c = i;
            for (int b = 0; b < 8; ++b)
                c = (c & 1u) ? 0xedb88320u ^ (c >> 1) : c >> 1;
            table[i] = c;
        }
        ready = 1;
    }
    const unsigned char *p = data;
    uint32_t c = crc ^ 0xffffffffu;
    for (size_t i = 0; i < len; ++i)
        c = (c >> 8) ^ table[(c ^ p[i]) & 0xffu];
    return c ^ 0xffffffffu;
}

void cli_input_provenance(const char *name, uint32_t crc, uint64_t bytes,
                          mcs_io_provenance *prov)
{
    const size_t room = MCS_IO_PROV_NAME_BYTES - 1u, len = strlen(name);
    memset(prov, 0, sizeof *prov);
    prov->source = MCS_IO_SOURCE_POINTS;
    prov->ninputs = 1u;
    prov->input[0].crc = crc;
    prov->input[0].bytes = bytes;
    if (len <= room) /* the end of a long path says most: its file name */
        memcpy(prov->input[0].name, name, len);
    else
        snprintf(prov->input[0].name, sizeof prov->input[0].name, "...%s",
                 name + len - (room - 3u));
}

/* "streams 0..3 of 4 (trials 0..10 of 11)", "stream 2 of 4 (trials 6..8 of 11)":
 * the trials of the range by the stream rule (streams.h). */
static void streams_text(const mcs_io_provenance *prov, const mcs_io_streams *r, char *buf,
                         size_t size)
{
    uint64_t first = 0u, count = 0u, last_first = 0u, last_count = 0u;
    cli_stream_share(prov->trials, prov->streams, r->first, &first, &count);
    cli_stream_share(prov->trials, prov->streams, r->end - 1u, &last_first, &last_count);
    const unsigned long long p = prov->streams, t = prov->trials;
    const unsigned long long a = first, b = last_first + last_count - 1u;
    if (r->end - r->first == 1u)
        snprintf(buf, size, "stream %llu of %llu (trials %llu..%llu of %llu)",
                 (unsigned long long)r->first, p, a, b, t);
    else
        snprintf(buf, size, "streams %llu..%llu of %llu (trials %llu..%llu of %llu)",
                 (unsigned long long)r->first, (unsigned long long)r->end - 1u, p, a, b, t);
}

/* printf onto the end of buf[size], which holds *used characters. */
#if defined(__GNUC__)
__attribute__((format(printf, 4, 5)))
#endif
static void append(char *buf, size_t size, size_t *used, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    const int w = vsnprintf(buf + *used, size - *used, fmt, ap);
    va_end(ap);
    if (w > 0)
        *used = *used + (size_t)w < size ? *used + (size_t)w : size - 1u;
}

const char *cli_provenance_describe(const mcs_io_provenance *prov, char *buf, size_t size)
{
    size_t used = 0u;
    buf[0] = '\0';
    if (prov->source == MCS_IO_SOURCE_POINTS) {
        if (prov->ninputs == 1u)
            append(buf, size, &used, "%s (%llu bytes, CRC-32 0x%08lx)", prov->input[0].name,
                   (unsigned long long)prov->input[0].bytes, (unsigned long)prov->input[0].crc);
        else
            append(buf, size, &used, "%u inputs:", (unsigned)prov->ninputs);
        for (size_t i = 0; prov->ninputs > 1u && i < prov->ninputs; ++i)
            append(buf, size, &used, "%s %s", i == 0u ? "" : ",", prov->input[i].name);
        return buf;
    }
    if (prov->dim == 2u)
        append(buf, size, &used, "%s (2D), K = %llu points", prov->pattern,
               (unsigned long long)prov->k);
    else
        append(buf, size, &used, "%s, N = %llu bins, K = %llu samples", prov->pattern,
               (unsigned long long)prov->n, (unsigned long long)prov->k);
    if (prov->importance)
        append(buf, size, &used, ", importance weights CRC-32 0x%08lx",
               (unsigned long)prov->importance_crc);
    for (size_t i = 0; i < prov->nranges; ++i) {
        char text[160];
        streams_text(prov, &prov->range[i], text, sizeof text);
        if (i == 0u || prov->range[i].seed != prov->range[i - 1u].seed)
            append(buf, size, &used, "%s seed %llu: %s", i == 0u ? "," : ";",
                   (unsigned long long)prov->range[i].seed, text);
        else
            append(buf, size, &used, ", %s", text);
    }
    return buf;
}
