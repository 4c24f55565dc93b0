/* Exact binned 2D moments and estimator variance (spectrum2d.h).
 *
 * Derivations (eq. 16 in 2D, <S_k S_l^*> = (1/N) sum_{m,n} e^{-2 pi i (k.m - l.n)} <s_m s_n>
 * with k.m = k1 m1/N1 + k2 m2/N2):
 * - random: <s_m s_n> = (K/N) d_mn + K(K-1)/N^2 (multinomial), so
 *   <S_k S_l^*> = (K/N) d_kl + (K(K-1)/N) d_k0 d_l0;
 * - jittered, strata of a x b bins: <s_m s_n> = (K/N) d_mn + (K/N)^2 (1 - g_mn),
 *   g_mn = [same stratum]; the g term sums to (K/N)^3 A(k) A(l)^* times the
 *   phase sum over the K strata origins, K [k = l mod (m, n)] / K;
 * - shifted grid, a x b bins per cell: s is the comb {(a i + u, b j + v)}
 *   with (u, v) uniform on the a x b offsets, so S_k is K N^{-1/2} times a
 *   phase on the comb m | k1, n | k2 and 0 off it; averaging the phase over
 *   (u, v) leaves d_kl (two comb points differ by a multiple of (m, n) that
 *   is not a multiple of (N1, N2) unless they are equal).
 * All three are unbiased: <S_k> = K N^{-1/2} d_k0. */
#include "mcspec/spectrum2d.h"
#include "patterns/pattern2d_internal.h"
#include "pointsets/pointset_internal.h"

#include <math.h>

static mcs_status check(const mcs_pattern2d *pat, size_t n_x, size_t n_y)
{
    if (pat == NULL)
        return MCS_ERR_NULL;
    if (!mcs_pattern2d_is_valid_(pat))
        return MCS_ERR_UNINIT;
    if (n_x == 0u || n_x > (size_t)MCS_SPECTRUM2D_MAX_SIDE || n_y == 0u ||
        n_y > (size_t)MCS_SPECTRUM2D_MAX_SIDE)
        return MCS_ERR_N_RANGE;
    if (pat->kind == MCS_PATTERN2D_RANDOM)
        return MCS_OK;
    if (pat->kind != MCS_PATTERN2D_JITTERED && pat->kind != MCS_PATTERN2D_SHIFTED_GRID)
        return MCS_ERR_KIND;
    if (n_x % pat->strata_x != 0u || n_y % pat->strata_y != 0u)
        return MCS_ERR_DOMAIN;
    return MCS_OK;
}

/* The checks of a read-out at wave vectors k = (k[0], k[1]) and l (l may be
 * k) with outputs out_a, out_b: NULL, then those of check, then
 * MCS_ERR_FREQ_RANGE. */
