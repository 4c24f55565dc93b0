/* Exact integrals of an integrand over the cells of a grid, and the exact
 * mean squared error of the jittered grid from them (integrand.h):
 * per cell C of area 1/K, Var f(x_C) = K int_C f^2 - (K int_C f)^2, and
 * MSE = (1/K^2) sum_C Var f(x_C). */
#include "integrand_internal.h"

#include <math.h>
#include <stddef.h>

#define SQRT_PI 1.77245385090551602730
#define SQRT_2 1.41421356237309504880

/* ---- Separable families: per axis sums ------------------------------------ */

/* Over the m cells [a/m, (a+1)/m) of one axis of f: sum_a J_a (J the cell
 * integral of the axis factor squared) into *sj and sum_a I_a^2 into *si2.
 * For a separable f = prod_d g_d, sum_C int_C f^2 = prod_d sum_a J_a and
 * sum_C (int_C f)^2 = prod_d sum_a I_a^2. */
typedef struct {
    double sj, si2;
} axis_sums;

/* The Gaussian exp(-(x - c)^2 / (2 s^2)) on [0,1): erf at the cell edges. */
static axis_sums gauss_axis(double c, double s, size_t m)
{
    const double w1 = s * SQRT_2, w2 = s;
    axis_sums r = {0.0, 0.0};
    double e1 = erf((0.0 - c) / w1), e2 = erf((0.0 - c) / w2);
    for (size_t a = 0; a < m; ++a) {
        const double x1 = (double)(a + 1u) / (double)m;
        const double n1 = erf((x1 - c) / w1), n2 = erf((x1 - c) / w2);
        const double i = 0.5 * w1 * SQRT_PI * (n1 - e1), j = 0.5 * w2 * SQRT_PI * (n2 - e2);
        r.sj += j;
        r.si2 += i * i;
        e1 = n1;
        e2 = n2;
    }
    return r;
}

/* The periodised Gaussian sum_n g(x - c - n), n = -3..3. Its square is
 * sum_{n,n'} g(x - c - n) g(x - c - n'), and g(x - a) g(x - b) =
 * exp(-(a - b)^2 / (4 s^2)) exp(-(x - (a + b)/2)^2 / s^2): grouped by
 * j = n + n', a Gaussian of width s / sqrt 2 at c + j/2 with weight
 * W_j = sum over n + n' = j of exp(-(n - n')^2 / (4 s^2)). */
static axis_sums periodic_axis(double c, double s, size_t m)
{
    enum { NI = 2 * MCS_INTEG_IMAGES + 1, NJ = 4 * MCS_INTEG_IMAGES + 1 };
    double wj[NJ] = {0.0};
    for (int n = -MCS_INTEG_IMAGES; n <= MCS_INTEG_IMAGES; ++n)
        for (int q = -MCS_INTEG_IMAGES; q <= MCS_INTEG_IMAGES; ++q)
            wj[n + q + 2 * MCS_INTEG_IMAGES] += exp(-(double)((n - q) * (n - q)) / (4.0 * s * s));
    const double w1 = s * SQRT_2, w2 = s;
    double e1[NI], e2[NJ];
    for (int n = 0; n < NI; ++n)
        e1[n] = erf((0.0 - c - (double)(n - MCS_INTEG_IMAGES)) / w1);
    for (int j = 0; j < NJ; ++j)
        e2[j] = erf((0.0 - c - 0.5 * (double)(j - 2 * MCS_INTEG_IMAGES)) / w2);
    axis_sums r = {0.0, 0.0};
    for (size_t a = 0; a < m; ++a) {
        const double x1 = (double)(a + 1u) / (double)m;
        double i = 0.0, jsum = 0.0;
        for (int n = 0; n < NI; ++n) {
            const double v = erf((x1 - c - (double)(n - MCS_INTEG_IMAGES)) / w1);
            i += v - e1[n];
            e1[n] = v;
        }
        for (int j = 0; j < NJ; ++j) {
            const double v = erf((x1 - c - 0.5 * (double)(j - 2 * MCS_INTEG_IMAGES)) / w2);
            jsum += wj[j] * (v - e2[j]);
            e2[j] = v;
        }
        i *= 0.5 * w1 * SQRT_PI;
        r.sj += 0.5 * w2 * SQRT_PI * jsum;
        r.si2 += i * i;
    }
    return r;
}

