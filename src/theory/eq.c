/* The note's closed forms of sections 1-3 (section 4, importance sampling,
 * is src/theory/eq_importance.c), and the helpers both files share. Every form
 * checks all its inputs with one call, so a failed call writes nothing. */
#include "mcspec/eq.h"
#include "eq_internal.h"
#include "theory_internal.h"
#include "core/internal.h"
#include "accumulators/readout.h"

#include <float.h>
#include <math.h>

/* ---- shared helpers ------------------------------------------------------- */

mcs_status mcs_eq_check_n_k(size_t n, size_t cap, size_t k)
{
    if (n == 0u || n > cap)
        return MCS_ERR_N_RANGE;
    if (k == 0u)
        return MCS_ERR_K_RANGE;
    return MCS_OK;
}

int mcs_eq_k_divides_n(size_t n, size_t k)
{
    return k <= n && n % k == 0u;
}

mcs_status mcs_eq_check_pair(int outputs, size_t n, size_t k, size_t freq_k, size_t freq_l)
{
    if (!outputs)
        return MCS_ERR_NULL;
    mcs_status st = mcs_eq_check_n_k(n, (size_t)MCS_MAX_N, k);
    if (st != MCS_OK)
        return st;
    if (freq_k >= n || freq_l >= n)
        return MCS_ERR_FREQ_RANGE;
    if (!mcs_eq_k_divides_n(n, k))
        return MCS_ERR_DOMAIN;
    return MCS_OK;
}

void mcs_eq_dft_at(size_t n, const double *x, const double *support, size_t freq, double *re,
                   double *im)
{
    double r = 0.0, i = 0.0;
    for (size_t t = 0; t < n; ++t) {
        if (support != NULL && !(support[t] > 0.0))
            continue;
        double a = mcs_twiddle_angle_((freq * t) % n, n);
        r += cos(a) * x[t];
        i -= sin(a) * x[t];
    }
    double scale = 1.0 / sqrt((double)n);
    *re = r * scale;
    *im = i * scale;
}

double mcs_eq_ac_energy(size_t n, const double *f, const double *support)
{
    double sum = 0.0;
    if (n > (size_t)MCS_MAX_COV_N) {
        /* Parseval: sum_{k>=1} |F_k|^2 = sum_n f_n^2 - |F_0|^2 = sum_n (f_n - fbar)^2,
         * in two passes (no cancellation of sum f^2 against N fbar^2) */
        double mean = 0.0;
        for (size_t b = 0; b < n; ++b)
            mean += mcs_eq_on_support(f, support, b);
        mean /= (double)n;
        for (size_t b = 0; b < n; ++b) {
            const double d = mcs_eq_on_support(f, support, b) - mean;
            sum += d * d;
        }
        return sum;
    }
    for (size_t b = 1; b < n; ++b) { /* the note's sum, term by term */
        double fr, fi;
        mcs_eq_dft_at(n, f, support, b, &fr, &fi);
        sum += fr * fr + fi * fi;
    }
    return sum;
}

/* ---- Section 1: the exact moments' read-out of two integrands ------------ */

/* A variance x: in [-tol, 0) it is rounding and reads 0, below -tol it
 * comes from no moments mcs_theory_init writes (MCS_ERR_INVARIANT). tol is
 * formed only for a negative x (it costs as much as x). */
static mcs_status clamp_variance(const mcs_theory *th, const mcs_readout *view, const double *f,
                                 double *x)
{
    if (*x >= 0.0)
        return MCS_OK;
    if (!(*x >= -mcs_theory_form_tolerance_(th, view, f)))
        return MCS_ERR_INVARIANT;
    *x = 0.0;
    return MCS_OK;
}

/* Var[I_f] + Var[I_g], less 2 Cov(I_f, I_g) when f and g are estimated from
 * one shared trial (eq. 4); independent trials have no covariance (eq. 2).
 * Variances: never negative, rounding clamped as mcs_theory_variance, and
 * each of Var[I_f], Var[I_g] (and of I_f - I_g) below its tolerance
 * refused. Six arguments at most (see readout.h): out is the result. */
