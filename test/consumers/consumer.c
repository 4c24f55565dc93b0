/* A C program using mcspec, built by test/consumers/run.sh against the
 * installed files only (pkg-config, static and shared), through
 * add_subdirectory and FetchContent, and with mismatched capacities (which
 * must not build). Exit status 0 when every check of mcspec_checks.h holds.
 * With EXPECT_MAX_N or EXPECT_MAX_SIDE defined it also checks that capacity
 * (the one its build passed it); with EXPECT_DFT_BACKEND (kissfft or fftw3)
 * the DFT back end. */
#include "mcspec_checks.h"

int main(void)
{
    int bad = mcspec_checks();
#ifdef EXPECT_MAX_N
    if (MCS_MAX_N != EXPECT_MAX_N) {
        printf("FAIL MCS_MAX_N is %d, expected %d\n", (int)MCS_MAX_N, (int)EXPECT_MAX_N);
        ++bad;
    }
#endif
#ifdef EXPECT_MAX_SIDE
    if (MCS_MAX_SIDE != EXPECT_MAX_SIDE) {
        printf("FAIL MCS_MAX_SIDE is %d, expected %d\n", (int)MCS_MAX_SIDE, (int)EXPECT_MAX_SIDE);
        ++bad;
    }
#endif
    return bad == 0 ? 0 : 1;
}
