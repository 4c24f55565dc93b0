/* Private to io.c and io_kinds.c: the record codec shared by every kind.
 *
 * A kind describes its payload as a layout: the payload length for its
 * shape and a few contiguous ranges, each with the rules its values obey
 * (io.c checks them the same way on save and on load). Its emit function
 * feeds the object's values, in payload order, to a sink that either checks
 * them or writes them; its load code decodes them in the same order. */
#ifndef MCSPEC_IO_INTERNAL_H
#define MCSPEC_IO_INTERNAL_H

#include <stddef.h>
#include <stdint.h>
#include "mcspec/io.h"

/* Rules a payload value obeys besides being finite (every value, with a zero
 * count, is 0: an empty accumulator holds nothing). */
#define IO_RULE_NONNEG 1u /* >= 0: a sum of (products of) weights, a mean power, an M2 */
#define IO_RULE_SPREAD 2u /* a sum of deviations from the mean: 0 with fewer than 2 trials */

#define IO_MAX_RANGES 8u

typedef struct {
    size_t first, len;
    unsigned rules;
} io_range;

typedef struct {
    uint32_t kind;
    uint32_t shape_len;
    uint64_t shape[MCS_IO_MAX_SHAPE];
    size_t payload_len;                /* binary64 values */
    size_t nranges;
    io_range ranges[IO_MAX_RANGES];    /* contiguous, covering the payload */
} io_layout;

/* Empties *lay for a kind with shape_len shape words (shape may be NULL when
 * there are none); ranges then follow with mcs_io_add_range. */
void mcs_io_layout_start(io_layout *lay, uint32_t kind, uint32_t shape_len,
                         const uint64_t *shape);

/* Appends a range of len values obeying rules to the payload. */
void mcs_io_add_range(io_layout *lay, size_t len, unsigned rules);

/* Fills *lay for a shape (shape_len words already checked); MCS_ERR_N_RANGE
 * when the shape is beyond this build's capacities. */
typedef mcs_status (*io_layout_fn)(const uint64_t *shape, io_layout *lay);

/* Receives payload values in order: checks them (out == NULL) or writes them. */
typedef struct {
    const io_layout *lay;
    uint64_t count;
    uint8_t *out;
    size_t index, range;
    int not_finite, broken;
} io_sink;

void mcs_io_sink_put(io_sink *sink, double v);

typedef void (*io_emit_fn)(const void *obj, io_sink *sink);

/* The value at payload index i (little-endian binary64). */
double mcs_io_get_f64(const uint8_t *payload, size_t i);

/* a[0 .. len) to the sink, in order; and back from payload[first ..). */
void mcs_io_put_array(io_sink *sink, const double *a, size_t len);
void mcs_io_get_array(double *a, const uint8_t *payload, size_t first, size_t len);

/* What a kind's save passes: the object, its emit function and its count. */
typedef struct {
    const void *obj;
    io_emit_fn emit;
    uint64_t count;
} io_source;

/* Save driver: checks the values emit gives, then (buf != NULL) writes the
 * record. Statuses as the mcs_io_save_* calls, after UNINIT. */
mcs_status mcs_io_save_record(const io_layout *lay, const io_source *src, size_t cap, void *buf,
                   size_t *len);

/* A kind as its load sees it: number, shape words, layout function. */
typedef struct {
    uint32_t kind;
    uint32_t shape_len;
    io_layout_fn layout;
} io_kind;

/* A record that passed every check, ready to commit. */
typedef struct {
    io_layout lay;
    const uint8_t *payload;
    uint64_t count;
} io_record;

/* Load checks: framing, kind, shape (through the kind's layout), values.
 * *rec written only on MCS_OK. */
mcs_status mcs_io_load_check(const io_kind *kind, size_t len, const void *buf, io_record *rec);

#endif /* MCSPEC_IO_INTERNAL_H */
