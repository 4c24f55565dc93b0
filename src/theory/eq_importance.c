/* The note's closed forms of section 4: importance sampling. Every form reads
 * N, p_n and the harmonic mean H from the caller's importance function, over
 * its support: a bin with p_n = 0 is never drawn (s_n = 0), so 1/p_n and f_n
 * are read as 0 there (eq.h). */
#include "mcspec/eq.h"
#include "eq_internal.h"
#include "patterns/importance_internal.h"
#include "core/internal.h"

#include <float.h>
#include <math.h>

/* imp NULL is "no importance function": the importance formulas are not
 * defined there (the note reduces them to section 3 by p = 1 instead).
 * Outputs given (else NULL), imp initialised, k >= 1. */
static mcs_status check_imp(int outputs, const mcs_importance *imp, size_t k)
{
    if (!outputs)
        return MCS_ERR_NULL;
    if (imp == NULL)
        return MCS_ERR_DOMAIN;
    if (!mcs_importance_is_valid_(imp))
        return MCS_ERR_UNINIT;
    if (k == 0u)
        return MCS_ERR_K_RANGE;
    return MCS_OK;
}

/* Writes a result formed from imp, the last check of every form. It is
 * finite for every object mcs_importance_init makes (1/p_n < 2^32 or a bin
 * outside the support, H >= 2^-32; f within its bound), so a value that is
 * not, or an object init does not make (a p_n zeroed on a bin that is
 * drawn, an empty support, a zeroed H: mcs_importance_sound_, O(N)), is
 * MCS_ERR_INVARIANT, nothing written. */
static mcs_status set_from_imp(const mcs_importance *imp, double *out, double v)
{
    return isfinite(v) && mcs_importance_sound_(imp) ? mcs_set_(out, v) : MCS_ERR_INVARIANT;
}

static mcs_status set_complex_from_imp(const mcs_importance *imp, double *re, double *im,
                                       double r, double i)
{
    if (!(isfinite(r) && isfinite(i) && mcs_importance_sound_(imp)))
        return MCS_ERR_INVARIANT;
    *re = r;
    *im = i;
    return MCS_OK;
}

/* f_b on the support (0 where the importance function never draws). */
static double f_on(const mcs_importance *imp, const double *f, size_t b)
{
    return mcs_eq_on_support(f, imp->p, b);
}

/* 1/p_b on the support, 0 outside it. */
static double q_on(const mcs_importance *imp, size_t b)
{
    return imp->p[b] > 0.0 ? 1.0 / imp->p[b] : 0.0;
}

/* check_imp, then freq < N (FREQ_RANGE) and, as asked, freq >= 1 and K
 * dividing N (DOMAIN). */
static mcs_status check_imp_freq(int outputs, const mcs_importance *imp, size_t k, size_t freq,
                                 int positive_freq, int need_divides)
{
    mcs_status st = check_imp(outputs, imp, k);
    if (st != MCS_OK)
        return st;
    if (freq >= imp->n)
        return MCS_ERR_FREQ_RANGE;
    if ((positive_freq && freq == 0u) || (need_divides && !mcs_eq_k_divides_n(imp->n, k)))
        return MCS_ERR_DOMAIN;
    return MCS_OK;
}

/* check_imp for the forms of f[imp->n] (finite, within MCS_ESTIMATE_MAX_ABS),
 * imp->n <= cap (N_RANGE). With 1/p_n < 2^32 (MCS_IMPORTANCE_MIN_G) every
 * F_k* F_l Q_{k-l} and p (f/p - fbar)^2 stays below 2^300. */
static mcs_status check_imp_f(const mcs_importance *imp, size_t k, const double *f,
                              const double *out, size_t cap)
{
    mcs_status st = check_imp(f != NULL && out != NULL, imp, k);
    if (st == MCS_OK && imp->n > cap)
        st = MCS_ERR_N_RANGE;
    return st == MCS_OK ? mcs_check_integrand_(imp->n, f) : st;
}

