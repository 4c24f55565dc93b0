/* Stand-in <stdlib.h> (see math.h here): deliberately declares nothing, so
 * malloc, free, abort or exit in a library source fails to compile. */
#ifndef MCS_FREESTANDING_STDLIB_H
#define MCS_FREESTANDING_STDLIB_H
#include <stddef.h>
#endif
