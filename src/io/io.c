/* Record framing, CRC-32 and the value codec shared by every kind
 * (docs/format.md). Every multi-byte field is assembled byte by byte, so
 * neither the host's byte order nor its struct layout reaches the bytes. */
#include "io_internal.h"

#include <float.h>
#include <math.h>
#include <string.h>

/* The payload is the bit pattern of each double; that needs IEEE-754
 * binary64 stored in the same byte order as a uint64_t (true of every target
 * mcspec builds for; the old ARM FPA word-swapped doubles are not). */
_Static_assert(DBL_MANT_DIG == 53 && DBL_MAX_EXP == 1024 && sizeof(double) == 8u,
               "mcspec io needs IEEE-754 binary64 doubles");
#if defined(__FLOAT_WORD_ORDER__) && defined(__BYTE_ORDER__)
#if __FLOAT_WORD_ORDER__ != __BYTE_ORDER__
#error "mcspec io needs doubles in the byte order of uint64_t"
#endif
#endif

/* "\x89MCS\r\n\x1a\n": a non-ASCII first byte and the CR LF, SUB, LF of PNG's
 * signature, so a text-mode transfer or a 7-bit channel breaks the magic. */
static const uint8_t io_magic[8] = {0x89u, 0x4du, 0x43u, 0x53u, 0x0du, 0x0au, 0x1au, 0x0au};

/* Header offsets. */
#define OFF_VERSION 8u
#define OFF_KIND 10u
#define OFF_SHAPE_LEN 12u
#define OFF_COUNT 16u
#define OFF_PAYLOAD_LEN 24u

static double get_f64(const uint8_t *payload, size_t i)
{
    const uint64_t bits = io_get_le(payload + 8u * i, 8u);
    double v;
    memcpy(&v, &bits, sizeof v);
    return v;
}

/* CRC-32 with the reflected polynomial 0xEDB88320, a byte per step from a
 * 256-entry table (1 KiB of constants; a linker dropping unused sections
 * drops it with the io functions). */