mcs_status mcs_eq41_importance_second(const mcs_importance *imp, size_t k, size_t bin_m,
                                      size_t bin_n, double *out)
{
    mcs_status st = check_imp(out != NULL, imp, k);
    if (st == MCS_OK && (bin_m >= imp->n || bin_n >= imp->n))
        st = MCS_ERR_BIN_RANGE;
    if (st != MCS_OK)
        return st;
    double kd = (double)k, nd = (double)imp->n;
    double v = (kd * kd - kd) / (nd * nd);
    if (bin_m == bin_n)
        v += kd / nd * q_on(imp, bin_n);
    /* s_n = 0 in every trial outside the support: its moments are 0 */
    if (!(imp->p[bin_m] > 0.0 && imp->p[bin_n] > 0.0))
        v = 0.0;
    return set_from_imp(imp, out, v);
}

/* (K/N) N^{-1/2} Q_{k-l}, the importance-sampled random cross spectrum. */
static void q_term(const mcs_importance *imp, size_t k, size_t freq_k, size_t freq_l,
                   double *re, double *im)
{
    size_t n = imp->n;
    double qr, qi;
    mcs_importance_q_unchecked(imp, (freq_k + n - freq_l) % n, &qr, &qi);
    double c = (double)k / (double)n / sqrt((double)n);
    *re = c * qr;
    *im = c * qi;
}

mcs_status mcs_eq43_importance_cross(const mcs_importance *imp, size_t k, size_t freq_k,
                                     size_t freq_l, double *re, double *im)
{
    mcs_status st = check_imp_freq(re != NULL && im != NULL, imp, k, freq_k, 0, 0);
    if (st == MCS_OK && freq_l >= imp->n)
        st = MCS_ERR_FREQ_RANGE;
    if (st == MCS_OK && freq_k == 0u && freq_l == 0u) /* the constant (K^2 - K)/N^2 adds there */
        st = MCS_ERR_DOMAIN;
    st = mcs_eq_check_complex(st, re, im);
    if (st != MCS_OK)
        return st;
    double qr, qi;
    q_term(imp, k, freq_k, freq_l, &qr, &qi);
    return set_complex_from_imp(imp, re, im, qr, qi);
}

mcs_status mcs_eq45_importance_power(const mcs_importance *imp, size_t k, size_t freq,
                                     double *out)
{
    mcs_status st = check_imp_freq(out != NULL, imp, k, freq, 1, 0);
    return st == MCS_OK ? set_from_imp(imp, out, (double)k / (double)imp->n / imp->harmonic_mean)
                        : st;
}

mcs_status mcs_eq46_importance_power0(const mcs_importance *imp, size_t k, double *out)
{
    mcs_status st = check_imp(out != NULL, imp, k);
    if (st != MCS_OK)
        return st;
    double kn = (double)k / (double)imp->n;
    return set_from_imp(imp, out, (double)k * kn + kn * (1.0 / imp->harmonic_mean - 1.0));
}

mcs_status mcs_eq49_importance_stratified_cross(const mcs_importance *imp, size_t k,
                                                size_t freq_k, size_t freq_l, double *re,
                                                double *im)
{
    mcs_status st = check_imp(re != NULL && im != NULL, imp, k);
    if (st == MCS_OK)
        st = mcs_eq_check_pair(1, imp->n, k, freq_k, freq_l);
    if (st == MCS_OK && (freq_k == 0u || freq_l == 0u))
        st = MCS_ERR_DOMAIN;
    st = mcs_eq_check_complex(st, re, im);
    if (st != MCS_OK)
        return st;
    double qr, qi, dr, di;
    q_term(imp, k, freq_k, freq_l, &qr, &qi);
    mcs_eq_delta_printed(imp->n, k, freq_k, freq_l, &dr, &di);
    return set_complex_from_imp(imp, re, im, qr + dr, qi + di);
}

mcs_status mcs_eq50_importance_stratified_power(const mcs_importance *imp, size_t k, size_t freq,
                                                double *out)
{
    mcs_status st = check_imp_freq(out != NULL, imp, k, freq, 1, 1);
    if (st != MCS_OK)
        return st;
    double kn = (double)k / (double)imp->n;
    return set_from_imp(imp, out,
                        kn * (1.0 / imp->harmonic_mean - mcs_eq_sinc2(imp->n, k, freq)));
}

