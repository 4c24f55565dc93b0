/* The provenance block of a version 2 record (docs/format.md, "Provenance"):
 * its byte codec, its rules, and the union that gives a merged record's
 * provenance. The block lists what a record holds in canonical order (stream
 * ranges sorted and coalesced, inputs sorted by checksum), so one set of
 * trials has one block whatever order its pieces were merged in, and a
 * merge that would count a stream or an input twice shows as an overlap. */
#include "io_internal.h"

#include <string.h>

/* Block offsets: the head, then a pattern's fields or a list of inputs. */
#define B_LEN 0u
#define B_SOURCE 4u
#define B_COUNT 6u
#define B_HEAD 8u
#define P_DIM 8u
#define P_IMPORTANCE 10u
#define P_IMPORTANCE_CRC 12u
#define P_NAME 16u
#define P_N 32u
#define P_K 40u
#define P_STREAMS 48u
#define P_TRIALS 56u
#define P_RANGES 64u
#define RANGE_BYTES 24u
#define I_CRC 0u
#define I_RESERVED 4u
#define I_BYTES 8u
#define I_NAME 16u
#define INPUT_BYTES (I_NAME + MCS_IO_PROV_NAME_BYTES)

_Static_assert(MCS_IO_PROV_MAX_BYTES == B_HEAD + INPUT_BYTES * MCS_IO_PROV_MAX_INPUTS &&
                   MCS_IO_PROV_MAX_BYTES >= P_RANGES + RANGE_BYTES * MCS_IO_PROV_MAX_RANGES,
               "MCS_IO_PROV_MAX_BYTES is the largest block");

/* ---- the rules, shared by the struct checks and the byte checks ---- */

/* A name of size bytes: NUL-terminated within them, and NUL after it (in a
 * record, so that the bytes are a function of the name); a pattern's is at
 * least one printable non-space ASCII character. */
/* The first NUL of name[size], or NULL. (The library uses no string
 * functions but mem*: check-alloc's list of what it may reference.) */
static const unsigned char *first_nul(const unsigned char *name, size_t size)
{
    for (size_t i = 0; i < size; ++i)
        if (name[i] == 0u)
            return name + i;
    return NULL;
}

static int name_ok(const unsigned char *name, size_t size, int pattern, int padded)
{
    const unsigned char *nul = first_nul(name, size);
    if (nul == NULL || (pattern && nul == name))
        return 0;
    for (const unsigned char *c = name; pattern && c < nul; ++c)
        if (*c <= 0x20u || *c >= 0x7fu)
            return 0;
    for (const unsigned char *c = nul; padded && c < name + size; ++c)
        if (*c != 0u)
            return 0;
    return 1;
}

/* The fields of a pattern besides its name and ranges. */
static int pattern_ok(uint64_t dim, uint64_t n, uint64_t k, uint64_t importance,
                      uint64_t importance_crc, uint64_t streams, uint64_t trials)
{
    return (dim == 1u || dim == 2u) && (dim != 1u || n >= 1u) && k >= 1u && importance <= 1u &&
           (importance == 1u || importance_crc == 0u) && streams >= 1u && trials >= streams;
}

/* Range r after prev (NULL for the first) in canonical order, within P streams. */
static int range_ok(const mcs_io_streams *prev, const mcs_io_streams *r, uint64_t streams)
{
    if (!(r->first < r->end && r->end <= streams))
        return 0;
    return prev == NULL || r->seed > prev->seed ||
           (r->seed == prev->seed && r->first > prev->end);
}

static int count_ok(uint64_t count, uint64_t max)
{
    return count >= 1u && count <= max;
}

