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

static void put_le(uint8_t *p, uint64_t v, size_t bytes)
{
    for (size_t i = 0; i < bytes; ++i)
        p[i] = (uint8_t)(v >> (8u * i));
}

static uint64_t get_le(const uint8_t *p, size_t bytes)
{
    uint64_t v = 0u;
    for (size_t i = 0; i < bytes; ++i)
        v |= (uint64_t)p[i] << (8u * i);
    return v;
}

double io_get_f64(const uint8_t *payload, size_t i)
{
    const uint64_t bits = get_le(payload + 8u * i, 8u);
    double v;
    memcpy(&v, &bits, sizeof v);
    return v;
}

/* CRC-32 with the reflected polynomial 0xEDB88320, four bits per step from a
 * 16-entry table: 64 bytes of constants instead of 1 KiB, fast enough for a
 * record (a 4096-bin spectrum is 80 KiB). */
static const uint32_t crc_nibble[16] = {
    0x00000000u, 0x1db71064u, 0x3b6e20c8u, 0x26d930acu, 0x76dc4190u, 0x6b6b51f4u,
    0x4db26158u, 0x5005713cu, 0xedb88320u, 0xf00f9344u, 0xd6d6a3e8u, 0xcb61b38cu,
    0x9b64c2b0u, 0x86d3d2d4u, 0xa00ae278u, 0xbdbdf21cu};

static uint32_t crc32_of(const uint8_t *p, size_t len)
{
    uint32_t c = 0xffffffffu;
    for (size_t i = 0; i < len; ++i) {
        c ^= p[i];
        c = (c >> 4) ^ crc_nibble[c & 15u];
        c = (c >> 4) ^ crc_nibble[c & 15u];
    }
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
    default: return "unknown";
    }
}

/* Bytes before the payload for shape_len shape words. */
static size_t head_bytes(uint32_t shape_len)
{
    return (size_t)MCS_IO_HEADER_BYTES + 8u * (size_t)shape_len;
}

/* Magic, header, lengths (the record fills buf exactly), CRC. */
static mcs_status frame(size_t len, const uint8_t *p, mcs_io_info *info)
{
    const size_t magic_len = len < sizeof io_magic ? len : sizeof io_magic;
    if (memcmp(p, io_magic, magic_len) != 0)
        return MCS_ERR_MAGIC;
    if (len < (size_t)MCS_IO_HEADER_BYTES)
        return MCS_ERR_TRUNCATED;
    if (get_le(p + OFF_VERSION, 2u) != MCS_IO_VERSION)
        return MCS_ERR_VERSION;
    const uint64_t shape_len = get_le(p + OFF_SHAPE_LEN, 4u);
    if (shape_len > MCS_IO_MAX_SHAPE)
        return MCS_ERR_FORMAT;
    /* payload_len is untrusted: compare it with the bytes there are rather
     * than multiply it (no overflow for any value). */
    const size_t fixed = head_bytes((uint32_t)shape_len) + MCS_IO_CRC_BYTES;
    const uint64_t payload_len = get_le(p + OFF_PAYLOAD_LEN, 8u);
    if (len < fixed || payload_len > (uint64_t)((len - fixed) / 8u))
        return MCS_ERR_TRUNCATED;
    if ((uint64_t)(len - fixed) != 8u * payload_len)
        return MCS_ERR_FORMAT;
    const size_t body = len - MCS_IO_CRC_BYTES;
    if (crc32_of(p, body) != (uint32_t)get_le(p + body, MCS_IO_CRC_BYTES))
        return MCS_ERR_CHECKSUM;
    memset(info, 0, sizeof *info);
    info->version = MCS_IO_VERSION;
    info->kind = (uint32_t)get_le(p + OFF_KIND, 2u);
    info->shape_len = (uint32_t)shape_len;
    for (size_t i = 0; i < info->shape_len; ++i)
        info->shape[i] = get_le(p + MCS_IO_HEADER_BYTES + 8u * i, 8u);
    info->count = get_le(p + OFF_COUNT, 8u);
    info->payload_len = payload_len;
    info->size = len;
    return MCS_OK;
}

mcs_status mcs_io_peek(size_t len, const void *buf, mcs_io_info *info)
{
    if (buf == NULL || info == NULL)
        return MCS_ERR_NULL;
    mcs_io_info tmp;
    mcs_status st = frame(len, (const uint8_t *)buf, &tmp);
    if (st != MCS_OK)
        return st;
    *info = tmp;
    return MCS_OK;
}

