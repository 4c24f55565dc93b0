/* Private to the io sources: the record codec shared by every kind.
 *
 * A kind describes its payload as a table of fields, in payload order: where
 * each array (or scalar) sits in the object, how many of its values are
 * written (a few sizes that follow from the shape) and the rules they obey.
 * One walker (io.c) reads that table to check an object's values, write
 * them, check a payload's values and load them back, so save, load and
 * validation cannot disagree about the order. */
#ifndef MCSPEC_IO_INTERNAL_H
#define MCSPEC_IO_INTERNAL_H

#include <stddef.h>
#include <stdint.h>
#include "mcspec/io.h"

/* Little-endian fields, byte by byte: neither the host's byte order nor its
 * struct layout reaches the bytes. */
static inline void io_put_le(uint8_t *p, uint64_t v, size_t bytes)
{
    for (size_t i = 0; i < bytes; ++i)
        p[i] = (uint8_t)(v >> (8u * i));
}

static inline uint64_t io_get_le(const uint8_t *p, size_t bytes)
{
    uint64_t v = 0u;
    for (size_t i = 0; i < bytes; ++i)
        v |= (uint64_t)p[i] << (8u * i);
    return v;
}

/* Rules a payload value obeys besides being finite (every value, with a zero
 * count, is 0: an empty accumulator holds nothing). */
#define IO_RULE_NONNEG 1u /* >= 0: a sum of (products of) weights, a mean power, an M2 */
#define IO_RULE_SPREAD 2u /* a sum of deviations from the mean: 0 with fewer than 2 trials */
#define IO_RULE_M2 (IO_RULE_NONNEG | IO_RULE_SPREAD) /* a sum of squared deviations */

/* Sizes a kind derives from its shape, named by index in its fields;
 * size 0 (IO_ONE) is always 1, for scalars and single rows. */
#define IO_MAX_DIMS 4u
#define IO_ONE 0u

/* How a field's values are laid out in the object. */
#define IO_AS_ROWS 0u  /* rows of len doubles, stride doubles apart */
#define IO_AS_COUNT 1u /* one uint64_t, stored as a double (exact: at most 2^53) */
#define IO_AS_UPPER 2u /* upper triangle of a len x len array, row by row; the
                        * load mirrors it into the lower one (exactly symmetric) */