/* prov against every rule; its block's bytes into *bytes. */
static int provenance_ok(const mcs_io_provenance *prov, size_t *bytes)
{
    if (prov->source == MCS_IO_SOURCE_NONE) {
        *bytes = 0u;
        return 1;
    }
    if (prov->source == MCS_IO_SOURCE_POINTS) {
        if (!count_ok(prov->ninputs, MCS_IO_PROV_MAX_INPUTS))
            return 0;
        for (size_t i = 0; i < prov->ninputs; ++i) {
            const mcs_io_input *in = &prov->input[i];
            if (!name_ok((const unsigned char *)in->name, sizeof in->name, 0, 0) ||
                (i > 0u && in->crc <= prov->input[i - 1u].crc))
                return 0;
        }
        *bytes = B_HEAD + INPUT_BYTES * (size_t)prov->ninputs;
        return 1;
    }
    if (prov->source != MCS_IO_SOURCE_PATTERN ||
        !name_ok((const unsigned char *)prov->pattern, sizeof prov->pattern, 1, 0) ||
        !pattern_ok(prov->dim, prov->n, prov->k, prov->importance, prov->importance_crc,
                    prov->streams, prov->trials) ||
        !count_ok(prov->nranges, MCS_IO_PROV_MAX_RANGES))
        return 0;
    for (size_t i = 0; i < prov->nranges; ++i)
        if (!range_ok(i > 0u ? &prov->range[i - 1u] : NULL, &prov->range[i], prov->streams))
            return 0;
    *bytes = P_RANGES + RANGE_BYTES * (size_t)prov->nranges;
    return 1;
}

mcs_status mcs_io_block_size(const mcs_io_provenance *prov, size_t *bytes)
{
    size_t b = 0u;
    if (!provenance_ok(prov, &b))
        return MCS_ERR_FORMAT;
    *bytes = b;
    return MCS_OK;
}

mcs_status mcs_io_provenance_bytes(const mcs_io_provenance *prov, size_t *bytes)
{
    if (prov == NULL || bytes == NULL)
        return MCS_ERR_NULL;
    return mcs_io_block_size(prov, bytes);
}

/* ---- bytes ---- */

mcs_status mcs_io_block_frame(const uint8_t *p, size_t rest)
{
    if (rest < 4u)
        return MCS_ERR_TRUNCATED;
    const uint64_t len = io_get_le(p + B_LEN, 4u);
    if (len < B_HEAD)
        return MCS_ERR_FORMAT;
    if ((uint64_t)rest < len)
        return MCS_ERR_TRUNCATED;
    return (uint64_t)rest == len ? MCS_OK : MCS_ERR_FORMAT;
}

static void read_range(const uint8_t *p, mcs_io_streams *r)
{
    r->seed = io_get_le(p, 8u);
    r->first = io_get_le(p + 8u, 8u);
    r->end = io_get_le(p + 16u, 8u);
}

/* A pattern block of count ranges: every rule, then (prov not NULL) read. */
static mcs_status read_pattern(const uint8_t *p, size_t count, mcs_io_provenance *prov)
{
    const uint64_t streams = io_get_le(p + P_STREAMS, 8u);
    if (!name_ok(p + P_NAME, MCS_IO_PROV_PATTERN_BYTES, 1, 1) ||
        !pattern_ok(io_get_le(p + P_DIM, 2u), io_get_le(p + P_N, 8u), io_get_le(p + P_K, 8u),
                    io_get_le(p + P_IMPORTANCE, 2u), io_get_le(p + P_IMPORTANCE_CRC, 4u),
                    streams, io_get_le(p + P_TRIALS, 8u)))
        return MCS_ERR_FORMAT;
    mcs_io_streams prev = {0u, 0u, 0u}, r;
    for (size_t i = 0; i < count; ++i) {
        read_range(p + P_RANGES + RANGE_BYTES * i, &r);
        if (!range_ok(i > 0u ? &prev : NULL, &r, streams))
            return MCS_ERR_FORMAT;
        prev = r;
    }
    if (prov == NULL)
        return MCS_OK;
    prov->dim = (uint32_t)io_get_le(p + P_DIM, 2u);
    memcpy(prov->pattern, p + P_NAME, MCS_IO_PROV_PATTERN_BYTES);
    prov->n = io_get_le(p + P_N, 8u);
    prov->k = io_get_le(p + P_K, 8u);
    prov->importance = (uint32_t)io_get_le(p + P_IMPORTANCE, 2u);
    prov->importance_crc = (uint32_t)io_get_le(p + P_IMPORTANCE_CRC, 4u);
    prov->streams = streams;
    prov->trials = io_get_le(p + P_TRIALS, 8u);
    prov->nranges = (uint32_t)count;
    for (size_t i = 0; i < count; ++i)
        read_range(p + P_RANGES + RANGE_BYTES * i, &prov->range[i]);
    return MCS_OK;
}

