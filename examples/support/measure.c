#include "measure.h"
#include "readout.h"

#include <math.h>
#include <string.h>

mcs_status ex_run_init(ex_run *run, mcs_pattern_kind kind, size_t n, size_t k,
                       const mcs_importance *importance, uint64_t seed, uint64_t stream)
{
    if (k > EX_MAX_K)
        return MCS_ERR_K_RANGE;
    mcs_status st = mcs_pattern_init(&run->pattern, kind, n, k, importance);
    if (st != MCS_OK)
        return st;
    mcs_rng_seed(&run->rng, seed, stream);
    run->n = n;
    run->k = k;
    run->draws = 1u;
    run->nfreq = run->npair = run->nf = run->ndiff = 0u;
    mcs_welford_init(&run->parseval);
    /* Twiddles by exact index: cos(2 pi t/N) for t < N, so k n_j is reduced mod N
     * in integers and no phase error grows with k n_j. */
    const double two_pi = 6.283185307179586476925286766559;
    for (size_t t = 0; t < n; ++t) {
        double a = two_pi * (double)t / (double)n;
        run->cos_table[t] = cos(a);
        run->sin_table[t] = sin(a);
    }
    return MCS_OK;
}

mcs_status ex_run_setup(ex_run *run, ex_exact *exact, mcs_spectrum *spectrum,
                        mcs_pattern_kind kind, size_t n, size_t k,
                        const mcs_importance *importance, uint64_t seed, uint64_t stream)
{
    mcs_status st = ex_run_init(run, kind, n, k, importance, seed, stream);
    if (st == MCS_OK && exact != NULL)
        st = ex_exact_init(exact, &run->pattern);
    if (st == MCS_OK && spectrum != NULL)
        st = mcs_spectrum_init(spectrum, n);
    return st;
}

int ex_run_probe(ex_run *run, size_t freq)
{
    if (freq >= run->n)
        return -1;
    for (size_t i = 0; i < run->nfreq; ++i)
        if (run->freq[i] == freq)
            return (int)i;
    if (run->nfreq >= EX_MAX_PROBE)
        return -1;
    size_t i = run->nfreq++;
    run->freq[i] = freq;
    mcs_welford_init(&run->s_re[i]);
    mcs_welford_init(&run->s_im[i]);
    return (int)i;
}

int ex_run_probe_pair(ex_run *run, size_t k, size_t l)
{
    if (k >= run->n || l >= run->n)
        return -1;
    for (size_t i = 0; i < run->npair; ++i)
        if (run->pair_k[i] == k && run->pair_l[i] == l)
            return (int)i;
    if (run->npair >= EX_MAX_PAIR || ex_run_probe(run, k) < 0 || ex_run_probe(run, l) < 0)
        return -1;
    size_t i = run->npair++;
    run->pair_k[i] = k;
    run->pair_l[i] = l;
    mcs_welford_init(&run->x_re[i]);
    mcs_welford_init(&run->x_im[i]);
    return (int)i;
}

int ex_run_integrand_on(ex_run *run, const double *f, size_t draw)
{
    if (run->nf >= EX_MAX_F || draw >= EX_MAX_DRAW)
        return -1;
    size_t i = run->nf++;
    run->f[i] = f;
    run->f_draw[i] = draw;
    if (draw >= run->draws)
        run->draws = draw + 1u;
    mcs_welford_init(&run->estimate[i]);
    return (int)i;
}

int ex_run_integrand(ex_run *run, const double *f)
{
    return ex_run_integrand_on(run, f, 0u);
}

int ex_run_difference(ex_run *run, int a, int b)
{
    if (run->ndiff >= EX_MAX_DIFF || a < 0 || b < 0 || (size_t)a >= run->nf ||
        (size_t)b >= run->nf)
        return -1;
    size_t i = run->ndiff++;
    run->diff_a[i] = (size_t)a;
    run->diff_b[i] = (size_t)b;
    mcs_welford_init(&run->difference[i]);
    return (int)i;
}

static size_t probe_index(const ex_run *run, size_t freq)
{
    for (size_t i = 0; i < run->nfreq; ++i)
        if (run->freq[i] == freq)
            return i;
    return 0u; /* unreachable: pairs probe both frequencies */
}

/* S at every probed frequency of one draw into re, im, and the accumulators;
 * then S_k S_l* at every probed pair. */
static void add_probes(ex_run *run, const size_t *bins, const double *weights)
{
    double re[EX_MAX_PROBE] = {0.0}, im[EX_MAX_PROBE] = {0.0}; /* defined even for an unprobed index */
    double norm = 1.0 / sqrt((double)run->n);
    for (size_t i = 0; i < run->nfreq; ++i) {
        size_t fr = run->freq[i];
        double a = 0.0, b = 0.0;
        for (size_t j = 0; j < run->k; ++j) {
            size_t t = (size_t)(((uint64_t)fr * (uint64_t)bins[j]) % (uint64_t)run->n);
            a += weights[j] * run->cos_table[t];
            b -= weights[j] * run->sin_table[t];
        }
        re[i] = a * norm;
        im[i] = b * norm;
        mcs_welford_add(&run->s_re[i], re[i]);
        mcs_welford_add(&run->s_im[i], im[i]);
    }
    for (size_t i = 0; i < run->npair; ++i) {
        size_t a = probe_index(run, run->pair_k[i]), b = probe_index(run, run->pair_l[i]);
        /* S_k S_l* = (a_r + i a_i)(b_r - i b_i) */
        mcs_welford_add(&run->x_re[i], re[a] * re[b] + im[a] * im[b]);
        mcs_welford_add(&run->x_im[i], im[a] * re[b] - re[a] * im[b]);
    }
}

