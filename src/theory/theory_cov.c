/* Exact covariances of linear functionals X = sum_n x_n s_n of one trial, per
 * pattern kind (see theory.h, "Exact spectra at any N"). A sample in bin b
 * adds v_b = x_b / p_b to X; what differs between kinds is which samples are
 * independent, and over what the one random choice of each is made. */
#include "theory_internal.h"

#include <math.h>
#include <stdint.h>

typedef struct {
    double re, im;
} cval;

/* Weighted Welford sums of one covariance: total weight, means, and the sum
 * of w W_old / W (x - mean_old)(y - mean_old)*, which is the weighted sum of
 * (x - mean)(y - mean)* over everything added (West 1979). With x = y every
 * term is w W_old / W |x - mean_old|^2 >= 0, so a variance is never negative. */
typedef struct {
    double w;
    cval mx, my;
    cval c;
} moments;

static void add(moments *m, double w, cval x, cval y)
{
    if (!(w > 0.0))
        return;
    const double w_old = m->w;
    m->w += w;
    const double r = w / m->w, g = w * (w_old / m->w);
    const cval dx = {x.re - m->mx.re, x.im - m->mx.im};
    const cval dy = {y.re - m->my.re, y.im - m->my.im};
    m->c.re += g * (dx.re * dy.re + dx.im * dy.im);
    m->c.im += g * (dx.im * dy.re - dx.re * dy.im);
    m->mx.re += r * dx.re;
    m->mx.im += r * dx.im;
    m->my.re += r * dy.re;
    m->my.im += r * dy.im;
}

/* out += scale * (the covariance of the sums in m). */
static void add_result(const moments *m, double scale, cval *out)
{
    if (m->w > 0.0) {
        out->re += scale * m->c.re / m->w;
        out->im += scale * m->c.im / m->w;
    }
}

static const moments no_moments = {0.0, {0.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}};

/* The same sums in two passes where the weights can be visited twice: first
 * the means (add_mean), then w (x - mean)(y - mean)* (add_dev), a sum of
 * non-negative terms for x = y, and no division per term. */
static void add_mean(moments *m, double w, cval x, cval y)
{
    m->w += w;
    m->mx.re += w * x.re;
    m->mx.im += w * x.im;
    m->my.re += w * y.re;
    m->my.im += w * y.im;
}

/* Between the passes: sums to means. */
static int to_means(moments *m)
{
    if (!(m->w > 0.0))
        return 0;
    m->mx.re /= m->w;
    m->mx.im /= m->w;
    m->my.re /= m->w;
    m->my.im /= m->w;
    return 1;
}

static void add_dev(moments *m, double w, cval x, cval y)
{
    const double ax = x.re - m->mx.re, bx = x.im - m->mx.im;
    const double ay = y.re - m->my.re, by = y.im - m->my.im;
    m->c.re += w * (ax * ay + bx * by);
    m->c.im += w * (bx * ay - ax * by);
}

/* ---- the weights ------------------------------------------------------------ */

/* Twiddle index of bin b: freq (b + shift) mod N, exactly, in integers. */
static size_t twiddle_index(const mcs_theory_spectrum *ts, const mcs_theory_weight *x, size_t b)
{
    const size_t n = ts->n;
    size_t i = b + x->shift;
    i = i >= n ? i - n : i;
    return (size_t)(((uint64_t)x->freq * (uint64_t)i) % (uint64_t)n);
}

/* The index of bin b + 1 from that of bin b. */
static size_t next_index(const mcs_theory_spectrum *ts, const mcs_theory_weight *x, size_t t)
{
    t += x->freq;
    return t >= ts->n ? t - ts->n : t;
}

/* v_b, the part one sample in bin b adds to X; t the twiddle index of b. */
static cval value(const mcs_theory_spectrum *ts, const mcs_theory_weight *x, size_t b, size_t t)
{
    const double ip = ts->inv_p[b];
    if (x->f != NULL) {
        size_t i = b + x->shift;
        i = i >= ts->n ? i - ts->n : i;
        return (cval){x->f[i] * ip, 0.0};
    }
    const double sc = ip * x->scale;
    return (cval){ts->cos_table[t] * sc, -ts->sin_table[t] * sc};
}

