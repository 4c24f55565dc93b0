/* Exact discrete moments of every pattern kind (see include/mcspec/theory.h
 * for the interval-overlap model); the read-out is src/accumulators/readout.c. */
#include "mcspec/theory.h"
#include "core/internal.h"
#include "accumulators/readout.h"
#include "theory_internal.h"

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

/* <r_m r_n> for jitter: the integral over beta in [0,1) of r_m(beta) r_n(beta).
 * Each r is constant between the fractional parts of its two edges, so the
 * integral is exact as a sum over the (at most 5) pieces. */
static double jitter_pair(double am, double bm, double an, double bn)
{
    double pts[6] = {0.0, frac_part(am), frac_part(bm), frac_part(an), frac_part(bn), 1.0};
    for (int i = 1; i < 5; ++i) /* insertion sort of the four inner points */
        for (int j = i; j > 0 && pts[j] < pts[j - 1]; --j) {
            double t = pts[j];
            pts[j] = pts[j - 1];
            pts[j - 1] = t;
        }
    double sum = 0.0;
    for (int i = 0; i < 5; ++i) {
        double w = pts[i + 1] - pts[i];
        if (w > 0.0) {
            double mid = pts[i] + 0.5 * w;
            sum += jitter_count(am, bm, mid) * jitter_count(an, bn, mid) * w;
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
            case MCS_PATTERN_JITTER: /* one shared beta: exact integral */
                rr = jitter_pair(am, bm, mcs_theory_edge_(pat, b), mcs_theory_edge_(pat, b + 1u));
                break;
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

/* ---- read-out (src/accumulators/readout.c): the expectations themselves -------------- */

mcs_status mcs_readout_open_theory(const void *obj, mcs_readout *view)
{
    const mcs_theory *th = (const mcs_theory *)obj;
    if (!theory_is_valid(th))
        return MCS_ERR_UNINIT;
    *view = (mcs_readout){.n = th->n,
                          .k = th->k,
                          .scale = 1.0,
                          .first = th->mean_s,
                          .second = th->second,
                          .cos_table = th->cos_table,
                          .sin_table = th->sin_table};
    return MCS_OK;
}

MCS_READOUT_DEFINE(theory, mcs_theory, mcs_readout_open_theory)
