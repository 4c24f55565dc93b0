/* The integrand families of utk (Perrier, Doignies and Coeurjolly's
 * IntegrationTest database; integrand.h, docs/measures.md): blinn_phong and
 * gaussian_mixture. Drawing, evaluation and the integrals I and Q, by
 * quadrature (integrand_quad.c) where there is no closed form. */
#include "integrand_internal.h"
#include "random/rng_inline.h"

#include <math.h>
#include <stddef.h>

/* Relative tolerance of every quadrature (integrand.h). */
#define QUAD_REL 3e-13

int mcs_integ_is_utk_(mcs_integrand_family family)
{
    return family == MCS_INTEGRAND_BLINN_PHONG || family == MCS_INTEGRAND_GAUSSIAN_MIXTURE;
}

static int real_ok(double x)
{
    return x - x == 0.0; /* NaN and inf fail */
}

/* ---- blinn_phong --------------------------------------------------------------
 * The quad light is [-1, 1] x {0} x [0, 1], the shading point p (p_y < 0),
 * the surface normal +z. In the quad's frame seen from p (x = e_x, y = e_z,
 * z = -e_y) its corners are (x0 or x0 + 2, y0 or y0 + 1, z0) with
 * x0 = -1 - p_x, y0 = -p_z, z0 = p_y < 0; the edge normals of the spherical
 * rectangle are in closed form, n0 = (0, z0, -y0) / |.|, n1 = (-z0, 0, x1),
 * n2 = (0, -z0, y1), n3 = (z0, 0, -x0), its interior angles
 * g_i = acos(-n_i . n_i+1), its solid angle S = g0 + g1 - k with
 * k = 2 pi - g2 - g3 (Urena, Fajardo and King 2013). frame[] keeps
 * S, k, n0_z, n2_z, x0, y0, z0. */

enum { F_S, F_K, F_N0Z, F_N2Z, F_X0, F_Y0, F_Z0 };

static void bp_frame(const double *p, double *fr)
{
    const double x0 = -1.0 - p[0], x1 = x0 + 2.0, y0 = -p[2], y1 = y0 + 1.0, z0 = p[1];
    const double l0 = sqrt(z0 * z0 + y0 * y0), l1 = sqrt(z0 * z0 + x1 * x1);
    const double l2 = sqrt(z0 * z0 + y1 * y1), l3 = sqrt(z0 * z0 + x0 * x0);
    /* -n_i . n_i+1 from the components above */
    const double d01 = (y0 * x1) / (l0 * l1), d12 = -(x1 * y1) / (l1 * l2);
    const double d23 = (y1 * x0) / (l2 * l3), d30 = -(x0 * y0) / (l3 * l0);
    const double g0 = acos(fmax(-1.0, fmin(1.0, d01))), g1 = acos(fmax(-1.0, fmin(1.0, d12)));
    const double g2 = acos(fmax(-1.0, fmin(1.0, d23))), g3 = acos(fmax(-1.0, fmin(1.0, d30)));
    const double k = MCS_INTEG_TWO_PI - g2 - g3;
    fr[F_S] = g0 + g1 - k;
    fr[F_K] = k;
    fr[F_N0Z] = -y0 / l0;
    fr[F_N2Z] = y1 / l2;
    fr[F_X0] = x0;
    fr[F_Y0] = y0;
    fr[F_Z0] = z0;
}

/* One column u1 of the map: the quad's x coordinate xu, and the range
 * [h0, h1] of the sine of the elevation along the column. */
typedef struct {
    const mcs_integrand *f;
    double xu, d, h0, h1;
} bp_col;