/* ---- random: K independent samples, bin b with probability length[b] ---- */

static void random_cov(const mcs_theory_spectrum *ts, const mcs_theory_weight *x,
                       const mcs_theory_weight *y, cval *out)
{
    moments m = no_moments;
    const size_t tx0 = twiddle_index(ts, x, 0u), ty0 = twiddle_index(ts, y, 0u);
    for (int pass = 0; pass < 2; ++pass) {
        size_t tx = tx0, ty = ty0;
        for (size_t b = 0; b < ts->n; ++b) {
            const cval vx = value(ts, x, b, tx), vy = x == y ? vx : value(ts, y, b, ty);
            if (pass == 0)
                add_mean(&m, ts->length[b], vx, vy);
            else
                add_dev(&m, ts->length[b], vx, vy);
            tx = next_index(ts, x, tx);
            ty = next_index(ts, y, ty);
        }
        if (pass == 0 && !to_means(&m))
            return;
    }
    add_result(&m, (double)ts->k, out); /* K independent samples: K times one */
}

/* ---- stratified: sample j uniform on the stratum [j, j+1) in t units ------ */

/* |[edge[c], edge[c+1]) cap [j, j + 1)| for a bin c that meets stratum j,
 * without the cancellation of two rounded edges: a bin inside the stratum
 * has K length[c] (its length is exact); one cut by the stratum's lower
 * end j has edge[c+1] - j, exact (the two lie within a factor of 2), plus
 * the edge's rounding edge_lo; one cut by its upper end likewise; one over
 * all of it has 1. Each keeps its relative accuracy however small the bin
 * (the plain difference erred by up to K 2^-53, 4e-10 of a bin of
 * g = 2.5e-7 at K = 19, which weighs 1/p ~ 1e5 and so carried the error
 * into every covariance). */
static double stratum_overlap(const mcs_theory_spectrum *ts, double j, size_t c)
{
    const double a = ts->edge[c], b = ts->edge[c + 1u];
    const int cut_low = a < j, cut_high = b > j + 1.0;
    if (!cut_low && !cut_high)
        return (double)ts->k * ts->length[c];
    if (cut_low && cut_high)
        return 1.0;
    if (cut_low)
        return (b - j) + ts->edge_lo[c + 1u];
    return ((j + 1.0) - a) - ts->edge_lo[c];
}

/* Stratum j holds bins lo..hi; the covariance of its one sample, whose
 * probability of bin c is the overlap of [edge[c], edge[c+1]) with it. */
static void stratum_cov(const mcs_theory_spectrum *ts, const mcs_theory_weight *x,
                        const mcs_theory_weight *y, double j, size_t lo, size_t hi, cval *out)
{
    moments m = no_moments;
    const size_t tx0 = twiddle_index(ts, x, lo), ty0 = twiddle_index(ts, y, lo);
    for (int pass = 0; pass < 2; ++pass) {
        size_t tx = tx0, ty = ty0;
        for (size_t c = lo; c <= hi; ++c) {
            const double o = stratum_overlap(ts, j, c);
            const cval vx = value(ts, x, c, tx), vy = x == y ? vx : value(ts, y, c, ty);
            if (pass == 0)
                add_mean(&m, o, vx, vy);
            else
                add_dev(&m, o, vx, vy);
            tx = next_index(ts, x, tx);
            ty = next_index(ts, y, ty);
        }
        if (pass == 0 && !to_means(&m))
            return;
    }
    add_result(&m, 1.0, out); /* the overlaps sum to the stratum's length, 1 */
}

/* Only strata with a bin edge strictly inside hold more than one bin; a
 * stratum inside one bin puts its sample there surely and adds nothing. The
 * strata are independent, so their covariances add: O(N) for any K. */
static void strat_cov(const mcs_theory_spectrum *ts, const mcs_theory_weight *x,
                      const mcs_theory_weight *y, cval *out)
{
    const double kd = (double)ts->k;
    size_t b = 1u;
    while (b < ts->n) {
        const double e = ts->edge[b];
        const double j = floor(e);
        if (e == j || !(j < kd)) { /* an edge on a stratum edge splits no stratum */
            ++b;
            continue;
        }
        /* bins b - 1 .. hi meet stratum j: b - 1 holds t = j (every earlier
         * edge is at most j), and the edges of b .. hi lie inside it */
        size_t hi = b;
        while (hi + 1u < ts->n && ts->edge[hi + 1u] < j + 1.0)
            ++hi;
        stratum_cov(ts, x, y, j, b - 1u, hi, out);
        b = hi + 1u;
    }
}

