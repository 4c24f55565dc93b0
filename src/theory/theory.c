/* Exact discrete moments of every pattern kind (see include/mcspec/theory.h
 * for the interval-overlap model); the read-out is src/accumulators/readout.c. */
#include "mcspec/theory.h"
#include "core/internal.h"
#include "accumulators/readout.h"
#include "theory_internal.h"

#include <float.h>
#include <math.h>

static int theory_is_valid(const mcs_theory *th)
{
    return th->n >= 1u && th->n <= (size_t)MCS_MAX_COV_N && th->k >= 1u &&
           mcs_kind_is_valid_(th->kind);
}

/* ---- exact moments -------------------------------------------------------- */

/* Samples of a shared beta in [0,1) that put j + beta in [a, b), summed over
 * j: r(beta) = ceil(b - beta) - ceil(a - beta) (t = u K units). */
static double jitter_count(double a, double b, double beta)
{
    return ceil(b - beta) - ceil(a - beta);
}

static double frac_part(double x)
{
    double f = x - floor(x);
    return f < 1.0 ? f : 0.0;
}

/* A bin's two edges in t = u K units and their roundings (edge + lo is the
 * exact edge: mcs_theory_edge_lo_). */
typedef struct {
    double a, b, lo_a, lo_b;
} bin_edges;

static bin_edges edges_of(const mcs_pattern *pat, size_t bin)
{
    const bin_edges e = {mcs_theory_edge_(pat, bin), mcs_theory_edge_(pat, bin + 1u),
                         mcs_theory_edge_lo_(pat, bin), mcs_theory_edge_lo_(pat, bin + 1u)};
    return e;
}

/* A breakpoint's rounding, for one strictly inside (0, 1): an edge on a whole
 * t moves its sample at beta = 0 in the rounded edges' model. */
static double point_lo(double frac, double lo)
{
    return frac > 0.0 ? lo : 0.0;
}

/* <r_m r_n> for jitter: the integral over beta in [0,1) of r_m(beta) r_n(beta).
 * Each r is constant between the fractional parts of its two edges, so the
 * integral is exact as a sum over the (at most 5) pieces. A piece's width
 * is the difference of two fractional parts, exact when they are close (a
 * small bin), plus that of their roundings: relative accuracy for any
 * width (without them a bin of g = 2.5e-7 at K = 19 erred by 4e-10). */
static double jitter_pair(const bin_edges *m, const bin_edges *n)
{
    double pts[6] = {0.0, frac_part(m->a), frac_part(m->b), frac_part(n->a), frac_part(n->b), 1.0};
    double los[6] = {0.0, point_lo(pts[1], m->lo_a), point_lo(pts[2], m->lo_b),
                     point_lo(pts[3], n->lo_a), point_lo(pts[4], n->lo_b), 0.0};
    for (int i = 1; i < 5; ++i) /* insertion sort of the four inner points */
        for (int j = i; j > 0 && pts[j] < pts[j - 1]; --j) {
            const double t = pts[j], tl = los[j];
            pts[j] = pts[j - 1];
            los[j] = los[j - 1];
            pts[j - 1] = t;
            los[j - 1] = tl;
        }
    double sum = 0.0;
    for (int i = 0; i < 5; ++i) {
        double w = pts[i + 1] - pts[i];
        if (w > 0.0) {
            double mid = pts[i] + 0.5 * w;
            sum += jitter_count(m->a, m->b, mid) * jitter_count(n->a, n->b, mid) *
                   (w + (los[i + 1] - los[i]));
        }
    }
    return sum;
}

/* |[a, b) intersect [j, j + 1)| in t units: P(u_j in the bin) for stratum j. */
static double stratum_overlap(double a, double b, double j)
{
    double lo = a > j ? a : j;
    double hi = b < j + 1.0 ? b : j + 1.0;
    return hi > lo ? hi - lo : 0.0;
}

/* sum_j P(u_j in I_m) P(u_j in I_n) over strata j: the same-stratum pairs that
 * independent sampling would count but stratification forbids. Strata meeting
 * both bins run from j_lo to j_hi; the inner ones lie inside both bins (only
 * possible for m = n) and contribute 1 each, so the cost is O(1) for any K. */
