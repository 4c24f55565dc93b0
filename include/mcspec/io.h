/* Save and load accumulators to and from caller buffers (docs/format.md).
 *
 * A record is a fixed 32-byte header (magic, format version, kind, shape
 * length, trial count, payload length), the shape words, the payload as
 * little-endian IEEE-754 binary64 holding only the entries in use, and a
 * CRC-32 of everything before it. All fields are written byte by byte, so a
 * record does not depend on the host's byte order, the compiler or MCS_MAX_*:
 * a file saved on a laptop loads on a cluster node or a microcontroller whose
 * capacities hold its N, and merges there with the library's merge.
 *
 * Saving is KissFFT's two-call size query: pass buf = NULL to learn the size,
 * then a buffer of at least that many bytes. Loading validates the whole
 * record (framing, checksum, kind, shape against this build's capacities,
 * finite values, the invariants every sequence of adds and merges keeps)
 * before it writes anything, so on any error the destination is
 * byte-identical and the status says what was wrong. Save refuses an object
 * that load would refuse, so every record save writes loads back.
 *
 * Nothing here allocates or touches stdio; the caller reads and writes files. */
#ifndef MCSPEC_IO_H
#define MCSPEC_IO_H

#include <stddef.h>
#include <stdint.h>
#include "status.h"
#include "spectrum.h"
#include "moment.h"
#include "autocorr.h"
#include "welford.h"
#include "pointset.h"
#include "pointset2d.h"
#include "spectrum2d.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The format version this build writes and the only one it reads. */
#define MCS_IO_VERSION 1u

/* Bytes of the fixed header, and of the trailing CRC-32. */
#define MCS_IO_HEADER_BYTES 32u
#define MCS_IO_CRC_BYTES 4u

/* Most shape words a record may carry (N for the 1D accumulators; room for
 * N1, N2, a frequency cutoff and the like for later kinds). */
#define MCS_IO_MAX_SHAPE 8u

/* Largest trial count a record may hold: 2^53, the last count that a double
 * (the 1/count and na nb / n of every merge) still represents exactly. */
#define MCS_IO_MAX_COUNT (UINT64_C(1) << 53)

/* Largest magnitude of a payload value: 2^500, about 3.3e150. No run comes
 * near it (a sum of s_n^2 over 2^53 trials reaches it only for s_n ~ 1e67),
 * and below it every read-out of a loaded object -- sums of up to 2^40 values
 * and products of two -- is finite, so a crafted record cannot make one
 * overflow. */
#define MCS_IO_MAX_MAGNITUDE 3.273390607896142e+150

/* Object kinds. Numbers are part of the format: never reuse or renumber; a
 * new accumulator takes the next free number and needs no version change. */
typedef enum {
    MCS_IO_KIND_SPECTRUM = 1, /* mcs_spectrum, shape [N] */
    MCS_IO_KIND_MOMENT = 2,   /* mcs_moment, shape [N] */
    MCS_IO_KIND_AUTOCORR = 3, /* mcs_autocorr, shape [N] */
    MCS_IO_KIND_WELFORD = 4,   /* mcs_welford, shape [] */
    MCS_IO_KIND_POINTSET = 5,  /* mcs_pointset, shape [F] */
    MCS_IO_KIND_POINTSET2D = 6, /* mcs_pointset2d, shape [F] */
    MCS_IO_KIND_SPECTRUM2D = 7 /* mcs_spectrum2d, shape [N1, N2] */
} mcs_io_kind;

/* What mcs_io_peek reads from a header. */
typedef struct {
    uint32_t version;                   /* format version (MCS_IO_VERSION) */
    uint32_t kind;                      /* an mcs_io_kind, or a kind this build does not know */
    uint32_t shape_len;                 /* shape words in use, <= MCS_IO_MAX_SHAPE */
    uint64_t shape[MCS_IO_MAX_SHAPE];   /* shape words; the rest 0 */
    uint64_t count;                     /* trials (values, for welford) accumulated */
    uint64_t payload_len;               /* binary64 values in the payload */
    size_t size;                        /* bytes of the whole record */
} mcs_io_info;

