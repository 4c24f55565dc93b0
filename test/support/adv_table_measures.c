/* Adversarial table: the measures of a point set (discrepancy.h, spacing.h)
 * and the type-1 NUFFT (nufft.h); the outcomes of the R_RANGE and F_ZEROOK
 * slots (adv_refine_rows); and the checks a row cannot express, run as
 * scenarios (exact work sizes at any alignment, overlapping buffers, edited
 * plans). */
#include "adv_table.h"
#include "adv_world.h"

#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* ---- outcomes adv_rows does not derive ---- */

void adv_refine_rows(adv_row *rows, size_t nrows)
{
    for (size_t i = 0; i < nrows; ++i) {
        adv_row *r = &rows[i];
        if (r->slot < 0 || r->mk == MK_ALIAS)
            continue;
        const adv_slot *s = &r->fn->slot[r->slot];
        if (r->mk == MK_DBL && s->kind == K_DBL && s->role == R_RANGE) {
            const double x = adv_scalar_double(r, r->slot);
            r->expect = !(x >= s->dlo && x <= s->dhi) ? EX_ERR : s->flags & F_OKIN ? EX_OK : EX_ANY;
        }
        if (r->mk == MK_OBJ && r->mv == OV_ZERO && (s->flags & F_ZEROOK))
            r->expect = EX_OK;
    }
}

#if defined(__GNUC__)
__attribute__((format(printf, 1, 2)))
#endif
static int broken(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(adv_note, sizeof adv_note, fmt, ap);
    va_end(ap);
    return ADV_BROKEN;
}

/* ---- float points ----
 * As adv_floats_begin (adv_table_core.c) but over the whole array the
 * pointer starts (found in the arena, so its length needs no slot), and up
 * to the largest array of these rows (a set of ADV_LONG_LEN points in
 * MCS_DISCREPANCY_MAX_DIM dimensions). */

#define FLOATS_CAP ((size_t)ADV_LONG_LEN * MCS_DISCREPANCY_MAX_DIM)
static double floats_saved[FLOATS_CAP];
static float floats_written[FLOATS_CAP];
static size_t floats_len;

static float toward_zero(double d)
{
    if (isnan(d))
        return NAN;
    if (!(fabs(d) <= (double)FLT_MAX))
        return d > 0.0 ? INFINITY : -INFINITY;
    float f = (float)d;
    return fabs((double)f) > fabs(d) ? nextafterf(f, 0.0f) : f;
}

static const float *floats_begin(void *points)
{
    floats_len = 0;
    for (int g = 0; points != NULL && g < adv_nregs; ++g)
        if (adv_arena + adv_regs[g].off == (unsigned char *)points)
            floats_len = adv_regs[g].bytes / sizeof(double);
    if (floats_len > FLOATS_CAP)
        floats_len = 0; /* not narrowed: the row shows the table's error */
    memcpy(floats_saved, points == NULL ? floats_saved : points, floats_len * sizeof(double));
    for (size_t j = 0; j < floats_len; ++j)
        floats_written[j] = toward_zero(floats_saved[j]);
    if (floats_len > 0u)
        memcpy(points, floats_written, floats_len * sizeof(float));
    return points;
}

/* The doubles back, except where the call wrote (an output aliasing them). */
static void floats_end(void *points)
{
    for (size_t i = 0; 2u * i < floats_len; ++i) {
        unsigned char *slot = (unsigned char *)points + i * sizeof(double);
        const size_t bytes = 2u * i + 1u < floats_len ? sizeof(double) : sizeof(float);
        if (memcmp(slot, &floats_written[2u * i], bytes) == 0)
            memcpy(slot, &floats_saved[i], sizeof(double));
    }
}

/* Coordinate j of double or float points. */
static double coord(const void *p, int is_f, size_t j)
{
    return is_f ? (double)((const float *)p)[j] : ((const double *)p)[j];
}

/* ---- read-outs of an accumulator after a successful update ----
 * (adv_health's job for the types it knows.) Each read-out fails or is
 * finite; standard errors, the star's squares, the distances and the exact
 * random expectations >= 0; every L2 count that of 1/K, the star's at most. */

static int disc_sound(const mcs_discrepancy *acc)
{
    uint64_t n = 0, c = 0;
    double v = 0.0;
    if (mcs_discrepancy_count(acc, MCS_DISCREPANCY_L2_STAR, &n) != MCS_OK)
        return broken("count refused after MCS_OK");
    for (int m = 0; m < MCS_DISCREPANCY_MEASURES; ++m) {
        const mcs_discrepancy_measure q = (mcs_discrepancy_measure)m;
        const char *name = mcs_discrepancy_measure_str(q);
        if (mcs_discrepancy_count(acc, q, &c) != MCS_OK || (m < 6 ? c != n : c > n))
            return broken("%s count %llu of %llu sets", name, (unsigned long long)c,
                          (unsigned long long)n);
        if (mcs_discrepancy_mean(acc, q, &v) == MCS_OK &&
            !(isfinite(v) && (m != MCS_DISCREPANCY_STAR || v >= 0.0)))
            return broken("%s mean %.17g with MCS_OK", name, v);
        if (mcs_discrepancy_stderr(acc, q, &v) == MCS_OK && !(isfinite(v) && v >= 0.0))
            return broken("%s stderr %.17g with MCS_OK", name, v);
        if (m < 6 && mcs_discrepancy_exact_random(acc, q, &v) == MCS_OK && !(isfinite(v) && v > 0.0))
            return broken("%s exact_random %.17g with MCS_OK", name, v);
    }
    return MCS_OK;
}

