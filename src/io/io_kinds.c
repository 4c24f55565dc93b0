/* The binned 1D accumulator kinds of the record format (docs/format.md):
 * spectrum, moment, autocorr and welford (the point-set and 2D ones are in
 * io_points.c). For each, its sizes for a shape and its table of fields in
 * payload order; io.c walks the table to save, check and load.
 *
 * Adding a kind: a new mcs_io_kind number, its sizes, count and init, a
 * field table and the two public wrappers, as below; the framing, checksum
 * and value checks of io.c need no change, nor does the version. */
#include "io_internal.h"
#include "accumulators/acc_internal.h"

#include <math.h>

/* One shape word N, 1 <= N <= max_n: sizes N and N/2 + 1. */
enum { SZ_N = 1, SZ_HALF = 2, SZ_PAIRS = 3 };

static mcs_status sizes_n(uint64_t n, uint64_t max_n, size_t *size)
{
    if (n == 0u || n > max_n)
        return MCS_ERR_N_RANGE;
    size[SZ_N] = (size_t)n;
    size[SZ_HALF] = (size_t)n / 2u + 1u;
    return MCS_OK;
}

/* ---- spectrum: counts, five half spectra k = 0..N/2, the open PAIR batch ----
 *
 * Payload: units, open_count, open_work (integers exact in a double: each is
 * at most the count, 2^53, or a sum of K (K + 1) / 2), then mean_re, mean_im,
 * m2_s, mean_pow, m2_pow over k = 0..N/2, then the open batch's open_sum[N]
 * and open_pairs[1 .. 2N) (entry 0 stands for a difference of -N, which no
 * pair has). With the open batch a loaded spectrum is the saved one: the same
 * read-outs, merges and later adds, to the bit. */

enum { SP_UNITS, SP_OPEN, SP_WORK, SP_SCALARS };

static mcs_status sizes_spectrum(const uint64_t *shape, size_t *size)
{
    mcs_status st = sizes_n(shape[0], MCS_MAX_N, size);
    if (st == MCS_OK)
        size[SZ_PAIRS] = 2u * (size_t)shape[0] - 1u;
    return st;
}

static int sp_zero(const io_values *values, size_t first, size_t len)
{
    for (size_t i = first; i < first + len; ++i)
        if (mcs_io_value(values, i) != 0.0)
            return 0;
    return 1;
}

/* The spectrum's own invariants (spectrum.c, spectrum_check), beyond the
 * rules every kind shares: whole unit and open counts with
 * units <= count - open_count and units = 0 exactly when every trial is in
 * the open batch; an open batch's work at least one pair per trial, and no
 * open batch leaving its work and sums 0; the closed statistics 0 with no
 * unit and the M2s 0 with fewer than 2 (a spread needs 2 units, not 2
 * trials). Values are finite and >= 0 here (checked first). */
/* What the add limit allows (spectrum.h: a trial's weights, so its s_n >= 0,
 * sum to at most MCS_SPECTRUM_MAX_SUM): |S_k| <= L = MCS_SPECTRUM_MAX_SUM /
 * sqrt(N) in every trial, so the means are within L and the mean powers
 * within L^2, the M2s within count (2 L)^2 and count L^4, the open sums
 * within open_count MCS_SPECTRUM_MAX_SUM and its square for pairs (a slack
 * of 2^-20 for the transform's rounding). A record beyond them holds sums no
 * trials give, and merging one could leave what no record holds (fuzz_load:
 * a mean of 5.2e120 beside an M2 of 0.15 loaded, merged into an M2 of
 * 3.5e242, and save refused it). */
static int spectrum_within_limits(const io_values *values, uint64_t count)
{
    const size_t n = values->size[SZ_N], h1 = values->size[SZ_HALF];
    const double slack = 1.0 + 0x1p-20, c = (double)count;
    const double open = mcs_io_value(values, SP_OPEN);
    const double l = MCS_SPECTRUM_MAX_SUM / sqrt((double)n) * slack;
    const double limit[5] = {l, l, c * 4.0 * l * l, l * l, c * l * l * l * l};
    for (size_t f = 0; f < 5u; ++f)
        for (size_t i = 0; i < h1; ++i)
            if (!(fabs(mcs_io_value(values, SP_SCALARS + f * h1 + i)) <= limit[f]))
                return 0;
    const double sum_limit = open * MCS_SPECTRUM_MAX_SUM * slack;
    const size_t pairs_at = SP_SCALARS + 5u * h1 + n;
    for (size_t i = 0; i < n; ++i)
        if (!(mcs_io_value(values, SP_SCALARS + 5u * h1 + i) <= sum_limit))
            return 0;
    for (size_t i = 0; i < 2u * n - 1u; ++i)
        if (!(mcs_io_value(values, pairs_at + i) <= sum_limit * MCS_SPECTRUM_MAX_SUM * slack))
            return 0;
    return 1;
}