/* A block of count inputs: every rule, then (prov not NULL) read. */
static mcs_status read_points(const uint8_t *p, size_t count, mcs_io_provenance *prov)
{
    for (size_t i = 0; i < count; ++i) {
        const uint8_t *in = p + B_HEAD + INPUT_BYTES * i;
        if (io_get_le(in + I_RESERVED, 4u) != 0u ||
            !name_ok(in + I_NAME, MCS_IO_PROV_NAME_BYTES, 0, 1) ||
            (i > 0u && io_get_le(in + I_CRC, 4u) <= io_get_le(in - INPUT_BYTES + I_CRC, 4u)))
            return MCS_ERR_FORMAT;
    }
    if (prov == NULL)
        return MCS_OK;
    prov->ninputs = (uint32_t)count;
    for (size_t i = 0; i < count; ++i) {
        const uint8_t *in = p + B_HEAD + INPUT_BYTES * i;
        prov->input[i].crc = (uint32_t)io_get_le(in + I_CRC, 4u);
        prov->input[i].bytes = io_get_le(in + I_BYTES, 8u);
        memcpy(prov->input[i].name, in + I_NAME, MCS_IO_PROV_NAME_BYTES);
    }
    return MCS_OK;
}

mcs_status mcs_io_block_read(const uint8_t *p, size_t bytes, mcs_io_provenance *prov)
{
    const uint64_t source = io_get_le(p + B_SOURCE, 2u);
    const size_t count = (size_t)io_get_le(p + B_COUNT, 2u);
    size_t want = 0u;
    if (source == MCS_IO_SOURCE_PATTERN && count_ok(count, MCS_IO_PROV_MAX_RANGES))
        want = P_RANGES + RANGE_BYTES * count;
    else if (source == MCS_IO_SOURCE_POINTS && count_ok(count, MCS_IO_PROV_MAX_INPUTS))
        want = B_HEAD + INPUT_BYTES * count;
    if (want == 0u || bytes != want)
        return MCS_ERR_FORMAT;
    mcs_status st = source == MCS_IO_SOURCE_PATTERN ? read_pattern(p, count, NULL)
                                                    : read_points(p, count, NULL);
    if (st != MCS_OK || prov == NULL)
        return st;
    memset(prov, 0, sizeof *prov);
    prov->source = (uint32_t)source;
    return source == MCS_IO_SOURCE_PATTERN ? read_pattern(p, count, prov)
                                           : read_points(p, count, prov);
}

/* A name into size bytes: its characters up to the NUL, then zeros. */
static void write_name(const char *name, size_t size, uint8_t *p)
{
    const unsigned char *n = (const unsigned char *)name;
    memcpy(p, n, (size_t)(first_nul(n, size) - n));
}

void mcs_io_block_write(const mcs_io_provenance *prov, uint8_t *p)
{
    size_t bytes = 0u;
    (void)mcs_io_block_size(prov, &bytes); /* accepted by the caller */
    memset(p, 0, bytes);
    io_put_le(p + B_LEN, bytes, 4u);
    io_put_le(p + B_SOURCE, prov->source, 2u);
    if (prov->source == MCS_IO_SOURCE_POINTS) {
        io_put_le(p + B_COUNT, prov->ninputs, 2u);
        for (size_t i = 0; i < prov->ninputs; ++i) {
            uint8_t *in = p + B_HEAD + INPUT_BYTES * i;
            io_put_le(in + I_CRC, prov->input[i].crc, 4u);
            io_put_le(in + I_BYTES, prov->input[i].bytes, 8u);
            write_name(prov->input[i].name, MCS_IO_PROV_NAME_BYTES, in + I_NAME);
        }
        return;
    }
    io_put_le(p + B_COUNT, prov->nranges, 2u);
    io_put_le(p + P_DIM, prov->dim, 2u);
    io_put_le(p + P_IMPORTANCE, prov->importance, 2u);
    io_put_le(p + P_IMPORTANCE_CRC, prov->importance_crc, 4u);
    write_name(prov->pattern, MCS_IO_PROV_PATTERN_BYTES, p + P_NAME);
    io_put_le(p + P_N, prov->n, 8u);
    io_put_le(p + P_K, prov->k, 8u);
    io_put_le(p + P_STREAMS, prov->streams, 8u);
    io_put_le(p + P_TRIALS, prov->trials, 8u);
    for (size_t i = 0; i < prov->nranges; ++i) {
        uint8_t *r = p + P_RANGES + RANGE_BYTES * i;
        io_put_le(r, prov->range[i].seed, 8u);
        io_put_le(r + 8u, prov->range[i].first, 8u);
        io_put_le(r + 16u, prov->range[i].end, 8u);
    }
}

