/* Runs adversarial rows in forked children, so that a crash, a sanitizer
 * report or a hang fails one row and the rest still run: the child reports
 * the start and the result of each row through a pipe; the parent kills it
 * when a row outlasts adv_timeout_ms and starts a new child after that row. */
#define _POSIX_C_SOURCE 200809L
#include "adv.h"

#include <poll.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

/* The slowest honest row (eq. 14 at N = MCS_MAX_N, O(N^2) trig) takes about
 * 0.4 s at -O2: a hang is a row well past that, with room for a loaded
 * machine and for the sanitizers (ADVERSARIAL_TIMEOUT_MS overrides it, e.g.
 * under valgrind). */
#if defined(__SANITIZE_ADDRESS__)
#define ADV_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define ADV_SANITIZED 1
#endif
#endif
#ifdef ADV_SANITIZED
int adv_timeout_ms = 6000;
#else
int adv_timeout_ms = 2000;
#endif

typedef struct {
    int row, done, failed;
    long calls;
    char why[200];
} report;

static void child(int fd, const adv_row *rows, size_t from, size_t nrows)
{
    report m;
    for (size_t i = from; i < nrows; ++i) {
        memset(&m, 0, sizeof m);
        m.row = (int)i;
        if (write(fd, &m, sizeof m) != (ssize_t)sizeof m)
            _exit(3);
        m.failed = adv_run_row(&rows[i], m.why, &m.calls);
        m.done = 1;
        if (write(fd, &m, sizeof m) != (ssize_t)sizeof m)
            _exit(3);
    }
    /* exit, not _exit: make check-alloc's allocation count sees the child's
     * calls too (the parent flushed stdio). Not under ASan, whose leak check
     * at exit would scan the whole arena of every child: nothing here
     * allocates, and the library's own allocations are check-alloc's job. */
#ifdef ADV_SANITIZED
    _exit(0);
#else
    exit(0);
#endif
}

static int read_report(int fd, report *m)
{
    size_t got = 0;
    while (got < sizeof *m) {
        ssize_t k = read(fd, (char *)m + got, sizeof *m - got);
        if (k <= 0)
            return 0;
        got += (size_t)k;
    }
    return 1;
}

#if defined(__GNUC__)
__attribute__((format(printf, 4, 5)))
#endif
static void blame(int *result, char (*why)[200], size_t row, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    result[row] = 1;
    vsnprintf(why[row], 200, fmt, ap);
    va_end(ap);
}

/* Collects one child's reports; returns the row to restart from. A child
 * that dies or hangs fails the row it was in (or the next one, if it died
 * between rows), and the next child starts after it. */
static size_t parent(int fd, pid_t pid, size_t from, size_t nrows, int *result,
                     char (*why)[200], long *calls)
{
    size_t row = from; /* the row the child is in, or the next one */
    report m;
    int status = 0;
    for (;;) {
        struct pollfd p = {fd, POLLIN, 0};
        if (poll(&p, 1, adv_timeout_ms) == 0) {
            kill(pid, SIGKILL);
            waitpid(pid, NULL, 0);
            blame(result, why, row, "no return within %d ms (hang)", adv_timeout_ms);
            return row + 1u;
        }
        if (!read_report(fd, &m)) {
            waitpid(pid, &status, 0);
            if (WIFSIGNALED(status))
                blame(result, why, row, "crashed (signal %d)", WTERMSIG(status));
            else
                blame(result, why, row, "child exited with status %d (sanitizer report above?)",
                      WEXITSTATUS(status));
            return row + 1u;
        }
        row = (size_t)m.row;
        if (!m.done)
            continue;
        result[row] = m.failed;
        memcpy(why[row], m.why, sizeof m.why);
        *calls += m.calls;
        if (++row == nrows) {
            waitpid(pid, &status, 0);
            if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
                blame(result, why, nrows - 1u,
                      "child exited with status %d after its last row (an at-exit check: an "
                      "allocation count, a leak?)", WEXITSTATUS(status));
            return nrows;
        }
    }
}

void adv_run(const adv_row *rows, size_t nrows, int *result, char (*why)[200], long *calls)
{
    size_t next = 0;
    fflush(stdout);
    fflush(stderr);
    while (next < nrows) {
        int fd[2];
        if (pipe(fd) != 0)
            break;
        pid_t pid = fork();
        if (pid == 0) {
            close(fd[0]);
            child(fd[1], rows, next, nrows);
        }
        close(fd[1]);
        if (pid < 0) {
            close(fd[0]);
            break;
        }
        next = parent(fd[0], pid, next, nrows, result, why, calls);
        close(fd[0]);
    }
    for (; next < nrows; ++next) { /* no fork: say so rather than pass silently */
        result[next] = 1;
        snprintf(why[next], 200, "could not fork");
    }
}