typedef struct {
    const double *f, *g;
    int shared;
} gradient_terms;

static mcs_status gradient_variance(const mcs_theory *th, const mcs_readout *view,
                                    const gradient_terms *t, double *out)
{
    const size_t k = th->k;
    double vf = mcs_readout_form(view, k, t->f, t->f), vg = mcs_readout_form(view, k, t->g, t->g);
    const double vfg = t->shared ? mcs_readout_form(view, k, t->f, t->g) : 0.0;
    double var = vf + vg - 2.0 * vfg;
    mcs_status st = clamp_variance(th, view, t->f, &vf);
    if (st == MCS_OK)
        st = clamp_variance(th, view, t->g, &vg);
    if (st != MCS_OK)
        return st;
    if (!t->shared)
        return mcs_set_(out, vf + vg);
    if (var < 0.0) { /* (f - g)^T Cov (f - g), expanded so no difference array is needed */
        const double kd = (double)k;
        const double tol = mcs_readout_form_bound(view, k, t->f, t->f) +
                           mcs_readout_form_bound(view, k, t->g, t->g) +
                           2.0 * mcs_readout_form_bound(view, k, t->f, t->g) +
                           2.0 * (mcs_theory_init_rounding_(th, t->f, 0.0) +
                                  mcs_theory_init_rounding_(th, t->g, 0.0)) /
                               (kd * kd);
        if (!(var >= -tol))
            return MCS_ERR_INVARIANT;
        var = 0.0;
    }
    return mcs_set_(out, var);
}

/* The read-out's checks of f and g on th, then both within
 * MCS_ESTIMATE_MAX_ABS (MAGNITUDE): f - g cannot overflow then either. The
 * caller checks its output first (six arguments at most: see readout.h). */
static mcs_status check_two(const mcs_theory *th, size_t n, size_t k, const double *f,
                            const double *g, mcs_readout *v)
{
    const mcs_readout_source src = {th, mcs_readout_open_theory};
    mcs_status st = mcs_readout_check_integrands(&src, n, k, f, g, v);
    if (st == MCS_OK)
        st = mcs_check_integrand_(n, f);
    return st == MCS_OK ? mcs_check_integrand_(n, g) : st;
}

mcs_status mcs_eq2_uncorrelated_variance(const mcs_theory *th, size_t n, size_t k,
                                         const double *f, const double *g, double *out)
{
    mcs_readout v;
    const gradient_terms t = {f, g, 0};
    mcs_status st = out == NULL ? MCS_ERR_NULL : check_two(th, n, k, f, g, &v);
    return st == MCS_OK ? gradient_variance(th, &v, &t, out) : st;
}

mcs_status mcs_eq4_correlated_variance(const mcs_theory *th, size_t n, size_t k,
                                       const double *f, const double *g, double *out)
{
    mcs_readout v;
    const gradient_terms t = {f, g, 1};
    mcs_status st = out == NULL ? MCS_ERR_NULL : check_two(th, n, k, f, g, &v);
    return st == MCS_OK ? gradient_variance(th, &v, &t, out) : st;
}

/* ---- Section 2 ------------------------------------------------------------ */

/* An integrand's closed form: outputs given (else NULL), n in [1, cap],
 * k >= 1, f[n] finite and within MCS_ESTIMATE_MAX_ABS. */
static mcs_status check_f(int outputs, size_t n, size_t cap, size_t k, const double *f)
{
    if (!outputs)
        return MCS_ERR_NULL;
    mcs_status st = mcs_eq_check_n_k(n, cap, k);
    return st == MCS_OK ? mcs_check_integrand_(n, f) : st;
}

/* A power spectrum for eq. 14: power[1..n) finite (NOT_FINITE) and within
 * MCS_EQ_MAX_POWER (MAGNITUDE). */