static double strat_pair(double am, double bm, double an, double bn)
{
    if (!(bm > am) || !(bn > an))
        return 0.0;
    double j_lo = fmax(floor(am), floor(an));
    double j_hi = fmin(ceil(bm), ceil(bn)) - 1.0;
    if (j_hi < j_lo)
        return 0.0;
    double sum = stratum_overlap(am, bm, j_lo) * stratum_overlap(an, bn, j_lo);
    if (j_hi > j_lo)
        sum += stratum_overlap(am, bm, j_hi) * stratum_overlap(an, bn, j_hi) +
               (j_hi - j_lo - 1.0);
    return sum;
}

/* Homogenized: the generator shifts the stratified bins by d uniform in [0, N),
 * so <s_m s_n> = (1/N) sum_d strat<s_{m-d} s_{n-d}>, a function of n - m only. */
static void homogenize(mcs_theory *th)
{
    size_t n = th->n;
    double mean = 0.0;
    for (size_t d = 0; d < n; ++d)
        mean += th->mean_s[d];
    mean /= (double)n;
    /* The lag averages go through mean_s as scratch (no stack array), then
     * fill every row; mean_s gets the (constant) homogenized mean last. */
    for (size_t d = 0; d < n; ++d) {
        double acc = 0.0;
        for (size_t a = 0; a < n; ++a)
            acc += th->second[a * n + (a + d) % n];
        th->mean_s[d] = acc / (double)n;
    }
    for (size_t m = 0; m < n; ++m)
        for (size_t b = 0; b < n; ++b)
            th->second[m * n + b] = th->mean_s[(b + n - m) % n];
    for (size_t m = 0; m < n; ++m)
        th->mean_s[m] = mean;
}

mcs_status mcs_theory_init(mcs_theory *th, const mcs_pattern *pat)
{
    if (th == NULL || pat == NULL)
        return MCS_ERR_NULL;
    mcs_status st = mcs_theory_check_pattern_(pat, (size_t)MCS_MAX_COV_N);
    if (st != MCS_OK)
        return st;

    const size_t n = pat->n;
    const double kd = (double)pat->k;
    th->kind = pat->kind;
    th->n = n;
    th->k = pat->k;
    th->has_importance = pat->importance != NULL;
    mcs_twiddles_(n, th->cos_table, th->sin_table);

    if (pat->kind == MCS_PATTERN_UNIFORM) {
        /* mean_s holds the bin counts r_n until the weights are applied */
        mcs_theory_uniform_counts_(pat, th->mean_s);
        for (size_t m = 0; m < n; ++m)
            th->mean_s[m] *= mcs_theory_inv_p_(pat, m);
        for (size_t m = 0; m < n; ++m)
            for (size_t b = 0; b < n; ++b)
                th->second[m * n + b] = th->mean_s[m] * th->mean_s[b];
        return MCS_OK;
    }

    for (size_t m = 0; m < n; ++m) {
        double len_m = mcs_theory_length_(pat, m), inv_pm = mcs_theory_inv_p_(pat, m);
        double am = mcs_theory_edge_(pat, m), bm = mcs_theory_edge_(pat, m + 1u);
        /* sum_j P(u_j in I_m) = K |I_m| for random, stratified and jitter alike. */
        th->mean_s[m] = kd * len_m * inv_pm;
        for (size_t b = 0; b < n; ++b) {
            double len_b = mcs_theory_length_(pat, b);
            double diag = m == b ? kd * len_m : 0.0; /* j = j': P(u_j in I_m cap I_n) */
            double rr;
            switch (pat->kind) {
            case MCS_PATTERN_RANDOM: /* j != j' independent: K (K - 1) |I_m| |I_n| */
                rr = diag + kd * (kd - 1.0) * len_m * len_b;
                break;
            case MCS_PATTERN_JITTER: { /* one shared beta: exact integral */
                const bin_edges em = edges_of(pat, m), eb = edges_of(pat, b);
                rr = jitter_pair(&em, &eb);
                break;
            }
            default: /* stratified, homogenized: independent across strata only */
                rr = diag + kd * kd * len_m * len_b -
                     strat_pair(am, bm, mcs_theory_edge_(pat, b), mcs_theory_edge_(pat, b + 1u));
                break;
            }
            th->second[m * n + b] = rr * inv_pm * mcs_theory_inv_p_(pat, b);
        }
    }
    if (pat->kind == MCS_PATTERN_HOMOGENIZED)
        homogenize(th);
    return MCS_OK;
}

