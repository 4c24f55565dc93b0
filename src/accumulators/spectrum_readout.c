/* Read-outs of the spectrum accumulator: the closed units' weighted Welford
 * statistics with the open PAIR batch, if any, joined as one more unit
 * (Chan et al. with M2 = 0 inside it), without writing anything. */
#include <math.h>

#include "spectrum_internal.h"

/* The statistics of one stored frequency. */
typedef struct {
    double mean_re, mean_im, mean_pow; /* means over all trials */
    double m2_s, m2_pow;               /* weighted M2 over the units */
    double units;                      /* units, the open batch included */
} freq_stats;

static void stats_at(const mcs_spectrum *acc, size_t q, freq_stats *fs)
{
    /* S_0 and S_{N/2} (N even) are real for a real s: their twiddles are
     * +-1, but the sine table's sin(pi) is 1.2e-16, which the SPARSE path's
     * sums carried into Im <S_{N/2}> (-7.7e-17 for the hand-worked N = 4
     * file). Their imaginary mean is 0 exactly, not rounding. */
    const int real = q == 0u || 2u * q == acc->n;
    fs->mean_re = acc->mean_re[q];
    fs->mean_im = real ? 0.0 : acc->mean_im[q];
    fs->mean_pow = acc->mean_pow[q];
    fs->m2_s = acc->m2_s[q];
    fs->m2_pow = acc->m2_pow[q];
    fs->units = (double)acc->units;
    if (acc->open_count == 0u)
        return;
    double xr, xi, xp;
    mcs_spectrum_open_values_(acc, q, &xr, &xi, &xp);
    const double wa = (double)mcs_spectrum_closed_(acc), wb = (double)acc->open_count;
    const double f = wb / (wa + wb), g = wa * wb / (wa + wb); /* f = 1, g = 0 when wa = 0 */
    const double dr = xr - fs->mean_re, di = xi - fs->mean_im, dp = xp - fs->mean_pow;
    fs->mean_re += f * dr;
    fs->mean_im = real ? 0.0 : fs->mean_im + f * di;
    fs->mean_pow += f * dp;
    fs->m2_s += g * (dr * dr + di * di);
    fs->m2_pow += g * (dp * dp);
    fs->units += 1.0;
}

/* Common read-out checks: outputs given (else NULL), acc initialised, freq in
 * [0, N), at least one trial and, for a standard error, two units. Then the
 * statistics of freq's stored frequency (k or N - k: S_{N-k} = conj(S_k),
 * s being real) and whether freq is the conjugate one. */
static mcs_status readout(int outputs, const mcs_spectrum *acc, size_t freq, int spread,
                          freq_stats *fs, int *conjugate)
{
    uint64_t units;
    mcs_status st = outputs ? mcs_spectrum_units(acc, &units) : MCS_ERR_NULL;
    if (st == MCS_OK && freq >= acc->n)
        st = MCS_ERR_FREQ_RANGE;
    if (st == MCS_OK && (acc->count == 0u || (spread && units < 2u)))
        st = MCS_ERR_EMPTY;
    if (st != MCS_OK)
        return st;
    const size_t q = freq > acc->n / 2u ? acc->n - freq : freq;
    *conjugate = q != freq;
    stats_at(acc, q, fs);
    return MCS_OK;
}

/* Standard error of a mean over T trials in U units from its weighted M2
 * (spectrum.h): sqrt(M2 / (U - 1) / T). */
static double stderr_of(const mcs_spectrum *acc, const freq_stats *fs, double m2)
{
    return sqrt(m2 / (fs->units - 1.0) / (double)acc->count);
}

/* Writes a read-out that is finite. Accepted input cannot make one that is
 * not (spectrum.h), but an object whose bytes were overwritten can: then
 * MCS_ERR_NOT_FINITE and the output is left alone, never a NaN with MCS_OK. */
static mcs_status set_finite(double *out, double value)
{
    return isfinite(value) ? mcs_set_(out, value) : MCS_ERR_NOT_FINITE;
}

mcs_status mcs_spectrum_mean(const mcs_spectrum *acc, size_t freq, double *re, double *im)
{
    freq_stats fs;
    int conj;
    mcs_status st = readout(re != NULL && im != NULL, acc, freq, 0, &fs, &conj);
    if (st != MCS_OK)
        return st;
    if (re == im) /* one double cannot hold both parts */
        return MCS_ERR_ALIAS;
    if (!isfinite(fs.mean_re) || !isfinite(fs.mean_im))
        return MCS_ERR_NOT_FINITE;
    *re = fs.mean_re;
    *im = conj ? -fs.mean_im : fs.mean_im;
    return MCS_OK;
}