static const uint32_t crc_table[256] = {
    0x00000000u, 0x77073096u, 0xee0e612cu, 0x990951bau, 0x076dc419u, 0x706af48fu,
    0xe963a535u, 0x9e6495a3u, 0x0edb8832u, 0x79dcb8a4u, 0xe0d5e91eu, 0x97d2d988u,
    0x09b64c2bu, 0x7eb17cbdu, 0xe7b82d07u, 0x90bf1d91u, 0x1db71064u, 0x6ab020f2u,
    0xf3b97148u, 0x84be41deu, 0x1adad47du, 0x6ddde4ebu, 0xf4d4b551u, 0x83d385c7u,
    0x136c9856u, 0x646ba8c0u, 0xfd62f97au, 0x8a65c9ecu, 0x14015c4fu, 0x63066cd9u,
    0xfa0f3d63u, 0x8d080df5u, 0x3b6e20c8u, 0x4c69105eu, 0xd56041e4u, 0xa2677172u,
    0x3c03e4d1u, 0x4b04d447u, 0xd20d85fdu, 0xa50ab56bu, 0x35b5a8fau, 0x42b2986cu,
    0xdbbbc9d6u, 0xacbcf940u, 0x32d86ce3u, 0x45df5c75u, 0xdcd60dcfu, 0xabd13d59u,
    0x26d930acu, 0x51de003au, 0xc8d75180u, 0xbfd06116u, 0x21b4f4b5u, 0x56b3c423u,
    0xcfba9599u, 0xb8bda50fu, 0x2802b89eu, 0x5f058808u, 0xc60cd9b2u, 0xb10be924u,
    0x2f6f7c87u, 0x58684c11u, 0xc1611dabu, 0xb6662d3du, 0x76dc4190u, 0x01db7106u,
    0x98d220bcu, 0xefd5102au, 0x71b18589u, 0x06b6b51fu, 0x9fbfe4a5u, 0xe8b8d433u,
    0x7807c9a2u, 0x0f00f934u, 0x9609a88eu, 0xe10e9818u, 0x7f6a0dbbu, 0x086d3d2du,
    0x91646c97u, 0xe6635c01u, 0x6b6b51f4u, 0x1c6c6162u, 0x856530d8u, 0xf262004eu,
    0x6c0695edu, 0x1b01a57bu, 0x8208f4c1u, 0xf50fc457u, 0x65b0d9c6u, 0x12b7e950u,
    0x8bbeb8eau, 0xfcb9887cu, 0x62dd1ddfu, 0x15da2d49u, 0x8cd37cf3u, 0xfbd44c65u,
    0x4db26158u, 0x3ab551ceu, 0xa3bc0074u, 0xd4bb30e2u, 0x4adfa541u, 0x3dd895d7u,
    0xa4d1c46du, 0xd3d6f4fbu, 0x4369e96au, 0x346ed9fcu, 0xad678846u, 0xda60b8d0u,
    0x44042d73u, 0x33031de5u, 0xaa0a4c5fu, 0xdd0d7cc9u, 0x5005713cu, 0x270241aau,
    0xbe0b1010u, 0xc90c2086u, 0x5768b525u, 0x206f85b3u, 0xb966d409u, 0xce61e49fu,
    0x5edef90eu, 0x29d9c998u, 0xb0d09822u, 0xc7d7a8b4u, 0x59b33d17u, 0x2eb40d81u,
    0xb7bd5c3bu, 0xc0ba6cadu, 0xedb88320u, 0x9abfb3b6u, 0x03b6e20cu, 0x74b1d29au,
    0xead54739u, 0x9dd277afu, 0x04db2615u, 0x73dc1683u, 0xe3630b12u, 0x94643b84u,
    0x0d6d6a3eu, 0x7a6a5aa8u, 0xe40ecf0bu, 0x9309ff9du, 0x0a00ae27u, 0x7d079eb1u,
    0xf00f9344u, 0x8708a3d2u, 0x1e01f268u, 0x6906c2feu, 0xf762575du, 0x806567cbu,
    0x196c3671u, 0x6e6b06e7u, 0xfed41b76u, 0x89d32be0u, 0x10da7a5au, 0x67dd4accu,
    0xf9b9df6fu, 0x8ebeeff9u, 0x17b7be43u, 0x60b08ed5u, 0xd6d6a3e8u, 0xa1d1937eu,
    0x38d8c2c4u, 0x4fdff252u, 0xd1bb67f1u, 0xa6bc5767u, 0x3fb506ddu, 0x48b2364bu,
    0xd80d2bdau, 0xaf0a1b4cu, 0x36034af6u, 0x41047a60u, 0xdf60efc3u, 0xa867df55u,
    0x316e8eefu, 0x4669be79u, 0xcb61b38cu, 0xbc66831au, 0x256fd2a0u, 0x5268e236u,
    0xcc0c7795u, 0xbb0b4703u, 0x220216b9u, 0x5505262fu, 0xc5ba3bbeu, 0xb2bd0b28u,
    0x2bb45a92u, 0x5cb36a04u, 0xc2d7ffa7u, 0xb5d0cf31u, 0x2cd99e8bu, 0x5bdeae1du,
    0x9b64c2b0u, 0xec63f226u, 0x756aa39cu, 0x026d930au, 0x9c0906a9u, 0xeb0e363fu,
    0x72076785u, 0x05005713u, 0x95bf4a82u, 0xe2b87a14u, 0x7bb12baeu, 0x0cb61b38u,
    0x92d28e9bu, 0xe5d5be0du, 0x7cdcefb7u, 0x0bdbdf21u, 0x86d3d2d4u, 0xf1d4e242u,
    0x68ddb3f8u, 0x1fda836eu, 0x81be16cdu, 0xf6b9265bu, 0x6fb077e1u, 0x18b74777u,
    0x88085ae6u, 0xff0f6a70u, 0x66063bcau, 0x11010b5cu, 0x8f659effu, 0xf862ae69u,
    0x616bffd3u, 0x166ccf45u, 0xa00ae278u, 0xd70dd2eeu, 0x4e048354u, 0x3903b3c2u,
    0xa7672661u, 0xd06016f7u, 0x4969474du, 0x3e6e77dbu, 0xaed16a4au, 0xd9d65adcu,
    0x40df0b66u, 0x37d83bf0u, 0xa9bcae53u, 0xdebb9ec5u, 0x47b2cf7fu, 0x30b5ffe9u,
    0xbdbdf21cu, 0xcabac28au, 0x53b39330u, 0x24b4a3a6u, 0xbad03605u, 0xcdd70693u,
    0x54de5729u, 0x23d967bfu, 0xb3667a2eu, 0xc4614ab8u, 0x5d681b02u, 0x2a6f2b94u,
    0xb40bbe37u, 0xc30c8ea1u, 0x5a05df1bu, 0x2d02ef8du};