static int spacing_sound(const mcs_spacing *acc)
{
    uint64_t n = 0;
    double v = 0.0;
    if (mcs_spacing_count(acc, &n) != MCS_OK)
        return broken("count refused after MCS_OK");
    for (int s = 0; s < MCS_SPACING_STATISTICS; ++s) {
        const mcs_spacing_statistic q = (mcs_spacing_statistic)s;
        if (mcs_spacing_mean(acc, q, &v) == MCS_OK && !(isfinite(v) && v >= 0.0))
            return broken("%s mean %.17g with MCS_OK", mcs_spacing_statistic_str(q), v);
        if (mcs_spacing_stderr(acc, q, &v) == MCS_OK && !(isfinite(v) && v >= 0.0))
            return broken("%s stderr %.17g with MCS_OK", mcs_spacing_statistic_str(q), v);
    }
    return MCS_OK;
}

static int disc_after(int st, const void *acc)
{
    return st == MCS_OK && acc != NULL ? disc_sound(acc) : st;
}

static int spacing_after(int st, const void *acc)
{
    return st == MCS_OK && acc != NULL ? spacing_sound(acc) : st;
}

/* The name of a measure or statistic, "unknown" exactly outside the enum. */
static int names_known(const char *s, int known)
{
    return s != NULL && known == (strcmp(s, "unknown") != 0) ? MCS_OK : ADV_BROKEN;
}

/* ---- discrepancy.h ---- */

/* The six D^2 finite and none below 0 by more than the rounding discrepancy.h
 * allows: a few (d + 70) u C0 (8 of them here). */
static int l2_sound(int st, size_t dim, const double *d2)
{
    if (st != MCS_OK)
        return st;
    const double d = (double)dim;
    const double c0[6] = {pow(1.0 / 3.0, d), pow(13.0 / 12.0, d), pow(4.0 / 3.0, d),
                          pow(4.0 / 3.0, d), pow(4.0 / 3.0, d), pow(1.0 / 12.0, d)};
    for (int m = 0; m < 6; ++m)
        if (d2[m] < -8.0 * (d + 70.0) * DBL_EPSILON / 2.0 * c0[m])
            return broken("%s = %.17g, below 0 by more than rounding (C0 %.3g)",
                          mcs_discrepancy_measure_str((mcs_discrepancy_measure)m), d2[m], c0[m]);
    return MCS_OK;
}

static int t_discrepancy_measure_str(const adv_val *a)
{
    return names_known(mcs_discrepancy_measure_str((mcs_discrepancy_measure)a[0].e),
                       a[0].e >= 0 && a[0].e < MCS_DISCREPANCY_MEASURES);
}
static int t_discrepancy_l2(const adv_val *a)
{
    return l2_sound(mcs_discrepancy_l2(a[0].z, a[1].z, a[2].p, a[3].p), a[1].z, a[3].p);
}
static int t_discrepancy_l2_f(const adv_val *a)
{
    const float *x = floats_begin(a[2].p);
    int st = mcs_discrepancy_l2_f(a[0].z, a[1].z, x, a[3].p);
    floats_end(a[2].p);
    return l2_sound(st, a[1].z, a[3].p);
}
static int t_discrepancy_l2_exact_random(const adv_val *a)
{
    int st = mcs_discrepancy_l2_exact_random((mcs_discrepancy_measure)a[0].e, a[1].z, a[2].z, a[3].p);
    return st == MCS_OK && !(*(double *)a[3].p > 0.0) ? broken("E[D^2] not > 0") : st;
}
static int t_discrepancy_l2_exact_jittered(const adv_val *a)
{
    int st = mcs_discrepancy_l2_exact_jittered((mcs_discrepancy_measure)a[0].e, a[1].z, a[2].z, a[3].p);
    return st == MCS_OK && !(*(double *)a[3].p > 0.0) ? broken("E[D^2] not > 0") : st;
}
static int t_discrepancy_l2_exact_jittered2d(const adv_val *a)
{
    int st = mcs_discrepancy_l2_exact_jittered2d((mcs_discrepancy_measure)a[0].e, a[1].z, a[2].z, a[3].p);
    return st == MCS_OK && !(*(double *)a[3].p > 0.0) ? broken("E[D^2] not > 0") : st;
}
static int t_discrepancy_star_work_size(const adv_val *a)
{
    int st = mcs_discrepancy_star_work_size(a[0].z, a[1].p);
    return st == MCS_OK && *(size_t *)a[1].p != MCS_DISCREPANCY_STAR_WORK_SIZE(a[0].z)
               ? broken("not MCS_DISCREPANCY_STAR_WORK_SIZE(k)")
               : st;
}
/* D* is in [0, 1] (the engine checks >= 0). */
static int star_sound(int st, const double *out)
{
    return st == MCS_OK && !(*out <= 1.0) ? broken("D* = %.17g above 1", *out) : st;
}
static int t_discrepancy_star(const adv_val *a)
{
    return star_sound(mcs_discrepancy_star(a[0].z, a[1].p, a[2].p, a[3].z, a[4].p), a[4].p);
}
static int t_discrepancy_star_f(const adv_val *a)
{
    const float *x = floats_begin(a[1].p);
    int st = mcs_discrepancy_star_f(a[0].z, x, a[2].p, a[3].z, a[4].p);
    floats_end(a[1].p);
    return star_sound(st, a[4].p);
}
static int t_discrepancy_init(const adv_val *a) { return disc_after(mcs_discrepancy_init(a[0].p, a[1].z), a[0].p); }
static int t_discrepancy_add(const adv_val *a)
{
    return disc_after(mcs_discrepancy_add(a[0].p, a[1].z, a[2].p, a[3].p, a[4].z), a[0].p);
}
static int t_discrepancy_add_f(const adv_val *a)
{
    const float *x = floats_begin(a[2].p);
    int st = mcs_discrepancy_add_f(a[0].p, a[1].z, x, a[3].p, a[4].z);
    floats_end(a[2].p);
    return disc_after(st, a[0].p);
}
static int t_discrepancy_merge(const adv_val *a) { return disc_after(mcs_discrepancy_merge(a[0].p, a[1].p), a[0].p); }
static int t_discrepancy_count(const adv_val *a) { return mcs_discrepancy_count(a[0].p, (mcs_discrepancy_measure)a[1].e, a[2].p); }
static int t_discrepancy_mean(const adv_val *a) { return mcs_discrepancy_mean(a[0].p, (mcs_discrepancy_measure)a[1].e, a[2].p); }
static int t_discrepancy_stderr(const adv_val *a) { return mcs_discrepancy_stderr(a[0].p, (mcs_discrepancy_measure)a[1].e, a[2].p); }
static int t_discrepancy_exact_random(const adv_val *a)
{
    int st = mcs_discrepancy_exact_random(a[0].p, (mcs_discrepancy_measure)a[1].e, a[2].p);
    return st == MCS_OK && !(*(double *)a[2].p > 0.0) ? broken("exact random mean not > 0") : st;
}