static mcs_status check_at(const mcs_pattern2d *pat, size_t n_x, size_t n_y, const size_t *k,
                           const size_t *l, const double *const out[2])
{
    if (out[0] == NULL || out[1] == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check(pat, n_x, n_y);
    if (st == MCS_OK && !(k[0] < n_x && k[1] < n_y && l[0] < n_x && l[1] < n_y))
        st = MCS_ERR_FREQ_RANGE;
    return st;
}

/* (-1)^(number of whole half-turns in pi q / n): with q mod n it gives
 * sin(pi q/n) and e^{-i pi q/n} from a reduced angle. */
static double half_turns_sign(size_t q, size_t n)
{
    return (q / n) % 2u ? -1.0 : 1.0;
}

/* sum_{u < a} e^{-2 pi i k u / n} = e^{-pi i k (a-1)/n} sin(pi k a/n) / sin(pi k/n)
 * (a at k = 0 mod n); k < n. Angles from integers reduced mod n. */
static void block_sum(size_t k, size_t a, size_t n, double *re, double *im)
{
    if (k == 0u || n == 0u) { /* n = 0 cannot reach here: the callers check it */
        *re = (double)a;
        *im = 0.0;
        return;
    }
    const double pi = MCS_TWO_PI * 0.5, nd = (double)n;
    const size_t ka = k * a, kb = k * (a - 1u);
    double mag = half_turns_sign(ka, n) * sin(pi * (double)(ka % n) / nd) /
                 sin(pi * (double)k / nd);
    double ph = pi * (double)(kb % n) / nd;
    mag *= half_turns_sign(kb, n);
    *re = mag * cos(ph);
    *im = -mag * sin(ph);
}

/* A pattern on its n_x x n_y bins (checked); keeps the helpers' argument
 * lists short enough to pass in registers. */
typedef struct {
    const mcs_pattern2d *pat;
    size_t n_x, n_y;
} grid;

/* A(k) = out[0] + i out[1] for a jittered stratum of (N1/m) x (N2/n) bins. */
static void stratum_sum(const grid *g, size_t k1, size_t k2, double *out)
{
    double ar, ai, br, bi;
    block_sum(k1, g->n_x / g->pat->strata_x, g->n_x, &ar, &ai);
    block_sum(k2, g->n_y / g->pat->strata_y, g->n_y, &br, &bi);
    out[0] = ar * br - ai * bi;
    out[1] = ar * bi + ai * br;
}

/* Cov(S_k, S_l) = out[0] + i out[1], k = (k[0], k[1]), l = (l[0], l[1]). */
static void covariance(const grid *g, const size_t *k, const size_t *l, double *out)
{
    const mcs_pattern2d *pat = g->pat;
    const double kd = (double)pat->k, kn = kd / ((double)g->n_x * (double)g->n_y);
    const int same = k[0] == l[0] && k[1] == l[1], zero = same && k[0] == 0u && k[1] == 0u;
    out[0] = 0.0;
    out[1] = 0.0;
    if (pat->kind == MCS_PATTERN2D_RANDOM) {
        out[0] = same && !zero ? kn : 0.0;
    } else if (pat->kind == MCS_PATTERN2D_SHIFTED_GRID) {
        int comb = k[0] % pat->strata_x == 0u && k[1] % pat->strata_y == 0u;
        out[0] = same && comb && !zero ? kd * kn : 0.0;
    } else if (k[0] % pat->strata_x == l[0] % pat->strata_x &&
               k[1] % pat->strata_y == l[1] % pat->strata_y) {
        double a[2], b[2];
        stratum_sum(g, k[0], k[1], a);
        stratum_sum(g, l[0], l[1], b);
        const double c3 = kn * kn * kn;
        out[0] = (same ? kn : 0.0) - c3 * (a[0] * b[0] + a[1] * b[1]); /* A(k) A(l)^* */
        out[1] = -c3 * (a[1] * b[0] - a[0] * b[1]);
    }
}

/* <S_k>: K N^{-1/2} at k = 0 and 0 elsewhere, all three kinds being unbiased. */
static double mean_re(const grid *g, const size_t *k)
{
    return k[0] == 0u && k[1] == 0u ? (double)g->pat->k / sqrt((double)g->n_x * (double)g->n_y)
                                    : 0.0;
}

mcs_status mcs_spectrum2d_exact_mean(const mcs_pattern2d *pat, size_t n_x, size_t n_y,
                                     size_t freq_k, size_t freq_l, double *re, double *im)
{
    const size_t k[2] = {freq_k, freq_l};
    const double *const out[2] = {re, im};
    mcs_status st = check_at(pat, n_x, n_y, k, k, out);
    if (st != MCS_OK)
        return st;
    const grid g = {pat, n_x, n_y};
    *re = mean_re(&g, k);
    *im = 0.0;
    return MCS_OK;
}

mcs_status mcs_spectrum2d_exact_covariance(const mcs_pattern2d *pat, size_t n_x, size_t n_y,
                                           size_t k1, size_t k2, size_t l1, size_t l2,
                                           double *re, double *im)
{
    const size_t k[2] = {k1, k2}, l[2] = {l1, l2};
    const double *const out[2] = {re, im};
    mcs_status st = check_at(pat, n_x, n_y, k, l, out);
    if (st != MCS_OK)
        return st;
    if (re == im)
        return MCS_ERR_ALIAS; /* one place cannot hold both parts */
    const grid g = {pat, n_x, n_y};
    double c[2];
    covariance(&g, k, l, c);
    *re = c[0];
    *im = c[1];
    return MCS_OK;
}

mcs_status mcs_spectrum2d_exact_power(const mcs_pattern2d *pat, size_t n_x, size_t n_y,
                                      size_t freq_k, size_t freq_l, double *out)
{
    const size_t k[2] = {freq_k, freq_l};
    const double *const outs[2] = {out, out};
    mcs_status st = check_at(pat, n_x, n_y, k, k, outs);
    if (st != MCS_OK)
        return st;
    const grid g = {pat, n_x, n_y};
    double c[2];
    covariance(&g, k, k, c);
    const double m = mean_re(&g, k);
    *out = c[0] + m * m;
    return MCS_OK;
}

static mcs_status check_f(const mcs_pattern2d *pat, size_t n_x, size_t n_y, const double *f_re,
                          const double *f_im, const double *out)
{
    if (f_re == NULL || f_im == NULL || out == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check(pat, n_x, n_y);
    if (st == MCS_OK && !(mcs_all_finite_(n_x * n_y, f_re) && mcs_all_finite_(n_x * n_y, f_im)))
        st = MCS_ERR_NOT_FINITE;
    return st;
}

/* (K/N)^3 sum over residue classes r of |sum_{k = r mod (m,n)} F_k^* A(k)|^2:
 * the cross terms of the jittered Var[I], O(N) in all. */
static double jittered_cross(const grid *g, const double *f_re, const double *f_im)
{
    const size_t m = g->pat->strata_x, n = g->pat->strata_y, n_x = g->n_x, n_y = g->n_y;
    double total = 0.0;
    for (size_t r2 = 0; r2 < n; ++r2)
        for (size_t r1 = 0; r1 < m; ++r1) {
            double sr = 0.0, si = 0.0;
            for (size_t k2 = r2; k2 < n_y; k2 += n)
                for (size_t k1 = r1; k1 < n_x; k1 += m) {
                    double a[2], fr = f_re[k2 * n_x + k1], fi = -f_im[k2 * n_x + k1];
                    stratum_sum(g, k1, k2, a);
                    sr += fr * a[0] - fi * a[1];
                    si += fr * a[1] + fi * a[0];
                }
            total += sr * sr + si * si;
        }
    const double kn = (double)g->pat->k / ((double)n_x * (double)n_y);
    return kn * kn * kn * total;
}

mcs_status mcs_spectrum2d_exact_variance(const mcs_pattern2d *pat, size_t n_x, size_t n_y,
                                         const double *f_re, const double *f_im, double *out)
{
    mcs_status st = check_f(pat, n_x, n_y, f_re, f_im, out);
    if (st != MCS_OK)
        return st;
    if (pat->kind != MCS_PATTERN2D_JITTERED)
        return mcs_spectrum2d_exact_variance14(pat, n_x, n_y, f_re, f_im, out); /* stationary */
    const double kd = (double)pat->k, kn = kd / ((double)n_x * (double)n_y);
    double diag = 0.0;
    for (size_t i = 0; i < n_x * n_y; ++i)
        diag += f_re[i] * f_re[i] + f_im[i] * f_im[i];
    const grid g = {pat, n_x, n_y};
    /* |F_k|^2 of a finite f can overflow: refused, never returned as inf. */
    const double v = (kn * diag - jittered_cross(&g, f_re, f_im)) / (kd * kd);
    return isfinite(v) ? mcs_set_(out, v) : MCS_ERR_MAGNITUDE;
}

mcs_status mcs_spectrum2d_exact_variance14(const mcs_pattern2d *pat, size_t n_x, size_t n_y,
                                           const double *f_re, const double *f_im, double *out)
{
    mcs_status st = check_f(pat, n_x, n_y, f_re, f_im, out);
    if (st != MCS_OK)
        return st;
    const grid g = {pat, n_x, n_y};
    double sum = 0.0;
    for (size_t k2 = 0; k2 < n_y; ++k2)
        for (size_t k1 = 0; k1 < n_x; ++k1) {
            if (k1 == 0u && k2 == 0u)
                continue;
            const size_t k[2] = {k1, k2};
            double c[2];
            covariance(&g, k, k, c); /* the power: <S_k> = 0 here */
            size_t i = k2 * n_x + k1;
            sum += (f_re[i] * f_re[i] + f_im[i] * f_im[i]) * c[0];
        }
    const double kd = (double)pat->k, v = sum / (kd * kd);
    return isfinite(v) ? mcs_set_(out, v) : MCS_ERR_MAGNITUDE;
}
