/* The record kinds of the fixed-size measure accumulators (docs/format.md):
 * mcs_integrate (kind 9), mcs_discrepancy (10) and mcs_spacing (11); the
 * pair correlation, over a caller buffer, is in io_points.c. As in
 * io_kinds.c: sizes for a shape and a table of fields in payload order,
 * which io.c walks to save, check and load.
 *
 * Each accumulator is a few Welfords (welford.h) side by side in its struct
 * with k_min and k_max. The payload is k_min, k_max, then the Welfords'
 * counts, means, M2s, M3s and M4s, each run over the Welfords in struct
 * order. The header's count is the sets added (the first Welford's count).
 * A record is checked by reading it back into an object and running the
 * measure's own state check (so the loader refuses what the read-outs
 * would), and then against the ranges each measure's values lie in. */
#include "io_internal.h"

#include <float.h>
#include <math.h>
#include <string.h>

/* The walker steps through a run of Welfords as rows of doubles. */
_Static_assert(sizeof(mcs_welford) == 5u * sizeof(double),
               "mcs_welford is a count and four doubles, unpadded");

/* Sizes: the Welfords in the run, and their stride in doubles. */
enum { W_ROWS = 1, W_STRIDE = 2 };

/* Payload indices: k_min, k_max, then the Welfords' counts. */
enum { AT_K_MIN = 0, AT_K_MAX = 1, AT_COUNTS = 2 };

/* Relative slack of the range checks: the rounding of a mean over up to
 * 2^53 values stays far inside it, as spectrum_within_limits' does. */
#define SLACK 0x1p-20

/* The run of Welfords starting at member w of t, in the order above (w.member
 * is a member designator, which parentheses would break). */
#define IO_WELFORD_RUN(t, w, member, as, rules) \
    {offsetof(t, w.member), as, W_ROWS, IO_ONE, W_STRIDE, rules} /* NOLINT(bugprone-macro-parentheses) */
#define IO_WELFORDS(t, w)                                                  \
    IO_WELFORD_RUN(t, w, count, IO_AS_COUNT, IO_RULE_NONNEG),              \
        IO_WELFORD_RUN(t, w, mean, IO_AS_ROWS, 0u),                        \
        IO_WELFORD_RUN(t, w, m2, IO_AS_ROWS, IO_RULE_M2),                  \
        IO_WELFORD_RUN(t, w, m3, IO_AS_ROWS, IO_RULE_SPREAD),              \
        IO_WELFORD_RUN(t, w, m4, IO_AS_ROWS, IO_RULE_M2)

static void sizes_welfords(size_t rows, size_t *size)
{
    size[W_ROWS] = rows;
    size[W_STRIDE] = 5u;
}

/* Mean of Welford w of the run (rows of them). */
static double mean_of(const io_values *values, size_t rows, size_t w)
{
    return mcs_io_value(values, AT_COUNTS + rows + w);
}

/* The first Welford's count is the header's (the store sets it from the
 * header, so it is compared here); then the object's own check. */
static int counts_agree(const io_values *values, uint64_t count)
{
    return mcs_io_value(values, AT_COUNTS) == (double)count;
}

/* ---- integrate: shape [family, dim]; Welfords sq, exact ---- */

static mcs_status sizes_integrate(const uint64_t *shape, size_t *size)
{
    if (shape[0] >= (uint64_t)MCS_INTEGRAND_FAMILIES || (shape[1] != 1u && shape[1] != 2u))
        return MCS_ERR_DOMAIN;
    sizes_welfords(2u, size);
    return MCS_OK;
}

static void shape_integrate(const void *obj, uint64_t *shape)
{
    const mcs_integrate *acc = (const mcs_integrate *)obj;
    shape[0] = (uint64_t)acc->family;
    shape[1] = acc->dim;
}

static mcs_status count_integrate(const void *obj, uint64_t *count)
{
    return mcs_integrate_count((const mcs_integrate *)obj, count);
}

static mcs_status init_integrate(void *obj, const uint64_t *shape)
{
    return mcs_integrate_init((mcs_integrate *)obj, (mcs_integrand_family)shape[0],
                              (size_t)shape[1]);
}

/* The accumulator's check (an exact count at most the sets', k_min <=
 * k_max, Welfords some adds give); the MSEs, measured and exact, are means
 * of squares (>= 0, the rule of the means here). */