/* ---- spacing.h ---- */

/* The least distance is at most the mean of the nearest ones. */
static int distances_sound(int st, const double *out)
{
    if (st == MCS_OK && !(out[0] <= out[1]))
        return broken("min %.17g above avg min %.17g", out[0], out[1]);
    return st;
}

static int t_spacing_statistic_str(const adv_val *a)
{
    return names_known(mcs_spacing_statistic_str((mcs_spacing_statistic)a[0].e),
                       a[0].e >= 0 && a[0].e < MCS_SPACING_STATISTICS);
}
static int t_spacing_packing_distance(const adv_val *a)
{
    int st = mcs_spacing_packing_distance(a[0].z, a[1].z, a[2].p);
    return st == MCS_OK && !(*(double *)a[2].p > 0.0) ? broken("d_max not > 0") : st;
}
static int t_spacing_exact_random(const adv_val *a)
{
    int st = mcs_spacing_exact_random((mcs_spacing_statistic)a[0].e, a[1].z, a[2].z, a[3].p);
    return st == MCS_OK && !(*(double *)a[3].p > 0.0) ? broken("E not > 0") : st;
}
static int t_spacing_work_size(const adv_val *a)
{
    int st = mcs_spacing_work_size(a[0].z, a[1].z, a[2].p);
    return st == MCS_OK && a[1].z <= SIZE_MAX / 32u && *(size_t *)a[2].p > MCS_SPACING_WORK_SIZE(a[1].z)
               ? broken("%zu bytes, above MCS_SPACING_WORK_SIZE(k)", *(size_t *)a[2].p)
               : st;
}
static int t_spacing_distances(const adv_val *a)
{
    return distances_sound(mcs_spacing_distances(a[0].z, a[1].z, a[2].p, a[3].p, a[4].z, a[5].p), a[5].p);
}
static int t_spacing_distances_f(const adv_val *a)
{
    const float *x = floats_begin(a[2].p);
    int st = mcs_spacing_distances_f(a[0].z, a[1].z, x, a[3].p, a[4].z, a[5].p);
    floats_end(a[2].p);
    return distances_sound(st, a[5].p);
}
static int t_spacing_init(const adv_val *a) { return spacing_after(mcs_spacing_init(a[0].p, a[1].z), a[0].p); }
static int t_spacing_add(const adv_val *a)
{
    return spacing_after(mcs_spacing_add(a[0].p, a[1].z, a[2].p, a[3].p, a[4].z), a[0].p);
}
static int t_spacing_add_f(const adv_val *a)
{
    const float *x = floats_begin(a[2].p);
    int st = mcs_spacing_add_f(a[0].p, a[1].z, x, a[3].p, a[4].z);
    floats_end(a[2].p);
    return spacing_after(st, a[0].p);
}
static int t_spacing_merge(const adv_val *a) { return spacing_after(mcs_spacing_merge(a[0].p, a[1].p), a[0].p); }
static int t_spacing_count(const adv_val *a) { return mcs_spacing_count(a[0].p, a[1].p); }
static int t_spacing_mean(const adv_val *a) { return mcs_spacing_mean(a[0].p, (mcs_spacing_statistic)a[1].e, a[2].p); }
static int t_spacing_stderr(const adv_val *a) { return mcs_spacing_stderr(a[0].p, (mcs_spacing_statistic)a[1].e, a[2].p); }

/* ---- nufft.h ---- */

/* c_k of k points by the direct sum in long double (k_y unused in 1D). */
static void direct_mode(size_t dim, const void *p, int is_f, size_t k, long kx, long ky,
                        long double *re, long double *im)
{
    const long double two_pi = 6.283185307179586476925286766559L;
    *re = 0.0L;
    *im = 0.0L;
    for (size_t j = 0; j < k; ++j) {
        long double t = (long double)kx * (long double)coord(p, is_f, j * dim);
        if (dim == 2u)
            t += (long double)ky * (long double)coord(p, is_f, j * dim + 1u);
        t -= floorl(t);
        *re += cosl(two_pi * t);
        *im -= sinl(two_pi * t);
    }
}

/* nufft.h's promises for c of k points: c_{-k} = conj(c_k) exactly (so c_0
 * real), and |c_k - exact| <= tol k (1e-14 k below tol = 1e-14, the
 * rounding floor it gives) at a few modes, the corners included. */
static int modes_sound(const mcs_nufft *plan, const void *p, int is_f, size_t k, const double *c)
{
    const long f = (long)plan->freq, side = 2 * f + 1;
    const size_t modes = plan->dim == 1u ? (size_t)side : (size_t)(side * side);
    for (size_t i = 0; i < modes; ++i) {
        const size_t m = modes - 1u - i; /* -k */
        if (c[2u * i] != c[2u * m] || c[2u * i + 1u] != -c[2u * m + 1u])
            return broken("c at %zu and %zu not conjugate", i, m);
    }
    const long at[4][2] = {{1, 0}, {f, f}, {-f, 1}, {0, -f}};
    const double bound = (plan->tol > 1e-14 ? plan->tol : 1e-14) * (double)k;
    for (int q = 0; q < 4; ++q) {
        const long kx = at[q][0], ky = plan->dim == 1u ? 0 : at[q][1];
        const size_t i = (size_t)(plan->dim == 1u ? kx + f : (ky + f) * side + kx + f);
        long double re, im;
        direct_mode(plan->dim, p, is_f, k, kx, ky, &re, &im);
        const double err = (double)hypotl((long double)c[2u * i] - re, (long double)c[2u * i + 1u] - im);
        if (!(err <= bound))
            return broken("c(%ld,%ld) off the direct sum by %.3g > tol K = %.3g", kx, ky, err, bound);
    }
    return MCS_OK;
}