/* 1 + a cos(t), t = 2 pi f x + phi: I = h + a [sin t]/(2 pi f),
 * J = h (1 + a^2/2) + 2 a [sin t]/(2 pi f) + a^2 [sin 2t]/(8 pi f). */
static axis_sums cosine_axis(double amp, long freq, double phase, size_t m)
{
    const double w = MCS_INTEG_TWO_PI * (double)freq, h = 1.0 / (double)m;
    axis_sums r = {0.0, 0.0};
    double s0 = sin(phase), d0 = sin(2.0 * phase);
    for (size_t a = 0; a < m; ++a) {
        const double t1 = w * ((double)(a + 1u) / (double)m) + phase;
        const double s1 = sin(t1), d1 = sin(2.0 * t1);
        const double i = h + amp * (s1 - s0) / w;
        const double j = h * (1.0 + 0.5 * amp * amp) + 2.0 * amp * (s1 - s0) / w +
                         amp * amp * (d1 - d0) / (4.0 * w);
        r.sj += j;
        r.si2 += i * i;
        s0 = s1;
        d0 = d1;
    }
    return r;
}

static axis_sums separable_axis(const mcs_integrand *f, size_t axis, size_t m)
{
    switch (f->family) {
    case MCS_INTEGRAND_GAUSSIAN: return gauss_axis(f->centre[axis], f->width, m);
    case MCS_INTEGRAND_GAUSSIAN_PERIODIC: return periodic_axis(f->centre[axis], f->width, m);
    default: return cosine_axis(f->amp[axis], f->freq[axis], f->phase[axis], m);
    }
}

/* ---- The Heaviside: the clipped rectangle --------------------------------------- */

double mcs_integ_halfplane_area_(const mcs_integrand *f, double x0, double x1, double y0,
                                 double y1)
{
    if (f->dim == 1u) {
        const double t = f->centre[0] - x0, h = x1 - x0;
        return t <= 0.0 ? 0.0 : t >= h ? h : t;
    }
    const double px[4] = {x0, x1, x1, x0}, py[4] = {y0, y0, y1, y1};
    double ox[8], oy[8], dist[4];
    for (int i = 0; i < 4; ++i)
        dist[i] = (px[i] - f->centre[0]) * f->normal[0] + (py[i] - f->centre[1]) * f->normal[1];
    int n = 0;
    for (int i = 0; i < 4; ++i) {
        const int j = (i + 1) & 3;
        if (dist[i] > 0.0) {
            ox[n] = px[i];
            oy[n++] = py[i];
        }
        if ((dist[i] > 0.0) != (dist[j] > 0.0)) {
            const double t = dist[i] / (dist[i] - dist[j]);
            ox[n] = px[i] + t * (px[j] - px[i]);
            oy[n++] = py[i] + t * (py[j] - py[i]);
        }
    }
    double a = 0.0;
    for (int i = 0; i < n; ++i) {
        const int j = (i + 1) % n;
        a += ox[i] * oy[j] - ox[j] * oy[i];
    }
    return 0.5 * fabs(a);
}

/* The variance sum over the cells of a 0/1 function from each cell's area
 * A: K A (1 - K A), clamped at 0 (rounding at A = 0 or 1/K). */
static double cell_var(double k, double area)
{
    const double ka = k * area, v = ka * (1.0 - ka);
    return v > 0.0 ? v : 0.0;
}

