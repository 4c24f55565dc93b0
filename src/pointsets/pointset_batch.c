/* Point-set accumulators a batch at a time (pointset.h, pointset2d.h): T
 * sets added in one call, and every read-out of an object as whole arrays,
 * for callers that pay per call (a binding such as python/mcspec, where one
 * call per set or per wave vector would cost more than the sums). Each is
 * the per-set or per-frequency call in a loop, so the bits are theirs; the
 * checks of the whole batch come first, so a refused batch changes
 * nothing. */
#include "pointset_internal.h"

#include "mcspec/pointset.h"
#include "mcspec/pointset2d.h"

#include <math.h>

/* What the checks need of an object: its header and buffer (for overlaps),
 * its wrap flag and its count (a struct, so that no helper takes more
 * arguments than registers: stack arguments make make stack's frames
 * dynamic). */
typedef struct {
    const void *hdr, *mem;
    size_t hdr_bytes, mem_bytes;
    int wrap;
    uint64_t count;
} batch_obj;

/* The checks of a batch of sets of k points of dims coordinates, in the
 * order of the single add (pointset.c): points, the object, K and the
 * path, the overlap with the object, every coordinate, the count. */
static mcs_status check_batch(const mcs_ps_points *pts, const batch_obj *o, size_t sets, size_t k)
{
    if (sets == 0u || k > SIZE_MAX / 2u / sets)
        return MCS_ERR_K_RANGE;
    const size_t all = sets * k;
    if (mcs_ps_points_overlap(pts, all, o->hdr, o->hdr_bytes) ||
        mcs_ps_points_overlap(pts, all, o->mem, o->mem_bytes))
        return MCS_ERR_ALIAS;
    int ones = 0;
    mcs_status st = mcs_ps_check_points(pts, all, o->wrap, &ones);
    return st != MCS_OK ? st : mcs_check_count_(o->count, (uint64_t)sets);
}

/* The statuses an add would give before it looks at the points: NULL,
 * UNINIT (from the count) and K_RANGE (from the path). */
static mcs_status check_1d(const mcs_pointset *acc, const mcs_ps_points *pts, size_t sets,
                           size_t k)
{
    uint64_t count = 0u;
    mcs_pointset_path path = MCS_POINTSET_PATH_DIRECT;
    mcs_status st = mcs_ps_points_null(pts) ? MCS_ERR_NULL : mcs_pointset_count(acc, &count);
    if (st == MCS_OK)
        st = mcs_pointset_path_for(acc, k, &path);
    if (st != MCS_OK)
        return st;
    const batch_obj o = {acc, acc->mem, sizeof *acc, acc->bytes, acc->wrap, count};
    return check_batch(pts, &o, sets, k);
}

mcs_status mcs_pointset_add_sets(mcs_pointset *acc, size_t sets, size_t k, const double *points)
{
    const mcs_ps_points pts = mcs_ps_points_d(points, NULL, 1);
    mcs_status st = check_1d(acc, &pts, sets, k);
    for (size_t t = 0; st == MCS_OK && t < sets; ++t)
        st = mcs_pointset_add(acc, k, points + t * k);
    return st;
}

mcs_status mcs_pointset_add_sets_f(mcs_pointset *acc, size_t sets, size_t k, const float *points)
{
    const mcs_ps_points pts = mcs_ps_points_f(points, NULL, 1);
    mcs_status st = check_1d(acc, &pts, sets, k);
    for (size_t t = 0; st == MCS_OK && t < sets; ++t)
        st = mcs_pointset_add_f(acc, k, points + t * k);
    return st;
}

static mcs_status check_2d(const mcs_pointset2d *acc, const mcs_ps_points *pts, size_t sets,
                           size_t k)
{
    uint64_t count = 0u;
    mcs_pointset_path path = MCS_POINTSET_PATH_DIRECT;
    mcs_status st = mcs_ps_points_null(pts) ? MCS_ERR_NULL : mcs_pointset2d_count(acc, &count);
    if (st == MCS_OK)
        st = mcs_pointset2d_path_for(acc, k, &path);
    if (st == MCS_OK && k > SIZE_MAX / 4u)
        st = MCS_ERR_POINT_RANGE; /* as the single add: 2 k coordinates cannot fit */
    if (st != MCS_OK)
        return st;
    const batch_obj o = {acc, acc->mem, sizeof *acc, acc->bytes, acc->wrap, count};
    return check_batch(pts, &o, sets, k);
}

mcs_status mcs_pointset2d_add_sets(mcs_pointset2d *acc, size_t sets, size_t k,
                                   const double *points)
{
    const mcs_ps_points pts = mcs_ps_points_d(points, NULL, 2);
    mcs_status st = check_2d(acc, &pts, sets, k);
    for (size_t t = 0; st == MCS_OK && t < sets; ++t)
        st = mcs_pointset2d_add(acc, k, points + 2u * t * k);
    return st;
}

mcs_status mcs_pointset2d_add_sets_f(mcs_pointset2d *acc, size_t sets, size_t k,
                                     const float *points)
{
    const mcs_ps_points pts = mcs_ps_points_f(points, NULL, 2);
    mcs_status st = check_2d(acc, &pts, sets, k);
    for (size_t t = 0; st == MCS_OK && t < sets; ++t)
        st = mcs_pointset2d_add_f(acc, k, points + 2u * t * k);
    return st;
}