/* Every integrand's estimate on its draw, then the differences. */
static mcs_status add_estimates(ex_run *run, size_t bins[][EX_MAX_K],
                                double weights[][EX_MAX_K])
{
    double est[EX_MAX_F] = {0.0};
    for (size_t i = 0; i < run->nf; ++i) {
        size_t d = run->f_draw[i];
        mcs_status st = mcs_estimate_bins(run->n, run->k, run->f[i], bins[d], weights[d], &est[i]);
        if (st != MCS_OK)
            return st;
        mcs_welford_add(&run->estimate[i], est[i]);
    }
    for (size_t i = 0; i < run->ndiff; ++i)
        mcs_welford_add(&run->difference[i], est[run->diff_a[i]] - est[run->diff_b[i]]);
    return MCS_OK;
}

/* sum_{k>=1} |S_k|^2 of one draw by Parseval, from the dense s (scratch s[N]). */
static mcs_status add_parseval(ex_run *run, const size_t *bins, const double *weights, double *s)
{
    mcs_status st = mcs_pattern_dense(run->n, run->k, bins, weights, s);
    if (st != MCS_OK)
        return st;
    double sum = 0.0, sum2 = 0.0;
    for (size_t b = 0; b < run->n; ++b) {
        sum += s[b];
        sum2 += s[b] * s[b];
    }
    return mcs_welford_add(&run->parseval, sum2 - sum * sum / (double)run->n);
}

mcs_status ex_run_go(ex_run *run, unsigned long trials, mcs_spectrum *spectrum,
                     mcs_moment *moment)
{
    static size_t bins[EX_MAX_DRAW][EX_MAX_K];
    static double weights[EX_MAX_DRAW][EX_MAX_K];
    static double s[MCS_MAX_N];
    for (unsigned long t = 0; t < trials; ++t) {
        mcs_status st = MCS_OK;
        for (size_t d = 0; d < run->draws && st == MCS_OK; ++d)
            st = mcs_pattern_draw(&run->pattern, &run->rng, run->k, bins[d], weights[d], NULL);
        if (st == MCS_OK && spectrum != NULL)
            st = mcs_spectrum_add_bins(spectrum, run->k, bins[0], weights[0]);
        if (st == MCS_OK && moment != NULL)
            st = mcs_moment_add_bins(moment, run->k, bins[0], weights[0]);
        if (st == MCS_OK) {
            add_probes(run, bins[0], weights[0]);
            st = add_estimates(run, bins, weights);
        }
        if (st == MCS_OK)
            st = add_parseval(run, bins[0], weights[0], s);
        if (st != MCS_OK)
            return st;
    }
    return MCS_OK;
}

/* Mean of the parts re and im, with their standard errors (se may be NULL). */
static ex_complex mean_parts(const mcs_welford *re, const mcs_welford *im, ex_complex *se)
{
    ex_complex m = {ex_mean(re, se != NULL ? &se->re : NULL),
                    ex_mean(im, se != NULL ? &se->im : NULL)};
    return m;
}

ex_complex ex_run_mean(const ex_run *run, int idx, ex_complex *stderr_out)
{
    return mean_parts(&run->s_re[idx], &run->s_im[idx], stderr_out);
}

ex_complex ex_run_mean_pair(const ex_run *run, int idx, ex_complex *stderr_out)
{
    return mean_parts(&run->x_re[idx], &run->x_im[idx], stderr_out);
}

double ex_run_mean_power(const ex_run *run, double *stderr_out)
{
    const double scale = run->n > 1u ? 1.0 / (double)(run->n - 1u) : EX_NA;
    double m = ex_mean(&run->parseval, stderr_out) * scale;
    *stderr_out *= scale;
    return m;
}

ex_row ex_estimator_mean_row(const ex_options *opt, const char *section, const char *pattern,
                             const ex_exact *ex, const ex_run *run, const double *f)
{
    double v = 0.0, se = 0.0;
    double closed = ex_or_na(mcs_eq11_unbiased_mean(run->n, f, &v), &v);
    double exact = ex_exact_estimator_mean(ex, f);
    double meas = ex_mean(&run->estimate[0], &se);
    ex_row r = ex_row_of(section, "<I>", "eq. 11", pattern, EX_NO_FREQ, EX_NO_FREQ, closed, exact,
                         meas, se, 1e-12);
    ex_row_print(opt, &r);
    return r;
}

size_t ex_pick_freqs(size_t n, const size_t *cand, size_t ncand, size_t *out)
{
    size_t count = 0;
    for (size_t i = 0; i < ncand; ++i) {
        size_t c = cand[i];
        int dup = c == 0u || c >= n;
        for (size_t j = 0; j < count && !dup; ++j)
            dup = out[j] == c;
        if (!dup)
            out[count++] = c;
    }
    return count;
}