static bp_col bp_column(const mcs_integrand *f, double u1)
{
    const double *fr = f->frame;
    const double au = u1 * fr[F_S] + fr[F_K], n0z = fr[F_N0Z];
    const double fu = (cos(au) * n0z - fr[F_N2Z]) / sin(au);
    double cu = (fu > 0.0 ? 1.0 : -1.0) / sqrt(fu * fu + n0z * n0z);
    cu = fmax(-1.0, fmin(1.0, cu));
    const double z0 = fr[F_Z0], x0 = fr[F_X0];
    double xu = -(cu * z0) / sqrt(fmax(1.0 - cu * cu, 0.0));
    xu = fmax(x0, fmin(x0 + 2.0, xu)); /* also when cu = +-1 gave an infinity */
    bp_col c;
    c.f = f;
    c.xu = xu;
    c.d = sqrt(xu * xu + z0 * z0);
    const double y0 = fr[F_Y0], y1 = y0 + 1.0;
    c.h0 = y0 / sqrt(c.d * c.d + y0 * y0);
    c.h1 = y1 / sqrt(c.d * c.d + y1 * y1);
    return c;
}

/* f at u2 on column c: S fr(o, l) cos(l), l = (xu, -z0, yv). */
static double bp_point(const bp_col *c, double u2)
{
    const mcs_integrand *f = c->f;
    const double hv = c->h0 + u2 * (c->h1 - c->h0), y0 = f->frame[F_Y0];
    const double yv = hv * hv < 1.0 ? hv * c->d / sqrt(1.0 - hv * hv) : hv > 0.0 ? y0 + 1.0 : y0;
    if (!(yv > 0.0))
        return 0.0; /* below the horizon of the shading point */
    const double lx = c->xu, ly = -f->frame[F_Z0], r = sqrt(lx * lx + ly * ly + yv * yv);
    const double hx = f->view[0] + lx / r, hy = f->view[1] + ly / r, hz = f->view[2] + yv / r;
    const double hn = sqrt(hx * hx + hy * hy + hz * hz);
    if (!(hz > 0.0))
        return 0.0;
    const double a = f->exponent;
    return f->frame[F_S] * (a + 8.0) / (8.0 * MCS_INTEG_PI) * pow(hz / hn, a) * (yv / r);
}

static void bp_inner(void *ctx, double u2, double *out)
{
    const double v = bp_point(ctx, u2);
    out[0] = v;
    out[1] = v * v;
    out[2] = out[3] = 0.0;
}

/* The outer quadrature's context: the integrand and the inner quadratures'
 * absolute floors (1e-14 of a first estimate of I and Q: a column far below
 * the lobe needs no relative accuracy of its own; +inf for the error
 * components, which never drive the bisection). */
typedef struct {
    const mcs_integrand *f;
    double floors[MCS_INTEG_QUAD_N];
} bp_ctx;

/* The column's integrals of f and f^2 over u2, from the horizon up, and
 * their error estimates (components 2 and 3, integrated over u1 beside
 * them, bound what the inner quadratures leave out). */
static void bp_outer(void *ctx, double u1, double *out)
{
    const bp_ctx *b = ctx;
    bp_col c = bp_column(b->f, u1);
    out[0] = out[1] = out[2] = out[3] = 0.0;
    if (!(c.h1 > 0.0))
        return;
    const double lo = c.h0 < 0.0 ? c.h0 / (c.h0 - c.h1) : 0.0; /* hv = 0 */
    if (!(lo < 1.0))
        return;
    double e[MCS_INTEG_QUAD_N];
    mcs_integ_quad_(bp_inner, &c, lo, 1.0, QUAD_REL, b->floors, out, e);
    out[2] = e[0];
    out[3] = e[1];
}

/* The relative error estimate of v[0], v[1] from the absolute ones e[]. */
static double rel_error(const double *v, const double *e)
{
    double r = 0.0;
    for (int n = 0; n < 2; ++n)
        r = fmax(r, v[n] > 0.0 ? e[n] / v[n] : (e[n] > 0.0 ? 1.0 : 0.0));
    return r;
}

/* I and Q of a drawn blinn_phong: a midpoint sum on 8 x 8 cells for the
 * floors, then the nested quadrature; the error is the outer one's plus
 * the integral over u1 of the inner ones'. */