static int spectrum_ok(const io_values *values, uint64_t count)
{
    if (!spectrum_within_limits(values, count))
        return 0;
    const size_t n = values->size[SZ_N], h1 = values->size[SZ_HALF];
    const double units = mcs_io_value(values, SP_UNITS), open = mcs_io_value(values, SP_OPEN);
    const double work = mcs_io_value(values, SP_WORK);
    if (units != floor(units) || open != floor(open) || open > (double)count)
        return 0;
    const double closed = (double)count - open; /* exact: both at most 2^53 */
    if (units > closed || (units == 0.0) != (closed == 0.0))
        return 0;
    if (open == 0.0 ? (work != 0.0 || !sp_zero(values, SP_SCALARS + 5u * h1, 3u * n - 1u))
                    : work < open)
        return 0;
    if (units == 0.0 && !sp_zero(values, SP_SCALARS, 5u * h1))
        return 0;
    return units >= 2.0 || (sp_zero(values, SP_SCALARS + 2u * h1, h1) &&
                            sp_zero(values, SP_SCALARS + 4u * h1, h1));
}

static mcs_status count_spectrum(const void *obj, uint64_t *count)
{
    return mcs_spectrum_count((const mcs_spectrum *)obj, count);
}

static mcs_status init_spectrum(void *obj, const uint64_t *shape)
{
    return mcs_spectrum_init((mcs_spectrum *)obj, (size_t)shape[0]);
}


static const io_kind kind_spectrum = {
    MCS_IO_KIND_SPECTRUM, 1u, sizes_spectrum, {offsetof(mcs_spectrum, n)},
    count_spectrum, init_spectrum, offsetof(mcs_spectrum, count), spectrum_ok, 10u,
    {IO_COUNT(mcs_spectrum, units, IO_RULE_NONNEG),
     IO_COUNT(mcs_spectrum, open_count, IO_RULE_NONNEG),
     IO_ARRAY(mcs_spectrum, open_work, IO_ONE, IO_RULE_NONNEG),
     IO_ARRAY(mcs_spectrum, mean_re, SZ_HALF, 0u),
     IO_ARRAY(mcs_spectrum, mean_im, SZ_HALF, 0u),
     IO_ARRAY(mcs_spectrum, m2_s, SZ_HALF, IO_RULE_M2),
     IO_ARRAY(mcs_spectrum, mean_pow, SZ_HALF, IO_RULE_NONNEG),
     IO_ARRAY(mcs_spectrum, m2_pow, SZ_HALF, IO_RULE_M2),
     IO_ARRAY(mcs_spectrum, open_sum, SZ_N, IO_RULE_NONNEG),
     IO_ARRAY(mcs_spectrum, open_pairs[1], SZ_PAIRS, IO_RULE_NONNEG)},
    NULL};

mcs_status mcs_io_save_spectrum(const mcs_spectrum *acc, size_t cap, void *buf, size_t *len)
{
    return mcs_io_save(&kind_spectrum, acc, cap, buf, len);
}

mcs_status mcs_io_load_spectrum(mcs_spectrum *acc, size_t len, const void *buf)
{
    return mcs_io_load(&kind_spectrum, acc, len, buf);
}

/* ---- moment: batch_count, batch_sparse, shift[N], then sum_d[N], lo_d[N]
 * and the upper triangles of sum_dd and lo_dd row by row, then the open
 * batch: batch_s[N], batch_d[N] and batch_w[N][N] whole (moment.h: sums of
 * d = s - c, c the first trial, with their Kahan compensations, and the open
 * batch of plain sums, so a loaded object is the saved one and reads out,
 * merges and adds like it, bit for bit). c is a trial's s (weights >= 0);
 * the sums of d are 0 before 2 trials. ---- */

enum { MO_BATCH, MO_SPARSE, MO_SHIFT };

/* Value i of a record's array (mcs_values_): an upper triangle's (m, q) is
 * (min, max) of its row by row storage, row m starting at m N - m (m - 1) / 2. */
static double record_at(const mcs_values_ *v, size_t i)
{
    const io_values *values = (const io_values *)v->base;
    if (v->upper != 0u) {
        const size_t n = v->upper;
        size_t m = i / n, q = i % n;
        if (m > q) {
            const size_t r = m;
            m = q;
            q = r;
        }
        i = m * n - m * (m - 1u) / 2u + (q - m);
    }
    return mcs_io_value(values, v->first + i);
}