static int t_nufft_size(const adv_val *a)
{
    int st = mcs_nufft_size(a[0].z, a[1].z, a[2].d, a[3].p);
    return st == MCS_OK && *(size_t *)a[3].p > MCS_NUFFT_SIZE(a[0].z, a[1].z)
               ? broken("%zu bytes, above MCS_NUFFT_SIZE", *(size_t *)a[3].p)
               : st;
}
/* A plan init accepts transforms one point right (at most F = 8 here: the
 * rows' buffer holds no larger plan). */
static int t_nufft_init(const adv_val *a)
{
    static double out[2u * 17u * 17u];
    static const double one[2] = {0.3, 0.7};
    int st = mcs_nufft_init(a[0].p, a[1].z, a[2].z, a[3].d, a[4].p, a[5].z);
    mcs_nufft *plan = a[0].p;
    if (st != MCS_OK || plan->freq > 8u)
        return st;
    if (mcs_nufft_type1(plan, one, 1u, out) != MCS_OK)
        return broken("the plan refuses a transform");
    return modes_sound(plan, one, 0, 1u, out);
}
/* The points as the call reads them, kept before it (out may overwrite
 * them): all of the array, as far as the copy holds. */
static double points_before[2u * ADV_LONG_LEN];

static const double *keep_points(const void *p, int is_f)
{
    size_t n = 0;
    for (int g = 0; p != NULL && g < adv_nregs; ++g)
        if (adv_arena + adv_regs[g].off == (const unsigned char *)p)
            n = adv_regs[g].bytes / sizeof(double);
    const size_t cap = sizeof points_before / sizeof points_before[0];
    n = n < cap ? n : cap;
    for (size_t j = 0; j < n; ++j)
        points_before[j] = coord(p, is_f, j);
    return points_before;
}

static int t_nufft_type1(const adv_val *a)
{
    const double *kept = keep_points(a[1].p, 0);
    int st = mcs_nufft_type1(a[0].p, a[1].p, a[2].z, a[3].p);
    return st == MCS_OK ? modes_sound(a[0].p, kept, 0, a[2].z, a[3].p) : st;
}
static int t_nufft_type1_f(const adv_val *a)
{
    const float *x = floats_begin(a[1].p);
    const double *kept = keep_points(x, 1);
    int st = mcs_nufft_type1_f(a[0].p, x, a[2].z, a[3].p);
    floats_end(a[1].p);
    return st == MCS_OK ? modes_sound(a[0].p, kept, 0, a[2].z, a[3].p) : st;
}

/* ---- the table ---- */

static const uint8_t nufft_vars[6] = {0, 1, 2, 3, 4, 5};

#define OUT_VAL(nm) OUT(nm, E_D, O_VAL, 0)
#define OUT_NN(nm) OUT(nm, E_D, O_NN, 0)
/* A length arrays follow, valid from lo_. */
#define K_LEN(nm, b, lo_, fl) \
    {.name = nm, .kind = K_SIZE, .role = Z_LEN, .base = b, .lo = lo_, .hi = SIZE_MAX, .flags = fl}
/* A size from lo_ up with no maximum, no array following it. */
#define K_ANY(nm, b, lo_, fl) \
    {.name = nm, .kind = K_SIZE, .role = Z_DEF, .base = b, .lo = lo_, .hi = SIZE_MAX, .flags = F_NOMAX | (fl)}
#define CONST_LEN(n) {.op = L_CONST, .c = n}
#define WORK(nm, bytes_slot, fl) AOUT(nm, E_U8, O_RAW, LEN(L_SLOT, bytes_slot), fl)
#define DIM_D SZ_DEF("dim", 2, 1, MCS_DISCREPANCY_MAX_DIM, F_OKIN)
#define DIM_S SZ_DEF("dim", 2, 1, MCS_SPACING_MAX_DIM, F_OKIN)
#define MEASURE(hi_) ENM("measure", 0, 0, hi_, F_OKIN)
#define STATISTIC ENM("statistic", 0, 0, 1, F_OKIN)
#define D_IN OBJ_IN("acc", T_DISC, 0)
#define S_IN OBJ_IN("acc", T_SPACING, 0)
#define STAR_K SZ_DEF("k", BK, 1, MCS_DISCREPANCY_STAR_MAX_K, F_OKIN)
#define STAR_WORK MCS_DISCREPANCY_STAR_WORK_SIZE(MCS_DISCREPANCY_STAR_MAX_K)
/* An add's set: ADV_LONG_LEN points of the accumulator's dimension (adv_state_nn). */
#define SET_POINTS AIN("points", E_D, R_POINT, LEN(L_OBJNN, 0), 0)
#define TOL(fl)                                                                             \
    {.name = "tol", .kind = K_DBL, .role = R_RANGE, .dbase = 1e-9, .dlo = MCS_NUFFT_TOL_MIN, \
     .dhi = MCS_NUFFT_TOL_MAX, .flags = fl}
/* A plan's points[k d]: L_KDIM reads d from the variant as the plan does. */
#define NUFFT_T1                                                                          \
    OBJ_IO("plan", T_NUFFT, 0), AIN("points", E_D, R_POINT, LEN2(L_KDIM, 2, 0), 0),         \
        K_LEN("k", BK, 1, F_OKIN), AOUT("out", E_D, O_VAL, LEN(L_OBJNN, 0), 0)