static mcs_status check_power(size_t n, const double *power)
{
    if (!mcs_all_finite_(n - 1u, power + 1))
        return MCS_ERR_NOT_FINITE;
    for (size_t b = 1; b < n; ++b)
        if (!(fabs(power[b]) <= MCS_EQ_MAX_POWER))
            return MCS_ERR_MAGNITUDE;
    return MCS_OK;
}

mcs_status mcs_eq11_unbiased_mean(size_t n, const double *f, double *out)
{
    mcs_status st = check_f(f != NULL && out != NULL, n, (size_t)MCS_MAX_N, 1u, f);
    if (st != MCS_OK)
        return st;
    double sum = 0.0;
    for (size_t b = 0; b < n; ++b)
        sum += f[b];
    *out = sum / (double)n; /* (1/K)(K/sqrt N) F_0* = (1/N) sum f */
    return MCS_OK;
}

/* (1/K^2) sum_{k,l >= 1} F_k* F_l <S_k S_l*>, every term through eq. 16 and
 * the theory's own twiddles: O(N^4), and no work arrays. */
static double eq13_sum(const mcs_readout *view, size_t k, const double *f)
{
    const size_t n = view->n;
    double total = 0.0;
    for (size_t a = 1; a < n; ++a) {
        double fkr, fki;
        mcs_readout_dft(view, f, a, &fkr, &fki);
        for (size_t b = 1; b < n; ++b) {
            double flr, fli, cr, ci;
            mcs_readout_dft(view, f, b, &flr, &fli);
            mcs_readout_cross_at(view, a, b, &cr, &ci);
            /* F_k* F_l = (fkr - i fki)(flr + i fli); the real part of the product */
            total += (fkr * flr + fki * fli) * cr - (fkr * fli - fki * flr) * ci;
        }
    }
    double kd = (double)k;
    return total / (kd * kd);
}

/* The tolerance of eq13_sum: its terms F_a* F_b <S_a S_b*> are each below
 * (sum |f|)^2 (sum |<s s^T>|) / N^2 and carry the roundings of three O(N)
 * and O(N^2) transforms, (4N + 16) DBL_EPSILON of them, and their sum adds
 * N^2 more; then init's rounding (mcs_theory_init_rounding_) of the form of
 * y = f - fbar, |y_n| <= |f_n| + |fbar|. */
static double eq13_tolerance(const mcs_theory *th, const mcs_readout *view, const double *f)
{
    const size_t n = view->n;
    double sf = 0.0, fbar = 0.0, sm = 0.0;
    for (size_t b = 0; b < n; ++b) {
        sf += fabs(f[b]);
        fbar += f[b];
    }
    fbar /= (double)n;
    for (size_t j = 0; j < n * n; ++j)
        sm += fabs(view->second[j]);
    const double nd = (double)n, kd = (double)th->k;
    return ((nd * nd + 4.0 * nd + 16.0) * DBL_EPSILON * sf * sf * sm +
            mcs_theory_init_rounding_(th, f, fabs(fbar))) /
           (kd * kd);
}

/* Eq. 13 is (1/K^2) E[(y^T s)^2], y = f - fbar (the k = 0 term is what
 * leaves out fbar): never negative. Below minus its tolerance it comes
 * from no moments init writes. */
mcs_status mcs_eq13_variance(const mcs_theory *th, size_t n, size_t k, const double *f,
                             double *out)
{
    mcs_readout v;
    mcs_status st = out == NULL ? MCS_ERR_NULL : check_two(th, n, k, f, f, &v);
    if (st != MCS_OK)
        return st;
    double sum = eq13_sum(&v, k, f);
    if (sum < 0.0) {
        if (!(sum >= -eq13_tolerance(th, &v, f)))
            return MCS_ERR_INVARIANT;
        sum = 0.0;
    }
    return mcs_set_(out, sum);
}

