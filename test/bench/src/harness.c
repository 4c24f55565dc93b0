#include "harness.h"

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

static double clock_seconds(clockid_t id)
{
    struct timespec ts;
    clock_gettime(id, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

double bench_now(void)
{
    return clock_seconds(CLOCK_MONOTONIC);
}

/* The clock slices are timed with: the thread's CPU time by default, so time
 * in which another process holds the core is not charged to the contender. */
static int use_wall_clock;

void bench_use_wall_clock(int wall)
{
    use_wall_clock = wall;
}

static double slice_clock(void)
{
    return clock_seconds(use_wall_clock ? CLOCK_MONOTONIC : CLOCK_THREAD_CPUTIME_ID);
}

/* Doubles the call count until one timed run takes >= 1 ms: warms caches and
 * branch predictors, and gives the first estimate of seconds per call. */
static int calibrate(bench_contender *c)
{
    for (size_t calls = 1u;; calls *= 2u) {
        double t0 = slice_clock();
        if (c->run(c->ctx, calls) != BENCH_OK)
            return BENCH_FAILED;
        double t = slice_clock() - t0;
        if (t >= 1e-3 || calls >= ((size_t)1u << 30)) {
            c->pace = t / (double)calls;
            return BENCH_OK;
        }
    }
}

/* One slice of about `seconds`: a fixed number of calls between two clock
 * reads (no clock inside the timed loop). The count comes from the fastest
 * pace seen, so a slice that another process preempted does not shrink the
 * next one. */
static int timed_slice(bench_contender *c, double seconds, bench_slice *out)
{
    if (c->slice != NULL)
        return c->slice(c->ctx, seconds, out);
    double want = seconds / (c->pace > 0.0 ? c->pace : seconds);
    size_t calls = want < 1.0 ? 1u : (size_t)want;
    if (c->period > 0u && calls < BENCH_PERIODS * c->period)
        calls = BENCH_PERIODS * c->period;
    double t0 = slice_clock();
    if (c->run(c->ctx, calls) != BENCH_OK)
        return BENCH_FAILED;
    double t = slice_clock() - t0;
    c->pace = t / (double)calls < c->pace ? t / (double)calls : c->pace;
    out->trials = (double)calls * (double)c->trials_per_call;
    out->seconds = t;
    return BENCH_OK;
}

static int prepare_all(bench_contender *list, size_t count, const bench_cell *cell,
                       bench_run *out)
{
    for (size_t c = 0; c < count; ++c) {
        int st = list[c].prepare(list[c].ctx, cell);
        if (st == BENCH_FAILED) {
            fprintf(stderr, "bench: %s failed to prepare N=%zu K=%zu\n", list[c].name, cell->n,
                    cell->k);
            return BENCH_FAILED;
        }
        out->available[c] = st == BENCH_OK;
        if (out->available[c] && list[c].slice == NULL && calibrate(&list[c]) != BENCH_OK)
            return BENCH_FAILED;
    }
    return BENCH_OK;
}

int bench_interleave(bench_contender *list, size_t count, const bench_cell *cell,
                     size_t rounds, double seconds, bench_run *out)
{
    if (count > BENCH_MAX_CONTENDERS || rounds > BENCH_MAX_ROUNDS || rounds == 0u)
        return BENCH_FAILED;
    memset(out, 0, sizeof *out);
    out->count = count;
    out->rounds = rounds;
    if (prepare_all(list, count, cell, out) != BENCH_OK)
        return BENCH_FAILED;
    for (size_t r = 0; r < rounds; ++r) {
        for (size_t i = 0; i < count; ++i) {
            size_t c = (r + i) % count; /* rotate who goes first */
            if (!out->available[c])
                continue;
            bench_slice s;
            if (timed_slice(&list[c], seconds, &s) != BENCH_OK) {
                fprintf(stderr, "bench: %s failed in a slice\n", list[c].name);
                return BENCH_FAILED;
            }
            out->rate[c][r] = s.seconds > 0.0 ? s.trials / s.seconds : (double)NAN;
        }
    }
    return BENCH_OK;
}

static void sort_doubles(double *x, size_t count)
{
    for (size_t i = 1; i < count; ++i) { /* insertion sort: at most 64 values */
        double v = x[i];
        size_t j = i;
        for (; j > 0 && x[j - 1u] > v; --j)
            x[j] = x[j - 1u];
        x[j] = v;
    }
}

/* Quantile q of a sorted array, linear between neighbours. */
static double quantile_sorted(const double *x, size_t count, double q)
{
    double pos = q * (double)(count - 1u);
    size_t lo = (size_t)pos;
    size_t hi = lo + 1u < count ? lo + 1u : lo;
    return x[lo] + (pos - (double)lo) * (x[hi] - x[lo]);
}

double bench_median(const double *x, size_t count)
{
    double tmp[BENCH_MAX_ROUNDS];
    if (count == 0u || count > BENCH_MAX_ROUNDS)
        return (double)NAN;
    memcpy(tmp, x, count * sizeof x[0]);
    sort_doubles(tmp, count);
    return quantile_sorted(tmp, count, 0.5);
}

double bench_median_rate(const bench_run *run, size_t c)
{
    return run->available[c] ? bench_median(run->rate[c], run->rounds) : (double)NAN;
}

double bench_median_ratio(const bench_run *run, size_t a, size_t b)
{
    if (!run->available[a] || !run->available[b])
        return (double)NAN;
    double ratio[BENCH_MAX_ROUNDS];
    for (size_t r = 0; r < run->rounds; ++r)
        ratio[r] = run->rate[a][r] / run->rate[b][r];
    return bench_median(ratio, run->rounds);
}

double bench_spread(const bench_run *run, size_t c)
{
    if (!run->available[c])
        return (double)NAN;
    double tmp[BENCH_MAX_ROUNDS];
    memcpy(tmp, run->rate[c], run->rounds * sizeof tmp[0]);
    sort_doubles(tmp, run->rounds);
    double med = quantile_sorted(tmp, run->rounds, 0.5);
    return (quantile_sorted(tmp, run->rounds, 0.75) - quantile_sorted(tmp, run->rounds, 0.25)) /
           med;
}

/* First "model name" line of /proc/cpuinfo, or "unknown". */
static void cpu_model(char *buf, size_t len)
{
    snprintf(buf, len, "unknown");
    FILE *f = fopen("/proc/cpuinfo", "r");
    if (f == NULL)
        return;
    char line[512];
    while (fgets(line, sizeof line, f) != NULL) {
        char *colon = strchr(line, ':');
        if (strncmp(line, "model name", 10) == 0 && colon != NULL) {
            colon += colon[1] == ' ' ? 2 : 1;
            colon[strcspn(colon, "\n")] = '\0';
            snprintf(buf, len, "%s", colon);
            break;
        }
    }
    fclose(f);
}

void bench_print_load(const char *label)
{
    char buf[128] = "unknown";
    FILE *f = fopen("/proc/loadavg", "r");
    if (f != NULL) {
        if (fgets(buf, sizeof buf, f) == NULL)
            snprintf(buf, sizeof buf, "unknown");
        fclose(f);
    }
    buf[strcspn(buf, "\n")] = '\0';
    printf("%s load average (1, 5, 15 min, runnable/total, last pid): %s\n", label, buf);
}

void bench_print_machine(const char *compiler_cmd, const char *compiler_version,
                         const char *flags)
{
    char model[256];
    cpu_model(model, sizeof model);
    printf("machine: %s, %ld CPUs online\n", model, sysconf(_SC_NPROCESSORS_ONLN));
    printf("compiler: %s = %s, flags: %s\n", compiler_cmd, compiler_version, flags);
    bench_print_load("start:");
}