#define IO_AS_SIZE 3u  /* one size_t, stored as a double (exact: at most 2^53 is allowed) */
#define IO_AS_POINTED 4u /* rows as IO_AS_ROWS, at the double * member the offset
                          * locates (an array in the caller's buffer: mcs_pcf) */

#define IO_MAX_FIELDS 10u

typedef struct {
    size_t offset;        /* of the first value in the object (offsetof) */
    unsigned char as;     /* IO_AS_* */
    unsigned char rows, len, stride; /* indices into the kind's sizes */
    unsigned rules;       /* IO_RULE_* */
} io_field;

/* The fields a kind's table lists (member of type t, sizes by index). */
#define IO_COUNT(t, member, rules) {offsetof(t, member), IO_AS_COUNT, IO_ONE, IO_ONE, IO_ONE, rules}
#define IO_ARRAY(t, member, len, rules) {offsetof(t, member), IO_AS_ROWS, IO_ONE, len, IO_ONE, rules}
#define IO_GRID(t, member, rows, len, stride, rules) \
    {offsetof(t, member), IO_AS_ROWS, rows, len, stride, rules}
#define IO_UPPER(t, member, n, rules) {offsetof(t, member), IO_AS_UPPER, IO_ONE, n, n, rules}
#define IO_SIZE(t, member, rules) {offsetof(t, member), IO_AS_SIZE, IO_ONE, IO_ONE, IO_ONE, rules}
#define IO_POINTED(t, member, len, rules) \
    {offsetof(t, member), IO_AS_POINTED, IO_ONE, len, IO_ONE, rules}

struct io_values;

/* A kind: its number and shape words, how its sizes follow from the shape
 * (MCS_ERR_N_RANGE or MCS_ERR_FREQ_RANGE for a shape beyond this build's
 * capacities, MCS_ERR_DOMAIN for a shape word no init takes), where the shape
 * words sit in the object (size_t members; or, when shape_of is not NULL,
 * what it reads from the object: shape words of other types), the
 * object's count (MCS_ERR_UNINIT), init and count member, an optional check of invariants
 * beyond the rules (nonzero when they hold), and the fields. */
typedef struct {
    uint32_t kind;
    uint32_t shape_len;
    mcs_status (*sizes)(const uint64_t *shape, size_t *size);
    size_t shape_at[MCS_IO_MAX_SHAPE];
    mcs_status (*count)(const void *obj, uint64_t *count);
    mcs_status (*init)(void *obj, const uint64_t *shape);
    size_t count_at; /* the object's uint64_t count, set last by a load */
    int (*valid)(const struct io_values *values, uint64_t count);
    size_t nfields;
    io_field fields[IO_MAX_FIELDS];
    void (*shape_of)(const void *obj, uint64_t *shape);
} io_kind;

/* The payload values of one record, read from the object being saved
 * (payload == NULL) or from the payload being loaded. */
typedef struct io_values {
    const io_kind *kind;
    size_t size[IO_MAX_DIMS];
    const void *obj;
    const uint8_t *payload;
    const uint64_t *shape; /* the record's shape words (kind->shape_len of them) */
} io_values;

/* Payload value i. */
double mcs_io_value(const io_values *values, size_t i);

/* Stores every payload value of values into obj, an object of its kind (as
 * its init left it), and count into its count member: how a kind's check
 * reads a payload back as an object, to run the object's own state check. */
void mcs_io_store(const io_values *values, uint64_t count, void *obj);

/* The mcs_io_save_* and mcs_io_load_* calls for a kind: the NULL checks,
 * the object's count, the rules and the kind's invariants, framing. */
mcs_status mcs_io_save(const io_kind *kind, const void *obj, size_t cap, void *buf, size_t *len);
mcs_status mcs_io_load(const io_kind *kind, void *obj, size_t len, const void *buf);

/* ---- the objects over caller memory (io_mem.c) ----
 * A load cannot set such an object up before the record has passed every
 * check (nothing may change on error), and the walker sets it up only after
 * them, through the kind's init: so a load walks the record twice, first
 * with mcs_io_init_checked, which stops the walk once the record passed
 * (MCS_IO_CHECKED), then, once the caller's buffer is known to hold the
 * object and the object is set up over it, with mcs_io_init_ready, to store
 * the values. */

/* The dry walk's verdict: every check passed. mcs_io_load returns no such
 * status of its own before it calls init. */
#define MCS_IO_CHECKED MCS_ERR_ALIAS

/* The inits of the two walks. */
mcs_status mcs_io_init_checked(void *obj, const uint64_t *shape);
mcs_status mcs_io_init_ready(void *obj, const uint64_t *shape);

/* What the kinds over caller memory differ by. */
typedef struct {
    void (*table)(io_kind *k, const void *acc); /* acc NULL: the checking walk's */
    void *(*state)(const void *acc);            /* the head the arrays follow (NULL: acc) */
    size_t acc_size;
    size_t mem_at, bytes_at; /* offsets of the object's void *mem and size_t bytes */
    mcs_status (*count)(const void *acc, uint64_t *count);
    /* the object's size query and init for a shape (and flags) */
    mcs_status (*size)(const uint64_t *shape, unsigned flags, size_t *need);
    mcs_status (*init)(void *acc, const uint64_t *shape, unsigned flags, void *mem,
                       size_t bytes);
} io_mem_kind;

/* Their save: the object's checks, then buf against the object and its
 * buffer, then the walk. (Six arguments: a seventh would be pushed, a frame
 * gcc calls dynamic, make stack.) */
mcs_status mcs_io_save_mem(const io_mem_kind *m, const void *acc, size_t cap, void *buf,
                           size_t *len);

/* The caller's memory of a load: its buffer and the object's flags. */
typedef struct {
    void *mem;
    size_t bytes;
    unsigned flags; /* 0, or the point sets' MCS_POINTSET_DIRECT_ONLY */
} io_mem_arg;

/* Their load: the record checked by a dry walk, then the caller's buffer
 * (MCS_ERR_SPACE, MCS_ERR_ALIAS), then the object set up over it and the
 * values stored. */
mcs_status mcs_io_load_mem(const io_mem_kind *m, void *acc, const io_mem_arg *arg, size_t len,
                           const void *buf);

/* The pcf's sizes for its shape words (io_pcf.c): MCS_ERR_DOMAIN,
 * MCS_ERR_N_RANGE; *need = MCS_PCF_SIZE(B). For mcs_io_load_size. */
mcs_status mcs_io_pcf_need(const uint64_t *shape, size_t *need);

/* ---- the provenance block of a version 2 record (io_provenance.c) ----
 * It sits between the payload and the CRC; its first 4 bytes are its length. */

/* The framing of the rest bytes at p between a version 2 record's payload
 * and its CRC: MCS_ERR_TRUNCATED (no room for the length field, or fewer
 * bytes than it says), MCS_ERR_FORMAT (more bytes, or a length below the
 * block's 8-byte head). Read before the CRC, as the header's lengths are. */
mcs_status mcs_io_block_frame(const uint8_t *p, size_t rest);

/* Checks the block of `bytes` bytes at p (framed) against the rules of
 * docs/format.md and, when prov is not NULL, reads it into *prov (zeroed
 * first). MCS_ERR_FORMAT; *prov untouched on error. */
mcs_status mcs_io_block_read(const uint8_t *p, size_t bytes, mcs_io_provenance *prov);

/* Bytes of the block of prov (0 for MCS_IO_SOURCE_NONE), after checking prov
 * against the rules: MCS_ERR_FORMAT. *bytes untouched on error. */
mcs_status mcs_io_block_size(const mcs_io_provenance *prov, size_t *bytes);

/* Writes the block of prov, which mcs_io_block_size accepted, to p. */
void mcs_io_block_write(const mcs_io_provenance *prov, uint8_t *p);

#endif /* MCSPEC_IO_INTERNAL_H */