/* ---- checks ---------------------------------------------------------------- */

/* Bounds every body mcs_theory_init writes keeps (the same bins as
 * mcs_theory_spectrum's, theory_spectrum.c): a sample weighs 1/p_b <= 2^33
 * (2^32 but for the CDF's rounding), so 0 <= <s_b> <= K max 1/p_b < 2^64,
 * and <s_b^2> <= <s_b>^2 + <s_b> max 1/p_b (r_b's variance is at most its
 * mean: r_b counts independent samples, or strata, or takes two neighbouring
 * values; the uniform pattern has none). */
#define MAX_INV_P 0x1p33
#define MAX_MEAN_S 0x1p64

/* How far init's second moments stray from those of a pattern: the bin
 * edges are rounded in t = u K units (to K 2^-53), which the strata
 * overlaps and jitter pieces inherit, so an entry errs by up to about
 * 16 DBL_EPSILON K / (p_m p_n); relative to sqrt(<s_m^2> <s_n^2>) (at least
 * K sqrt(L_m L_n) / (p_m p_n), a bin's length L >= 2^-32) that is below
 * 2^-16. Measured worst over every kind and an importance function at its
 * smallest weight: 2.3e-7 past Cauchy-Schwarz. */
#define SECOND_TOL 0x1p-12

static int in_range(double x, double lo, double hi)
{
    return x >= lo && x <= hi; /* NaN is in no range */
}

/* What every read-out reads besides the second moments, O(N): the flag
 * init sets (homogenized has no importance), <s_b> in [0, 2^64], twiddles
 * in [-1, 1]. */
static int first_is_sound(const mcs_theory *th)
{
    int sound = th->has_importance == 0 ||
                (th->has_importance == 1 && th->kind != MCS_PATTERN_HOMOGENIZED);
    for (size_t b = 0; b < th->n; ++b) {
        sound &= in_range(th->mean_s[b], 0.0, MAX_MEAN_S);
        sound &= in_range(th->cos_table[b], -1.0, 1.0) & in_range(th->sin_table[b], -1.0, 1.0);
    }
    return sound;
}

/* <s_b^2> between <s_b>^2 (s_b's variance is not negative) and
 * <s_b>^2 + 2^34 <s_b> (above), each with room for init's rounding; <s_b>
 * already checked. */
static int diagonal_is_sound(const mcs_theory *th, size_t b)
{
    const double m = th->mean_s[b], d = th->second[b * th->n + b];
    return in_range(d, m * m * (1.0 - SECOND_TOL), m * m + 2.0 * MAX_INV_P * m);
}

/* <s_a s_b> (diagonals already checked): Cauchy-Schwarz,
 * <s_a s_b>^2 <= <s_a^2> <s_b^2>, and not below 0 (s is never negative),
 * each to SECOND_TOL of sqrt(<s_a^2> <s_b^2>) (the root only for a negative
 * entry, which init leaves at rounding level where it leaves one). No
 * product overflows: the diagonals are below 2^129. */
static int entry_is_sound(const mcs_theory *th, size_t a, size_t b)
{
    const size_t n = th->n;
    const double x = th->second[a * n + b];
    const double cs = th->second[a * n + a] * th->second[b * n + b];
    return x * x <= cs * (1.0 + SECOND_TOL) && (x >= 0.0 || -x <= SECOND_TOL * sqrt(cs));
}

/* Every second moment, O(N^2): what the read-outs of the whole matrix read. */
static int second_is_sound(const mcs_theory *th)
{
    const size_t n = th->n;
    int sound = 1;
    for (size_t b = 0; b < n; ++b)
        sound &= diagonal_is_sound(th, b);
    for (size_t a = 0; sound && a < n; ++a)
        for (size_t b = 0; b < n; ++b)
            sound &= entry_is_sound(th, a, b);
    return sound;
}

/* The largest 1/p_b the moments of bin b allow, O(1): 1/p_b <= <s_b^2> /
 * <s_b> when K L_b < 1 (<r_b^2> >= <r_b> = K L_b), 1/p_b <= <s_b> when
 * K L_b >= 1 (<s_b> = K L_b / p_b), and never above MAX_INV_P; 0 for a bin
 * no sample reaches (<s_b> = 0: then every moment of it is 0). */
