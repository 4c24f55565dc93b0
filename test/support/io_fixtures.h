/* Shared by the record tests (test_io.c, test_io_corrupt.c): one accumulator
 * of every kind filled from seeded trials, a table that drives a check over
 * every kind, and an independent writer of record bytes (its own bitwise
 * CRC-32 and little-endian fields) for hand-built headers. */
#ifndef IO_FIXTURES_H
#define IO_FIXTURES_H

#include <stddef.h>
#include <stdint.h>

#include "mcspec.h"

/* Payload values of a spectrum record (docs/format.md): units, open_count,
 * open_work, five half spectra, open_sum[N], open_pairs[1 .. 2N). */
#define IO_SPECTRUM_VALUES(n) (3u + 5u * ((n) / 2u + 1u) + 3u * (n) - 1u)

/* Record sizes by docs/format.md. */
#define IO_SPECTRUM_BYTES(n) (60u + 40u * ((n) / 2u + 1u) + 24u * (n))
#define IO_MOMENT_BYTES(n) (44u + 8u * (IO_MOMENT_VALUES(n)))
/* counts, shift, sum_d, lo_d, two upper triangles, batch_s, batch_d, batch_w */
#define IO_MOMENT_VALUES(n) (2u + 5u * (n) + (n) * ((n) + 1u) + (n) * (n))
#define IO_AUTOCORR_BYTES(n) (44u + 8u * (2u * (n) + 2u * ((n) / 2u + 1u) + 2u))
#define IO_WELFORD_BYTES 68u
#define IO_POINTSET_BYTES(f) (44u + 16u * ((f) + 1u))
#define IO_POINTSET2D_BYTES(f) (44u + 32u * ((f) + 1u) * ((f) + 1u))
#define IO_SPECTRUM2D_BYTES(n1, n2) (52u + 40u * (n1) * ((n2) / 2u + 1u))

/* The largest shapes of the fixtures' objects over caller memory (their
 * caps are far larger: the fixtures' buffers are static). The 2D point set
 * is made without the NUFFT (MCS_POINTSET_DIRECT_ONLY), the 1D one with. */
#define IO_FIX_FREQ_1D 1024u
#define IO_FIX_FREQ_2D 64u
#define IO_FIX_SIDE 64u
#define IO_FIX_FLAGS_2D MCS_POINTSET_DIRECT_ONLY

#define IO_MAX2(a, b) ((a) > (b) ? (a) : (b))
/* Room for a record of every kind one size past this build's capacities
 * (the fixtures' shapes for the objects over caller memory). */
#define IO_REC_MAX                                                                     \
    IO_MAX2(IO_MAX2(IO_MAX2(IO_SPECTRUM_BYTES(MCS_MAX_N + 2u), IO_AUTOCORR_BYTES(MCS_MAX_N + 2u)), \
                    IO_MOMENT_BYTES(MCS_MAX_COV_N + 1u)),                              \
            IO_MAX2(IO_POINTSET2D_BYTES(IO_FIX_FREQ_2D + 1u),                        \
                    IO_MAX2(IO_SPECTRUM2D_BYTES(IO_FIX_SIDE + 1u, IO_FIX_SIDE + 1u),   \
                            IO_POINTSET_BYTES(IO_FIX_FREQ_1D + 1u))))

/* The objects over caller memory, each with its buffer (the whole is what
 * a byte comparison of "the object" compares). */
typedef struct {
    mcs_pointset acc;
    _Alignas(64) unsigned char mem[MCS_POINTSET_SIZE(IO_FIX_FREQ_1D)];
} io_pointset;
typedef struct {
    mcs_pointset2d acc;
    _Alignas(64) unsigned char mem[MCS_POINTSET2D_SIZE_DIRECT(IO_FIX_FREQ_2D)];
} io_pointset2d;
typedef struct {
    mcs_spectrum2d acc;
    _Alignas(64) unsigned char mem[MCS_SPECTRUM2D_SIZE(IO_FIX_SIDE, IO_FIX_SIDE)];
} io_spectrum2d;

/* One accumulator of each kind. */
typedef struct {
    mcs_spectrum spec;
    mcs_moment mom;
    mcs_autocorr ac;
    mcs_welford wf;
    io_pointset ps;
    io_pointset2d ps2;
    io_spectrum2d sp2;
} io_set;


typedef struct {
    const char *name;
    mcs_io_kind kind;
    size_t offset, obj_size, shape_len;
    mcs_status (*load)(void *dst, size_t len, const void *buf);
    mcs_status (*save)(const void *src, size_t cap, void *buf, size_t *len);
    mcs_status (*merge)(void *dst, const void *src);
} io_kind_ops;

#define IO_NKINDS 7u
extern const io_kind_ops io_kinds[IO_NKINDS];

/* The kind's member of s. */
void *io_obj(io_set *s, const io_kind_ops *o);

/* Fills every member of s from `trials` seeded trials: the binned kinds over
 * n bins (moment at min(n, MCS_MAX_COV_N)), the point sets with cutoffs
 * min(n, IO_FIX_FREQ_1D or _2D), the 2D spectrum over min(n, IO_FIX_SIDE) x
 * min(n/2 + 1, IO_FIX_SIDE) bins. Fails the test on any library error. */
void io_fill(io_set *s, size_t n, size_t trials, uint64_t seed);

/* Fails the test unless a and b, objects of kind o, hold the same: their
 * bytes, or for the objects over caller memory (whose headers point into
 * their own buffers) their records and settings. */
void io_assert_same(const io_kind_ops *o, const void *a, const void *b, const char *what);

/* Saves src of kind o into buf (IO_REC_MAX bytes) after checking that the
 * size query agrees; returns the size. */
size_t io_save(const io_kind_ops *o, const void *src, uint8_t *buf);

/* Loads buf[len] into dst's member of kind o and fails the test unless the
 * status is want and dst is byte-identical to before. */
void io_expect_refused(const io_kind_ops *o, io_set *dst, const io_set *before, mcs_status want,
                       size_t len, const uint8_t *buf, const char *what, size_t at);

/* The independent writer. */
uint32_t io_ref_crc(const uint8_t *p, size_t len);
void io_put_le(uint8_t *p, uint64_t v, size_t bytes);
void io_put_f64(uint8_t *p, double v);
uint64_t io_get_le(const uint8_t *p, size_t bytes);
/* Rewrites the CRC of a record of len bytes after an edit. */
void io_recrc(uint8_t *p, size_t len);
/* A record with this header and np values (values[] or zeros); its size. */
size_t io_build(uint8_t *p, uint32_t version, uint32_t kind, uint32_t s, const uint64_t *shape,
                uint64_t count, uint64_t np, const double *values);
/* Offset of payload value i in a record of s shape words. */
size_t io_payload_at(size_t s, size_t i);

#endif /* IO_FIXTURES_H */