mcs_status mcs_eq14_variance(size_t n, size_t k, const double *f, const double *power,
                             double *out)
{
    int outputs = f != NULL && power != NULL && out != NULL;
    mcs_status st = check_f(outputs, n, (size_t)MCS_MAX_N, k, f);
    if (st == MCS_OK)
        st = check_power(n, power);
    if (st != MCS_OK)
        return st;
    double sum = 0.0;
    for (size_t b = 1; b < n; ++b) {
        double fr, fi;
        mcs_eq_dft_at(n, f, NULL, b, &fr, &fi);
        sum += (fr * fr + fi * fi) * power[b];
    }
    double kd = (double)k;
    *out = sum / (kd * kd);
    return MCS_OK;
}

/* ---- Section 3 ------------------------------------------------------------ */

/* A closed form at one frequency: outputs given (else NULL), n and k in
 * range, freq < n; DOMAIN for freq 0 when positive_freq, and for K not
 * dividing N when need_divides (the stratified forms put N/K bins in each
 * stratum). */
static mcs_status check_freq(int outputs, size_t n, size_t k, size_t freq, int positive_freq,
                             int need_divides)
{
    if (!outputs)
        return MCS_ERR_NULL;
    mcs_status st = mcs_eq_check_n_k(n, (size_t)MCS_MAX_N, k);
    if (st != MCS_OK)
        return st;
    if (freq >= n)
        return MCS_ERR_FREQ_RANGE;
    if ((positive_freq && freq == 0u) || (need_divides && !mcs_eq_k_divides_n(n, k)))
        return MCS_ERR_DOMAIN;
    return MCS_OK;
}

mcs_status mcs_eq23_random_power(size_t n, size_t k, size_t freq, double *out)
{
    mcs_status st = check_freq(out != NULL, n, k, freq, 1, 0);
    return st == MCS_OK ? mcs_set_(out, (double)k / (double)n) : st;
}

mcs_status mcs_eq24_random_variance(size_t n, size_t k, const double *f, double *out)
{
    mcs_status st = check_f(f != NULL && out != NULL, n, (size_t)MCS_MAX_N, k, f);
    return st == MCS_OK ? mcs_set_(out, mcs_eq_ac_energy(n, f, NULL) / ((double)k * (double)n)) : st;
}

mcs_status mcs_eq25_random_variance(size_t n, size_t k, const double *f, double *out)
{
    mcs_status st = check_f(f != NULL && out != NULL, n, (size_t)MCS_MAX_N, k, f);
    if (st != MCS_OK)
        return st;
    double mean = 0.0;
    for (size_t b = 0; b < n; ++b)
        mean += f[b];
    mean /= (double)n;
    double ss = 0.0; /* two passes: no cancellation of sum f^2 against N fbar^2 */
    for (size_t b = 0; b < n; ++b)
        ss += (f[b] - mean) * (f[b] - mean);
    *out = ss / ((double)n * (double)k);
    return MCS_OK;
}

/* The printed bracket of eq. 30: (1 - e^{-2 pi i k/K}) / (1 - e^{-2 pi i k/N})
 * for k not a multiple of N. */
static void eq30_ratio(size_t n, size_t k, size_t freq, double *re, double *im)
{
    double a = 2.0 * MCS_PI * (double)(freq % k) / (double)k;
    double b = 2.0 * MCS_PI * (double)freq / (double)n;
    double nr = 1.0 - cos(a), ni = sin(a); /* 1 - e^{-ia} */
    double dr = 1.0 - cos(b), di = sin(b);
    double d2 = dr * dr + di * di;
    *re = (nr * dr + ni * di) / d2;
    *im = (ni * dr - nr * di) / d2;
}

/* Geometric sum over one stratum, sum_{a < N/K} e^{-2 pi i freq a/N}, summed
 * directly so it is defined at freq = 0 too. */
static void stratum_sum(size_t n, size_t k, size_t freq, double *re, double *im)
{
    double r = 0.0, i = 0.0;
    for (size_t a = 0; a < n / k; ++a) {
        double t = mcs_twiddle_angle_((freq * a) % n, n);
        r += cos(t);
        i -= sin(t);
    }
    *re = r;
    *im = i;
}