static uint32_t crc32_of(const uint8_t *p, size_t len)
{
    uint32_t c = 0xffffffffu;
    for (size_t i = 0; i < len; ++i)
        c = (c >> 8) ^ crc_table[(c ^ p[i]) & 0xffu];
    return c ^ 0xffffffffu;
}

mcs_status mcs_io_crc32(size_t len, const void *data, uint32_t *crc)
{
    if (crc == NULL || (data == NULL && len > 0u))
        return MCS_ERR_NULL;
    *crc = len > 0u ? crc32_of((const uint8_t *)data, len) : 0u;
    return MCS_OK;
}

const char *mcs_io_kind_str(uint32_t kind)
{
    switch (kind) {
    case MCS_IO_KIND_SPECTRUM: return "spectrum";
    case MCS_IO_KIND_MOMENT: return "moment";
    case MCS_IO_KIND_AUTOCORR: return "autocorr";
    case MCS_IO_KIND_WELFORD: return "welford";
    case MCS_IO_KIND_POINTSET: return "pointset";
    case MCS_IO_KIND_POINTSET2D: return "pointset2d";
    case MCS_IO_KIND_SPECTRUM2D: return "spectrum2d";
    case MCS_IO_KIND_PCF: return "pcf";
    case MCS_IO_KIND_INTEGRATE: return "integrate";
    case MCS_IO_KIND_DISCREPANCY: return "discrepancy";
    case MCS_IO_KIND_SPACING: return "spacing";
    default: return "unknown";
    }
}

/* Bytes before the payload for shape_len shape words. */
static size_t head_bytes(uint32_t shape_len)
{
    return (size_t)MCS_IO_HEADER_BYTES + 8u * (size_t)shape_len;
}

/* Version 1 and 2 records differ only by the provenance block of version 2,
 * between the payload and the CRC; a record without provenance is version 1. */
#define VERSION_PLAIN 1u

/* Magic, header, lengths (the record fills buf exactly, a version 2 block
 * included), CRC, then the block's contents; out->block gets the block's
 * offset (0: none). */
typedef struct {
    mcs_io_info info;
    size_t block, block_bytes;
} io_frame;

