/* A renderer that links its own KissFFT, built for float (the vendored
 * kiss_fft.c compiled into this program with kiss_fft_scalar=float, plain
 * names), beside mcspec's double build. Each must compute with its own:
 * KissFFT's unnormalised transform of x_n = cos(2 pi 5 n / 64) is 32 at
 * k = 5 and 59 and 0 elsewhere (to float rounding), and mcspec's checks
 * (mcspec_checks.h) hold to double rounding. Before mcspec hid KissFFT's
 * names, mcspec's transforms ran through this float code: |S_5|^2 of a single
 * sample came out 0.003916 where 1/64 is right. */
#include <stdlib.h>
#include "kiss_fft.h"
#include "mcspec_checks.h"

#define FLOAT_N 64

static int check_float_kissfft(void)
{
    kiss_fft_cpx in[FLOAT_N], out[FLOAT_N];
    kiss_fft_cfg cfg = kiss_fft_alloc(FLOAT_N, 0, NULL, NULL);
    int bad = 0;
    if (cfg == NULL) {
        printf("FAIL kiss_fft_alloc\n");
        return 1;
    }
    for (int j = 0; j < FLOAT_N; ++j) {
        in[j].r = (float)cos(2.0 * CHECK_PI * 5.0 * j / FLOAT_N);
        in[j].i = 0.0f;
    }
    kiss_fft(cfg, in, out);
    for (int k = 0; k < FLOAT_N; ++k) {
        const double want = (k == 5 || k == FLOAT_N - 5) ? FLOAT_N / 2.0 : 0.0;
        if (fabs((double)out[k].r - want) > 1e-4 || fabs((double)out[k].i) > 1e-4) {
            printf("FAIL float kiss_fft at k = %d: %g + %g i, expected %g\n", k,
                   (double)out[k].r, (double)out[k].i, want);
            ++bad;
        }
    }
    kiss_fft_free(cfg);
    if (bad == 0)
        printf("float KissFFT %u-byte scalars: cos(2 pi 5 n/64) transform right\n",
               (unsigned)sizeof(kiss_fft_scalar));
    return bad;
}

int main(void)
{
    const int bad = check_float_kissfft() + mcspec_checks();
    return bad == 0 ? 0 : 1;
}