static int integrate_ok(const io_values *values, uint64_t count)
{
    mcs_integrate a;
    uint64_t n = 0u;
    if (!counts_agree(values, count) || init_integrate(&a, values->shape) != MCS_OK)
        return 0;
    mcs_io_store(values, count, &a);
    return mcs_integrate_count(&a, &n) == MCS_OK && mean_of(values, 2u, 0u) >= 0.0 &&
           mean_of(values, 2u, 1u) >= 0.0;
}

static const io_kind kind_integrate = {
    .kind = MCS_IO_KIND_INTEGRATE,
    .shape_len = 2u,
    .sizes = sizes_integrate,
    .count = count_integrate,
    .init = init_integrate,
    .count_at = offsetof(mcs_integrate, sq.count),
    .valid = integrate_ok,
    .nfields = 7u,
    .fields = {IO_SIZE(mcs_integrate, k_min, IO_RULE_NONNEG),
               IO_SIZE(mcs_integrate, k_max, IO_RULE_NONNEG), IO_WELFORDS(mcs_integrate, sq)},
    .shape_of = shape_integrate};

mcs_status mcs_io_save_integrate(const mcs_integrate *acc, size_t cap, void *buf, size_t *len)
{
    return mcs_io_save(&kind_integrate, acc, cap, buf, len);
}

mcs_status mcs_io_load_integrate(mcs_integrate *acc, size_t len, const void *buf)
{
    return mcs_io_load(&kind_integrate, acc, len, buf);
}

/* ---- discrepancy: shape [dim]; Welfords inv_k, d2[0..6] ---- */

enum { DI_ROWS = 1 + MCS_DISCREPANCY_MEASURES };

static mcs_status sizes_discrepancy(const uint64_t *shape, size_t *size)
{
    if (shape[0] == 0u || shape[0] > (uint64_t)MCS_DISCREPANCY_MAX_DIM)
        return MCS_ERR_DOMAIN;
    sizes_welfords(DI_ROWS, size);
    return MCS_OK;
}

static mcs_status count_discrepancy(const void *obj, uint64_t *count)
{
    return mcs_discrepancy_count((const mcs_discrepancy *)obj, MCS_DISCREPANCY_L2_STAR, count);
}

static mcs_status init_discrepancy(void *obj, const uint64_t *shape)
{
    return mcs_discrepancy_init((mcs_discrepancy *)obj, (size_t)shape[0]);
}

/* Per L2 measure (discrepancy.h's table): C0^(1/d), and the largest
 * h1(x, y), so that 0 <= D^2 <= C0 + max h (g >= 0 for each). */
static const double c0_root[MCS_DISCREPANCY_L2_COUNT] = {1.0 / 3.0,  13.0 / 12.0, 4.0 / 3.0,
                                                         4.0 / 3.0, 4.0 / 3.0,   1.0 / 12.0};
static const double h_max[MCS_DISCREPANCY_L2_COUNT] = {1.0, 1.5, 1.5, 2.0, 2.0, 0.25};

/* Whether mean lies in [lo, hi] within the slack. */
static int within(double mean, double lo, double hi)
{
    return mean >= lo - fabs(lo) * SLACK && mean <= hi + fabs(hi) * SLACK;
}

/* The accumulator's check (L2 counts equal to the sets', a star count at
 * most that, k_min <= k_max), then the ranges: the mean of 1/K between
 * 1/k_max and 1/k_min; each L2 mean within [-(rounding), C0 + max h]; the
 * star's (D* squared, D* <= 1) in [0, 1], and only in 2D, and only if some
 * set had K <= MCS_DISCREPANCY_STAR_MAX_K (every set, when its count is the
 * sets'). */
static int discrepancy_ok(const io_values *values, uint64_t count)
{
    mcs_discrepancy a;
    uint64_t n = 0u;
    if (!counts_agree(values, count) || init_discrepancy(&a, values->shape) != MCS_OK)
        return 0;
    mcs_io_store(values, count, &a);
    if (mcs_discrepancy_count(&a, MCS_DISCREPANCY_L2_STAR, &n) != MCS_OK)
        return 0;
    if (count == 0u)
        return 1;
    const double d = (double)a.dim;
    if (!within(a.inv_k.mean, 1.0 / (double)a.k_max, 1.0 / (double)a.k_min))
        return 0;
    for (size_t m = 0; m < (size_t)MCS_DISCREPANCY_L2_COUNT; ++m) {
        const double c0 = pow(c0_root[m], d);
        const double rounding = 16.0 * (d + 70.0) * DBL_EPSILON * c0;
        if (!within(a.d2[m].mean, -rounding, c0 + pow(h_max[m], d)))
            return 0;
    }
    const mcs_welford *star = &a.d2[MCS_DISCREPANCY_STAR];
    if (star->count == 0u)
        return 1;
    const size_t star_max = (size_t)MCS_DISCREPANCY_STAR_MAX_K;
    return a.dim == 2u && a.k_min <= star_max && (star->count < count || a.k_max <= star_max) &&
           star->mean >= 0.0 && within(star->mean, 0.0, 1.0);
}

