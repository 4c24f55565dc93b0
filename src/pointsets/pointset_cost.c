/* The cost model behind MCS_POINTSET_PATH_AUTO (pointset.h, pointset2d.h).
 *
 * Modelled time of the sums of one trial of K points at cutoff F, in
 * nanoseconds, with n the NUFFT's grid points per axis (about 4.3 F), C the
 * points it takes per transform (chunk_of in pointset.c and pointset2d.c:
 * at least 8192 coordinates, and (2F + 1)^d modes' worth) and
 * T = ceil(K / C) its transforms:
 *
 *   1D DIRECT  K (D1 H + P1 (H / 32 + 32))         H = F + 1 padded to 32
 *   1D NUFFT   S1 K + T G1 n log2 n
 *   2D DIRECT  K (D2 (F + 1)(2F + 2) + P2 (F + 1))
 *   2D NUFFT   S2 K + T G2 n^2 log2 n
 *
 * D: one point at one stored frequency (a complex multiply-add of the outer
 * product); P: one entry of a point's phase rows; S: one point spread onto
 * the grid (w = 16 kernel values per axis, then w^d adds); G: per n log2 n
 * (n^2 log2 n) of a transform, with the grid's clearing and the gather of
 * its modes into the sums, which grow alike (fitted apart, they traded off
 * against each other). The Welford update of the statistics, U (F + 1) or
 * U (F + 1)(2F + 2) with U about 1.5 and 2.5, is the same for both paths and
 * left out, as are the argument checks.
 *
 * The constants are fitted by test/bench/pointset_costs.c (built by `make
 * benches`; run build/bench/pointset_costs), which times each forced path
 * on one pre-drawn random trial over a grid of K = 16..65536 and
 * F = 16..16384 (1D) or 4..640 (2D), and prints least-squares fits (the
 * direct path's, then the NUFFT's from its times less the direct fit's U)
 * and AUTO's time over the faster forced path's in every cell. Three runs
 * on the development machine (AMD EPYC, 2 shared cores, gcc 12 -O2) gave
 * D1 0.56-0.63, P1 2.0-3.2, S1 114-121, G1 0.35-0.39, D2 0.26-0.27,
 * P2 9.7-10.3, S2 296-325, G2 0.69-0.72, rounded below (P1 at the low end:
 * the direct sum's measured 81 ns a point at F = 16 against the NUFFT's
 * 116 ns, which P1 = 3 would have got the wrong way round). The crossovers
 * that follow: in 1D, DIRECT while F is below about 70 (a point costs about
 * 0.66 H + 64 ns against 115), in 2D while F is below about 16
 * (0.5 (F + 1)^2 + 10 (F + 1) against 320), NUFFT beyond once K amortises
 * the transform (2D, F = 128: K above about 150; F = 640: above about 120). The fits are
 * noisy on a shared machine, but only the ratio near a crossover matters,
 * where the two paths cost about the same anyway. */
#include <math.h>

#include "pointset_internal.h"

#define D1 0.60  /* 1D direct, per point and stored frequency */
#define P1 2.0   /* 1D direct, per point and phase-row entry */
#define S1 115.0 /* 1D NUFFT, per point spread */
#define G1 0.37  /* 1D NUFFT, per n log2 n of one transform */
#define D2 0.26  /* 2D direct, per point and stored wave vector */
#define P2 10.0  /* 2D direct, per point and phase-row entry */
#define S2 320.0 /* 2D NUFFT, per point spread */
#define G2 0.70  /* 2D NUFFT, per n^2 log2 n of one transform */

mcs_pointset_path mcs_ps_auto_path_(int dims, size_t freq, size_t n, size_t chunk, size_t k)
{
    const double kd = (double)k, f = (double)freq, nd = (double)n;
    const double transforms = ceil(kd / (double)chunk);
    double direct, nufft;
    if (dims == 1) {
        const double h = floor(f / 32.0 + 1.0) * 32.0;
        direct = kd * (D1 * h + P1 * (h / 32.0 + 32.0));
        nufft = S1 * kd + transforms * G1 * nd * log2(nd);
    } else {
        direct = kd * (D2 * (f + 1.0) * (2.0 * f + 2.0) + P2 * (f + 1.0));
        nufft = S2 * kd + transforms * G2 * nd * nd * log2(nd);
    }
    return nufft < direct ? MCS_POINTSET_PATH_NUFFT : MCS_POINTSET_PATH_DIRECT;
}