static double inv_p_bound(const mcs_theory *th, size_t b)
{
    const double m = th->mean_s[b];
    if (!(m > 0.0))
        return 0.0;
    return fmin(fmax(th->second[b * th->n + b] / m, m), MAX_INV_P);
}

double mcs_theory_init_rounding_(const mcs_theory *th, const double *x, double c)
{
    double sm = 0.0, st = 0.0;
    for (size_t b = 0; b < th->n; ++b) {
        const double w = (x != NULL ? fabs(x[b]) : 1.0) + c;
        sm += w * th->mean_s[b];
        st += w * inv_p_bound(th, b);
    }
    return 64.0 * DBL_EPSILON * (sm * sm + (double)th->k * (st * st));
}

/* ---- read-out (src/accumulators/readout.c): the expectations themselves -------------- */

static void fill_view(const mcs_theory *th, mcs_readout *view)
{
    *view = (mcs_readout){.n = th->n,
                          .k = th->k,
                          .scale = 1.0,
                          .first = th->mean_s,
                          .second = th->second,
                          .cos_table = th->cos_table,
                          .sin_table = th->sin_table,
                          .exact_rounding = mcs_theory_init_rounding_(th, NULL, 0.0)};
}

/* The zeros theory proves for th (theory_internal.h), formed before a
 * read-out writes (its outputs may lie in *th); 0 for an object that is not
 * set up (the read-out then refuses it). */
static int zeros_of(const mcs_theory *th, mcs_theory_zeros *z)
{
    if (th == NULL || !theory_is_valid(th))
        return 0;
    *z = mcs_theory_zeros_of_(th->kind, th->n, th->k, th->has_importance == 1, th->mean_s);
    return 1;
}

/* A complex read-out at (k, l) with the zeros of z applied: all of it where
 * zero says so, its imaginary part where both S are real (or k = l). */
static void apply_zeros(const mcs_theory_zeros *z, int zero, size_t k, size_t l, double *re,
                        double *im)
{
    if (zero)
        *re = *im = 0.0;
    if (mcs_theory_im_zero_(z, k, l))
        *im = 0.0;
}

/* Opens th for a read-out of <s> alone (bin_mean, mean, estimator_mean):
 * MCS_ERR_UNINIT, then MCS_ERR_INVARIANT for the O(N) part. */
static mcs_status open_first(const void *obj, mcs_readout *view)
{
    const mcs_theory *th = (const mcs_theory *)obj;
    if (!theory_is_valid(th))
        return MCS_ERR_UNINIT;
    if (!first_is_sound(th))
        return MCS_ERR_INVARIANT;
    fill_view(th, view);
    return MCS_OK;
}

/* For every read-out of the second moments: open_first, then all of them
 * (O(N^2), the order of the read-out's own cost or less). */
mcs_status mcs_readout_open_theory(const void *obj, mcs_readout *view)
{
    mcs_status st = open_first(obj, view);
    if (st == MCS_OK && !second_is_sound((const mcs_theory *)obj))
        st = MCS_ERR_INVARIANT;
    return st;
}


/* Opens th for a read-out at bins or frequencies a, b (range the status of
 * one outside [0, N)), outputs given: MCS_ERR_NULL, the checks of
 * mcs_readout_open_theory, then range. */
static mcs_status open_at(int outputs, const mcs_theory *th, size_t a, size_t b,
                          mcs_status range, mcs_readout *view)
{
    if (!outputs || th == NULL)
        return MCS_ERR_NULL;
    mcs_status st = mcs_readout_open_theory(th, view);
    return st == MCS_OK && (a >= th->n || b >= th->n) ? range : st;
}

/* The two bounds of the shared read-out for exact moments (readout.c:
 * power_bound, variance_rounding), each plus init's rounding (above), which
 * the read-out does not know of: a power or a variance in [-bound, 0) is
 * rounding and reads 0; one below -bound comes from no moments init writes. */
static double sum_abs_second(const mcs_readout *view)
{
    double a = 0.0;
    for (size_t j = 0; j < view->n * view->n; ++j)
        a += fabs(view->second[j]);
    return a;
}