/* (1/K) N^{-3/2} Re sum_{k >= k0, l >= l0} F_k* F_l Q_{k-l}: F of f, Q of 1/p,
 * both eq. 7 over the support, each coefficient computed where it is used
 * (O(N^3) trig, no work arrays). */
static double fq_variance(const mcs_importance *imp, size_t k, const double *f, size_t k0,
                          size_t l0)
{
    size_t n = imp->n;
    double sum = 0.0;
    for (size_t a = k0; a < n; ++a) {
        double far, fai;
        mcs_eq_dft_at(n, f, imp->p, a, &far, &fai);
        for (size_t b = l0; b < n; ++b) {
            double fbr, fbi, qr, qi;
            mcs_eq_dft_at(n, f, imp->p, b, &fbr, &fbi);
            mcs_importance_q_unchecked(imp, (a + n - b) % n, &qr, &qi);
            double ar = far * fbr + fai * fbi; /* F_a* F_b */
            double ai = far * fbi - fai * fbr;
            sum += ar * qr - ai * qi;
        }
    }
    double nd = (double)n;
    return sum / ((double)k * nd * sqrt(nd));
}

/* The same double sums for N above MCS_MAX_COV_N, by Parseval in O(N). With
 * q = 1/p, fbar the mean of f: sum over all k, l of F_k* F_l Q_{k-l} is
 * sqrt(N) sum f^2 q, its row k = 0 and its column l = 0 are each
 * F_0 sum f q, and its corner F_0^2 Q_0; so, over N^{3/2} K,
 *   k, l >= 1 (eq. 52 printed): (1/N) sum q (f - fbar)^2,
 *   k >= 1, all l (eq. 55):     (1/N) sum f q (f - fbar),
 *   all k, l less |F_0|^2/N (eq. 52 corrected): (1/N) sum p (f q - fbar)^2,
 * each written so that no large sums cancel (mean p = 1). */
static double fq_variance_parseval(const mcs_importance *imp, size_t k, const double *f,
                                   size_t k0, size_t l0)
{
    const size_t n = imp->n;
    double fbar = 0.0, sum = 0.0;
    for (size_t b = 0; b < n; ++b)
        fbar += f_on(imp, f, b);
    fbar /= (double)n;
    for (size_t b = 0; b < n; ++b) {
        const double fb = f_on(imp, f, b), q = q_on(imp, b), d = fb - fbar;
        if (k0 == 0u)
            sum += imp->p[b] * (fb * q - fbar) * (fb * q - fbar);
        else
            sum += l0 == 0u ? fb * q * d : q * d * d;
    }
    return sum / ((double)n * (double)k);
}

/* Eq. 52 printed and corrected are, by Parseval, (1/K)(1/N) sum_n q_n
 * (f_n - fbar)^2 and (1/K)(1/N) sum_n p_n (f_n q_n - fbar)^2 (see above):
 * sums of squares, so never negative, and a negative value of the term-by-
 * term double sum is its rounding. That rounding is below (N^2 + 4N + 16) eps
 * times the sum of the terms' magnitudes (three N-term transforms per term,
 * then N^2 terms), which |F_k| <= N^{-1/2} sum |f| and |Q_j| <= N^{1/2} / H
 * bound by (sum_n |f_n|)^2 / (H K). A value in [-bound, 0) reads 0; one below
 * is no rounding: the object's p is not one init gives (overwritten since),
 * MCS_ERR_INVARIANT (fuzz_api found -3.8e-4 with MCS_OK). Eq. 55 can be
 * negative. */
static mcs_status set_nonnegative(const mcs_importance *imp, size_t k, const double *f,
                                  double v, double *out)
{
    if (!(v < 0.0))
        return set_from_imp(imp, out, v);
    const double nd = (double)imp->n;
    double abs_sum = 0.0;
    for (size_t b = 0; b < imp->n; ++b)
        abs_sum += fabs(f_on(imp, f, b));
    const double bound = (nd * nd + 4.0 * nd + 16.0) * DBL_EPSILON * abs_sum * abs_sum /
                         (imp->harmonic_mean * (double)k);
    return -v <= bound ? set_from_imp(imp, out, 0.0) : MCS_ERR_INVARIANT;
}