static double heaviside_sum(const mcs_integrand *f, size_t mx, size_t my)
{
    const double k = (double)mx * (double)my;
    double sum = 0.0;
    if (f->dim == 1u) {
        size_t a = (size_t)(f->centre[0] * (double)mx);
        if (a >= mx)
            a = mx - 1u;
        return cell_var(k, mcs_integ_halfplane_area_(f, (double)a / (double)mx,
                                                     (double)(a + 1u) / (double)mx, 0.0, 1.0));
    }
    for (size_t b = 0; b < my; ++b) {
        const double y0 = (double)b / (double)my, y1 = (double)(b + 1u) / (double)my;
        for (size_t a = 0; a < mx; ++a) {
            const double x0 = (double)a / (double)mx, x1 = (double)(a + 1u) / (double)mx;
            const double cx = 0.5 * (x0 + x1) - f->centre[0], cy = 0.5 * (y0 + y1) - f->centre[1];
            const double mid = cx * f->normal[0] + cy * f->normal[1];
            const double half = 0.5 * ((x1 - x0) * fabs(f->normal[0]) + (y1 - y0) * fabs(f->normal[1]));
            if (fabs(mid) >= half) /* the line misses the cell: f is constant on it */
                continue;
            sum += cell_var(k, mcs_integ_halfplane_area_(f, x0, x1, y0, y1));
        }
    }
    return sum;
}

/* ---- The disk: its area over a rectangle ---------------------------------------- */

/* int of sqrt(r^2 - u^2) from 0 to u, |u| <= r. */
static double chord_integral(double u, double r)
{
    const double t = u / r;
    const double h = sqrt(fmax(r * r - u * u, 0.0));
    return 0.5 * (u * h + r * r * asin(t > 1.0 ? 1.0 : t < -1.0 ? -1.0 : t));
}

/* The area of the disk of radius r at the origin inside [x0,x1] x [y0,y1]:
 * int over u of the chord [-h(u), h(u)] clipped to [y0, y1], h = sqrt(r^2 -
 * u^2), in pieces between the u where h meets |y0| or |y1| (on each piece
 * each end of the clipped chord is either h, -h or a side, fixed). */
static double disk_rect(double r, double x0, double x1, double y0, double y1)
{
    const double a = fmax(x0, -r), b = fmin(x1, r);
    if (a >= b || y0 >= r || y1 <= -r)
        return 0.0;
    double cut[6];
    int n = 0;
    cut[n++] = a;
    const double ys[2] = {y0, y1};
    for (int i = 0; i < 2; ++i)
        if (fabs(ys[i]) < r) {
            const double u = sqrt(r * r - ys[i] * ys[i]);
            if (-u > a && -u < b)
                cut[n++] = -u;
            if (u > a && u < b)
                cut[n++] = u;
        }
    cut[n++] = b;
    for (int i = 1; i < n; ++i) /* insertion sort of at most 6 */
        for (int j = i; j > 0 && cut[j - 1] > cut[j]; --j) {
            const double t = cut[j];
            cut[j] = cut[j - 1];
            cut[j - 1] = t;
        }
    double area = 0.0;
    for (int i = 0; i + 1 < n; ++i) {
        const double u0 = cut[i], u1 = cut[i + 1];
        if (u1 <= u0)
            continue;
        const double um = 0.5 * (u0 + u1), hm = sqrt(fmax(r * r - um * um, 0.0));
        const int top_h = hm < y1, bot_h = -hm > y0;
        const double top = top_h ? hm : y1, bot = bot_h ? -hm : y0;
        if (top <= bot)
            continue;
        const double hint = chord_integral(u1, r) - chord_integral(u0, r);
        area += (top_h ? hint : y1 * (u1 - u0)) - (bot_h ? -hint : y0 * (u1 - u0));
    }
    return area;
}

/* The cells of one axis the disk's shadow [c - r, c + r] (mod 1) meets:
 * first (possibly negative, taken mod m) and how many. */
static void shadow(double c, double r, size_t m, long *first, size_t *count)
{
    const long lo = (long)floor((c - r) * (double)m), hi = (long)floor((c + r) * (double)m);
    const size_t n = (size_t)(hi - lo + 1);
    *first = lo;
    *count = n < m ? n : m;
}

static size_t wrap_index(long i, size_t m)
{
    const long r = i % (long)m;
    return (size_t)(r < 0 ? r + (long)m : r);
}