/* Reads and checks the framing of the record in buf[len]: magic, version,
 * lengths (the record must fill buf exactly) and the CRC-32. It does not look
 * at the kind, the shape or the values, so it also describes records of kinds
 * this build does not know. MCS_ERR_NULL, MCS_ERR_MAGIC, MCS_ERR_TRUNCATED,
 * MCS_ERR_VERSION, MCS_ERR_FORMAT (shape_len above MCS_IO_MAX_SHAPE, or bytes
 * after the record), MCS_ERR_CHECKSUM. *info untouched on error. */
mcs_status mcs_io_peek(size_t len, const void *buf, mcs_io_info *info);

/* Name of a kind ("spectrum", "moment", "autocorr", "welford", "pointset",
 * "pointset2d", "spectrum2d"), or "unknown". */
const char *mcs_io_kind_str(uint32_t kind);

/* CRC-32 (IEEE 802.3, reflected, as zlib's crc32) of data[len]; data may be
 * NULL when len is 0. MCS_ERR_NULL. *crc untouched on error. */
mcs_status mcs_io_crc32(size_t len, const void *data, uint32_t *crc);

/* Saving, one call per kind: with buf == NULL, *len gets the record size and
 * nothing else happens (cap ignored); otherwise the record is written to
 * buf[0 .. size) and *len gets its size. MCS_ERR_NULL (acc, len),
 * MCS_ERR_UNINIT, MCS_ERR_SPACE (cap < size), MCS_ERR_NOT_FINITE and
 * MCS_ERR_INVARIANT (an object load would refuse, e.g. overflowed sums or a
 * count above MCS_IO_MAX_COUNT). buf and *len untouched on error. */
mcs_status mcs_io_save_spectrum(const mcs_spectrum *acc, size_t cap, void *buf, size_t *len);
mcs_status mcs_io_save_moment(const mcs_moment *acc, size_t cap, void *buf, size_t *len);
mcs_status mcs_io_save_autocorr(const mcs_autocorr *acc, size_t cap, void *buf, size_t *len);
mcs_status mcs_io_save_welford(const mcs_welford *acc, size_t cap, void *buf, size_t *len);
mcs_status mcs_io_save_pointset(const mcs_pointset *acc, size_t cap, void *buf, size_t *len);
mcs_status mcs_io_save_pointset2d(const mcs_pointset2d *acc, size_t cap, void *buf, size_t *len);
mcs_status mcs_io_save_spectrum2d(const mcs_spectrum2d *acc, size_t cap, void *buf, size_t *len);

/* Loading, one call per kind: buf[len] must hold exactly one record of that
 * kind. On success *acc is as its init for the record's N left it (a spectrum
 * on the AUTO path) plus the record's statistics, so it merges and reads out
 * like the object that was saved. Statuses, in the order they are checked:
 * MCS_ERR_NULL, the framing errors of mcs_io_peek, MCS_ERR_KIND (another or
 * an unknown kind), MCS_ERR_FORMAT (shape or payload length not what the kind
 * needs), MCS_ERR_N_RANGE (N, N1 or N2 = 0 or above this build's capacity),
 * MCS_ERR_FREQ_RANGE (a point-set cutoff F = 0 or above this build's),
 * MCS_ERR_NOT_FINITE (a NaN or infinite value), MCS_ERR_INVARIANT (a count
 * above MCS_IO_MAX_COUNT, data with a zero count, spread with one trial, a
 * negative M2, mean power, sum of weights or of weight products, a value
 * above MCS_IO_MAX_MAGNITUDE).
 * *acc byte-identical on error. */
mcs_status mcs_io_load_spectrum(mcs_spectrum *acc, size_t len, const void *buf);
mcs_status mcs_io_load_moment(mcs_moment *acc, size_t len, const void *buf);
mcs_status mcs_io_load_autocorr(mcs_autocorr *acc, size_t len, const void *buf);
mcs_status mcs_io_load_welford(mcs_welford *acc, size_t len, const void *buf);
mcs_status mcs_io_load_pointset(mcs_pointset *acc, size_t len, const void *buf);
mcs_status mcs_io_load_pointset2d(mcs_pointset2d *acc, size_t len, const void *buf);
mcs_status mcs_io_load_spectrum2d(mcs_spectrum2d *acc, size_t len, const void *buf);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_IO_H */
