/* Adaptive Gauss-Kronrod quadrature for the integrands without a closed
 * form (integrand_utk.c): the (7, 15) pair on a panel, bisected depth first
 * until the panel's error estimate is within its share (its length over
 * b - a) of the tolerance, or at the rounding floor, or 24 bisections deep,
 * or MAX_PANELS computed;
 * the estimates of the panels kept add up to the error returned. The
 * estimate per panel is QUADPACK's (Piessens et al. 1983, qk15): with
 * D = |K15 - G7| and R the integral of |f - mean| by the Kronrod rule,
 * R min(1, (200 D / R)^1.5), and at least 50 eps times the integral of |f|.
 * Each frame stays small (make stack), so it nests without allocating. */
#include "integrand_internal.h"

#include <float.h>
#include <math.h>
#include <stddef.h>

#define MAX_DEPTH 24
#define MAX_PANELS 2048 /* per call: a guard that the tolerances above never meet */

/* Kronrod nodes on [-1, 1] (the odd ones are Gauss's), and the weights. */
static const double xk[8] = {
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245, 0.0};
static const double wk[8] = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
static const double wg[4] = {0.129484966168869693270611432679082,
                             0.279705391489276667901467771423780,
                             0.381830050505118944950369775488975,
                             0.417959183673469387755102040816327};

/* One panel: its integrals, error estimates and rounding floors. */
typedef struct {
    double v[MCS_INTEG_QUAD_N], e[MCS_INTEG_QUAD_N], round[MCS_INTEG_QUAD_N];
} panel;

static panel gk15(mcs_integ_quad_fn fn, void *ctx, double a, double b)
{
    const double h = 0.5 * (b - a), c = 0.5 * (a + b);
    double y[15][MCS_INTEG_QUAD_N];
    for (int i = 0; i < 7; ++i) {
        fn(ctx, c - h * xk[i], y[i]);
        fn(ctx, c + h * xk[i], y[14 - i]);
    }
    fn(ctx, c, y[7]);
    panel p;
    for (int n = 0; n < MCS_INTEG_QUAD_N; ++n) {
        double k = wk[7] * y[7][n], g = wg[3] * y[7][n], ab = wk[7] * fabs(y[7][n]);
        for (int i = 0; i < 7; ++i) {
            const double s = y[i][n] + y[14 - i][n];
            k += wk[i] * s;
            ab += wk[i] * (fabs(y[i][n]) + fabs(y[14 - i][n]));
            if (i & 1)
                g += wg[i / 2] * s;
        }
        const double mean = 0.5 * k;
        double asc = wk[7] * fabs(y[7][n] - mean);
        for (int i = 0; i < 7; ++i)
            asc += wk[i] * (fabs(y[i][n] - mean) + fabs(y[14 - i][n] - mean));
        const double d = fabs(h * (k - g)), r = fabs(h) * asc;
        const double e = r > 0.0 && d > 0.0 ? r * fmin(1.0, pow(200.0 * d / r, 1.5)) : d;
        p.v[n] = h * k;
        p.round[n] = 50.0 * DBL_EPSILON * fabs(h) * ab;
        p.e[n] = fmax(e, p.round[n]);
    }
    return p;
}

/* 1 if panel p of [a, b] is kept: within its share of tol[] (per unit
 * length) or at its rounding floor, or below DBL_MIN (subnormal values). */
static int kept(const panel *p, double a, double b, const double *tol)
{
    for (int n = 0; n < MCS_INTEG_QUAD_N; ++n)
        if (!(p->e[n] <= tol[n] * (b - a) || p->e[n] <= 2.0 * p->round[n] + DBL_MIN))
            return 0;
    return 1;
}

void mcs_integ_quad_(mcs_integ_quad_fn fn, void *ctx, double a, double b, double rel,
                     const double *floors, double *out, double *err)
{
    panel p = gk15(fn, ctx, a, b);
    double tol[MCS_INTEG_QUAD_N];
    for (int n = 0; n < MCS_INTEG_QUAD_N; ++n) {
        tol[n] = fmax(rel * fabs(p.v[n]), floors[n]) / (b - a);
        out[n] = err[n] = 0.0;
    }
    /* depth first: the left half now, the right one's ends on a stack (a
     * split pushes one, so MAX_DEPTH entries suffice) */
    double sa[MAX_DEPTH], sb[MAX_DEPTH];
    unsigned char sd[MAX_DEPTH];
    int top = 0, depth = 0, left = MAX_PANELS - 1;
    double ca = a, cb = b;
    for (;;) {
        if (kept(&p, ca, cb, tol) || depth == MAX_DEPTH || left < 2) {
            for (int n = 0; n < MCS_INTEG_QUAD_N; ++n) {
                out[n] += p.v[n];
                err[n] += p.e[n];
            }
            if (top == 0)
                return;
            --top;
            ca = sa[top];
            cb = sb[top];
            depth = sd[top];
            p = gk15(fn, ctx, ca, cb);
            continue;
        }
        const double m = 0.5 * (ca + cb);
        sa[top] = m;
        sb[top] = cb;
        sd[top++] = (unsigned char)(depth + 1);
        cb = m;
        ++depth;
        left -= 2;
        p = gk15(fn, ctx, ca, cb);
    }
}
