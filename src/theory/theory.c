/* Exact discrete moments of every pattern kind (see include/mcspec/theory.h
 * for the interval-overlap model) and their checks; the read-outs are
 * theory_readout.c. */
#include "mcspec/theory.h"
#include "core/internal.h"
#include "theory_internal.h"

#include <float.h>
#include <math.h>

int mcs_theory_valid_(const mcs_theory *th)
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
int mcs_theory_first_sound_(const mcs_theory *th)
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
int mcs_theory_diagonal_sound_(const mcs_theory *th, size_t b)
{
    const double m = th->mean_s[b], d = th->second[b * th->n + b];
    return in_range(d, m * m * (1.0 - SECOND_TOL), m * m + 2.0 * MAX_INV_P * m);
}

/* <s_a s_b> (diagonals already checked): Cauchy-Schwarz,
 * <s_a s_b>^2 <= <s_a^2> <s_b^2>, and not below 0 (s is never negative),
 * each to SECOND_TOL of sqrt(<s_a^2> <s_b^2>) (the root only for a negative
 * entry, which init leaves at rounding level where it leaves one). No
 * product overflows: the diagonals are below 2^129. */
int mcs_theory_entry_sound_(const mcs_theory *th, size_t a, size_t b)
{
    const size_t n = th->n;
    const double x = th->second[a * n + b];
    const double cs = th->second[a * n + a] * th->second[b * n + b];
    return x * x <= cs * (1.0 + SECOND_TOL) && (x >= 0.0 || -x <= SECOND_TOL * sqrt(cs));
}

/* Every second moment, O(N^2): what the read-outs of the whole matrix read. */
int mcs_theory_second_sound_(const mcs_theory *th)
{
    const size_t n = th->n;
    int sound = 1;
    for (size_t b = 0; b < n; ++b)
        sound &= mcs_theory_diagonal_sound_(th, b);
    for (size_t a = 0; sound && a < n; ++a)
        for (size_t b = 0; b < n; ++b)
            sound &= mcs_theory_entry_sound_(th, a, b);
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