static void bp_moments(mcs_integrand *g)
{
    bp_ctx b = {g, {0.0, 0.0, (double)INFINITY, (double)INFINITY}};
    for (int i = 0; i < 8; ++i) {
        const bp_col c = bp_column(g, (i + 0.5) / 8.0);
        for (int j = 0; j < 8; ++j) {
            const double v = bp_point(&c, (j + 0.5) / 8.0);
            b.floors[0] += 1e-14 / 64.0 * v;
            b.floors[1] += 1e-14 / 64.0 * v * v;
        }
    }
    const double none[MCS_INTEG_QUAD_N] = {0.0, 0.0, (double)INFINITY, (double)INFINITY};
    double v[MCS_INTEG_QUAD_N], e[MCS_INTEG_QUAD_N];
    mcs_integ_quad_(bp_outer, &b, 0.0, 1.0, QUAD_REL, none, v, e);
    e[0] += v[2];
    e[1] += v[3];
    g->integral = v[0];
    g->square = v[1];
    g->error = rel_error(v, e);
}

static void bp_draw(mcs_integrand *g, mcs_rng *rng)
{
    /* p uniform on the half sphere y < 0: p_y uniform (Archimedes), as
     * utk's normalised Gaussian with y = -|y| (its radius pow(r, 1 / 3) is
     * pow(r, 0) = 1 in C++ integer division); p_y <= -0.01 here, off the
     * light's plane, where the map degenerates (docs/measures.md) */
    const double py = -(MCS_INTEGRAND_BLINN_PHONG_MIN_DEPTH +
                        (1.0 - MCS_INTEGRAND_BLINN_PHONG_MIN_DEPTH) * mcs_rng_double_(rng));
    const double phi = MCS_INTEG_TWO_PI * mcs_rng_double_(rng);
    const double rho = sqrt(fmax(1.0 - py * py, 0.0));
    g->shading[0] = rho * cos(phi);
    g->shading[1] = py;
    g->shading[2] = rho * sin(phi);
    g->exponent = MCS_INTEGRAND_BLINN_PHONG_MIN_EXPONENT +
                  mcs_rng_double_(rng) * (MCS_INTEGRAND_BLINN_PHONG_MAX_EXPONENT -
                                          MCS_INTEGRAND_BLINN_PHONG_MIN_EXPONENT);
    const double cp = mcs_rng_double_(rng), ct = mcs_rng_double_(rng);
    const double sp = sqrt(1.0 - cp * cp), st = sqrt(1.0 - ct * ct);
    g->view[0] = cp * st;
    g->view[1] = -sp * st;
    g->view[2] = ct;
    bp_frame(g->shading, g->frame);
    bp_moments(g);
}

static int bp_valid(const mcs_integrand *f)
{
    const double *p = f->shading, *o = f->view;
    const double p2 = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
    const double o2 = o[0] * o[0] + o[1] * o[1] + o[2] * o[2];
    if (f->dim != 2u || !(fabs(p2 - 1.0) <= 1e-12) ||
        !(p[1] <= -MCS_INTEGRAND_BLINN_PHONG_MIN_DEPTH) ||
        !(fabs(o2 - 1.0) <= 1e-12) || !(o[0] >= 0.0) || !(o[1] <= 0.0) || !(o[2] >= 0.0) ||
        !(f->exponent >= MCS_INTEGRAND_BLINN_PHONG_MIN_EXPONENT &&
          f->exponent <= MCS_INTEGRAND_BLINN_PHONG_MAX_EXPONENT))
        return 0;
    double fr[7];
    bp_frame(p, fr);
    for (int i = 0; i < 7; ++i)
        if (!(fr[i] == f->frame[i]))
            return 0; /* the frame is p's own */
    return 1;
}