mcs_status mcs_spectrum_mean_stderr(const mcs_spectrum *acc, size_t freq, double *stderr_out)
{
    freq_stats fs;
    int conj;
    mcs_status st = readout(stderr_out != NULL, acc, freq, 1, &fs, &conj);
    return st == MCS_OK ? set_finite(stderr_out, stderr_of(acc, &fs, fs.m2_s)) : st;
}

mcs_status mcs_spectrum_power(const mcs_spectrum *acc, size_t freq, double *power)
{
    freq_stats fs;
    int conj;
    mcs_status st = readout(power != NULL, acc, freq, 0, &fs, &conj);
    return st == MCS_OK ? set_finite(power, fs.mean_pow) : st;
}

mcs_status mcs_spectrum_power_stderr(const mcs_spectrum *acc, size_t freq, double *stderr_out)
{
    freq_stats fs;
    int conj;
    mcs_status st = readout(stderr_out != NULL, acc, freq, 1, &fs, &conj);
    return st == MCS_OK ? set_finite(stderr_out, stderr_of(acc, &fs, fs.m2_pow)) : st;
}

/* ---- every stored frequency at once ---------------------------------------- */

/* The five arrays of mcs_spectrum_read_all, in argument order; NULL where
 * not wanted. */
enum { ALL_MEAN_RE, ALL_MEAN_IM, ALL_MEAN_SE, ALL_POWER, ALL_POWER_SE, ALL_COUNT };

/* The values of stored frequency q, each as its per-frequency call forms it
 * (the same stats_at and stderr_of, so the same bits); the standard errors
 * only where asked (they need two units). */
static void values_at(const mcs_spectrum *acc, size_t q, double *const out[ALL_COUNT],
                      double v[ALL_COUNT])
{
    freq_stats fs;
    stats_at(acc, q, &fs);
    v[ALL_MEAN_RE] = fs.mean_re;
    v[ALL_MEAN_IM] = fs.mean_im;
    v[ALL_MEAN_SE] = out[ALL_MEAN_SE] != NULL ? stderr_of(acc, &fs, fs.m2_s) : 0.0;
    v[ALL_POWER] = fs.mean_pow;
    v[ALL_POWER_SE] = out[ALL_POWER_SE] != NULL ? stderr_of(acc, &fs, fs.m2_pow) : 0.0;
}

/* Whether two of the arrays (each n_out doubles) share a byte, or one lies
 * in *acc (which is read while they are written). */
static int arrays_alias(const mcs_spectrum *acc, size_t n_out, double *const out[ALL_COUNT])
{
    const size_t bytes = mcs_bytes_(n_out, sizeof(double));
    int hit = 0;
    for (int a = 0; a < ALL_COUNT; ++a) {
        if (out[a] == NULL)
            continue;
        hit |= mcs_overlap_(out[a], bytes, acc, sizeof *acc);
        for (int b = a + 1; b < ALL_COUNT; ++b)
            hit |= out[b] != NULL && mcs_overlap_(out[a], bytes, out[b], bytes);
    }
    return hit;
}

mcs_status mcs_spectrum_read_all(const mcs_spectrum *acc, size_t n_out, double *mean_re,
                                 double *mean_im, double *mean_stderr, double *power,
                                 double *power_stderr)
{
    double *const out[ALL_COUNT] = {mean_re, mean_im, mean_stderr, power, power_stderr};
    int any = 0;
    for (int a = 0; a < ALL_COUNT; ++a)
        any |= out[a] != NULL;
    uint64_t units = 0u;
    mcs_status st = any ? mcs_spectrum_units(acc, &units) : MCS_ERR_NULL;
    if (st != MCS_OK)
        return st;
    if (n_out != acc->n / 2u + 1u)
        return MCS_ERR_MISMATCH;
    if (acc->count == 0u || ((mean_stderr != NULL || power_stderr != NULL) && units < 2u))
        return MCS_ERR_EMPTY;
    if (arrays_alias(acc, n_out, out))
        return MCS_ERR_ALIAS;
    /* Every value is checked before any is written (an overwritten object
     * can hold a non-finite one), then formed again and written. */
    double v[ALL_COUNT];
    for (size_t q = 0; q < n_out; ++q) {
        values_at(acc, q, out, v);
        for (int a = 0; a < ALL_COUNT; ++a)
            if (out[a] != NULL && !isfinite(v[a]))
                return MCS_ERR_NOT_FINITE;
    }
    for (size_t q = 0; q < n_out; ++q) {
        values_at(acc, q, out, v);
        for (int a = 0; a < ALL_COUNT; ++a)
            if (out[a] != NULL)
                out[a][q] = v[a];
    }
    return MCS_OK;
}