static const io_kind kind_discrepancy = {
    .kind = MCS_IO_KIND_DISCREPANCY,
    .shape_len = 1u,
    .sizes = sizes_discrepancy,
    .shape_at = {offsetof(mcs_discrepancy, dim)},
    .count = count_discrepancy,
    .init = init_discrepancy,
    .count_at = offsetof(mcs_discrepancy, inv_k.count),
    .valid = discrepancy_ok,
    .nfields = 7u,
    .fields = {IO_SIZE(mcs_discrepancy, k_min, IO_RULE_NONNEG),
               IO_SIZE(mcs_discrepancy, k_max, IO_RULE_NONNEG),
               IO_WELFORDS(mcs_discrepancy, inv_k)}};

mcs_status mcs_io_save_discrepancy(const mcs_discrepancy *acc, size_t cap, void *buf,
                                   size_t *len)
{
    return mcs_io_save(&kind_discrepancy, acc, cap, buf, len);
}

mcs_status mcs_io_load_discrepancy(mcs_discrepancy *acc, size_t len, const void *buf)
{
    return mcs_io_load(&kind_discrepancy, acc, len, buf);
}

/* ---- spacing: shape [dim]; Welfords stat[min, avg min] ---- */

static mcs_status sizes_spacing(const uint64_t *shape, size_t *size)
{
    if (shape[0] == 0u || shape[0] > (uint64_t)MCS_SPACING_MAX_DIM)
        return MCS_ERR_DOMAIN;
    sizes_welfords(MCS_SPACING_STATISTICS, size);
    return MCS_OK;
}

static mcs_status count_spacing(const void *obj, uint64_t *count)
{
    return mcs_spacing_count((const mcs_spacing *)obj, count);
}

static mcs_status init_spacing(void *obj, const uint64_t *shape)
{
    return mcs_spacing_init((mcs_spacing *)obj, (size_t)shape[0]);
}

/* The accumulator's check (equal counts, k_min <= k_max), then the ranges:
 * k_min >= 2 (no add takes fewer), distances >= 0 (the rule of the means),
 * the mean minimum distance at most the mean average minimum distance (per
 * set the minimum of the nearest distances is at most their mean), and both
 * at most the torus' largest distance sqrt(d) / 2 over d_max at k_max. */
static int spacing_ok(const io_values *values, uint64_t count)
{
    mcs_spacing a;
    uint64_t n = 0u;
    double d_max = 0.0;
    if (!counts_agree(values, count) || init_spacing(&a, values->shape) != MCS_OK)
        return 0;
    mcs_io_store(values, count, &a);
    if (mcs_spacing_count(&a, &n) != MCS_OK)
        return 0;
    if (count == 0u)
        return 1;
    if (a.k_min < 2u || mcs_spacing_packing_distance(a.dim, a.k_max, &d_max) != MCS_OK)
        return 0;
    const double lo = a.stat[MCS_SPACING_MIN_DISTANCE].mean;
    const double hi = a.stat[MCS_SPACING_AVG_MIN_DISTANCE].mean;
    const double top = sqrt((double)a.dim) / 2.0 / d_max;
    return lo >= 0.0 && within(lo, 0.0, hi) && within(hi, 0.0, top);
}

static const io_kind kind_spacing = {
    .kind = MCS_IO_KIND_SPACING,
    .shape_len = 1u,
    .sizes = sizes_spacing,
    .shape_at = {offsetof(mcs_spacing, dim)},
    .count = count_spacing,
    .init = init_spacing,
    .count_at = offsetof(mcs_spacing, stat[0].count),
    .valid = spacing_ok,
    .nfields = 7u,
    .fields = {IO_SIZE(mcs_spacing, k_min, IO_RULE_NONNEG),
               IO_SIZE(mcs_spacing, k_max, IO_RULE_NONNEG), IO_WELFORDS(mcs_spacing, stat[0])}};

mcs_status mcs_io_save_spacing(const mcs_spacing *acc, size_t cap, void *buf, size_t *len)
{
    return mcs_io_save(&kind_spacing, acc, cap, buf, len);
}

mcs_status mcs_io_load_spacing(mcs_spacing *acc, size_t len, const void *buf)
{
    return mcs_io_load(&kind_spacing, acc, len, buf);
}
