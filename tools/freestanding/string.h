/* Stand-in <string.h> (see math.h here): the four allow-listed byte functions. */
#ifndef MCS_FREESTANDING_STRING_H
#define MCS_FREESTANDING_STRING_H
#include <stddef.h>
void *memcpy(void *restrict dst, const void *restrict src, size_t n);
void *memmove(void *dst, const void *src, size_t n);
void *memset(void *dst, int c, size_t n);
int memcmp(const void *a, const void *b, size_t n);
#endif
