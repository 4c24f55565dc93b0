/* Record files for the mcspec command (see record.h): reading a file into
 * an accumulator, saving one to a buffer or atomically to a file, and the
 * provenance that travels with a record. */
#include "record.h"
#include "atomic.h"
#include "cli.h"
#include "input.h"
#include "psets.h"
#include "record_ops.h"
#include "streams.h"

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Largest record file read: above any kind of a usable size (a spectrum at
 * MCS_MAX_N = 4096 is 82 KB, a pointset2d record 32 (F + 1)^2 bytes, 134 MB
 * at F = 2048), small enough to refuse a wrong file early. */
#define RECORD_FILE_MAX ((size_t)1 << 30)

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
    *ops = st == MCS_OK ? cli_ops_of(info->kind) : NULL;
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
        char what[480], rec[160];
        snprintf(what, sizeof what, "%s: %s", path, cli_record_describe(&info, rec, sizeof rec));
        obj = cli_alloc_with_buffer(cmd, what, ops->size, bytes, MCS_OK, &mem);
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
    const kind_ops *ops = cli_ops_of(acc->kind);
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

/* ---- --save of the measure commands ---- */

static int from_stdin(const cli_save_target *t)
{
    return t->input == NULL || strcmp(t->input, "-") == 0;
}

int cli_save_begin(const char *cmd, cli_save_target *t)
{
    if (t->save == NULL)
        return 0;
    int rc = cli_write_check(cmd, t->save);
    if (rc == 0 && from_stdin(t))
        rc = cli_ps_checksum_stdin(cmd, &t->crc, &t->bytes);
    return rc;
}

int cli_save_points(const char *cmd, const cli_save_target *t, mcs_io_kind kind, void *obj)
{
    if (t->save == NULL)
        return 0;
    uint32_t crc = t->crc;
    uint64_t bytes = t->bytes;
    int rc = from_stdin(t) ? 0 : cli_ps_checksum_path(cmd, t->input, &crc, &bytes);
    mcs_io_provenance *prov = rc == 0 ? cli_alloc(cmd, 1, sizeof *prov) : NULL;
    if (rc == 0 && prov == NULL)
        rc = CLI_EXIT_FAIL;
    if (rc == 0) {
        const cli_acc acc = {kind, obj};
        cli_input_provenance(cli_input_name(t->input), crc, bytes, prov);
        rc = cli_acc_write_with(cmd, t->save, &acc, prov);
    }
    free(prov);
    return rc;
}

int cli_save_drawn(const char *cmd, const char *save, const cli_run *run, mcs_io_kind kind,
                   void *obj)
{
    if (save == NULL)
        return 0;
    mcs_io_provenance *prov = cli_alloc(cmd, 1, sizeof *prov);
    if (prov == NULL)
        return CLI_EXIT_FAIL;
    const cli_acc acc = {kind, obj};
    cli_run_provenance(run, 0u, 1u, prov);
    const int rc = cli_acc_write_with(cmd, save, &acc, prov);
    free(prov);
    return rc;
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
