/* The moment accumulator's checks of its stored sums (acc_internal.h): on
 * an object, with what its own copy of the data implies, for the read-outs,
 * merges and record writer; and the direct check of its powers, for the
 * loader and the record writer (on a record's values or an object's). */
#include "mcspec/moment.h"
#include "acc_internal.h"

#include <math.h>

/* The sums of an object set up by init (its n checked) as the shared check
 * reads them (acc_internal.h). */
static mcs_moment_sums_ object_sums(const mcs_moment *acc)
{
    const mcs_moment_sums_ s = {acc->n,
                                acc->count,
                                acc->batch_count,
                                acc->batch_sparse,
                                mcs_memory_values_(acc->shift),
                                mcs_memory_values_(acc->sum_d),
                                mcs_memory_values_(acc->lo_d),
                                mcs_memory_values_(acc->sum_dd),
                                mcs_memory_values_(acc->lo_dd),
                                mcs_memory_values_(acc->batch_s),
                                mcs_memory_values_(acc->batch_d),
                                mcs_memory_values_(acc->batch_w)};
    return s;
}

/* The object's own copy of what its N implies: both triangles of its sums
 * equal (a record keeps one), its twiddle table that of its N (an N
 * overwritten since init reads another table: cos(2 pi / N) at index 1, 0
 * past N) with every entry in [-1, 1]. */
static int own_copy_ok(const mcs_moment *acc)
{
    const size_t n = acc->n;
    int ok = 1;
    for (size_t m = 0; m < n; ++m) {
        ok &= (fabs(acc->cos_table[m]) <= 1.0) & (fabs(acc->sin_table[m]) <= 1.0);
        for (size_t q = m + 1u; q < n; ++q)
            ok &= (acc->sum_dd[m * n + q] == acc->sum_dd[q * n + m]) &
                  (acc->lo_dd[m * n + q] == acc->lo_dd[q * n + m]);
    }
    if (n >= 2u) {
        const double a = mcs_twiddle_angle_(1u, n);
        ok &= acc->cos_table[1] == cos(a) && acc->sin_table[1] == sin(a);
    } else if ((size_t)MCS_MAX_COV_N >= 2u) {
        ok &= acc->cos_table[1] == 0.0 && acc->sin_table[1] == 0.0;
    }
    return ok;
}

int mcs_moment_stored_valid(const mcs_moment *acc)
{
    const mcs_moment_sums_ s = object_sums(acc);
    return own_copy_ok(acc) && mcs_moment_sums_ok_(&s);
}

/* MCS_POWER_FREQS_ frequencies at a time, the twiddles along a row by
 * rotation (within 40 eps: R allows 64) and those of the rows from cos and
 * sin; its own function, so that its frame and its callers' each stay
 * below `make stack`'s 1 KiB. */
int mcs_moment_powers_ok(const mcs_moment_sums_ *s)
{
    const size_t n = s->n;
    if (s->count == 0u || n == 0u)
        return 1;
    const double nd = (double)n, t = (double)s->count;
    double acc, var_r;
    const double floor = -(4.0 * mcs_moment_power_rounding_(s, &acc, &var_r) + acc +
                           mcs_moment_underflow_(n, 1));
    const double var_floor = -(4.0 * var_r + acc + mcs_moment_underflow_(n, 1));
    for (size_t k0 = 0; k0 < n; k0 += MCS_POWER_FREQS_) {
        const size_t len = n - k0 < MCS_POWER_FREQS_ ? n - k0 : MCS_POWER_FREQS_;
        double second[MCS_POWER_FREQS_] = {0.0};
        mcs_rotations_ col;
        for (size_t m = 0; m < n; ++m) {
            double yr[MCS_POWER_FREQS_] = {0.0}, yi[MCS_POWER_FREQS_] = {0.0};
            mcs_rotations_start_(&col, k0, len, n);
            for (size_t q = 0; q < n; ++q) {
                if (q != 0u)
                    mcs_rotations_step_(&col, q);
                const double x = mcs_moment_total_at_(s, m, q);
                for (size_t f = 0; f < len; ++f) {
                    yr[f] += col.zc[f] * x;
                    yi[f] += col.zs[f] * x;
                }
            }
            for (size_t f = 0; f < len; ++f) { /* Re e^{-i a m} (yr + i yi) */
                double cm, sm;
                mcs_twiddle_pair_((k0 + f) * m, n, &cm, &sm);
                second[f] += cm * yr[f] + sm * yi[f];
            }
        }
        for (size_t f = 0; f < len; ++f) {
            double fr = 0.0, fi = 0.0, mr = 0.0, mi = 0.0;
            for (size_t m = 0; m < n; ++m) {
                double cm, sm;
                mcs_twiddle_pair_((k0 + f) * m, n, &cm, &sm);
                const double d = mcs_moment_first_at_(s, m) / t, mean = MCS_AT_(s->shift, m) + d;
                fr += cm * d;
                fi -= sm * d;
                mr += cm * mean;
                mi -= sm * mean;
            }
            const double var = (second[f] / t - (fr * fr + fi * fi)) / nd;
            const double power = var + (mr * mr + mi * mi) / nd;
            if (!(power >= floor) || !(var >= var_floor)) /* a fuzz_load record read var < 0 */
                return 0;
        }
    }
    return 1;
}

int mcs_moment_powers_valid(const mcs_moment *acc)
{
    const mcs_moment_sums_ s = object_sums(acc);
    return mcs_moment_powers_ok(&s);
}
