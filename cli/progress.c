/* Progress lines on a terminal's stderr (see progress.h). */
#include "progress.h"

#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <unistd.h>

/* First line after this many seconds (unless MCSPEC_PROGRESS_DELAY says
 * otherwise), then at most one per interval. */
#define PROGRESS_DELAY 1.0
#define PROGRESS_INTERVAL 0.25

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void cli_progress_init(cli_progress *pr, int want, const char *label, const char *unit,
                       uint64_t total)
{
    pr->enabled = want && isatty(STDERR_FILENO);
    pr->label = label;
    pr->unit = unit;
    pr->total = total;
    pr->from = 0;
    pr->start = pr->enabled ? now() : 0.0;
    /* MCSPEC_PROGRESS_DELAY (seconds) moves the first line; the tests set 0. */
    const char *env = getenv("MCSPEC_PROGRESS_DELAY");
    char *end = NULL;
    double d = env != NULL ? strtod(env, &end) : PROGRESS_DELAY;
    pr->delay = env != NULL && end != env && *end == '\0' && d >= 0.0 ? d : PROGRESS_DELAY;
    pr->last = pr->start;
    pr->shown = 0;
}

void cli_progress_span(cli_progress *pr, uint64_t from, uint64_t total)
{
    pr->from = from < total ? from : 0u;
    pr->total = total;
}

/* "42 s", "3 min 07 s", "2 h 05 min". */
static void duration(char *buf, size_t size, double s)
{
    const unsigned long t = (unsigned long)(s + 0.5);
    if (t < 60u)
        snprintf(buf, size, "%lu s", t);
    else if (t < 3600u)
        snprintf(buf, size, "%lu min %02lu s", t / 60u, t % 60u);
    else
        snprintf(buf, size, "%lu h %02lu min", t / 3600u, t / 60u % 60u);
}

void cli_progress_update(cli_progress *pr, uint64_t done)
{
    /* The clock is read once per 256 calls: a trial can cost well under a
     * microsecond, a clock read tens of nanoseconds. */
    if (!pr->enabled || (done & 255u) != 0u)
        return;
    double t = now();
    if (t - pr->start < pr->delay || (pr->shown && t - pr->last < PROGRESS_INTERVAL))
        return;
    pr->last = t;
    pr->shown = 1;
    char taken[32], left[32];
    duration(taken, sizeof taken, t - pr->start);
    if (pr->total > 0u && done > pr->from) {
        const double own = (double)(done - pr->from), all = (double)(pr->total - pr->from);
        /* At the rate so far: (t - start) / own per unit, all - own units to go. */
        duration(left, sizeof left, (t - pr->start) * (all - own) / own);
        /* EL (erase to the end of the line): a shorter line leaves no tail. */
        fprintf(stderr, "\r%s: %3.0f%% (%llu of %llu %s, %s, about %s left)\033[K", pr->label,
                100.0 * own / all, (unsigned long long)(done - pr->from),
                (unsigned long long)(pr->total - pr->from), pr->unit, taken, left);
    } else {
        fprintf(stderr, "\r%s: %llu %s (%s)\033[K", pr->label, (unsigned long long)done,
                pr->unit, taken);
    }
    fflush(stderr);
}

void cli_progress_end(cli_progress *pr)
{
    if (pr->enabled && pr->shown) {
        /* Erase to the end of the line (ECMA-48 EL), the cursor back at column 0. */
        fputs("\r\033[K", stderr);
        fflush(stderr);
    }
    pr->shown = 0;
}