/* The checks of a read-out into up to three arrays of len doubles each
 * (NULL when not wanted, not all): none may overlap another, the header
 * or the buffer; the count must be at least 1, or 2 with a standard error
 * (stderr_given). */
static mcs_status check_arrays(double *const *arr, int n, size_t len, const batch_obj *o,
                               int stderr_given)
{
    int any = 0;
    const size_t bytes = mcs_bytes_(len, sizeof(double));
    for (int i = 0; i < n; ++i) {
        if (arr[i] == NULL)
            continue;
        any = 1;
        if (mcs_overlap_(arr[i], bytes, o->hdr, o->hdr_bytes) ||
            mcs_overlap_(arr[i], bytes, o->mem, o->mem_bytes))
            return MCS_ERR_ALIAS;
        for (int j = 0; j < i; ++j)
            if (arr[j] != NULL && mcs_overlap_(arr[i], bytes, arr[j], bytes))
                return MCS_ERR_ALIAS;
    }
    if (!any)
        return MCS_ERR_NULL;
    return o->count < (stderr_given ? 2u : 1u) ? MCS_ERR_EMPTY : MCS_OK;
}

mcs_status mcs_pointset_read_all(const mcs_pointset *acc, size_t n_out, double *power,
                                 double *power_stderr)
{
    uint64_t count = 0u;
    mcs_status st = mcs_pointset_count(acc, &count);
    if (st == MCS_OK && n_out != acc->freq_max + 1u)
        st = MCS_ERR_MISMATCH;
    double *const arr[2] = {power, power_stderr};
    const batch_obj o = {acc, st == MCS_OK ? acc->mem : NULL, sizeof *acc,
                         st == MCS_OK ? acc->bytes : 0u, 0, count};
    if (st == MCS_OK)
        st = check_arrays(arr, 2, n_out, &o, power_stderr != NULL);
    for (size_t f = 0; st == MCS_OK && f < n_out; ++f) {
        if (power != NULL)
            st = mcs_pointset_power(acc, (long)f, &power[f]);
        if (st == MCS_OK && power_stderr != NULL)
            st = mcs_pointset_power_stderr(acc, (long)f, &power_stderr[f]);
    }
    return st;
}

mcs_status mcs_pointset2d_read_all(const mcs_pointset2d *acc, size_t side, double *power,
                                   double *power_stderr)
{
    uint64_t count = 0u;
    mcs_status st = mcs_pointset2d_count(acc, &count);
    if (st == MCS_OK && side != 2u * acc->freq_max + 1u)
        st = MCS_ERR_MISMATCH;
    double *const arr[2] = {power, power_stderr};
    const batch_obj o = {acc, st == MCS_OK ? acc->mem : NULL, sizeof *acc,
                         st == MCS_OK ? acc->bytes : 0u, 0, count};
    if (st == MCS_OK)
        st = check_arrays(arr, 2, side * side, &o, power_stderr != NULL);
    const long f = st == MCS_OK ? (long)acc->freq_max : 0L;
    for (long fy = -f; st == MCS_OK && fy <= f; ++fy)
        for (long fx = -f; st == MCS_OK && fx <= f; ++fx) {
            const size_t i = (size_t)(fy + f) * side + (size_t)(fx + f);
            if (power != NULL)
                st = mcs_pointset2d_power(acc, fx, fy, &power[i]);
            if (st == MCS_OK && power_stderr != NULL)
                st = mcs_pointset2d_power_stderr(acc, fx, fy, &power_stderr[i]);
        }
    return st;
}

mcs_status mcs_pointset2d_radial_all(const mcs_pointset2d *acc, size_t n_out, double *radial,
                                     double *radial_stderr, double *anisotropy_db)
{
    uint64_t count = 0u;
    mcs_status st = mcs_pointset2d_count(acc, &count);
    if (st == MCS_OK && n_out != acc->freq_max + 1u)
        st = MCS_ERR_MISMATCH;
    double *const arr[3] = {radial, radial_stderr, anisotropy_db};
    const batch_obj o = {acc, st == MCS_OK ? acc->mem : NULL, sizeof *acc,
                         st == MCS_OK ? acc->bytes : 0u, 0, count};
    if (st == MCS_OK)
        st = check_arrays(arr, 3, n_out, &o, radial_stderr != NULL);
    for (size_t r = 0; st == MCS_OK && r < n_out; ++r) {
        if (radial != NULL)
            st = mcs_pointset2d_radial(acc, r, &radial[r]);
        if (st == MCS_OK && radial_stderr != NULL)
            st = mcs_pointset2d_radial_stderr(acc, r, &radial_stderr[r]);
        if (st == MCS_OK && anisotropy_db != NULL) {
            double db = (double)NAN;
            const mcs_status sa = r == 0u ? MCS_ERR_DOMAIN : mcs_pointset2d_anisotropy(acc, r, &db);
            anisotropy_db[r] = sa == MCS_OK ? db : (double)NAN;
            st = sa == MCS_ERR_DOMAIN ? MCS_OK : sa;
        }
    }
    return st;
}
