/* The library's version, the capacity tag of config.h, and the build
 * checks that stop a build of the sources that would compute wrong numbers
 * while returning MCS_OK. They live here because every build of the library
 * compiles this file with the flags of all the others (a CMake glob of
 * the .c files under src/, a renderer that copies the sources), and the capacity tag defined
 * below makes every library object need it. */
#include "mcspec/config.h"
#include "mcspec/version.h"

/* -ffast-math (and -Ofast) implies -ffinite-math-only: the compiler may then
 * assume no NaN or infinity exists and delete every isfinite() input check,
 * so NaN weights would be accepted with MCS_OK. */
#if defined(__FAST_MATH__) || (defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__)
#error "mcspec: do not compile the library with -ffast-math, -Ofast or -ffinite-math-only: its NaN and infinity checks would be optimised away. Build it with its own flags (Makefile, CMakeLists.txt) and link it, or drop those flags for src/*/*.c."
#endif

/* KissFFT as dft.c uses it (src/vendor/kissfft/VENDORED.md): without these
 * it would run in float on double buffers and call malloc, and its
 * external names would clash with a renderer's own KissFFT. */
#if !defined(kiss_fft_scalar) || !defined(KISS_FFT_MALLOC) || !defined(KISS_FFT_FREE) || \
    !defined(NDEBUG)
#error "mcspec: compile src/*/*.c (not src/vendor/) and src/vendor/kissfft/kiss_fft.c with the KissFFT configuration: -Dkiss_fft_scalar=double -DNDEBUG '-DKISS_FFT_MALLOC(n)=((void*)0)' '-DKISS_FFT_FREE(p)=((void)0)' plus the renames of KISS_RENAME in the Makefile (docs/integrating.md); or use the Makefile or CMakeLists.txt."
#endif
#if !defined(kiss_fft) || !defined(kiss_fft_alloc) || !defined(kiss_fft_stride) || \
    !defined(kiss_fft_cleanup) || !defined(kiss_fft_next_fast_size)
#error "mcspec: compile src/*/*.c (not src/vendor/) and src/vendor/kissfft/kiss_fft.c with KissFFT's names renamed: -Dkiss_fft=mcs_kiss_fft -Dkiss_fft_alloc=mcs_kiss_fft_alloc -Dkiss_fft_stride=mcs_kiss_fft_stride -Dkiss_fft_cleanup=mcs_kiss_fft_cleanup -Dkiss_fft_next_fast_size=mcs_kiss_fft_next_fast_size (KISS_RENAME in the Makefile, docs/integrating.md)."
#endif
_Static_assert(_Generic((kiss_fft_scalar)0, double: 1, default: 0),
               "mcspec: kiss_fft_scalar must be double (-Dkiss_fft_scalar=double)");

/* Defined for the capacities of this build only: code compiled with other
 * MCS_MAX_* values references another name and does not link. The text is
 * for `strings libmcspec.a`. */
#define MCS_VERSION_STR_(x) #x
#define MCS_VERSION_STR(x) MCS_VERSION_STR_(x)
const char MCS_CONFIG_LINK_TAG[] =
    "mcspec " MCS_VERSION_STRING " MCS_MAX_N=" MCS_VERSION_STR(MCS_MAX_N)
    " MCS_MAX_COV_N=" MCS_VERSION_STR(MCS_MAX_COV_N) " MCS_MAX_FREQ=" MCS_VERSION_STR(MCS_MAX_FREQ)
    " MCS_MAX_FREQ_1D=" MCS_VERSION_STR(MCS_MAX_FREQ_1D) " MCS_MAX_SIDE=" MCS_VERSION_STR(MCS_MAX_SIDE);

const char *mcs_version(void)
{
    return MCS_VERSION_STRING;
}