/* The double sums of eq. 52 as printed and corrected and eq. 55, checked:
 * (1/K) N^{-3/2} sum_{k >= k0, l >= l0} F_k* F_l Q_{k-l} (less |F_0|^2/N K
 * when k0 = 0, eq. 52 corrected), term by term up to MCS_MAX_COV_N. */
static mcs_status fq_form(const mcs_importance *imp, size_t k, const double *f, size_t k0,
                          size_t l0, double *out)
{
    mcs_status st = check_imp_f(imp, k, f, out, (size_t)MCS_MAX_N);
    if (st != MCS_OK)
        return st;
    if (imp->n > (size_t)MCS_MAX_COV_N) {
        const double v = fq_variance_parseval(imp, k, f, k0, l0);
        return k0 == l0 ? set_nonnegative(imp, k, f, v, out) : set_from_imp(imp, out, v);
    }
    if (k0 != 0u) {
        const double v = fq_variance(imp, k, f, k0, l0);
        return l0 != 0u ? set_nonnegative(imp, k, f, v, out) : set_from_imp(imp, out, v);
    }
    const double nd = (double)imp->n;
    double sum = 0.0;
    for (size_t b = 0; b < imp->n; ++b)
        sum += f_on(imp, f, b);
    const double f0_sq = sum * sum / nd; /* |F_0|^2 of f on the support */
    const double v = (fq_variance(imp, 1u, f, 0u, 0u) - f0_sq / nd) / (double)k;
    return set_nonnegative(imp, k, f, v, out);
}

mcs_status mcs_eq52_variance_printed(const mcs_importance *imp, size_t k, const double *f,
                                     double *out)
{
    return fq_form(imp, k, f, 1u, 1u, out); /* k, l >= 1 only, as printed */
}

mcs_status mcs_eq55_variance_convolution(const mcs_importance *imp, size_t k, const double *f,
                                         double *out)
{
    return fq_form(imp, k, f, 1u, 0u, out); /* (F (x) Q)_k: the convolution over every l */
}

mcs_status mcs_eq52_variance_corrected(const mcs_importance *imp, size_t k, const double *f,
                                       double *out)
{
    return fq_form(imp, k, f, 0u, 0u, out); /* every k, l, less the mean term */
}

mcs_status mcs_eq58_bound_printed(const mcs_importance *imp, size_t k, const double *f,
                                  double *out)
{
    mcs_status st = check_imp_f(imp, k, f, out, (size_t)MCS_MAX_N);
    if (st != MCS_OK) /* sum_{k >= 1} |F_k|^2 needs the DFT of f */
        return st;
    return set_from_imp(imp, out,
                        mcs_eq_ac_energy(imp->n, f, imp->p) / imp->harmonic_mean / (double)k);
}

mcs_status mcs_eq58_bound_corrected(const mcs_importance *imp, size_t k, const double *f,
                                    double *out)
{
    mcs_status st = check_imp_f(imp, k, f, out, (size_t)MCS_MAX_N);
    if (st != MCS_OK)
        return st;
    /* sum_{all n} |F_n|^2 = sum f_n^2 (Parseval, eq. 7 is unitary), f on the
     * support; sum_k Var S_k = sum_n Var s_n = K/H - K N_s / N^2 over the N_s
     * bins of the support (K/H - K/N when that is every bin) */
    const double nd = (double)imp->n;
    double energy = 0.0, support = 0.0;
    for (size_t b = 0; b < imp->n; ++b) {
        const double fb = f_on(imp, f, b);
        energy += fb * fb;
        support += imp->p[b] > 0.0 ? 1.0 : 0.0;
    }
    return set_from_imp(imp, out,
                        energy * (1.0 / imp->harmonic_mean - support / (nd * nd)) / (double)k);
}