void io_sink_put(io_sink *sink, double v)
{
    if (sink->out != NULL) {
        uint64_t bits;
        memcpy(&bits, &v, sizeof bits);
        put_le(sink->out + 8u * sink->index, bits, 8u);
        sink->index += 1u;
        return;
    }
    const io_layout *lay = sink->lay;
    while (sink->range + 1u < lay->nranges &&
           sink->index >= lay->ranges[sink->range].first + lay->ranges[sink->range].len)
        sink->range += 1u;
    const unsigned rules = lay->ranges[sink->range].rules;
    if (!isfinite(v))
        sink->not_finite = 1;
    else if (fabs(v) > MCS_IO_MAX_MAGNITUDE || (sink->count == 0u && v != 0.0) ||
             ((rules & IO_RULE_NONNEG) && v < 0.0) ||
             ((rules & IO_RULE_SPREAD) && sink->count < 2u && v != 0.0))
        sink->broken = 1;
    sink->index += 1u;
}

/* The verdict of a checking pass: non-finite values first (they are what an
 * overflow leaves), then broken invariants, then the count itself. */
static mcs_status sink_status(const io_sink *sink)
{
    if (sink->not_finite)
        return MCS_ERR_NOT_FINITE;
    if (sink->broken || sink->count > MCS_IO_MAX_COUNT)
        return MCS_ERR_INVARIANT;
    return MCS_OK;
}

static void write_header(const io_layout *lay, uint64_t count, uint8_t *p)
{
    memcpy(p, io_magic, sizeof io_magic);
    put_le(p + OFF_VERSION, MCS_IO_VERSION, 2u);
    put_le(p + OFF_KIND, lay->kind, 2u);
    put_le(p + OFF_SHAPE_LEN, lay->shape_len, 4u);
    put_le(p + OFF_COUNT, count, 8u);
    put_le(p + OFF_PAYLOAD_LEN, lay->payload_len, 8u);
    for (size_t i = 0; i < lay->shape_len; ++i)
        put_le(p + MCS_IO_HEADER_BYTES + 8u * i, lay->shape[i], 8u);
}

mcs_status io_save(const io_layout *lay, const io_source *src, size_t cap, void *buf,
                   size_t *len)
{
    const size_t head = head_bytes(lay->shape_len);
    const size_t size = head + 8u * lay->payload_len + MCS_IO_CRC_BYTES;
    io_sink sink = {lay, src->count, NULL, 0u, 0u, 0, 0};
    src->emit(src->obj, &sink);
    mcs_status st = sink_status(&sink);
    if (st != MCS_OK)
        return st;
    if (buf == NULL) {
        *len = size;
        return MCS_OK;
    }
    if (cap < size)
        return MCS_ERR_SPACE;
    uint8_t *p = (uint8_t *)buf;
    write_header(lay, src->count, p);
    io_sink writer = {lay, src->count, p + head, 0u, 0u, 0, 0};
    src->emit(src->obj, &writer);
    put_le(p + size - MCS_IO_CRC_BYTES, crc32_of(p, size - MCS_IO_CRC_BYTES), MCS_IO_CRC_BYTES);
    *len = size;
    return MCS_OK;
}

mcs_status io_load_check(const io_kind *kind, size_t len, const void *buf, io_record *rec)
{
    mcs_io_info info;
    io_layout lay;
    mcs_status st = frame(len, (const uint8_t *)buf, &info);
    if (st != MCS_OK)
        return st;
    if (info.kind != kind->kind)
        return MCS_ERR_KIND;
    if (info.shape_len != kind->shape_len)
        return MCS_ERR_FORMAT;
    st = kind->layout(info.shape, &lay);
    if (st != MCS_OK)
        return st;
    if (info.payload_len != (uint64_t)lay.payload_len)
        return MCS_ERR_FORMAT;
    const uint8_t *pl = (const uint8_t *)buf + head_bytes(kind->shape_len);
    io_sink sink = {&lay, info.count, NULL, 0u, 0u, 0, 0};
    for (size_t i = 0; i < lay.payload_len; ++i)
        io_sink_put(&sink, io_get_f64(pl, i));
    st = sink_status(&sink);
    if (st != MCS_OK)
        return st;
    rec->lay = lay;
    rec->payload = pl;
    rec->count = info.count;
    return MCS_OK;
}