static mcs_values_ record_values(const io_values *values, size_t first, size_t upper)
{
    const mcs_values_ v = {NULL, record_at, values, first, upper};
    return v;
}

/* The moment's invariants (docs/format.md): those of its read-outs
 * (acc_internal.h, mcs_moment_sums_ok_: the same check on the same values)
 * and every power >= 0 within its rounding (mcs_moment_powers_ok), on the
 * record's payload when loading, on the object when saving. Values are
 * finite here. */
static int moment_ok(const io_values *values, uint64_t count)
{
    if (values->payload == NULL) {
        const mcs_moment *acc = (const mcs_moment *)values->obj;
        return mcs_moment_stored_valid(acc) && mcs_moment_powers_valid(acc);
    }
    const size_t n = values->size[SZ_N], tri = n * (n + 1u) / 2u;
    const size_t at = MO_SHIFT, open = MO_SHIFT + 3u * n + 2u * tri; /* batch_s[0] */
    const mcs_moment_sums_ s = {n,
                                count,
                                (uint64_t)mcs_io_value(values, MO_BATCH),
                                (uint64_t)mcs_io_value(values, MO_SPARSE),
                                record_values(values, at, 0u),
                                record_values(values, at + n, 0u),
                                record_values(values, at + 2u * n, 0u),
                                record_values(values, at + 3u * n, n),
                                record_values(values, at + 3u * n + tri, n),
                                record_values(values, open, 0u),
                                record_values(values, open + n, 0u),
                                record_values(values, open + 2u * n, 0u)};
    return mcs_moment_sums_ok_(&s) && mcs_moment_powers_ok(&s);
}

static mcs_status sizes_moment(const uint64_t *shape, size_t *size)
{
    return sizes_n(shape[0], MCS_MAX_COV_N, size);
}

static mcs_status count_moment(const void *obj, uint64_t *count)
{
    return mcs_moment_count((const mcs_moment *)obj, count);
}

static mcs_status init_moment(void *obj, const uint64_t *shape)
{
    return mcs_moment_init((mcs_moment *)obj, (size_t)shape[0]);
}

static const io_kind kind_moment = {
    MCS_IO_KIND_MOMENT, 1u, sizes_moment, {offsetof(mcs_moment, n)},
    count_moment, init_moment, offsetof(mcs_moment, count), moment_ok, 10u,
    {IO_COUNT(mcs_moment, batch_count, IO_RULE_SPREAD),
     IO_COUNT(mcs_moment, batch_sparse, IO_RULE_SPREAD),
     IO_ARRAY(mcs_moment, shift, SZ_N, IO_RULE_NONNEG),
     IO_ARRAY(mcs_moment, sum_d, SZ_N, IO_RULE_SPREAD),
     IO_ARRAY(mcs_moment, lo_d, SZ_N, IO_RULE_SPREAD),
     IO_UPPER(mcs_moment, sum_dd, SZ_N, IO_RULE_SPREAD),
     IO_UPPER(mcs_moment, lo_dd, SZ_N, IO_RULE_SPREAD),
     IO_ARRAY(mcs_moment, batch_s, SZ_N, IO_RULE_M2),
     IO_ARRAY(mcs_moment, batch_d, SZ_N, IO_RULE_SPREAD),
     IO_GRID(mcs_moment, batch_w, SZ_N, SZ_N, SZ_N, IO_RULE_SPREAD)},
    NULL};

mcs_status mcs_io_save_moment(const mcs_moment *acc, size_t cap, void *buf, size_t *len)
{
    return mcs_io_save(&kind_moment, acc, cap, buf, len);
}

mcs_status mcs_io_load_moment(mcs_moment *acc, size_t len, const void *buf)
{
    return mcs_io_load(&kind_moment, acc, len, buf);
}

/* ---- autocorr: sum_s[N] and sum_dc, then lo_s[N], sum_lag and lo_lag for
 * the lags 0..N/2, and lo_dc (autocorr.h: sum_lag holds centred lag sums
 * for trials of K >= N, which may be negative; the lo_ are the Kahan
 * compensations, so a loaded object is the saved one) ---- */

/* The autocorrelation's invariants (docs/format.md): those of its read-outs
 * (acc_internal.h, mcs_autocorr_sums_ok_) and every power >= 0 within its
 * rounding (mcs_autocorr_powers_ok), on the payload when loading, on the
 * object when saving. Payload: sum_s[N], sum_dc, lo_s[N], sum_lag[H],
 * lo_lag[H], lo_dc. */
