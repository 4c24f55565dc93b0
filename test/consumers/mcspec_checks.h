/* The checks every consumer program runs against the mcspec it was built
 * with (C11 and C++17 alike): the version it reports, the DFT of a cosine,
 * the power spectrum of two known trials through both of the spectrum's
 * paths, and a rejected input (check_backend: the DFT back end, when the
 * build says which to expect). Every expected value is a closed form
 * computed here, independently of the library:
 * - s_n = cos(2 pi 5 n / 64): S_5 = S_59 = sqrt(64) / 2 = 4, every other S_k 0;
 * - one sample at bin 3: |S_k|^2 = 1/N for every k;
 * - samples at bins 0 and 16: |S_k|^2 = (2 + 2 cos(pi k / 2)) / N;
 *   so the mean over the two trials is (3 + 2 cos(pi k / 2)) / (2 N).
 * Returns the number of failed checks (each printed). */
#ifndef MCSPEC_CONSUMER_CHECKS_H
#define MCSPEC_CONSUMER_CHECKS_H

#include <math.h>
#include <stdio.h>
#include <string.h>
#include "mcspec.h"

#define CHECK_N 64u
#define CHECK_PI 3.14159265358979323846

/* Big structs in static storage: mcs_spectrum is 400 KB at the defaults. */
static mcs_dft check_plan;
static mcs_spectrum check_sparse;
static mcs_spectrum check_dense;

static int check_close(const char *what, size_t freq, double got, double want)
{
    if (fabs(got - want) <= 1e-12 * (1.0 + fabs(want)))
        return 0;
    printf("FAIL %s at k = %u: %.17g, expected %.17g\n", what, (unsigned)freq, got, want);
    return 1;
}

static int check_status(const char *what, mcs_status st)
{
    if (st == MCS_OK)
        return 0;
    printf("FAIL %s: %s\n", what, mcs_status_str(st));
    return 1;
}

static int check_dft(void)
{
    double s[CHECK_N], re[CHECK_N], im[CHECK_N];
    int bad = 0;
    for (size_t j = 0; j < CHECK_N; ++j)
        s[j] = cos(2.0 * CHECK_PI * 5.0 * (double)j / (double)CHECK_N);
    bad += check_status("mcs_dft_init", mcs_dft_init(&check_plan, CHECK_N));
    bad += check_status("mcs_dft_real", mcs_dft_real(&check_plan, CHECK_N, s, re, im));
    for (size_t k = 0; k < CHECK_N && bad == 0; ++k) {
        const double want = (k == 5u || k == CHECK_N - 5u) ? sqrt((double)CHECK_N) / 2.0 : 0.0;
        bad += check_close("Re S_k of cos(2 pi 5 n/64)", k, re[k], want);
        bad += check_close("Im S_k of cos(2 pi 5 n/64)", k, im[k], 0.0);
    }
    return bad;
}

static int check_spectrum(void)
{
    const size_t one_bin[1] = {3u};
    const double one_weight[1] = {1.0};
    const size_t two_bins[2] = {0u, 16u};
    const double two_weights[2] = {1.0, 1.0};
    double one_dense[CHECK_N] = {0.0};
    double two_dense[CHECK_N] = {0.0};
    int bad = 0;
    one_dense[3] = 1.0;
    two_dense[0] = 1.0;
    two_dense[16] = 1.0;
    bad += check_status("mcs_spectrum_init", mcs_spectrum_init(&check_sparse, CHECK_N));
    bad += check_status("mcs_spectrum_init", mcs_spectrum_init(&check_dense, CHECK_N));
    bad += check_status("add_bins", mcs_spectrum_add_bins(&check_sparse, 1u, one_bin, one_weight));
    bad += check_status("add_bins", mcs_spectrum_add_bins(&check_sparse, 2u, two_bins, two_weights));
    bad += check_status("add_dense", mcs_spectrum_add_dense(&check_dense, CHECK_N, one_dense));
    bad += check_status("add_dense", mcs_spectrum_add_dense(&check_dense, CHECK_N, two_dense));
    for (size_t k = 0; k < CHECK_N && bad == 0; ++k) {
        const double want = (3.0 + 2.0 * cos(CHECK_PI * (double)k / 2.0)) / (2.0 * CHECK_N);
        double sparse = -1.0, dense = -1.0;
        bad += check_status("mcs_spectrum_power", mcs_spectrum_power(&check_sparse, k, &sparse));
        bad += check_status("mcs_spectrum_power", mcs_spectrum_power(&check_dense, k, &dense));
        bad += check_close("<|S_k|^2>, sparse trials", k, sparse, want);
        bad += check_close("<|S_k|^2>, dense trials (FFT path)", k, dense, want);
    }
    return bad;
}