static double power_tolerance(const mcs_theory *th, const mcs_readout *view)
{
    const double n = (double)th->n;
    return ((2.0 * n + 16.0) * DBL_EPSILON * sum_abs_second(view) +
            mcs_theory_init_rounding_(th, NULL, 0.0)) /
           n;
}

static double variance_tolerance(const mcs_theory *th, const mcs_readout *view)
{
    const double n = (double)th->n;
    double b = 0.0;
    for (size_t j = 0; j < th->n; ++j)
        b += fabs(th->mean_s[j]);
    return (4.0 * (n + 2.0) * DBL_EPSILON * (sum_abs_second(view) + b * b) +
            mcs_theory_init_rounding_(th, NULL, 0.0)) /
           n;
}

/* A value that cannot be negative, judged against its tolerance. */
static mcs_status clamp_nonnegative(double tol, double *v)
{
    if (*v >= 0.0)
        return MCS_OK;
    if (!(*v >= -tol))
        return MCS_ERR_INVARIANT;
    *v = 0.0;
    return MCS_OK;
}

/* <|S_freq|^2> from the shared eq. 16, real (as mcs_readout_power); 0 where
 * S_freq is 0 in every trial. */
static mcs_status power_at(const mcs_theory *th, const mcs_readout *view, size_t freq, double *p)
{
    double im;
    mcs_theory_zeros z;
    mcs_readout_cross_at(view, freq, freq, p, &im);
    mcs_status st = clamp_nonnegative(*p < 0.0 ? power_tolerance(th, view) : 0.0, p);
    if (st == MCS_OK && zeros_of(th, &z) && mcs_theory_s_zero_(&z, freq))
        *p = 0.0;
    return st;
}

/* Cov(S_freq, S_freq) with the arithmetic of the shared covariance_at
 * (readout.c): <S_k S_k*> less |<S_k>|^2. */
static mcs_status variance_at(const mcs_theory *th, const mcs_readout *view, size_t freq,
                              double *re, double *im)
{
    double kr, ki;
    mcs_readout_cross_at(view, freq, freq, re, im);
    mcs_readout_dft(view, view->first, freq, &kr, &ki);
    *re += -1.0 * (kr * kr + ki * ki);
    *im += -1.0 * (ki * kr - kr * ki);
    mcs_status st = clamp_nonnegative(*re < 0.0 ? variance_tolerance(th, view) : 0.0, re);
    mcs_theory_zeros z;
    if (st == MCS_OK && zeros_of(th, &z))
        apply_zeros(&z, mcs_theory_cov_zero_(&z, freq, freq), freq, freq, re, im);
    return st;
}

mcs_status mcs_theory_bin_mean(const mcs_theory *th, size_t bin, double *out)
{
    const mcs_readout_source src = {th, open_first};
    return mcs_readout_bin_mean(&src, bin, out);
}

/* The O(N) part, then the entry read and the two diagonals it is judged by. */
mcs_status mcs_theory_bin_second(const mcs_theory *th, size_t bin_m, size_t bin_n,
                                 double *out)
{
    mcs_readout v;
    mcs_status st = out == NULL || th == NULL ? MCS_ERR_NULL : open_first(th, &v);
    if (st == MCS_OK && (bin_m >= th->n || bin_n >= th->n))
        st = MCS_ERR_BIN_RANGE;
    if (st == MCS_OK && !(diagonal_is_sound(th, bin_m) && diagonal_is_sound(th, bin_n) &&
                          entry_is_sound(th, bin_m, bin_n)))
        st = MCS_ERR_INVARIANT;
    const mcs_readout_source src = {th, open_first};
    return st == MCS_OK ? mcs_readout_bin_second(&src, bin_m, bin_n, out) : st;
}

mcs_status mcs_theory_mean(const mcs_theory *th, size_t freq, double *re, double *im)
{
    const mcs_readout_source src = {th, open_first};
    mcs_theory_zeros z;
    const int known = zeros_of(th, &z);
    mcs_status st = mcs_readout_mean(&src, freq, re, im);
    if (st == MCS_OK && known) {
        if (mcs_theory_mean_zero_(&z, freq))
            *re = *im = 0.0;
        if (mcs_theory_real_freq_(&z, freq))
            *im = 0.0;
    }
    return st;
}