/* -(K/N)^3 A B* for the two brackets A = ar + i ai, B = br + i bi of eq. 30. */
static void delta_of(size_t n, size_t k, double ar, double ai, double br, double bi, double *re,
                     double *im)
{
    bi = -bi; /* the second bracket is the conjugate one, at l */
    double c = (double)k / (double)n;
    c = -c * c * c;
    *re = c * (ar * br - ai * bi);
    *im = c * (ar * bi + ai * br);
}

void mcs_eq_delta_printed(size_t n, size_t k, size_t freq_k, size_t freq_l, double *re,
                          double *im)
{
    double ar, ai, br, bi;
    eq30_ratio(n, k, freq_k, &ar, &ai);
    eq30_ratio(n, k, freq_l, &br, &bi);
    delta_of(n, k, ar, ai, br, bi, re, im);
}

mcs_status mcs_eq30_stratified_delta_printed(size_t n, size_t k, size_t freq_k, size_t freq_l,
                                             double *re, double *im)
{
    mcs_status st = mcs_eq_check_pair(re != NULL && im != NULL, n, k, freq_k, freq_l);
    if (st == MCS_OK && (freq_k == 0u || freq_l == 0u)) /* the ratios are 0/0 there */
        st = MCS_ERR_DOMAIN;
    st = mcs_eq_check_complex(st, re, im);
    if (st == MCS_OK)
        mcs_eq_delta_printed(n, k, freq_k, freq_l, re, im);
    return st;
}

/* Delta_kl with the strata phase sum: the K strata at offsets q N/K add
 * e^{-2 pi i (k - l) q/K}, which sums to K for k = l (mod K) and to 0 else. */
static void eq30_corrected(size_t n, size_t k, size_t fk, size_t fl, double *re, double *im)
{
    if ((fk + n - fl) % n % k != 0u) {
        *re = 0.0;
        *im = 0.0;
        return;
    }
    double ar, ai, br, bi;
    stratum_sum(n, k, fk, &ar, &ai);
    stratum_sum(n, k, fl, &br, &bi);
    delta_of(n, k, ar, ai, br, bi, re, im);
}

mcs_status mcs_eq30_stratified_delta_corrected(size_t n, size_t k, size_t freq_k,
                                               size_t freq_l, double *re, double *im)
{
    mcs_status st = mcs_eq_check_pair(re != NULL && im != NULL, n, k, freq_k, freq_l);
    st = mcs_eq_check_complex(st, re, im);
    if (st == MCS_OK)
        eq30_corrected(n, k, freq_k, freq_l, re, im);
    return st;
}

mcs_status mcs_eq30_stratified_cross(size_t n, size_t k, size_t freq_k, size_t freq_l,
                                     double *re, double *im)
{
    mcs_status st = mcs_eq_check_pair(re != NULL && im != NULL, n, k, freq_k, freq_l);
    st = mcs_eq_check_complex(st, re, im);
    if (st != MCS_OK)
        return st;
    double dr, di;
    eq30_corrected(n, k, freq_k, freq_l, &dr, &di);
    double kn = (double)k / (double)n;
    if (freq_k == freq_l)
        dr += kn; /* eq. 28's delta term, as for random */
    if (freq_k == 0u && freq_l == 0u)
        dr += (double)k * kn; /* eq. 28's constant K^2/N^2 term */
    *re = dr;
    *im = di;
    return MCS_OK;
}

/* sin^2(pi freq / K) has period K in freq: reducing first makes it exactly 0
 * on multiples of K. */
static double sin2_over_k(size_t k, size_t freq)
{
    double s = sin(MCS_PI * (double)(freq % k) / (double)k);
    return s * s;
}