#ifdef EXPECT_DFT_BACKEND
/* The back end the consumer's build expects, EXPECT_DFT_BACKEND as a bare
 * token (kissfft or fftw3: -DEXPECT_DFT_BACKEND=fftw3), against
 * mcs_dft_backend(); and the plan check_dft ran, so the transform it found
 * right is the back end's own: the FFTW path exactly when it is fftw3. */
#define CHECK_STR_(x) #x
#define CHECK_STR(x) CHECK_STR_(x)

static int check_backend(const char *want)
{
    const int fftw_wanted = strcmp(want, "fftw3") == 0;
    int bad = 0;
    if (strcmp(mcs_dft_backend(), want) != 0) {
        printf("FAIL mcs_dft_backend() is %s, expected %s\n", mcs_dft_backend(), want);
        ++bad;
    }
    if ((check_plan.path == MCS_DFT_PATH_FFTW) != fftw_wanted) {
        printf("FAIL the N = %u plan is on path %d, expected %sthe FFTW path (%d)\n",
               (unsigned)CHECK_N, (int)check_plan.path, fftw_wanted ? "" : "any but ",
               (int)MCS_DFT_PATH_FFTW);
        ++bad;
    }
    if (bad == 0)
        printf("DFT back end %s, N = %u transformed on path %d\n", mcs_dft_backend(),
               (unsigned)CHECK_N, (int)check_plan.path);
    return bad;
}
#endif

static int mcspec_checks(void)
{
    int bad = 0;
    if (strcmp(mcs_version(), MCS_VERSION_STRING) != 0) {
        printf("FAIL mcs_version() is %s, the headers say %s\n", mcs_version(), MCS_VERSION_STRING);
        ++bad;
    }
    bad += check_dft();
#ifdef EXPECT_DFT_BACKEND
    bad += check_backend(CHECK_STR(EXPECT_DFT_BACKEND));
#endif
    bad += check_spectrum();
    {
        const size_t out_of_range[1] = {CHECK_N};
        const double weight[1] = {1.0};
        const mcs_status st = mcs_spectrum_add_bins(&check_sparse, 1u, out_of_range, weight);
        if (st != MCS_ERR_BIN_RANGE || strcmp(mcs_status_str(st), "MCS_ERR_BIN_RANGE") != 0) {
            printf("FAIL bin N gave %s, expected MCS_ERR_BIN_RANGE\n", mcs_status_str(st));
            ++bad;
        }
    }
    if (bad == 0)
        printf("mcspec %s (MCS_MAX_N %d, MCS_MAX_COV_N %d, MCS_MAX_FREQ %d, MCS_MAX_FREQ_1D %d,"
               " MCS_MAX_SIDE %d): DFT, power spectrum (sparse and FFT paths) and input check"
               " right\n",
               mcs_version(), (int)MCS_MAX_N, (int)MCS_MAX_COV_N, (int)MCS_MAX_FREQ,
               (int)MCS_MAX_FREQ_1D, (int)MCS_MAX_SIDE);
    return bad;
}

#endif /* MCSPEC_CONSUMER_CHECKS_H */
