/* The vectorisable kernel of the moment accumulator, written once and
 * compiled twice by moment.c (simd_clones.h): KERNEL(name) names this copy.
 * Both copies do the same IEEE operations in the same order per entry (no
 * contraction into FMA: ISO C mode), so they give the same bits. */

/* Half of x x^T into the open batch w (n x n): for every bin m where x is not
 * 0, x_m^2 / 2 on the diagonal and x_m x_q for q > m along row m, in blocks
 * of a fixed count the compiler vectorises at -O2, then a scalar tail. Rows
 * of zeros cost a compare. */
static MCS_NOINLINE void KERNEL(moment_rows)(size_t n, const double *restrict x,
                                             double *restrict w)
{
    for (size_t m = 0; m < n; ++m) {
        const double xm = x[m];
        if (xm == 0.0)
            continue;
        double *restrict row = &w[m * n];
        row[m] += 0.5 * (xm * xm);
        size_t q = m + 1u;
        for (; q + 8u <= n; q += 8u)
            for (size_t r = 0; r < 8u; ++r)
                row[q + r] += xm * x[q + r];
        for (; q < n; ++q)
            row[q] += xm * x[q];
    }
}