static int autocorr_ok(const io_values *values, uint64_t count)
{
    if (values->payload == NULL) {
        const mcs_autocorr *acc = (const mcs_autocorr *)values->obj;
        return mcs_autocorr_stored_valid(acc) && mcs_autocorr_powers_valid(acc);
    }
    const size_t n = values->size[SZ_N], h1 = values->size[SZ_HALF];
    const mcs_autocorr_sums_ s = {n,
                                  count,
                                  record_values(values, 0u, 0u),
                                  record_values(values, n + 1u, 0u),
                                  record_values(values, 2u * n + 1u, 0u),
                                  record_values(values, 2u * n + 1u + h1, 0u),
                                  mcs_io_value(values, n),
                                  mcs_io_value(values, 2u * n + 1u + 2u * h1)};
    return mcs_autocorr_sums_ok_(&s) && mcs_autocorr_powers_ok(&s);
}

static mcs_status sizes_autocorr(const uint64_t *shape, size_t *size)
{
    return sizes_n(shape[0], MCS_MAX_N, size);
}

static mcs_status count_autocorr(const void *obj, uint64_t *count)
{
    return mcs_autocorr_count((const mcs_autocorr *)obj, count);
}

static mcs_status init_autocorr(void *obj, const uint64_t *shape)
{
    return mcs_autocorr_init((mcs_autocorr *)obj, (size_t)shape[0]);
}

static const io_kind kind_autocorr = {
    MCS_IO_KIND_AUTOCORR, 1u, sizes_autocorr, {offsetof(mcs_autocorr, n)},
    count_autocorr, init_autocorr, offsetof(mcs_autocorr, count), autocorr_ok, 6u,
    {IO_ARRAY(mcs_autocorr, sum_s, SZ_N, IO_RULE_NONNEG),
     IO_ARRAY(mcs_autocorr, sum_dc, IO_ONE, IO_RULE_NONNEG),
     IO_ARRAY(mcs_autocorr, lo_s, SZ_N, 0u),
     IO_ARRAY(mcs_autocorr, sum_lag, SZ_HALF, 0u),
     IO_ARRAY(mcs_autocorr, lo_lag, SZ_HALF, 0u),
     IO_ARRAY(mcs_autocorr, lo_dc, IO_ONE, 0u)},
    NULL};

mcs_status mcs_io_save_autocorr(const mcs_autocorr *acc, size_t cap, void *buf, size_t *len)
{
    return mcs_io_save(&kind_autocorr, acc, cap, buf, len);
}

mcs_status mcs_io_load_autocorr(mcs_autocorr *acc, size_t len, const void *buf)
{
    return mcs_io_load(&kind_autocorr, acc, len, buf);
}

/* ---- welford: mean, m2, m3, m4; no shape, and an object always counts ---- */

static mcs_status sizes_welford(const uint64_t *shape, size_t *size)
{
    (void)shape;
    (void)size;
    return MCS_OK;
}

static mcs_status count_welford(const void *obj, uint64_t *count)
{
    *count = ((const mcs_welford *)obj)->count;
    return MCS_OK;
}

static mcs_status init_welford(void *obj, const uint64_t *shape)
{
    (void)shape;
    return mcs_welford_init((mcs_welford *)obj);
}

/* The accumulator's own state check (welford.c: moments within what values
 * up to MCS_WELFORD_MAX_ABS give), through a read-out of the values as an
 * object: a record the read-outs would refuse is refused on load. */
static int welford_ok(const io_values *values, uint64_t count)
{
    mcs_welford w;
    double v = 0.0;
    if (count == 0u || mcs_welford_init(&w) != MCS_OK)
        return 1;
    w.count = count;
    w.mean = mcs_io_value(values, 0u);
    w.m2 = mcs_io_value(values, 1u);
    w.m3 = mcs_io_value(values, 2u);
    w.m4 = mcs_io_value(values, 3u);
    return mcs_welford_mean(&w, &v) != MCS_ERR_INVARIANT;
}

static const io_kind kind_welford = {
    MCS_IO_KIND_WELFORD, 0u, sizes_welford, {0u},
    count_welford, init_welford, offsetof(mcs_welford, count), welford_ok, 4u,
    {IO_ARRAY(mcs_welford, mean, IO_ONE, 0u),
     IO_ARRAY(mcs_welford, m2, IO_ONE, IO_RULE_M2),
     IO_ARRAY(mcs_welford, m3, IO_ONE, IO_RULE_SPREAD),
     IO_ARRAY(mcs_welford, m4, IO_ONE, IO_RULE_M2)},
    NULL};

mcs_status mcs_io_save_welford(const mcs_welford *acc, size_t cap, void *buf, size_t *len)
{
    return mcs_io_save(&kind_welford, acc, cap, buf, len);
}

mcs_status mcs_io_load_welford(mcs_welford *acc, size_t len, const void *buf)
{
    return mcs_io_load(&kind_welford, acc, len, buf);
}