static double eq32(size_t n, size_t k, size_t freq)
{
    double kn = (double)k / (double)n;
    double sn = sin(MCS_PI * (double)freq / (double)n);
    return -kn * kn * kn * sin2_over_k(k, freq) / (sn * sn);
}

mcs_status mcs_eq31_stratified_delta_printed(size_t n, size_t k, size_t freq, double *out)
{
    mcs_status st = check_freq(out != NULL, n, k, freq, 1, 1);
    if (st != MCS_OK)
        return st;
    double kn = (double)k / (double)n;
    double num = 1.0 - cos(2.0 * MCS_PI * (double)(freq % k) / (double)k);
    double den = 1.0 - cos(2.0 * MCS_PI * (double)freq / (double)n);
    double ratio = num / den;
    *out = -kn * kn * kn * ratio * ratio;
    return MCS_OK;
}

mcs_status mcs_eq32_stratified_delta(size_t n, size_t k, size_t freq, double *out)
{
    mcs_status st = check_freq(out != NULL, n, k, freq, 1, 1);
    return st == MCS_OK ? mcs_set_(out, eq32(n, k, freq)) : st;
}

mcs_status mcs_eq33_stratified_power_exact(size_t n, size_t k, size_t freq, double *out)
{
    mcs_status st = check_freq(out != NULL, n, k, freq, 1, 1);
    return st == MCS_OK ? mcs_set_(out, (double)k / (double)n + eq32(n, k, freq)) : st;
}

/* sinc^2(pi freq / K) with sinc x = sin x / x, freq in [1, N). The limit
 * forms are functions of the signed frequency: index freq > N/2 is freq - N,
 * and sinc^2 is even, so fold it to min(freq, N - freq) (sin^2(pi freq/K) is
 * unchanged by the fold because K divides N). */
double mcs_eq_sinc2(size_t n, size_t k, size_t freq)
{
    size_t folded = freq <= n - freq ? freq : n - freq;
    double x = MCS_PI * (double)folded / (double)k;
    return sin2_over_k(k, folded) / (x * x);
}

mcs_status mcs_eq33_stratified_power_limit(size_t n, size_t k, size_t freq, double *out)
{
    mcs_status st = check_freq(out != NULL, n, k, freq, 1, 1);
    return st == MCS_OK ? mcs_set_(out, (double)k / (double)n * (1.0 - mcs_eq_sinc2(n, k, freq)))
                        : st;
}

mcs_status mcs_eq34_uniform_spectrum(size_t n, size_t k, size_t freq, double *re, double *im)
{
    mcs_status st = check_freq(re != NULL && im != NULL, n, k, freq, 0, 1);
    if (st == MCS_OK && (n / k) % 2u != 0u) /* (alpha + 1/2) N/K must be a whole bin */
        st = MCS_ERR_DOMAIN;
    st = mcs_eq_check_complex(st, re, im);
    if (st != MCS_OK)
        return st;
    *re = 0.0;
    *im = 0.0;
    if (freq % k == 0u) { /* e^{-2 pi i k beta/K} at k = mu K, beta = 1/2: (-1)^mu */
        double mag = (double)k / sqrt((double)n);
        *re = (freq / k) % 2u == 0u ? mag : -mag;
    }
    return MCS_OK;
}

mcs_status mcs_eq35_jitter_mean(size_t n, size_t k, size_t freq, double *re, double *im)
{
    mcs_status st = mcs_eq_check_complex(check_freq(re != NULL && im != NULL, n, k, freq, 0, 1),
                                         re, im);
    if (st != MCS_OK)
        return st;
    *re = freq == 0u ? (double)k / sqrt((double)n) : 0.0;
    *im = 0.0;
    return MCS_OK;
}

mcs_status mcs_eq37_jitter_power(size_t n, size_t k, size_t freq, double *out)
{
    mcs_status st = check_freq(out != NULL, n, k, freq, 0, 1);
    return st == MCS_OK ? mcs_set_(out, freq % k == 0u ? (double)k * (double)k / (double)n : 0.0)
                        : st;
}