static mcs_status frame(size_t len, const uint8_t *p, io_frame *out)
{
    const size_t magic_len = len < sizeof io_magic ? len : sizeof io_magic;
    if (memcmp(p, io_magic, magic_len) != 0)
        return MCS_ERR_MAGIC;
    if (len < (size_t)MCS_IO_HEADER_BYTES)
        return MCS_ERR_TRUNCATED;
    const uint64_t version = io_get_le(p + OFF_VERSION, 2u);
    if (version != VERSION_PLAIN && version != MCS_IO_VERSION)
        return MCS_ERR_VERSION;
    const uint64_t shape_len = io_get_le(p + OFF_SHAPE_LEN, 4u);
    if (shape_len > MCS_IO_MAX_SHAPE)
        return MCS_ERR_FORMAT;
    /* payload_len is untrusted: compare it with the bytes there are rather
     * than multiply it (no overflow for any value). */
    const size_t fixed = head_bytes((uint32_t)shape_len) + MCS_IO_CRC_BYTES;
    const uint64_t payload_len = io_get_le(p + OFF_PAYLOAD_LEN, 8u);
    if (len < fixed || payload_len > (uint64_t)((len - fixed) / 8u))
        return MCS_ERR_TRUNCATED;
    const size_t block = head_bytes((uint32_t)shape_len) + 8u * (size_t)payload_len;
    const size_t rest = len - fixed - 8u * (size_t)payload_len; /* the block's bytes */
    if (version == VERSION_PLAIN && rest != 0u)
        return MCS_ERR_FORMAT;
    if (version != VERSION_PLAIN) {
        mcs_status st = mcs_io_block_frame(p + block, rest);
        if (st != MCS_OK)
            return st;
    }
    const size_t body = len - MCS_IO_CRC_BYTES;
    if (crc32_of(p, body) != (uint32_t)io_get_le(p + body, MCS_IO_CRC_BYTES))
        return MCS_ERR_CHECKSUM;
    if (version != VERSION_PLAIN && mcs_io_block_read(p + block, rest, NULL) != MCS_OK)
        return MCS_ERR_FORMAT;
    mcs_io_info *info = &out->info;
    memset(out, 0, sizeof *out);
    info->version = (uint32_t)version;
    info->kind = (uint32_t)io_get_le(p + OFF_KIND, 2u);
    info->shape_len = (uint32_t)shape_len;
    for (size_t i = 0; i < info->shape_len; ++i)
        info->shape[i] = io_get_le(p + MCS_IO_HEADER_BYTES + 8u * i, 8u);
    info->count = io_get_le(p + OFF_COUNT, 8u);
    info->payload_len = payload_len;
    info->size = len;
    out->block = version != VERSION_PLAIN ? block : 0u;
    out->block_bytes = rest;
    return MCS_OK;
}

mcs_status mcs_io_peek(size_t len, const void *buf, mcs_io_info *info)
{
    if (buf == NULL || info == NULL)
        return MCS_ERR_NULL;
    io_frame tmp;
    mcs_status st = frame(len, (const uint8_t *)buf, &tmp);
    if (st != MCS_OK)
        return st;
    *info = tmp.info;
    return MCS_OK;
}

mcs_status mcs_io_peek_provenance(size_t len, const void *buf, mcs_io_provenance *prov)
{
    if (buf == NULL || prov == NULL)
        return MCS_ERR_NULL;
    io_frame f;
    mcs_status st = frame(len, (const uint8_t *)buf, &f);
    if (st != MCS_OK)
        return st;
    if (f.block == 0u) {
        memset(prov, 0, sizeof *prov);
        prov->source = MCS_IO_SOURCE_NONE;
        return MCS_OK;
    }
    return mcs_io_block_read((const uint8_t *)buf + f.block, f.block_bytes, prov);
}

mcs_status mcs_io_set_provenance(const mcs_io_provenance *prov, size_t cap, void *buf,
                                 size_t *len)
{
    if (prov == NULL || buf == NULL || len == NULL)
        return MCS_ERR_NULL;
    io_frame f;
    uint8_t *p = (uint8_t *)buf;
    mcs_status st = frame(*len, p, &f);
    size_t bytes = 0u;
    if (st == MCS_OK)
        st = mcs_io_block_size(prov, &bytes);
    if (st != MCS_OK)
        return st;
    /* The record without its block ends where the block (or the CRC) starts. */
    const size_t plain = f.block != 0u ? f.block : *len - MCS_IO_CRC_BYTES;
    const size_t size = plain + bytes + MCS_IO_CRC_BYTES;
    if (cap < size)
        return MCS_ERR_SPACE;
    io_put_le(p + OFF_VERSION, bytes != 0u ? MCS_IO_VERSION : VERSION_PLAIN, 2u);
    if (bytes != 0u)
        mcs_io_block_write(prov, p + plain);
    io_put_le(p + plain + bytes, crc32_of(p, plain + bytes), MCS_IO_CRC_BYTES);
    *len = size;
    return MCS_OK;
}

