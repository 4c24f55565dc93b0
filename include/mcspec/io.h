/* Save and load accumulators to and from caller buffers (docs/format.md).
 *
 * A record is a fixed 32-byte header (magic, format version, kind, shape
 * length, trial count, payload length), the shape words, the payload as
 * little-endian IEEE-754 binary64 holding only the entries in use, in
 * version 2 a provenance block (where the trials came from: a pattern run
 * and its streams, or the input files), and a CRC-32 of everything before
 * it. All fields are written byte by byte, so a
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
 * Provenance: mcs_io_save_* write a record without it (version 1, the bytes
 * of every earlier build); mcs_io_set_provenance adds a block to a saved
 * record (version 2), mcs_io_peek_provenance reads it back, and
 * mcs_io_provenance_merge gives the provenance of a merge, refusing the
 * merges that would count trials twice or mix patterns. Loading ignores the
 * block (after checking it): an accumulator holds statistics, not history.
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
#include "pcf.h"
#include "integrate.h"
#include "discrepancy.h"
#include "spacing.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The newest format version, which this build reads with every earlier one:
 * 2 is version 1 plus a provenance block. A record without provenance is
 * written as version 1, so it loads in builds that know no other. */
#define MCS_IO_VERSION 2u

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
    MCS_IO_KIND_SPECTRUM2D = 7, /* mcs_spectrum2d, shape [N1, N2] */
    MCS_IO_KIND_PCF = 8,        /* mcs_pcf, shape [dim, estimator, B, radius, sigma]
                                 * (radius and sigma as the bits of their binary64) */
    MCS_IO_KIND_INTEGRATE = 9,  /* mcs_integrate, shape [family, dim] */
    MCS_IO_KIND_DISCREPANCY = 10, /* mcs_discrepancy, shape [dim] */
    MCS_IO_KIND_SPACING = 11    /* mcs_spacing, shape [dim] */
} mcs_io_kind;

/* What mcs_io_peek reads from a header. */
typedef struct {
    uint32_t version;                   /* format version: 1, or 2 (with provenance) */
    uint32_t kind;                      /* an mcs_io_kind, or a kind this build does not know */
    uint32_t shape_len;                 /* shape words in use, <= MCS_IO_MAX_SHAPE */
    uint64_t shape[MCS_IO_MAX_SHAPE];   /* shape words; the rest 0 */
    uint64_t count;                     /* trials (values, for welford) accumulated */
    uint64_t payload_len;               /* binary64 values in the payload */
    size_t size;                        /* bytes of the whole record */
} mcs_io_info;

/* Reads and checks the framing of the record in buf[len]: magic, version,
 * lengths (the record must fill buf exactly), the CRC-32 and, in version 2,
 * the provenance block. It does not look at the kind, the shape or the
 * values, so it also describes records of kinds this build does not know.
 * MCS_ERR_NULL, MCS_ERR_MAGIC, MCS_ERR_TRUNCATED, MCS_ERR_VERSION,
 * MCS_ERR_FORMAT (shape_len above MCS_IO_MAX_SHAPE, bytes after the record,
 * a provenance block that breaks the rules), MCS_ERR_CHECKSUM. *info
 * untouched on error. */
mcs_status mcs_io_peek(size_t len, const void *buf, mcs_io_info *info);

/* Name of a kind ("spectrum", "moment", "autocorr", "welford", "pointset",
 * "pointset2d", "spectrum2d", "pcf", "integrate", "discrepancy", "spacing"),
 * or "unknown". */
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
mcs_status mcs_io_save_pcf(const mcs_pcf *acc, size_t cap, void *buf, size_t *len);
mcs_status mcs_io_save_integrate(const mcs_integrate *acc, size_t cap, void *buf, size_t *len);
mcs_status mcs_io_save_discrepancy(const mcs_discrepancy *acc, size_t cap, void *buf,
                                   size_t *len);
mcs_status mcs_io_save_spacing(const mcs_spacing *acc, size_t cap, void *buf, size_t *len);
/* The point-set, 2D and pcf saves also return MCS_ERR_ALIAS for a buf that
 * overlaps the object's header or buffer (they read it while writing buf). */