/* ---- the union ---- */

/* Two checked names, equal up to their NUL. */
static int same_name(const char *a, const char *b, size_t size)
{
    const unsigned char *na = (const unsigned char *)a, *nb = (const unsigned char *)b;
    const size_t len = (size_t)(first_nul(na, size) - na);
    return len == (size_t)(first_nul(nb, size) - nb) && memcmp(na, nb, len) == 0;
}

/* The same pattern and run: every field but the ranges. */
static int same_run(const mcs_io_provenance *a, const mcs_io_provenance *b)
{
    return a->dim == b->dim && same_name(a->pattern, b->pattern, sizeof a->pattern) &&
           a->n == b->n && a->k == b->k && a->importance == b->importance &&
           a->importance_crc == b->importance_crc && a->streams == b->streams &&
           a->trials == b->trials;
}

/* (seed, first) order. */
static int range_before(const mcs_io_streams *a, const mcs_io_streams *b)
{
    return a->seed < b->seed || (a->seed == b->seed && a->first < b->first);
}

/* The ranges of dst and src merged in order into dst, a range touching the
 * one before it (same seed) joined to it. The union goes to a scratch list
 * first (768 bytes), so dst changes only when all of it fits and no stream
 * is in both. */
static mcs_status merge_ranges(mcs_io_provenance *dst, const mcs_io_provenance *src)
{
    mcs_io_streams out[MCS_IO_PROV_MAX_RANGES] = {{0u, 0u, 0u}};
    size_t i = 0u, j = 0u, count = 0u;
    while (i < dst->nranges || j < src->nranges) {
        const int from_dst = j == src->nranges ||
                             (i < dst->nranges && range_before(&dst->range[i], &src->range[j]));
        const mcs_io_streams *r = from_dst ? &dst->range[i++] : &src->range[j++];
        mcs_io_streams *last = count > 0u ? &out[count - 1u] : NULL;
        if (last != NULL && last->seed == r->seed && r->first < last->end)
            return MCS_ERR_ALIAS; /* a stream of this seed in both */
        if (last != NULL && last->seed == r->seed && r->first == last->end) {
            last->end = r->end;
            continue;
        }
        if (count == MCS_IO_PROV_MAX_RANGES)
            return MCS_ERR_SPACE;
        out[count++] = *r;
    }
    /* The entries past the union 0, so equal unions are equal structs. */
    memset(dst->range, 0, sizeof dst->range);
    memcpy(dst->range, out, count * sizeof out[0]);
    dst->nranges = (uint32_t)count;
    return MCS_OK;
}

/* The inputs of src into dst's sorted list, from the back (no scratch: the
 * union of distinct inputs is as long as both lists). */
static mcs_status merge_inputs(mcs_io_provenance *dst, const mcs_io_provenance *src)
{
    size_t i = 0u, j = 0u;
    while (i < dst->ninputs && j < src->ninputs) {
        const uint32_t a = dst->input[i].crc, b = src->input[j].crc;
        if (a == b)
            return MCS_ERR_ALIAS; /* the same input in both */
        i += a < b;
        j += b < a;
    }
    if ((size_t)dst->ninputs + src->ninputs > MCS_IO_PROV_MAX_INPUTS)
        return MCS_ERR_SPACE;
    size_t a = dst->ninputs, b = src->ninputs, w = a + b;
    while (b > 0u) {
        if (a > 0u && dst->input[a - 1u].crc > src->input[b - 1u].crc)
            dst->input[--w] = dst->input[--a];
        else
            dst->input[--w] = src->input[--b];
    }
    dst->ninputs += src->ninputs;
    return MCS_OK;
}

mcs_status mcs_io_provenance_merge(mcs_io_provenance *dst, const mcs_io_provenance *src)
{
    size_t bytes = 0u;
    if (dst == NULL || src == NULL)
        return MCS_ERR_NULL;
    if (!provenance_ok(dst, &bytes) || !provenance_ok(src, &bytes))
        return MCS_ERR_FORMAT;
    if (dst->source != src->source || dst->source == MCS_IO_SOURCE_NONE)
        return MCS_ERR_KIND;
    if (dst->source == MCS_IO_SOURCE_POINTS)
        return merge_inputs(dst, src);
    if (!same_run(dst, src))
        return MCS_ERR_MISMATCH;
    return merge_ranges(dst, src);
}