const adv_fn adv_fns_measures[] = {
    FN(discrepancy_measure_str, EF_NONE, 1, 0, ENM("measure", 0, 0, 6, F_FREE)),
    FN(discrepancy_l2, EF_NONE, 1, 0, K_LEN("k", BK, 1, F_OKIN), DIM_D,
       AIN("points", E_D, R_POINT, LEN2(L_PROD, 0, 1), 0), AOUT("d2", E_D, O_VAL, CONST_LEN(6), 0)),
    FN(discrepancy_l2_f, EF_NONE, 1, 0, K_LEN("k", BK, 1, F_OKIN), DIM_D,
       AIN("points", E_D, R_POINT, LEN2(L_PROD, 0, 1), 0), AOUT("d2", E_D, O_VAL, CONST_LEN(6), 0)),
    FN(discrepancy_l2_exact_random, EF_NONE, 1, 0, MEASURE(5), K_ANY("k", BK, 1, F_OKIN), DIM_D,
       OUT_NN("out")),
    /* n from 1: n^dim fits a size_t for every dim; n^2 up to the largest n */
    FN(discrepancy_l2_exact_jittered, EF_NONE, 1, 0, MEASURE(5),
       SZ_DEF("n", 1, 1, ((size_t)1 << (4u * sizeof(size_t))) - 1u, F_OKIN), DIM_D, OUT_NN("out")),
    FN(discrepancy_l2_exact_jittered2d, EF_NONE, 1, 0, MEASURE(5),
       SZ_DEF("nx", 4, 1, SIZE_MAX / 4u, F_OKIN), SZ_DEF("ny", 4, 1, SIZE_MAX / 4u, F_OKIN),
       OUT_NN("out")),
    FN(discrepancy_star_work_size, EF_NONE, 1, 0, STAR_K, OUT("bytes", E_Z, O_RAW, 0)),
    FN(discrepancy_star, EF_NONE, 1, 0, STAR_K, AIN("points", E_D, R_POINT, LEN(L_2SLOT, 0), 0),
       WORK("work", 3, 0), K_LEN("work_bytes", STAR_WORK, 1, 0), OUT_NN("out")),
    FN(discrepancy_star_f, EF_NONE, 1, 0, STAR_K, AIN("points", E_D, R_POINT, LEN(L_2SLOT, 0), 0),
       WORK("work", 3, 0), K_LEN("work_bytes", STAR_WORK, 1, 0), OUT_NN("out")),
    FN(discrepancy_init, EF_INIT, 1, 0, OBJ_OUT("acc", T_DISC), DIM_D),
    FN(discrepancy_add, EF_ADD, 1, 0, OBJ_IO("acc", T_DISC, 0), K_LEN("k", ADV_LONG_LEN, 1, F_OKIN),
       SET_POINTS, WORK("work", 4, F_NULLOK),
       K_LEN("work_bytes", MCS_DISCREPANCY_STAR_WORK_SIZE(ADV_LONG_LEN), 1, 0)),
    FN(discrepancy_add_f, EF_ADD, 1, 0, OBJ_IO("acc", T_DISC, 0), K_LEN("k", ADV_LONG_LEN, 1, F_OKIN),
       SET_POINTS, WORK("work", 4, F_NULLOK),
       K_LEN("work_bytes", MCS_DISCREPANCY_STAR_WORK_SIZE(ADV_LONG_LEN), 1, 0)),
    FN(discrepancy_merge, EF_MERGE, 1, 0, OBJ_IO("dst", T_DISC, 0), OBJ_IN("src", T_DISC, F_SIZED)),
    FN(discrepancy_count, EF_NONE, 1, 0, D_IN, MEASURE(6), OUT("count", E_U64, O_RAW, 0)),
    FN(discrepancy_mean, EF_NONE, 1, 0, D_IN, MEASURE(6), OUT_VAL("out")),
    FN(discrepancy_stderr, EF_NONE, 1, 0, D_IN, MEASURE(6), OUT_NN("out")),
    FN(discrepancy_exact_random, EF_NONE, 1, 0, D_IN, MEASURE(5), OUT_NN("out")),

    FN(spacing_statistic_str, EF_NONE, 1, 0, ENM("statistic", 0, 0, 1, F_FREE)),
    FN(spacing_packing_distance, EF_NONE, 1, 0, DIM_S, K_ANY("k", 64, 1, F_OKIN), OUT_NN("out")),
    /* 1D: both statistics have a value; 3D to 8D none (MCS_ERR_DOMAIN) */
    FN(spacing_exact_random, EF_NONE, 1, 0, STATISTIC, SZ_DEF("dim", 1, 1, MCS_SPACING_MAX_DIM, 0),
       K_ANY("k", 64, 2, F_OKIN), OUT_NN("out")),
    FN(spacing_work_size, EF_NONE, 1, 0, DIM_S, K_ANY("k", 64, 2, 0), OUT("bytes", E_Z, O_RAW, 0)),
    FN(spacing_distances, EF_NONE, 1, 0, K_LEN("k", 64, 2, F_OKIN), DIM_S,
       AIN("points", E_D, R_POINT, LEN2(L_PROD, 0, 1), 0), WORK("work", 4, 0),
       K_LEN("work_bytes", MCS_SPACING_WORK_SIZE(ADV_LONG_LEN), 1, 0),
       AOUT("out", E_D, O_NN, CONST_LEN(2), 0)),
    FN(spacing_distances_f, EF_NONE, 1, 0, K_LEN("k", 64, 2, F_OKIN), DIM_S,
       AIN("points", E_D, R_POINT, LEN2(L_PROD, 0, 1), 0), WORK("work", 4, 0),
       K_LEN("work_bytes", MCS_SPACING_WORK_SIZE(ADV_LONG_LEN), 1, 0),
       AOUT("out", E_D, O_NN, CONST_LEN(2), 0)),
    FN(spacing_init, EF_INIT, 1, 0, OBJ_OUT("acc", T_SPACING), DIM_S),
    FN(spacing_add, EF_ADD, 1, 0, OBJ_IO("acc", T_SPACING, 0), K_LEN("k", ADV_LONG_LEN, 2, F_OKIN),
       SET_POINTS, WORK("work", 4, 0), K_LEN("work_bytes", MCS_SPACING_WORK_SIZE(ADV_LONG_LEN), 1, 0)),
    FN(spacing_add_f, EF_ADD, 1, 0, OBJ_IO("acc", T_SPACING, 0), K_LEN("k", ADV_LONG_LEN, 2, F_OKIN),
       SET_POINTS, WORK("work", 4, 0), K_LEN("work_bytes", MCS_SPACING_WORK_SIZE(ADV_LONG_LEN), 1, 0)),
    FN(spacing_merge, EF_MERGE, 1, 0, OBJ_IO("dst", T_SPACING, 0), OBJ_IN("src", T_SPACING, F_SIZED)),
    FN(spacing_count, EF_NONE, 1, 0, S_IN, OUT("count", E_U64, O_RAW, 0)),
    FN(spacing_mean, EF_NONE, 1, 0, S_IN, STATISTIC, OUT_NN("out")),
    FN(spacing_stderr, EF_NONE, 1, 0, S_IN, STATISTIC, OUT_NN("out")),

    FN(nufft_size, EF_NONE, 1, 0, SZ_DEF("dim", 2, 1, 2, F_OKIN),
       SZ_DEF("freq", 8, 1, MCS_NUFFT_MAX_FREQ_2D, F_OKIN), TOL(F_OKIN), OUT("bytes", E_Z, O_RAW, 0)),
    FN(nufft_init, EF_NONE, 1, 0, OBJ_OUT("plan", T_NUFFT), SZ_DEF("dim", 2, 1, 2, F_OKIN),
       SZ_DEF("freq", 8, 1, MCS_NUFFT_MAX_FREQ_2D, 0), TOL(F_OKIN), WORK("mem", 5, 0),
       K_LEN("bytes", MCS_NUFFT_SIZE(2, 8), 1, 0)),
    FNV(nufft_type1, EF_NONE, nufft_vars, 0, NUFFT_T1),
    FNV(nufft_type1_f, EF_NONE, nufft_vars, 0, NUFFT_T1),
};
const size_t adv_fns_measures_count = sizeof adv_fns_measures / sizeof adv_fns_measures[0];