/* Loading, one call per kind: buf[len] must hold exactly one record of that
 * kind. On success *acc is as its init for the record's N left it (a spectrum
 * on the AUTO path) plus the record's statistics, so it merges and reads out
 * like the object that was saved. Statuses, in the order they are checked:
 * MCS_ERR_NULL, the framing errors of mcs_io_peek, MCS_ERR_KIND (another or
 * an unknown kind), MCS_ERR_FORMAT (shape or payload length not what the kind
 * needs), MCS_ERR_N_RANGE (N, N1 or N2 = 0 or above this build's capacity),
 * MCS_ERR_FREQ_RANGE (a point-set cutoff F = 0 or above its cap),
 * MCS_ERR_NOT_FINITE (a NaN or infinite value), MCS_ERR_INVARIANT (a count
 * above MCS_IO_MAX_COUNT, data with a zero count, spread with one trial, a
 * negative M2, mean power, sum of weights or of weight products, a value
 * above MCS_IO_MAX_MAGNITUDE).
 * *acc byte-identical on error. */
mcs_status mcs_io_load_spectrum(mcs_spectrum *acc, size_t len, const void *buf);
mcs_status mcs_io_load_moment(mcs_moment *acc, size_t len, const void *buf);
mcs_status mcs_io_load_autocorr(mcs_autocorr *acc, size_t len, const void *buf);
mcs_status mcs_io_load_welford(mcs_welford *acc, size_t len, const void *buf);

/* The fixed-size measure accumulators (integrate.h, discrepancy.h,
 * spacing.h), as above, and MCS_ERR_DOMAIN (a family, or a dim, that no
 * init takes) before the values are read. MCS_ERR_INVARIANT also for what
 * the measure's own state check refuses (Welford states no adds give, counts
 * that differ where they must agree, k_min above k_max) and for values out
 * of the measure's range (docs/format.md lists them per kind). */
mcs_status mcs_io_load_integrate(mcs_integrate *acc, size_t len, const void *buf);
mcs_status mcs_io_load_discrepancy(mcs_discrepancy *acc, size_t len, const void *buf);
mcs_status mcs_io_load_spacing(mcs_spacing *acc, size_t len, const void *buf);

/* The objects that live over caller memory (pointset.h, pointset2d.h,
 * spectrum2d.h) are loaded over a buffer mem[bytes] the caller passes, as
 * their init takes it: *acc is then as the init for the record's shape
 * (and flags, 0 or MCS_POINTSET_DIRECT_ONLY, for the point sets) left it,
 * over mem, plus the record's statistics (path AUTO, wrap off). Statuses as
 * above, with MCS_ERR_NULL for mem, MCS_ERR_DOMAIN (an unknown flag) before
 * the record's, and after them MCS_ERR_SPACE (bytes below what the record's
 * object needs: mcs_io_load_size) and MCS_ERR_ALIAS (mem, *acc and buf
 * overlapping). *acc and mem byte-identical on error. Records of these
 * kinds written by builds whose objects had compile-time capacities have
 * the same layout (shape [F], or [N1, N2]) and load as any other. */
mcs_status mcs_io_load_pointset(mcs_pointset *acc, unsigned flags, void *mem, size_t bytes,
                                size_t len, const void *buf);
mcs_status mcs_io_load_pointset2d(mcs_pointset2d *acc, unsigned flags, void *mem, size_t bytes,
                                  size_t len, const void *buf);
mcs_status mcs_io_load_spectrum2d(mcs_spectrum2d *acc, void *mem, size_t bytes, size_t len,
                                  const void *buf);

/* The pair correlation (pcf.h) over mem[bytes] as mcs_pcf_init takes it:
 * *acc is then as mcs_pcf_init for the record's dim, estimator, bins, radius
 * and sigma left it over mem, plus the record's statistics. Statuses as the
 * loads above, with MCS_ERR_DOMAIN (a dim, estimator, radius or sigma no
 * init takes) beside MCS_ERR_N_RANGE (B), and MCS_ERR_INVARIANT also for a
 * k_min below 2, a set size whose cutoff passes 1/2 (no add takes it) and an
 * RDF mean above what K (K - 1) / 2 pairs in one ring give. */