/* ---- gaussian_mixture ------------------------------------------------------------
 * g_i(x) = exp(-(x - mu_i)^T A_i (x - mu_i) / 2) on its box B_i. A product
 * g_i g_j is exp(-c / 2) exp(-(x - m)^T A (x - m) / 2), A = A_i + A_j,
 * m = A^-1 (A_i mu_i + A_j mu_j), c = sum_i mu_i^T A_i mu_i - m^T A m. */

/* erf(b) - erf(a), a <= b, by erfc in the tails (no cancellation). */
static double erf_diff(double a, double b)
{
    if (a > 0.0)
        return erfc(a) - erfc(b);
    if (b < 0.0)
        return erfc(-b) - erfc(-a);
    return erf(b) - erf(a);
}

/* int_lo^hi exp(-a (x - m)^2 / 2) dx. */
static double gauss_seg(double a, double m, double lo, double hi)
{
    const double s = sqrt(0.5 * a);
    return 0.5 * sqrt(2.0 * MCS_INTEG_PI / a) * erf_diff(s * (lo - m), s * (hi - m));
}

/* A Gaussian exp(-(x - m)^T A (x - m) / 2) over a rectangle: per x, its
 * integral over y is by erf (complete the square in y), then x by quadrature. */
typedef struct {
    double a[3], m[2], ylo, yhi;
} gm_rect;

static void gm_column(void *ctx, double x, double *out)
{
    const gm_rect *r = ctx;
    const double t = x - r->m[0], a11 = r->a[0], a12 = r->a[1], a22 = r->a[2];
    const double shift = a12 * t / a22, det = a11 * a22 - a12 * a12;
    out[0] = exp(-0.5 * det / a22 * t * t) *
             gauss_seg(a22, 0.0, r->ylo - r->m[1] + shift, r->yhi - r->m[1] + shift);
    out[1] = out[2] = out[3] = 0.0;
}

/* The integral into *v; returns its relative error estimate (0 by erf). */
static double gm_box(const double *a, const double *m, size_t dim, const double *lo,
                     const double *hi, double *v)
{
    if (dim == 1u) {
        *v = gauss_seg(a[0], m[0], lo[0], hi[0]);
        return 0.0;
    }
    gm_rect r = {{a[0], a[1], a[2]}, {m[0], m[1]}, lo[1], hi[1]};
    const double none[MCS_INTEG_QUAD_N] = {0.0, 0.0, 0.0, 0.0};
    double w[MCS_INTEG_QUAD_N], e[MCS_INTEG_QUAD_N];
    mcs_integ_quad_(gm_column, &r, lo[0], hi[0], QUAD_REL, none, w, e);
    *v = w[0];
    return rel_error(w, e);
}

/* int over B_i cap B_j of g_i g_j into *v; returns its relative error estimate. */
static double gm_pair(const mcs_integrand *f, size_t i, size_t j, double *v)
{
    *v = 0.0;
    const size_t d = f->dim;
    double lo[2] = {0.0, 0.0}, hi[2] = {0.0, 0.0};
    for (size_t k = 0; k < d; ++k) {
        lo[k] = fmax(f->box_lo[i][k], f->box_lo[j][k]);
        hi[k] = fmin(f->box_hi[i][k], f->box_hi[j][k]);
        if (!(hi[k] > lo[k]))
            return 0.0;
    }
    const double *ai = f->precision[i], *aj = f->precision[j], *mi = f->mean[i], *mj = f->mean[j];
    double a[3], m[2], c;
    if (d == 1u) {
        a[0] = ai[0] + aj[0];
        m[0] = (ai[0] * mi[0] + aj[0] * mj[0]) / a[0];
        c = ai[0] * aj[0] / a[0] * (mi[0] - mj[0]) * (mi[0] - mj[0]);
    } else {
        for (int k = 0; k < 3; ++k)
            a[k] = ai[k] + aj[k];
        const double b0 = ai[0] * mi[0] + ai[1] * mi[1] + aj[0] * mj[0] + aj[1] * mj[1];
        const double b1 = ai[1] * mi[0] + ai[2] * mi[1] + aj[1] * mj[0] + aj[2] * mj[1];
        const double det = a[0] * a[2] - a[1] * a[1];
        m[0] = (a[2] * b0 - a[1] * b1) / det;
        m[1] = (a[0] * b1 - a[1] * b0) / det;
        const double qi = ai[0] * mi[0] * mi[0] + 2.0 * ai[1] * mi[0] * mi[1] + ai[2] * mi[1] * mi[1];
        const double qj = aj[0] * mj[0] * mj[0] + 2.0 * aj[1] * mj[0] * mj[1] + aj[2] * mj[1] * mj[1];
        c = qi + qj - (m[0] * b0 + m[1] * b1);
    }
    const double e = gm_box(a, m, d, lo, hi, v);
    *v *= i == j || c <= 0.0 ? 1.0 : exp(-0.5 * c);
    return e;
}