/* ---- checks a row cannot express (scenarios) ---- */

static _Alignas(64) unsigned char pool[1u << 18];
static _Alignas(64) unsigned char pool_before[1u << 18];
static double set_a[2u * 200u];

/* The bytes of pool from off on, bytes of them and 64 after, as a guarded
 * buffer: everything else in the pool 0xA5. */
static unsigned char *guarded(size_t off, size_t bytes)
{
    memset(pool, 0xA5, off + bytes + 64u);
    return pool + off;
}

static int guards_intact(size_t off, size_t bytes)
{
    for (size_t i = 0; i < off + bytes + 64u; ++i)
        if ((i < off || i >= off + bytes) && pool[i] != 0xA5)
            return 0;
    return 1;
}

static void keep_pool(void) { memcpy(pool_before, pool, sizeof pool); }
static int pool_kept(void) { return memcmp(pool_before, pool, sizeof pool) == 0; }

/* Points of a set in [0, 1), spread. */
static void spread_set(size_t k, size_t dim, double *p)
{
    for (size_t j = 0; j < k * dim; ++j)
        p[j] = fmod(0.6180339887 * (double)j + 0.7548776662 * (double)(j % dim) + 0.05, 1.0);
}

static const size_t offsets[4] = {0u, 1u, 3u, 7u};

/* Star, spacing (1D and 2D, on the grid), both adds: with the queried work
 * at every offset the same doubles; one byte less refused, changing nothing. */
static int measures_exact_work(void)
{
    double first[2] = {0.0, 0.0}, v[2] = {0.0, 0.0};
    size_t need = 0;
    spread_set(200u, 2u, set_a);
    for (int form = 0; form < 5; ++form) {
        const size_t dim = form == 2 ? 1u : 2u, k = form == 0 || form == 3 ? 50u : 200u;
        mcs_discrepancy dacc;
        mcs_spacing sacc;
        mcs_status st = form == 0 || form == 3 ? mcs_discrepancy_star_work_size(k, &need)
                                               : mcs_spacing_work_size(dim, k, &need);
        if (st != MCS_OK || need == 0u || need + 72u > sizeof pool)
            return broken("form %d: no work to query (%s, %zu bytes)", form, mcs_status_str(st), need);
        for (int q = 0; q < 4; ++q) {
            for (int less = 0; less < 2; ++less) {
                const size_t off = offsets[q], bytes = need - (size_t)less;
                unsigned char *w = guarded(off, need);
                (void)mcs_discrepancy_init(&dacc, 2u);
                (void)mcs_spacing_init(&sacc, dim);
                const mcs_discrepancy d0 = dacc;
                const mcs_spacing s0 = sacc;
                v[0] = v[1] = -1.0;
                keep_pool();
                switch (form) {
                case 0: st = mcs_discrepancy_star(k, set_a, w, bytes, v); break;
                case 1:
                case 2: st = mcs_spacing_distances(k, dim, set_a, w, bytes, v); break;
                case 3: st = mcs_discrepancy_add(&dacc, k, set_a, w, bytes); break;
                default: st = mcs_spacing_add(&sacc, k, set_a, w, bytes); break;
                }
                if (form == 3)
                    (void)mcs_discrepancy_mean(&dacc, MCS_DISCREPANCY_STAR, &v[0]);
                if (form == 4)
                    (void)mcs_spacing_mean(&sacc, MCS_SPACING_MIN_DISTANCE, &v[0]);
                if (less && (st != MCS_ERR_SPACE || !pool_kept() || v[0] != -1.0 || v[1] != -1.0 ||
                             memcmp(&dacc, &d0, sizeof d0) != 0 ||
                             memcmp(&sacc, &s0, sizeof s0) != 0))
                    return broken("form %d, offset %zu: %zu bytes of %zu gave %s or wrote", form, off,
                                  bytes, need, mcs_status_str(st));
                if (less)
                    continue;
                if (st != MCS_OK || !guards_intact(off, need))
                    return broken("form %d, offset %zu: the queried %zu bytes gave %s or wrote past them",
                                  form, off, need, mcs_status_str(st));
                if (q == 0)
                    first[0] = v[0], first[1] = v[1];
                else if (v[0] != first[0] || (form < 3 && v[1] != first[1]))
                    return broken("form %d: offset %zu gives %.17g, offset 0 %.17g", form, off, v[0],
                                  first[0]);
            }
        }
    }
    return MCS_OK;
}