/* ---- jitter: sample j at j + beta, one beta uniform on [0, 1) ------------- */

static double frac_part(double t)
{
    const double f = t - floor(t);
    return f < 1.0 ? f : 0.0;
}

/* The beta at which a sample crosses edge b: frac(edge[b]). Without
 * importance edge b is b K / N, and its fractional part (b K mod N) / N is
 * taken in integers, so edges that coincide in exact arithmetic coincide here
 * (rounded, 46 * 10 / 50 and 6 * 10 / 50 differ in their last bits and would
 * leave a sliver of beta where one sample has moved and its twin has not). */
static double breakpoint_of(const mcs_theory_spectrum *ts, size_t b)
{
    if (ts->has_importance)
        return frac_part(ts->edge[b]);
    const uint64_t n = ts->n, r = ((uint64_t)b * ((uint64_t)ts->k % n)) % n;
    return (double)r / (double)n;
}

/* X just above beta = 0, where bin b holds ceil(edge[b+1]) - ceil(edge[b])
 * samples (those j with j + beta in the bin). */
static cval jitter_start(const mcs_theory_spectrum *ts, const mcs_theory_weight *x)
{
    cval v = {0.0, 0.0};
    size_t t = twiddle_index(ts, x, 0u);
    double lower = ceil(ts->edge[0]);
    for (size_t b = 0; b < ts->n; ++b) {
        const double upper = ceil(ts->edge[b + 1u]);
        if (upper != lower) {
            const cval s = value(ts, x, b, t);
            v.re += (upper - lower) * s.re;
            v.im += (upper - lower) * s.im;
        }
        lower = upper;
        t = next_index(ts, x, t);
    }
    return v;
}

/* Passing beta = frac(edge[b]) moves one sample from bin b - 1 into bin b. */
static void jitter_step(const mcs_theory_spectrum *ts, const mcs_theory_weight *x, size_t b,
                        cval *v)
{
    const size_t t = twiddle_index(ts, x, b);
    const size_t t_prev = t >= x->freq ? t - x->freq : t + ts->n - x->freq;
    const cval in = value(ts, x, b, t), out = value(ts, x, b - 1u, t_prev);
    v->re += in.re - out.re;
    v->im += in.im - out.im;
}

/* The rounding of breakpoint b (edge_lo: its exact value is the breakpoint
 * plus this); 0 without importance, whose breakpoints are r / N with r an
 * exact integer. */
static double breakpoint_lo(const mcs_theory_spectrum *ts, size_t b)
{
    return ts->has_importance ? ts->edge_lo[b] : 0.0;
}

/* X(beta) is constant between the sorted fractional edges: the covariance
 * over beta is the weighted one over those pieces. A piece's width is the
 * difference of two breakpoints, exact when they are close (a small bin),
 * plus the difference of their roundings: relative accuracy for any width. */
static void jitter_cov(const mcs_theory_spectrum *ts, const mcs_theory_weight *x,
                       const mcs_theory_weight *y, cval *out)
{
    moments m = no_moments;
    cval vx = jitter_start(ts, x), vy = x == y ? vx : jitter_start(ts, y);
    double at = 0.0, at_lo = 0.0;
    for (size_t i = 0; i + 1u < ts->n; ++i) {
        const size_t b = ts->order[i];
        const double next = breakpoint_of(ts, b), next_lo = breakpoint_lo(ts, b);
        if (!(next > 0.0))
            continue; /* an edge on a whole t moves its sample at beta = 0: in the start */
        add(&m, (next - at) + (next_lo - at_lo), vx, x == y ? vx : vy);
        at = next;
        at_lo = next_lo;
        jitter_step(ts, x, b, &vx);
        if (x != y)
            jitter_step(ts, y, b, &vy);
    }
    add(&m, (1.0 - at) - at_lo, vx, x == y ? vx : vy);
    add_result(&m, 1.0, out);
}