void mcs_integ_mixture_cell_(const mcs_integrand *f, double x0, double x1, double *i1,
                             double *square)
{
    double si = 0.0, sq = 0.0;
    for (size_t i = 0; i < f->boxes; ++i) {
        const double lo = fmax(x0, f->box_lo[i][0]), hi = fmin(x1, f->box_hi[i][0]);
        if (!(hi > lo))
            continue;
        si += gauss_seg(f->precision[i][0], f->mean[i][0], lo, hi);
        for (size_t j = i; j < f->boxes; ++j) {
            const double l2 = fmax(lo, f->box_lo[j][0]), h2 = fmin(hi, f->box_hi[j][0]);
            if (!(h2 > l2))
                continue;
            const double ai = f->precision[i][0], aj = f->precision[j][0], a = ai + aj;
            const double m = (ai * f->mean[i][0] + aj * f->mean[j][0]) / a;
            const double dm = f->mean[i][0] - f->mean[j][0], c = ai * aj / a * dm * dm;
            sq += (j == i ? 1.0 : 2.0) * exp(-0.5 * c) * gauss_seg(a, m, l2, h2);
        }
    }
    *i1 = si;
    *square = sq;
}

static void gm_precision(double angle, double v0, double v1, double *a)
{
    const double c = cos(angle), s = sin(angle), i0 = 1.0 / v0, i1 = 1.0 / v1;
    a[0] = c * c * i0 + s * s * i1;
    a[1] = c * s * (i0 - i1);
    a[2] = s * s * i0 + c * c * i1;
}

static void gm_draw(mcs_integrand *g, mcs_rng *rng)
{
    const size_t d = g->dim, lo = 2u * d, hi = 2u * d * d;
    const double vmin = MCS_INTEGRAND_MIXTURE_MIN_VARIANCE, vmax = MCS_INTEGRAND_MIXTURE_MAX_VARIANCE;
    g->boxes = lo + (size_t)mcs_rng_bounded_(rng, (uint32_t)(hi - lo + 1u));
    for (size_t i = 0; i < g->boxes; ++i) {
        /* utk: a random orthogonal matrix (its first column a uniform direction) */
        const double angle = d == 2u ? MCS_INTEG_PI * mcs_rng_double_(rng) : 0.0;
        for (size_t k = 0; k < d; ++k) {
            const double x = mcs_rng_double_(rng), y = mcs_rng_double_(rng);
            g->box_lo[i][k] = fmin(x, y);
            g->box_hi[i][k] = fmax(x, y);
        }
        for (size_t k = 0; k < d; ++k)
            g->mean[i][k] = g->box_lo[i][k] + mcs_rng_double_(rng) * (g->box_hi[i][k] - g->box_lo[i][k]);
        const double v0 = vmin + mcs_rng_double_(rng) * (vmax - vmin);
        if (d == 1u) {
            g->precision[i][0] = 1.0 / v0;
            continue;
        }
        const double v1 = vmin + mcs_rng_double_(rng) * (vmax - vmin);
        gm_precision(angle, v0, v1, g->precision[i]);
    }
    /* every term is positive: the sums' relative errors are at most the terms' */
    double i1 = 0.0, q = 0.0, err = 0.0, v;
    for (size_t i = 0; i < g->boxes; ++i) {
        err = fmax(err, gm_box(g->precision[i], g->mean[i], d, g->box_lo[i], g->box_hi[i], &v));
        i1 += v;
        for (size_t j = i; j < g->boxes; ++j) {
            err = fmax(err, gm_pair(g, i, j, &v));
            q += (j == i ? 1.0 : 2.0) * v;
        }
    }
    g->integral = i1;
    g->square = q;
    g->error = err;
}