mcs_status mcs_theory_power(const mcs_theory *th, size_t freq, double *out)
{
    mcs_readout v;
    double p = 0.0;
    mcs_status st = open_at(out != NULL, th, freq, freq, MCS_ERR_FREQ_RANGE, &v);
    if (st == MCS_OK)
        st = power_at(th, &v, freq, &p);
    return st == MCS_OK ? mcs_set_(out, p) : st;
}

/* A complex read-out at k = l (power or variance): computed first, written
 * last into two different doubles. */
typedef mcs_status (*diagonal_at)(const mcs_theory *th, const mcs_readout *view, size_t freq,
                                  double *re, double *im);

static mcs_status power_im(const mcs_theory *th, const mcs_readout *view, size_t freq,
                           double *re, double *im)
{
    *im = 0.0; /* <s s^T> is symmetric: the imaginary part is rounding */
    return power_at(th, view, freq, re);
}

static mcs_status read_diagonal(const mcs_theory *th, size_t freq, double *re, double *im,
                                diagonal_at at)
{
    mcs_readout v;
    mcs_status st = open_at(re != NULL && im != NULL, th, freq, freq, MCS_ERR_FREQ_RANGE, &v);
    if (st == MCS_OK && mcs_overlap_(re, sizeof *re, im, sizeof *im))
        st = MCS_ERR_ALIAS;
    double r = 0.0, i = 0.0;
    if (st == MCS_OK)
        st = at(th, &v, freq, &r, &i);
    if (st == MCS_OK) {
        *re = r;
        *im = i;
    }
    return st;
}

mcs_status mcs_theory_cross(const mcs_theory *th, size_t freq_k, size_t freq_l, double *re,
                            double *im)
{
    if (freq_k == freq_l)
        return read_diagonal(th, freq_k, re, im, power_im);
    const mcs_readout_source src = {th, mcs_readout_open_theory};
    mcs_theory_zeros z;
    const int known = zeros_of(th, &z);
    mcs_status st = mcs_readout_cross(&src, freq_k, freq_l, re, im);
    if (st == MCS_OK && known)
        apply_zeros(&z, mcs_theory_cross_zero_(&z, freq_k, freq_l), freq_k, freq_l, re, im);
    return st;
}

mcs_status mcs_theory_covariance(const mcs_theory *th, size_t freq_k, size_t freq_l,
                                 double *re, double *im)
{
    if (freq_k == freq_l)
        return read_diagonal(th, freq_k, re, im, variance_at);
    const mcs_readout_source src = {th, mcs_readout_open_theory};
    mcs_theory_zeros z;
    const int known = zeros_of(th, &z);
    mcs_status st = mcs_readout_covariance(&src, freq_k, freq_l, re, im);
    if (st == MCS_OK && known)
        apply_zeros(&z, mcs_theory_cov_zero_(&z, freq_k, freq_l), freq_k, freq_l, re, im);
    return st;
}

/* Every entry of a matrix read-out (re, im of n * n, not in *th) with the
 * zeros of z; cov picks the covariance's rule, else the cross moment's. */
static void matrix_zeros(const mcs_theory_zeros *z, size_t n, int cov, double *re, double *im)
{
    for (size_t k = 0; k < n; ++k)
        for (size_t l = 0; l < n; ++l) {
            const int zero = cov ? mcs_theory_cov_zero_(z, k, l) : mcs_theory_cross_zero_(z, k, l);
            apply_zeros(z, zero, k, l, &re[k * n + l], &im[k * n + l]);
        }
}

/* The matrices: every diagonal judged first (O(N^3), as the matrix), so a
 * refused one leaves the outputs unwritten; then the shared matrix. */
static mcs_status check_diagonals(const mcs_theory *th, size_t n, const double *re,
                                  const double *im, diagonal_at at)
{
    const mcs_readout_source src = {th, mcs_readout_open_theory};
    mcs_readout v;
    mcs_status st = mcs_readout_open_n(re != NULL && im != NULL, &src, n, &v);
    for (size_t k = 0; st == MCS_OK && k < n; ++k) {
        double r, i;
        st = at(th, &v, k, &r, &i);
    }
    return st;
}

