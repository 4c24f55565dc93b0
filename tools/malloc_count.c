/* Runtime half of the allocation-free claim (make check-alloc).
 *
 * tools/ar_counted.sh builds the library archive with every allocator
 * reference renamed: a call to malloc from library code becomes a call to
 * mcs_count_malloc, and so on. This object defines those names: each counts
 * the call and forwards to the real allocator, so a program still works.
 * Calls from anything else (the test or example, Unity, libc's own stdio
 * buffers) are not renamed and not counted: the count is exactly the number
 * of allocations made directly by library code.
 *
 * At exit the count is appended to the file named by MCS_MALLOC_LOG (one
 * line per program: "<count> <program>"), and a program whose library code
 * allocated reports it on stderr and exits with status 70, so a test runner
 * or the make recipe fails even without reading the log. */
#define _GNU_SOURCE 1 /* NOLINT(bugprone-reserved-identifier,cert-dcl37-c,cert-dcl51-cpp): feature macro for strndup, readlink */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

void *mcs_count_malloc(size_t n);
void *mcs_count_calloc(size_t m, size_t n);
void *mcs_count_realloc(void *p, size_t n);
void *mcs_count_reallocarray(void *p, size_t m, size_t n);
void mcs_count_free(void *p);
void *mcs_count_aligned_alloc(size_t a, size_t n);
int mcs_count_posix_memalign(void **p, size_t a, size_t n);
void *mcs_count_memalign(size_t a, size_t n);
void *mcs_count_valloc(size_t n);
char *mcs_count_strdup(const char *s);
char *mcs_count_strndup(const char *s, size_t n);

static unsigned long lib_calls;     /* allocator calls from library code */
static const char *first_name = ""; /* the first allocator library code called */

static void count(const char *name)
{
    if (lib_calls++ == 0u)
        first_name = name;
}

void *mcs_count_malloc(size_t n) { count("malloc"); return malloc(n); }
void *mcs_count_calloc(size_t m, size_t n) { count("calloc"); return calloc(m, n); }
void *mcs_count_realloc(void *p, size_t n) { count("realloc"); return realloc(p, n); }
void *mcs_count_reallocarray(void *p, size_t m, size_t n)
{
    count("reallocarray");
    if (m != 0u && n > (size_t)-1 / m)
        return NULL;
    return realloc(p, m * n != 0u ? m * n : 1u);
}
void mcs_count_free(void *p) { count("free"); free(p); }
void *mcs_count_aligned_alloc(size_t a, size_t n) { count("aligned_alloc"); return aligned_alloc(a, n); }
int mcs_count_posix_memalign(void **p, size_t a, size_t n)
{
    count("posix_memalign");
    return posix_memalign(p, a, n);
}
void *mcs_count_memalign(size_t a, size_t n)
{
    count("memalign");
    void *p = NULL;
    return posix_memalign(&p, a, n) == 0 ? p : NULL;
}
void *mcs_count_valloc(size_t n)
{
    count("valloc");
    void *p = NULL;
    return posix_memalign(&p, (size_t)sysconf(_SC_PAGESIZE), n) == 0 ? p : NULL;
}
char *mcs_count_strdup(const char *s) { count("strdup"); return strdup(s); }
char *mcs_count_strndup(const char *s, size_t n) { count("strndup"); return strndup(s, n); }

static const char *program_name(void)
{
    static char buf[512];
    ssize_t len = readlink("/proc/self/exe", buf, sizeof buf - 1u);
    if (len <= 0)
        return "?";
    buf[len] = '\0';
    return buf;
}

__attribute__((destructor)) static void mcs_count_report(void)
{
    const char *log = getenv("MCS_MALLOC_LOG");
    if (log != NULL && log[0] != '\0') {
        FILE *f = fopen(log, "a");
        if (f != NULL) {
            (void)fprintf(f, "%lu %s\n", lib_calls, program_name());
            (void)fclose(f);
        }
    }
    if (lib_calls != 0u) {
        (void)fflush(NULL); /* _exit below skips the stdio flush; keep the program's output */
        (void)fprintf(stderr, "malloc_count: library code made %lu allocator call(s), the first to %s\n",
                lib_calls, first_name);
        (void)fflush(stderr);
        _exit(70);
    }
}