/* Heap sort of order[0 .. count-1] by breakpoint: in place, no recursion. */
static double breakpoint(const mcs_theory_spectrum *ts, size_t i)
{
    return breakpoint_of(ts, ts->order[i]);
}

static void sift_down(mcs_theory_spectrum *ts, size_t root, size_t count)
{
    for (;;) {
        size_t child = 2u * root + 1u;
        if (child >= count)
            return;
        if (child + 1u < count && breakpoint(ts, child + 1u) > breakpoint(ts, child))
            ++child;
        if (!(breakpoint(ts, child) > breakpoint(ts, root)))
            return;
        const size_t t = ts->order[root];
        ts->order[root] = ts->order[child];
        ts->order[child] = t;
        root = child;
    }
}

void mcs_theory_sort_breakpoints_(mcs_theory_spectrum *ts)
{
    const size_t count = ts->n - 1u;
    for (size_t i = 0; i < count; ++i)
        ts->order[i] = i + 1u;
    for (size_t i = count / 2u; i-- > 0u;)
        sift_down(ts, i, count);
    for (size_t end = count; end > 1u; --end) {
        const size_t t = ts->order[0];
        ts->order[0] = ts->order[end - 1u];
        ts->order[end - 1u] = t;
        sift_down(ts, 0u, end - 1u);
    }
}

/* ---- homogenized: the stratified pattern shifted by d uniform in [0, N) --- */

/* E[X | shift d] = sum_b v_b <r_b>, weights shifted by d, <r_b> = K length[b]
 * the stratified pattern's mean count. */
static cval shifted_mean(const mcs_theory_spectrum *ts, const mcs_theory_weight *xd)
{
    cval v = {0.0, 0.0};
    size_t t = twiddle_index(ts, xd, 0u);
    for (size_t b = 0; b < ts->n; ++b) {
        const cval s = value(ts, xd, b, t);
        const double count = (double)ts->k * ts->length[b];
        v.re += s.re * count;
        v.im += s.im * count;
        t = next_index(ts, xd, t);
    }
    return v;
}

/* Total covariance over the shift: the mean over d of the stratified
 * covariance of the shifted weights, plus the covariance over d of the
 * conditional means (both non-negative for x = y). */
static void homogenized_cov(const mcs_theory_spectrum *ts, const mcs_theory_weight *x,
                            const mcs_theory_weight *y, cval *out)
{
    const size_t n = ts->n;
    cval within = {0.0, 0.0};
    moments between = no_moments;
    for (size_t d = 0; d < n; ++d) {
        mcs_theory_weight xd = *x, yd = *y;
        xd.shift = (x->shift + d) % n;
        yd.shift = (y->shift + d) % n;
        const mcs_theory_weight *yp = x == y ? &xd : &yd;
        strat_cov(ts, &xd, yp, &within);
        const cval mx = shifted_mean(ts, &xd);
        add(&between, 1.0, mx, x == y ? mx : shifted_mean(ts, &yd));
    }
    out->re += within.re / (double)n;
    out->im += within.im / (double)n;
    add_result(&between, 1.0, out);
}

/* ---- dispatch ------------------------------------------------------------ */

void mcs_theory_strat_cov_(const mcs_theory_spectrum *ts, const mcs_theory_weight *x,
                           const mcs_theory_weight *y, double *re, double *im)
{
    cval c = {0.0, 0.0};
    strat_cov(ts, x, y, &c);
    *re = c.re;
    *im = c.im;
}

void mcs_theory_cov_(const mcs_theory_spectrum *ts, const mcs_theory_weight *x,
                     const mcs_theory_weight *y, double *re, double *im)
{
    cval c = {0.0, 0.0};
    switch (ts->kind) {
    case MCS_PATTERN_RANDOM:
        random_cov(ts, x, y, &c);
        break;
    case MCS_PATTERN_STRATIFIED:
        strat_cov(ts, x, y, &c);
        break;
    case MCS_PATTERN_HOMOGENIZED:
        homogenized_cov(ts, x, y, &c);
        break;
    case MCS_PATTERN_JITTER:
        jitter_cov(ts, x, y, &c);
        break;
    default: /* uniform: deterministic */
        break;
    }
    *re = c.re;
    *im = c.im;
}