/* Every plan variant: the bytes mcs_nufft_size reports, at every offset,
 * make a plan whose transform of the same points is bit-equal; one byte
 * less refused, plan and buffer unchanged. */
static int nufft_exact_work(void)
{
    static double out[2u * 17u * 17u], first[2u * 17u * 17u];
    static const double tols[6] = {1e-9, 1e-15, 1e-1, 1e-6, 1e-14, 1e-1};
    spread_set(30u, 2u, set_a);
    for (int v = 0; v < 6; ++v) {
        const size_t dim = v < 3 ? 1u : 2u, modes = dim == 1u ? 17u : 289u;
        size_t need = 0;
        if (mcs_nufft_size(dim, 8u, tols[v], &need) != MCS_OK || need + 72u > sizeof pool)
            return broken("no size for variant %d", v);
        for (int q = 0; q < 4; ++q)
            for (int less = 1; less >= 0; --less) {
                const size_t off = offsets[q];
                mcs_nufft plan, before;
                memset(&plan, 0x5A, sizeof plan);
                before = plan;
                unsigned char *mem = guarded(off, need);
                keep_pool();
                mcs_status st = mcs_nufft_init(&plan, dim, 8u, tols[v], mem, need - (size_t)less);
                if (less) {
                    if (st != MCS_ERR_SPACE || !pool_kept() || memcmp(&plan, &before, sizeof plan) != 0)
                        return broken("variant %d: %zu bytes of %zu gave %s or wrote", v, need - 1u,
                                      need, mcs_status_str(st));
                    continue;
                }
                if (st == MCS_OK)
                    st = mcs_nufft_type1(&plan, set_a, 30u, out);
                if (st != MCS_OK || !guards_intact(off, need))
                    return broken("variant %d, offset %zu: %s, or wrote past its buffer", v, off,
                                  mcs_status_str(st));
                if (q == 0)
                    memcpy(first, out, 2u * modes * sizeof(double));
                else if (memcmp(first, out, 2u * modes * sizeof(double)) != 0)
                    return broken("variant %d: the buffer at offset %zu changes c", v, off);
            }
    }
    return MCS_OK;
}

int measures_work_of_exactly_the_queried_size_at_any_alignment_is_enough(const adv_val *a)
{
    (void)a;
    int st = measures_exact_work();
    return st == MCS_OK ? nufft_exact_work() : st;
}

/* The plan's and the measures' MCS_ERR_ALIAS cases, each refused with the
 * pool (every buffer of the call) byte for byte as it was. */
static int refused(int st, const char *what)
{
    if (st == MCS_ERR_ALIAS && pool_kept())
        return MCS_OK;
    return broken("%s: %s%s", what, mcs_status_str((mcs_status)st),
                  pool_kept() ? "" : ", and the buffers changed");
}

int measures_overlapping_buffers_are_refused_unchanged(const adv_val *a)
{
    const size_t k = 40u, need = MCS_SPACING_WORK_SIZE(40);
    double *pts = (double *)(void *)(pool + 4096u); /* 640 bytes */
    unsigned char *over = pool + 4096u + 320u;       /* the work from the middle of the points */
    mcs_discrepancy *dacc = (mcs_discrepancy *)(void *)(pool + 16384u);
    mcs_spacing *sacc = (mcs_spacing *)(void *)(pool + 16384u);
    double *out = (double *)(void *)(pool + 32768u);
    size_t star_need = 0, grid_need = 0;
    int st;
    (void)a;
    memset(pool, 0x5A, sizeof pool);
    spread_set(k, 2u, pts);
    (void)mcs_discrepancy_star_work_size(k, &star_need);
    (void)mcs_spacing_work_size(2u, k, &grid_need);
    if (grid_need == 0u || grid_need > need)
        return broken("40 points in 2D take no grid (%zu bytes)", grid_need);
    keep_pool();
    if ((st = refused(mcs_discrepancy_star(k, pts, over, star_need, out), "star, work on the points")))
        return st;
    if ((st = refused(mcs_spacing_distances(k, 2u, pts, over, need, out),
                      "distances, work on the points")))
        return st;
    (void)mcs_discrepancy_init(dacc, 2u);
    keep_pool();
    if ((st = refused(mcs_discrepancy_add(dacc, k, pts, over, star_need),
                      "discrepancy add, work on the points")))
        return st;
    if ((st = refused(mcs_discrepancy_add(dacc, k, pts, pool + 16384u - 64u, star_need),
                      "discrepancy add, work on the accumulator")))
        return st;
    (void)mcs_spacing_init(sacc, 2u);
    keep_pool();
    if ((st = refused(mcs_spacing_add(sacc, k, pts, over, need), "spacing add, work on the points")))
        return st;
    if ((st = refused(mcs_spacing_add(sacc, k, pts, pool + 16384u - 64u, need),
                      "spacing add, work on the accumulator")))
        return st;

    /* The plan: a header inside its buffer; points or c in the buffer or on
     * the header (points put where the grid goes, so they are points). */
    for (size_t dim = 1u; dim <= 2u; ++dim) {
        size_t bytes = 0;
        mcs_nufft *inside = (mcs_nufft *)(void *)(pool + 65536u + 128u);
        mcs_nufft *plan = (mcs_nufft *)(void *)(pool + 16384u);
        unsigned char *mem = pool + 65536u;
        (void)mcs_nufft_size(dim, 8u, 1e-9, &bytes);
        memset(pool, 0x5A, sizeof pool);
        keep_pool();
        if ((st = refused(mcs_nufft_init(inside, dim, 8u, 1e-9, mem, bytes),
                          "init, the plan in its buffer")))
            return st;
        if (mcs_nufft_init(plan, dim, 8u, 1e-9, mem, bytes) != MCS_OK)
            return broken("no plan");
        double *grid = plan->grid;
        spread_set(10u, dim, grid);
        spread_set(10u, dim, pts);
        keep_pool();
        if ((st = refused(mcs_nufft_type1(plan, grid, 10u, out), "type1, points in the buffer")))
            return st;
        if ((st = refused(mcs_nufft_type1(plan, pts, 10u, plan->corr), "type1, c in the buffer")))
            return st;
        if ((st = refused(mcs_nufft_type1(plan, pts, 10u, (double *)(void *)(pool + 16384u - 64u)),
                          "type1, c on the plan")))
            return st;
        const double *on_plan = (const double *)(const void *)(pool + 16384u + 64u);
        if ((st = refused(mcs_nufft_type1(plan, on_plan, 1u, out), "type1, points on the plan")))
            return st;
    }
    return MCS_OK;
}

