/* Adaptive Gauss-Kronrod quadrature for the integrands without a closed
 * form (integrand_utk.c): the (7, 15) pair on panels of [a, b], the panel of
 * largest error estimate |K15 - G7| bisected until the sum of the estimates
 * is below the tolerance or the panels run out. Fixed storage on the stack
 * (MCS_INTEG_QUAD_PANELS panels), so it nests once without allocating. */
#include "integrand_internal.h"

#include <math.h>
#include <stddef.h>

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

typedef struct {
    double a, b, v[MCS_INTEG_QUAD_N], e[MCS_INTEG_QUAD_N];
} panel;

static void gk15(mcs_integ_quad_fn fn, void *ctx, panel *p)
{
    const double h = 0.5 * (p->b - p->a), c = 0.5 * (p->a + p->b);
    double k[MCS_INTEG_QUAD_N] = {0.0}, g[MCS_INTEG_QUAD_N] = {0.0}, y1[MCS_INTEG_QUAD_N],
           y2[MCS_INTEG_QUAD_N];
    for (int i = 0; i < 8; ++i) {
        fn(ctx, c - h * xk[i], y1);
        if (i < 7)
            fn(ctx, c + h * xk[i], y2);
        for (int n = 0; n < MCS_INTEG_QUAD_N; ++n) {
            const double s = i < 7 ? y1[n] + y2[n] : y1[n];
            k[n] += wk[i] * s;
            if (i & 1)
                g[n] += wg[i / 2] * s;
        }
    }
    for (int n = 0; n < MCS_INTEG_QUAD_N; ++n) {
        p->v[n] = h * k[n];
        p->e[n] = fabs(h * (k[n] - g[n]));
    }
}

double mcs_integ_quad_(mcs_integ_quad_fn fn, void *ctx, double a, double b, double rel,
                       double *out)
{
    panel ps[MCS_INTEG_QUAD_PANELS];
    size_t np = 1;
    ps[0].a = a;
    ps[0].b = b;
    gk15(fn, ctx, &ps[0]);
    double worst = 0.0;
    for (;;) {
        double v[MCS_INTEG_QUAD_N] = {0.0}, e[MCS_INTEG_QUAD_N] = {0.0};
        for (size_t i = 0; i < np; ++i)
            for (int n = 0; n < MCS_INTEG_QUAD_N; ++n) {
                v[n] += ps[i].v[n];
                e[n] += ps[i].e[n];
            }
        int done = 1;
        worst = 0.0;
        for (int n = 0; n < MCS_INTEG_QUAD_N; ++n) {
            out[n] = v[n];
            const double r = v[n] != 0.0 ? e[n] / fabs(v[n]) : (e[n] > 0.0 ? 1.0 : 0.0);
            worst = r > worst ? r : worst;
            done = done && r <= rel;
        }
        if (done || np == (size_t)MCS_INTEG_QUAD_PANELS)
            return worst;
        size_t w = 0; /* the panel with the largest share of the relative error */
        double big = -1.0;
        for (size_t i = 0; i < np; ++i) {
            double s = 0.0;
            for (int n = 0; n < MCS_INTEG_QUAD_N; ++n)
                s += v[n] != 0.0 ? ps[i].e[n] / fabs(v[n]) : ps[i].e[n];
            if (s > big) {
                big = s;
                w = i;
            }
        }
        const double mid = 0.5 * (ps[w].a + ps[w].b);
        ps[np].a = mid;
        ps[np].b = ps[w].b;
        ps[w].b = mid;
        gk15(fn, ctx, &ps[w]);
        gk15(fn, ctx, &ps[np]);
        ++np;
    }
}
