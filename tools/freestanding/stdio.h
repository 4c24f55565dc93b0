/* Stand-in <stdio.h> (see math.h here): deliberately empty; KissFFT includes
 * it, but with NDEBUG it prints nothing, and the library must not either. */
#ifndef MCS_FREESTANDING_STDIO_H
#define MCS_FREESTANDING_STDIO_H
#endif