mcs_status mcs_theory_cross_matrix(const mcs_theory *th, size_t n, double *re, double *im)
{
    mcs_status st = check_diagonals(th, n, re, im, power_im);
    const mcs_readout_source src = {th, mcs_readout_open_theory};
    if (st == MCS_OK)
        st = mcs_readout_cross_matrix(&src, n, re, im);
    for (size_t k = 0; st == MCS_OK && k < n; ++k) /* rounding, as power_at found */
        re[k * n + k] = fmax(re[k * n + k], 0.0);
    mcs_theory_zeros z;
    if (st == MCS_OK && zeros_of(th, &z))
        matrix_zeros(&z, n, 0, re, im);
    return st;
}

mcs_status mcs_theory_covariance_matrix(const mcs_theory *th, size_t n, double *re,
                                        double *im)
{
    mcs_status st = check_diagonals(th, n, re, im, variance_at);
    if (st != MCS_OK)
        return st;
    const mcs_readout_source src = {th, mcs_readout_open_theory};
    st = mcs_readout_covariance_matrix(&src, n, re, im); /* its bounds hold init's rounding */
    for (size_t k = 0; st == MCS_OK && k < n; ++k) /* rounding, as variance_at found */
        re[k * n + k] = fmax(re[k * n + k], 0.0);
    mcs_theory_zeros z;
    if (st == MCS_OK && zeros_of(th, &z))
        matrix_zeros(&z, n, 1, re, im);
    return st;
}

mcs_status mcs_theory_estimator_mean(const mcs_theory *th, size_t n, size_t k, const double *f,
                                     double *out)
{
    const mcs_readout_source src = {th, open_first};
    return mcs_readout_estimator_mean(&src, n, k, f, out);
}

mcs_status mcs_theory_bias(const mcs_theory *th, size_t n, size_t k, const double *f,
                           double *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    const mcs_readout_source src = {th, open_first};
    mcs_readout v;
    mcs_status st = mcs_readout_check_integrand(&src, n, k, f, &v);
    if (st == MCS_OK)
        st = mcs_check_integrand_(n, f);
    if (st != MCS_OK)
        return st;
    const double bias = mcs_theory_bias_of_(th->kind, n, k, th->mean_s, f);
    return isfinite(bias) ? mcs_set_(out, bias) : MCS_ERR_INVARIANT;
}

double mcs_theory_form_tolerance_(const mcs_theory *th, const mcs_readout *view,
                                  const double *f)
{
    const double kd = (double)th->k;
    return mcs_readout_form_bound(view, th->k, f, f) +
           mcs_theory_init_rounding_(th, f, 0.0) / (kd * kd);
}

/* As mcs_readout_variance, with a variance below minus its tolerance
 * refused. */
mcs_status mcs_theory_variance(const mcs_theory *th, size_t n, size_t k, const double *f,
                               double *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    const mcs_readout_source src = {th, mcs_readout_open_theory};
    mcs_readout v;
    mcs_status st = mcs_readout_check_integrand(&src, n, k, f, &v);
    if (st != MCS_OK)
        return st;
    double var = mcs_readout_form(&v, k, f, f);
    if (!isfinite(var)) /* f so large that the form overflows */
        return MCS_ERR_MAGNITUDE;
    st = clamp_nonnegative(var < 0.0 ? mcs_theory_form_tolerance_(th, &v, f) : 0.0, &var);
    mcs_theory_zeros z;
    if (st == MCS_OK && zeros_of(th, &z) && mcs_theory_estimator_zero_(&z, n, f, f))
        var = 0.0;
    return st == MCS_OK ? mcs_set_(out, var) : st;
}

mcs_status mcs_theory_estimator_covariance(const mcs_theory *th, size_t n, size_t k,
                                           const double *f, const double *g, double *out)
{
    const mcs_readout_source src = {th, mcs_readout_open_theory};
    /* judged before the read-out writes: out may be an element of f or g */
    mcs_theory_zeros z;
    const int zero = f != NULL && g != NULL && zeros_of(th, &z) && n == th->n &&
                     mcs_theory_estimator_zero_(&z, n, f, g);
    mcs_status st = mcs_readout_estimator_covariance(&src, n, k, f, g, out);
    if (st == MCS_OK && zero)
        *out = 0.0;
    return st;
}