/* Every field of a plan edited alone: MCS_ERR_UNINIT before a pointer is
 * followed, c and the buffer unchanged; a header copied elsewhere works. */
int nufft_edited_plan_headers_are_refused_unchanged(const adv_val *a)
{
    static double c[2u * 17u * 17u], ref[2u * 17u * 17u], unwritten[2u * 17u * 17u];
    (void)a;
    memset(unwritten, 0x5A, sizeof unwritten);
    spread_set(30u, 2u, set_a);
    for (size_t dim = 1u; dim <= 2u; ++dim) {
        size_t bytes = 0;
        mcs_nufft plan;
        unsigned char *mem = pool + 64u;
        (void)mcs_nufft_size(dim, 8u, 1e-9, &bytes);
        if (mcs_nufft_init(&plan, dim, 8u, 1e-9, mem, bytes) != MCS_OK ||
            mcs_nufft_type1(&plan, set_a, 30u, ref) != MCS_OK)
            return broken("no plan");
        for (int e = 0; e <= 15; ++e) {
            mcs_nufft p = plan;
            switch (e) {
            case 0: p.dim = 3u - dim; break;
            case 1: p.freq += 1u; break;
            case 2: p.freq -= 1u; break;
            case 3: p.n += 2u; break;
            case 4: p.width += 1u; break;
            case 5: p.beta *= 1.5; break;
            case 6: p.fft_len += 1u; break;
            case 7: p.bytes -= 1u; break;
            case 8: p.mem = (unsigned char *)p.mem + 64; break;
            case 9: p.grid += 8; break;
            case 10: p.scratch += 8; break;
            case 11: p.corr += 1; break;
            case 12: p.twiddle = dim == 1u ? NULL : p.corr; break;
            case 13: p.fft = (unsigned char *)p.fft + 64; break;
            case 14: p.key ^= 1u; break;
            default: break; /* the copy itself */
            }
            memset(c, 0x5A, sizeof c);
            keep_pool();
            const mcs_status st = mcs_nufft_type1(&p, set_a, 30u, c);
            if (e == 15 ? st != MCS_OK || memcmp(c, ref, sizeof(double) * (dim == 1u ? 34u : 578u)) != 0
                        : st != MCS_ERR_UNINIT || !pool_kept() || memcmp(c, unwritten, sizeof c) != 0)
                return broken("%zuD plan, edit %d: %s", dim, e, mcs_status_str(st));
        }
    }
    return MCS_OK;
}

/* The rows' tolerances all lie outside [MCS_NUFFT_TOL_MIN, MCS_NUFFT_TOL_MAX]
 * and their cutoffs are the 2D cap: the edges themselves, inclusive, and the
 * next double or integer past them, in 1D and 2D; and the bytes at the caps
 * within MCS_NUFFT_SIZE. */
int nufft_size_accepts_the_edges_of_tol_and_freq_and_no_more(const adv_val *a)
{
    const double tol_in[2] = {MCS_NUFFT_TOL_MIN, MCS_NUFFT_TOL_MAX};
    const double tol_out[2] = {nextafter(MCS_NUFFT_TOL_MIN, 0.0), nextafter(MCS_NUFFT_TOL_MAX, 1.0)};
    (void)a;
    for (size_t dim = 1u; dim <= 2u; ++dim) {
        const size_t cap = dim == 1u ? MCS_NUFFT_MAX_FREQ_1D : MCS_NUFFT_MAX_FREQ_2D;
        for (int e = 0; e < 2; ++e) {
            size_t bytes = 7u;
            mcs_status st = mcs_nufft_size(dim, 8u, tol_in[e], &bytes);
            if (st != MCS_OK)
                return broken("%zuD, tol %.17g: %s", dim, tol_in[e], mcs_status_str(st));
            bytes = 7u;
            st = mcs_nufft_size(dim, 8u, tol_out[e], &bytes);
            if (st != MCS_ERR_DOMAIN || bytes != 7u)
                return broken("%zuD, tol %.17g: %s", dim, tol_out[e], mcs_status_str(st));
            st = mcs_nufft_size(dim, cap, tol_in[e], &bytes);
            if (st != MCS_OK || bytes > MCS_NUFFT_SIZE(dim, cap))
                return broken("%zuD, F = %zu, tol %.3g: %s, %zu bytes", dim, cap, tol_in[e],
                              mcs_status_str(st), bytes);
            bytes = 7u;
            st = mcs_nufft_size(dim, cap + 1u, tol_in[e], &bytes);
            if (st != MCS_ERR_FREQ_RANGE || bytes != 7u)
                return broken("%zuD, F = %zu: %s", dim, cap + 1u, mcs_status_str(st));
        }
    }
    return MCS_OK;
}