mcs_status mcs_io_load_pcf(mcs_pcf *acc, void *mem, size_t bytes, size_t len, const void *buf);

/* Bytes of caller memory the load of the record in buf[len] needs for its
 * object, into *bytes: the object's size query for the record's shape (and
 * flags, for the point sets; ignored by the other kinds), 0 for the kinds
 * whose objects hold their own arrays (spectrum, moment, autocorr,
 * welford, integrate, discrepancy, spacing). Reads the framing
 * (mcs_io_peek) and the shape, not the values.
 * MCS_ERR_NULL, MCS_ERR_DOMAIN (an unknown flag; a pcf shape word no init
 * takes), the framing errors of mcs_io_peek, MCS_ERR_KIND (a kind this
 * build does not know), MCS_ERR_FORMAT (a shape of the wrong length),
 * MCS_ERR_FREQ_RANGE and MCS_ERR_N_RANGE (a shape beyond the caps). *bytes
 * untouched on error. */
mcs_status mcs_io_load_size(size_t len, const void *buf, unsigned flags, size_t *bytes);

/* ---- Provenance (docs/format.md, "Provenance") ---------------------------- */

/* Capacities of a provenance, part of the format (not build options): the
 * stream ranges of a pattern record, the inputs of a point-set record, and
 * the bytes of a pattern's and an input's name, each with its NUL. */
#define MCS_IO_PROV_MAX_RANGES 32u
#define MCS_IO_PROV_MAX_INPUTS 16u
#define MCS_IO_PROV_PATTERN_BYTES 16u
#define MCS_IO_PROV_NAME_BYTES 64u

/* Bytes of the largest provenance block (16 inputs of 80 bytes after an
 * 8-byte head; a pattern block is at most 64 + 24 * 32 = 832): a record
 * with provenance is at most this much longer than mcs_io_save_* wrote it. */
#define MCS_IO_PROV_MAX_BYTES (8u + 80u * MCS_IO_PROV_MAX_INPUTS)

/* Where a record's trials came from. Numbers are part of the format. */
typedef enum {
    MCS_IO_SOURCE_NONE = 0,    /* not said: a version 1 record */
    MCS_IO_SOURCE_PATTERN = 1, /* drawn from a named pattern, a run split into streams */
    MCS_IO_SOURCE_POINTS = 2   /* point sets read from input files */
} mcs_io_source;

/* Streams first .. end - 1 of the run with this seed: stream i drew its
 * trials from PCG32 seeded (initstate = seed, initseq = i), so two records
 * holding the same (seed, i) hold the same trials. */
typedef struct {
    uint64_t seed;  /* the run's seed */
    uint64_t first; /* first stream, < end */
    uint64_t end;   /* one past the last stream, <= the run's streams */
} mcs_io_streams;

/* One input file of a point-set record. */
typedef struct {
    uint32_t crc;   /* mcs_io_crc32 of the file's bytes */
    uint64_t bytes; /* its length in bytes */
    char name[MCS_IO_PROV_NAME_BYTES]; /* its name as the writer gives it (mcspec: the path,
                                        * shortened to its last 60 bytes after "..."),
                                        * NUL-terminated; may be empty */
} mcs_io_input;

/* A record's provenance. For MCS_IO_SOURCE_PATTERN the fields up to range[]
 * (the rest 0 when read), for MCS_IO_SOURCE_POINTS ninputs and input[] (the
 * rest 0). The lists are in their canonical order, which makes the union of
 * a set of records one value whatever the order of their merges:
 * - range[]: sorted by (seed, first); two ranges of one seed neither overlap
 *   nor touch (touching ones are one range), so the P streams of a run
 *   merged in any order are the one range [0, P);
 * - input[]: sorted by crc, no crc twice.
 * Every call below checks these rules and the field rules given here
 * (MCS_ERR_FORMAT). */