/* ---- the field walker: one pass over a kind's payload, in payload order ---- */

/* What one pass does with each value: read from the object being saved
 * (payload == NULL) or from the payload; then written to out, stored into
 * the object, or (neither) checked against the field's rules. */
typedef struct {
    const io_values *values;
    uint64_t count;
    uint8_t *out;
    void *into;
    size_t index;
    int not_finite, broken;
} io_pass;

/* The place of the value at byte offset at of a field: in the object, or,
 * for IO_AS_POINTED, as far into the array its pointer member points to. */
static const unsigned char *place_of(const void *obj, const io_field *field, size_t at)
{
    const unsigned char *p = (const unsigned char *)obj;
    if (field->as != IO_AS_POINTED)
        return p + at;
    const double *array;
    memcpy(&array, p + field->offset, sizeof array);
    return (const unsigned char *)(const void *)array + (at - field->offset);
}

static unsigned char *place_in(void *obj, const io_field *field, size_t at)
{
    unsigned char *p = (unsigned char *)obj;
    if (field->as != IO_AS_POINTED)
        return p + at;
    double *array;
    memcpy(&array, p + field->offset, sizeof array);
    return (unsigned char *)(void *)array + (at - field->offset);
}

static double read_value(const void *obj, const io_field *field, size_t at)
{
    const unsigned char *p = place_of(obj, field, at);
    if (field->as == IO_AS_COUNT) {
        uint64_t u;
        memcpy(&u, p, sizeof u);
        return (double)u;
    }
    if (field->as == IO_AS_SIZE) {
        size_t z;
        memcpy(&z, p, sizeof z);
        return (double)z;
    }
    double v;
    memcpy(&v, p, sizeof v);
    return v;
}

/* Stores v at byte offset at, and at the mirrored place of an upper
 * triangle's value (row m, column c of an n x n array). */
static void store_value(void *obj, const io_field *field, size_t n, size_t at, double v)
{
    unsigned char *p = (unsigned char *)obj;
    if (field->as == IO_AS_COUNT) {
        const uint64_t u = (uint64_t)v;
        memcpy(p + at, &u, sizeof u);
        return;
    }
    if (field->as == IO_AS_SIZE) {
        const size_t z = (size_t)v; /* exact: the check refused values above SIZE_MAX */
        memcpy(p + at, &z, sizeof z);
        return;
    }
    memcpy(place_in(obj, field, at), &v, sizeof v);
    if (field->as == IO_AS_UPPER) {
        const size_t mc = (at - field->offset) / sizeof(double), m = mc / n, c = mc % n;
        memcpy(p + field->offset + sizeof(double) * (c * n + m), &v, sizeof v);
    }
}

/* A count field holds a whole number in [0, 2^53] written as +0.0 or more:
 * -0.0 or a fraction would load as the integer below it and save back as
 * other bytes (fuzz_load found a spectrum whose units were -0.0). */
static int bad_count(double v)
{
    return signbit(v) || v != floor(v) || v > (double)MCS_MAX_COUNT;
}

/* A size field is a count that also fits a size_t (a 32-bit build's). */
static int bad_size(double v)
{
    return bad_count(v) || v > (double)SIZE_MAX;
}