/* The disk's area (with its images) inside cell [x0,x1] x [y0,y1] of [0,1)^2;
 * 1D: the arc's length inside [x0,x1]. */
static double disk_cell(const mcs_integrand *f, double x0, double x1, double y0, double y1)
{
    const double r = f->width;
    double area = 0.0;
    for (int nx = -1; nx <= 1; ++nx) {
        const double cx = f->centre[0] + (double)nx;
        if (f->dim == 1u) {
            const double lo = fmax(x0, cx - r), hi = fmin(x1, cx + r);
            area += hi > lo ? hi - lo : 0.0;
            continue;
        }
        for (int ny = -1; ny <= 1; ++ny) {
            const double cy = f->centre[1] + (double)ny;
            area += disk_rect(r, x0 - cx, x1 - cx, y0 - cy, y1 - cy);
        }
    }
    return area;
}

static double disk_sum(const mcs_integrand *f, size_t mx, size_t my)
{
    const double k = (double)mx * (double)my;
    long fx = 0, fy = 0;
    size_t nx = 0, ny = 1;
    shadow(f->centre[0], f->width, mx, &fx, &nx);
    if (f->dim == 2u)
        shadow(f->centre[1], f->width, my, &fy, &ny);
    double sum = 0.0;
    for (size_t t = 0; t < ny; ++t) {
        const size_t b = f->dim == 2u ? wrap_index(fy + (long)t, my) : 0u;
        const double y0 = (double)b / (double)my, y1 = (double)(b + 1u) / (double)my;
        for (size_t s = 0; s < nx; ++s) {
            const size_t a = wrap_index(fx + (long)s, mx);
            const double x0 = (double)a / (double)mx, x1 = (double)(a + 1u) / (double)mx;
            sum += cell_var(k, disk_cell(f, x0, x1, y0, y1));
        }
    }
    return sum;
}

int mcs_integ_has_jittered_(const mcs_integrand *f)
{
    return f->family != MCS_INTEGRAND_BLINN_PHONG &&
           (f->family != MCS_INTEGRAND_GAUSSIAN_MIXTURE || f->dim == 1u);
}

/* The 1D mixture: per cell by erf (integrand_utk.c); a cell's variance
 * K J - (K I)^2, clamped at 0 (rounding where f is flat on the cell). */
static double mixture_sum(const mcs_integrand *f, size_t m)
{
    const double k = (double)m;
    double sum = 0.0;
    for (size_t a = 0; a < m; ++a) {
        double i1, j;
        mcs_integ_mixture_cell_(f, (double)a / k, (double)(a + 1u) / k, &i1, &j);
        const double v = k * j - (k * i1) * (k * i1);
        sum += v > 0.0 ? v : 0.0;
    }
    return sum;
}

double mcs_integ_jittered_(const mcs_integrand *f, size_t mx, size_t my)
{
    const double k = (double)mx * (double)my;
    switch (f->family) {
    case MCS_INTEGRAND_GAUSSIAN:
    case MCS_INTEGRAND_GAUSSIAN_PERIODIC:
    case MCS_INTEGRAND_COSINE: {
        const axis_sums ax = separable_axis(f, 0u, mx);
        axis_sums ay = {1.0, 1.0};
        if (f->dim == 2u)
            ay = separable_axis(f, 1u, my);
        /* (1/K^2) (K sum_C J_C - K^2 sum_C I_C^2) */
        const double v = ax.sj * ay.sj / k - ax.si2 * ay.si2;
        return v > 0.0 ? v : 0.0;
    }
    case MCS_INTEGRAND_HEAVISIDE: return heaviside_sum(f, mx, my) / (k * k);
    case MCS_INTEGRAND_DISK: return disk_sum(f, mx, my) / (k * k);
    case MCS_INTEGRAND_GAUSSIAN_MIXTURE: return mixture_sum(f, mx) / (k * k); /* 1D only */
    case MCS_INTEGRAND_BLINN_PHONG:
    case MCS_INTEGRAND_FAMILIES: break;
    }
    return 0.0;
}