/* A_i symmetric with eigenvalues in [1 / vmax, 1 / vmin] (1e-12 slack). */
static int gm_precision_ok(const double *a, size_t d)
{
    const double lo = (1.0 - 1e-12) / MCS_INTEGRAND_MIXTURE_MAX_VARIANCE;
    const double hi = (1.0 + 1e-12) / MCS_INTEGRAND_MIXTURE_MIN_VARIANCE;
    if (d == 1u)
        return a[0] >= lo && a[0] <= hi;
    const double mid = 0.5 * (a[0] + a[2]), h = 0.5 * (a[0] - a[2]);
    const double rad = sqrt(h * h + a[1] * a[1]);
    return mid - rad >= lo && mid + rad <= hi; /* NaN fails */
}

static int gm_valid(const mcs_integrand *f)
{
    const size_t d = f->dim;
    if (f->boxes < 2u * d || f->boxes > 2u * d * d)
        return 0;
    for (size_t i = 0; i < f->boxes; ++i) {
        for (size_t k = 0; k < d; ++k)
            if (!(f->box_lo[i][k] >= 0.0 && f->box_lo[i][k] <= f->box_hi[i][k] &&
                  f->box_hi[i][k] < 1.0 && f->mean[i][k] >= f->box_lo[i][k] &&
                  f->mean[i][k] <= f->box_hi[i][k]))
                return 0;
        if (!gm_precision_ok(f->precision[i], d))
            return 0;
    }
    return 1;
}

static double gm_eval(const mcs_integrand *f, const double *x)
{
    double v = 0.0;
    for (size_t i = 0; i < f->boxes; ++i) {
        const double *lo = f->box_lo[i], *hi = f->box_hi[i], *m = f->mean[i], *a = f->precision[i];
        if (x[0] < lo[0] || x[0] > hi[0])
            continue;
        const double t = x[0] - m[0];
        if (f->dim == 1u) {
            v += exp(-0.5 * a[0] * t * t);
            continue;
        }
        if (x[1] < lo[1] || x[1] > hi[1])
            continue;
        const double s = x[1] - m[1];
        v += exp(-0.5 * (a[0] * t * t + 2.0 * a[1] * t * s + a[2] * s * s));
    }
    return v;
}

/* ---- Dispatch ------------------------------------------------------------------- */

int mcs_integ_utk_valid_(const mcs_integrand *f)
{
    const double i1 = f->integral, q = f->square;
    if (!real_ok(i1) || !real_ok(q) || !(i1 >= 0.0) || !(q >= i1 * i1 * (1.0 - 1e-9)) ||
        !(f->error >= 0.0 && f->error < 1.0))
        return 0; /* Cauchy-Schwarz on the unit square: Q >= I^2 */
    return f->family == MCS_INTEGRAND_BLINN_PHONG ? bp_valid(f) : gm_valid(f);
}

void mcs_integ_utk_draw_(mcs_integrand *g, mcs_rng *rng)
{
    if (g->family == MCS_INTEGRAND_BLINN_PHONG)
        bp_draw(g, rng);
    else
        gm_draw(g, rng);
}

double mcs_integ_utk_eval_(const mcs_integrand *f, const double *x)
{
    if (f->family == MCS_INTEGRAND_GAUSSIAN_MIXTURE)
        return gm_eval(f, x);
    const bp_col c = bp_column(f, x[0]);
    return bp_point(&c, x[1]);
}