typedef struct {
    uint32_t source;                         /* an mcs_io_source */
    /* MCS_IO_SOURCE_PATTERN: what was drawn, and how the run was split */
    uint32_t dim;                            /* 1 (binned, N bins) or 2 (points in the square) */
    char pattern[MCS_IO_PROV_PATTERN_BYTES]; /* its name ("stratified", "jittered"):
                                              * printable ASCII, no space, NUL-terminated */
    uint64_t n;                              /* bins N, >= 1 when dim = 1 */
    uint64_t k;                              /* samples per trial K, >= 1 */
    uint32_t importance;                     /* 1: warped by an importance function; 0: none */
    uint32_t importance_crc;                 /* with importance, the CRC-32 of its N weights as
                                              * mcspec read them, each as little-endian
                                              * binary64; else 0 */
    uint64_t streams;                        /* P >= 1, the streams the run was split into */
    uint64_t trials;                         /* T >= P, the trials of the whole run (stream i
                                              * took floor(T/P), one more for i < T mod P) */
    uint32_t nranges;                        /* 1 .. MCS_IO_PROV_MAX_RANGES */
    mcs_io_streams range[MCS_IO_PROV_MAX_RANGES]; /* the streams the record holds */
    /* MCS_IO_SOURCE_POINTS */
    uint32_t ninputs;                        /* 1 .. MCS_IO_PROV_MAX_INPUTS */
    mcs_io_input input[MCS_IO_PROV_MAX_INPUTS]; /* the files the record's point sets came from */
} mcs_io_provenance;

/* Reads the provenance of the record in buf[len] into *prov: its block, or,
 * for a version 1 record, source MCS_IO_SOURCE_NONE and every field 0. The
 * framing is checked as mcs_io_peek does (the kind and values are not).
 * MCS_ERR_NULL and the statuses of mcs_io_peek. *prov untouched on error. */
mcs_status mcs_io_peek_provenance(size_t len, const void *buf, mcs_io_provenance *prov);

/* Bytes the block of prov adds to a record (0 for MCS_IO_SOURCE_NONE): a
 * record of len bytes from mcs_io_save_* needs len + *bytes with it.
 * MCS_ERR_NULL, MCS_ERR_FORMAT (prov breaks the rules above). *bytes
 * untouched on error. */
mcs_status mcs_io_provenance_bytes(const mcs_io_provenance *prov, size_t *bytes);

/* Gives the record in buf[*len] (either version, as mcs_io_save_* or this
 * call wrote it) the provenance prov, in place: the block it had, if any, is
 * replaced by prov's, the version becomes 2 and the CRC is rewritten; with
 * source MCS_IO_SOURCE_NONE the block is removed and the record is version 1
 * again, byte for byte as saved. *len gets the new size; cap is the bytes
 * buf holds. The statuses of mcs_io_peek for buf[*len], MCS_ERR_NULL,
 * MCS_ERR_FORMAT (prov breaks the rules), MCS_ERR_SPACE (cap below the new
 * size). buf and *len untouched on error. */
mcs_status mcs_io_set_provenance(const mcs_io_provenance *prov, size_t cap, void *buf,
                                 size_t *len);

/* dst <- the provenance of the merge of a record of dst with one of src: the
 * union of their stream ranges (pattern) or inputs (points), in canonical
 * order, so every order and tree of merges of a set of records gives the
 * same provenance. Records of different seeds of one run may merge; a
 * caller wanting one seed compares the seeds itself. MCS_ERR_NULL,
 * MCS_ERR_FORMAT (dst or src breaks the rules), MCS_ERR_KIND (different
 * sources, or MCS_IO_SOURCE_NONE: the union of an unknown is not known),
 * MCS_ERR_MISMATCH (another pattern or run: dim, pattern, n, k, importance,
 * importance_crc, streams or trials differ), MCS_ERR_ALIAS (the same trials
 * in both: a stream of one seed, or an input crc, in dst and src; so also
 * dst == src), MCS_ERR_SPACE (the union needs more than
 * MCS_IO_PROV_MAX_RANGES ranges or MCS_IO_PROV_MAX_INPUTS inputs). *dst
 * untouched on error. */
mcs_status mcs_io_provenance_merge(mcs_io_provenance *dst, const mcs_io_provenance *src);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_IO_H */