static void check_value(io_pass *pass, double v, const io_field *field)
{
    const unsigned rules = field->rules;
    if (!isfinite(v))
        pass->not_finite = 1;
    else if (fabs(v) > MCS_IO_MAX_MAGNITUDE || (pass->count == 0u && v != 0.0) ||
             ((rules & IO_RULE_NONNEG) && v < 0.0) ||
             ((rules & IO_RULE_SPREAD) && pass->count < 2u && v != 0.0) ||
             (field->as == IO_AS_COUNT && bad_count(v)) || (field->as == IO_AS_SIZE && bad_size(v)))
        pass->broken = 1;
}

static void visit(io_pass *pass, const io_field *field, size_t at)
{
    const io_values *values = pass->values;
    const double v = values->payload != NULL ? get_f64(values->payload, pass->index)
                                              : read_value(values->obj, field, at);
    if (pass->out != NULL) {
        uint64_t bits;
        memcpy(&bits, &v, sizeof bits);
        io_put_le(pass->out + 8u * pass->index, bits, 8u);
    } else if (pass->into != NULL) {
        store_value(pass->into, field, values->size[field->len], at, v);
    } else {
        check_value(pass, v, field);
    }
    pass->index += 1u;
}

/* Every payload value in order, with the byte offset of its place in the
 * object. */
static void walk(io_pass *pass)
{
    const io_kind *kind = pass->values->kind;
    const size_t *size = pass->values->size;
    for (size_t f = 0; f < kind->nfields; ++f) {
        const io_field *field = &kind->fields[f];
        const size_t len = size[field->len], stride = size[field->stride];
        const size_t rows = field->as == IO_AS_UPPER ? len : size[field->rows];
        /* an upper triangle's row r starts at column r */
        for (size_t r = 0; r < rows; ++r)
            for (size_t c = field->as == IO_AS_UPPER ? r : 0u; c < len; ++c)
                visit(pass, field, field->offset + sizeof(double) * (r * stride + c));
    }
}

static size_t field_values(const io_field *field, const size_t *size)
{
    const size_t len = size[field->len];
    return field->as == IO_AS_UPPER ? len * (len + 1u) / 2u : size[field->rows] * len;
}

static size_t payload_len(const io_kind *kind, const size_t *size)
{
    size_t len = 0u;
    for (size_t f = 0; f < kind->nfields; ++f)
        len += field_values(&kind->fields[f], size);
    return len;
}

double mcs_io_value(const io_values *values, size_t i)
{
    if (values->payload != NULL)
        return get_f64(values->payload, i);
    const io_kind *kind = values->kind;
    for (size_t f = 0; f < kind->nfields; ++f) {
        const io_field *field = &kind->fields[f];
        const size_t in_field = field_values(field, values->size);
        if (i >= in_field) {
            i -= in_field;
            continue;
        }
        const size_t len = values->size[field->len];
        size_t r = i / len, c = i % len;
        if (field->as == IO_AS_UPPER) /* row r of the triangle holds len - r values from column r */
            for (r = 0u, c = i; c >= len - r; ++r)
                c -= len - r;
        const size_t col = field->as == IO_AS_UPPER ? r + c : c;
        return read_value(values->obj, field,
                          field->offset + sizeof(double) * (r * values->size[field->stride] + col));
    }
    return 0.0; /* i beyond the payload: not asked for */
}

/* The verdict of a checking pass: non-finite values first (they are what an
 * overflow leaves), then broken rules or invariants, then the count itself. */
static mcs_status check_values(const io_values *values, uint64_t count)
{
    io_pass pass = {values, count, NULL, NULL, 0u, 0, 0};
    walk(&pass);
    if (pass.not_finite)
        return MCS_ERR_NOT_FINITE;
    if (pass.broken || count > MCS_IO_MAX_COUNT)
        return MCS_ERR_INVARIANT;
    if (values->kind->valid != NULL && !values->kind->valid(values, count))
        return MCS_ERR_INVARIANT;
    return MCS_OK;
}

static void write_header(const io_kind *kind, const uint64_t *shape, uint64_t count,
                         size_t payload, uint8_t *p)
{
    memcpy(p, io_magic, sizeof io_magic);
    io_put_le(p + OFF_VERSION, VERSION_PLAIN, 2u); /* no provenance */
    io_put_le(p + OFF_KIND, kind->kind, 2u);
    io_put_le(p + OFF_SHAPE_LEN, kind->shape_len, 4u);
    io_put_le(p + OFF_COUNT, count, 8u);
    io_put_le(p + OFF_PAYLOAD_LEN, payload, 8u);
    for (size_t i = 0; i < kind->shape_len; ++i)
        io_put_le(p + MCS_IO_HEADER_BYTES + 8u * i, shape[i], 8u);
}

mcs_status mcs_io_save(const io_kind *kind, const void *obj, size_t cap, void *buf, size_t *len)
{
    uint64_t count, shape[MCS_IO_MAX_SHAPE] = {0u};
    io_values values = {kind, {1u}, obj, NULL, shape};
    if (obj == NULL || len == NULL)
        return MCS_ERR_NULL;
    mcs_status st = kind->count(obj, &count); /* MCS_ERR_UNINIT */
    if (st != MCS_OK)
        return st;
    for (size_t i = 0; i < kind->shape_len && kind->shape_of == NULL; ++i) {
        size_t word;
        memcpy(&word, (const unsigned char *)obj + kind->shape_at[i], sizeof word);
        shape[i] = word;
    }
    if (kind->shape_of != NULL)
        kind->shape_of(obj, shape);
    (void)kind->sizes(shape, values.size); /* cannot fail: an initialised object's shape */
    st = check_values(&values, count);
    if (st != MCS_OK)
        return st;
    const size_t head = head_bytes(kind->shape_len), payload = payload_len(kind, values.size);
    const size_t size = head + 8u * payload + MCS_IO_CRC_BYTES;
    if (buf == NULL) {
        *len = size;
        return MCS_OK;
    }
    if (cap < size)
        return MCS_ERR_SPACE;
    uint8_t *p = (uint8_t *)buf;
    write_header(kind, shape, count, payload, p);
    io_pass writer = {&values, count, p + head, NULL, 0u, 0, 0};
    walk(&writer);
    io_put_le(p + size - MCS_IO_CRC_BYTES, crc32_of(p, size - MCS_IO_CRC_BYTES), MCS_IO_CRC_BYTES);
    *len = size;
    return MCS_OK;
}

mcs_status mcs_io_load(const io_kind *kind, void *obj, size_t len, const void *buf)
{
    io_frame f;
    const mcs_io_info *info = &f.info;
    io_values values = {kind, {1u}, NULL, NULL, info->shape};
    if (obj == NULL || buf == NULL)
        return MCS_ERR_NULL;
    mcs_status st = frame(len, (const uint8_t *)buf, &f);
    if (st != MCS_OK)
        return st;
    if (info->kind != kind->kind)
        return MCS_ERR_KIND;
    if (info->shape_len != kind->shape_len)
        return MCS_ERR_FORMAT;
    st = kind->sizes(info->shape, values.size);
    if (st != MCS_OK)
        return st;
    if (info->payload_len != (uint64_t)payload_len(kind, values.size))
        return MCS_ERR_FORMAT;
    values.payload = (const uint8_t *)buf + head_bytes(kind->shape_len);
    st = check_values(&values, info->count);
    if (st != MCS_OK)
        return st;
    st = kind->init(obj, info->shape); /* leaves obj as it was on error */
    if (st != MCS_OK)
        return st;
    mcs_io_store(&values, info->count, obj);
    return MCS_OK;
}

void mcs_io_store(const io_values *values, uint64_t count, void *obj)
{
    io_pass store = {values, count, NULL, obj, 0u, 0, 0};
    walk(&store);
    memcpy((unsigned char *)obj + values->kind->count_at, &count, sizeof count);
}
