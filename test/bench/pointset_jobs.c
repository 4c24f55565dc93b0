/* pointset_jobs: the point-set jobs of issue 24 timed in one interleaved run
 * against the direct path and a numpy direct-sum peer (`make bench-pointsets`,
 * part of `make bench`; docs/speed.md).
 *
 *   build/bench/pointset_jobs [--quick] [--rounds R] [--job A|B|C|1D]
 *                             [--python PATH] [--numpy-peer SCRIPT]
 *
 * Jobs: A = 64 sets x 1024 points, F = 64; B = 16 x 16384, F = 128;
 * C = 16 x 16384, F = 640 (2D); 1D = 256 sets x 65536 points, F = 16384.
 * Round r draws set r of the job (uniform points, PCG32 seeded (24, r)) and
 * adds it once under each contender, the first contender rotating from round
 * to round: AUTO (mcs_pointset*_add, the default path), DIRECT (the same
 * accumulator type with the path forced to MCS_POINTSET_PATH_DIRECT), and
 * the numpy peer (test/bench/src/pointset_jobs_numpy.py, a co-process), each
 * timed by its thread's CPU clock. A job's time is its sets times the
 * median time of a set; a ratio is the median of the per-round ratios, so it
 * compares adds that ran next to each other. The numpy peer's set would take
 * minutes at F = 640 (16384 points x 822 k wave vectors); it times whole
 * chunks of wave vectors up to a budget (NUMPY_BUDGET s) and scales that to
 * the set's wave vectors (the direct sum costs the same per wave vector),
 * and the table says which fraction it timed. After the rounds, AUTO's and
 * DIRECT's accumulators hold the same sets: the largest
 * |P_auto - P_direct| / max(P, 1) over every wave vector is printed, the
 * agreement the NUFFT promises (1e-9). No assertion on time. */
#define _POSIX_C_SOURCE 200809L

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "mcspec.h"

#define MAX_ROUNDS 64
#define NUMPY_BUDGET 1.0

typedef struct {
    const char *name;
    int dim;
    size_t sets, k, freq;
    double target_direct; /* AUTO at least this many times faster than DIRECT */
} job;

static const job jobs[] = {
    {"A", 2, 64, 1024, 64, 1.0},
    {"B", 2, 16, 16384, 128, 1.0},
    {"C", 2, 16, 16384, 640, 20.0},
    {"1D", 1, 256, 65536, 16384, 1.0},
};
#define NJOBS (sizeof jobs / sizeof jobs[0])
#define TARGET_NUMPY 10.0

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static double median(const double *v, size_t n)
{
    double s[MAX_ROUNDS];
    memcpy(s, v, n * sizeof *v);
    qsort(s, n, sizeof *s, cmp_double);
    return n % 2u ? s[n / 2u] : 0.5 * (s[n / 2u - 1u] + s[n / 2u]);
}

/* An accumulator of the job's dimension over its own buffer. */
typedef struct {
    int dim;
    void *obj, *mem;
} acc_t;

static int acc_new(const job *j, mcs_pointset_path path, acc_t *a)
{
    size_t bytes = 0u;
    const unsigned flags = path == MCS_POINTSET_PATH_DIRECT ? MCS_POINTSET_DIRECT_ONLY : 0u;
    mcs_status st = j->dim == 2 ? mcs_pointset2d_size(j->freq, flags, &bytes)
                                : mcs_pointset_size(j->freq, flags, &bytes);
    a->dim = j->dim;
    a->obj = malloc(j->dim == 2 ? sizeof(mcs_pointset2d) : sizeof(mcs_pointset));
    a->mem = st == MCS_OK ? malloc(bytes) : NULL;
    if (a->obj == NULL || a->mem == NULL)
        return -1;
    st = j->dim == 2 ? mcs_pointset2d_init(a->obj, j->freq, flags, a->mem, bytes)
                     : mcs_pointset_init(a->obj, j->freq, flags, a->mem, bytes);
    if (st == MCS_OK)
        st = j->dim == 2 ? mcs_pointset2d_set_path(a->obj, path)
                         : mcs_pointset_set_path(a->obj, path);
    return st == MCS_OK ? 0 : -1;
}

static void acc_free(acc_t *a)
{
    free(a->obj);
    free(a->mem);
}

static double time_add(acc_t *a, size_t k, const double *pts)
{
    const double t0 = now();
    const mcs_status st = a->dim == 2 ? mcs_pointset2d_add(a->obj, k, pts)
                                      : mcs_pointset_add(a->obj, k, pts);
    const double t = now() - t0;
    if (st != MCS_OK) {
        fprintf(stderr, "pointset_jobs: add failed: %s\n", mcs_status_str(st));
        exit(1);
    }
    return t;
}

/* The largest |P_a - P_b| / max(P_b, 1) over the stored wave vectors. */
static double agreement(const job *j, const acc_t *a, const acc_t *b)
{
    double worst = 0.0;
    const long f = (long)j->freq;
    for (long fy = 0; fy <= (j->dim == 2 ? f : 0); ++fy)
        for (long fx = j->dim == 2 ? -f : 0; fx <= f; ++fx) {
            double pa = 0.0, pb = 0.0;
            if (j->dim == 2) {
                (void)mcs_pointset2d_power(a->obj, fx, fy, &pa);
                (void)mcs_pointset2d_power(b->obj, fx, fy, &pb);
            } else {
                (void)mcs_pointset_power(a->obj, fx, &pa);
                (void)mcs_pointset_power(b->obj, fx, &pb);
            }
            const double e = fabs(pa - pb) / fmax(fabs(pb), 1.0);
            worst = e > worst ? e : worst;
        }
    return worst;
}

/* The numpy co-process. */
static FILE *np_in, *np_out;
static char np_path[256];

static int numpy_start(const char *python, const char *script)
{
    int to[2], from[2];
    if (python == NULL || access(python, X_OK) != 0 || pipe(to) != 0 || pipe(from) != 0)
        return -1;
    const pid_t pid = fork();
    if (pid < 0)
        return -1;
    if (pid == 0) {
        dup2(to[0], 0);
        dup2(from[1], 1);
        close(to[1]);
        close(from[0]);
        execl(python, python, "-c",
              "import numpy, sys; sys.argv = sys.argv[1:]; exec(open(sys.argv[0]).read())",
              script, (char *)NULL);
        _exit(127);
    }
    close(to[0]);
    close(from[1]);
    np_in = fdopen(to[1], "w");
    np_out = fdopen(from[0], "r");
    snprintf(np_path, sizeof np_path, "/tmp/mcspec-pointset-jobs-%ld.bin", (long)getpid());
    /* A first empty exchange would block; probe with a one-point set. */
    const double probe[2] = {0.25, 0.5};
    FILE *fp = fopen(np_path, "wb");
    if (fp == NULL || fwrite(probe, sizeof probe, 1, fp) != 1 || fclose(fp) != 0)
        return -1;
    fprintf(np_in, "%s 1 2 1 1\n", np_path);
    fflush(np_in);
    double s = 0.0;
    long done = 0, total = 0;
    return fscanf(np_out, "%lf %ld %ld", &s, &done, &total) == 3 ? 0 : -1;
}

/* The peer's time for the whole set (extrapolated from *fraction of it). */
static double numpy_time(const job *j, const double *pts, double *fraction)
{
    FILE *fp = fopen(np_path, "wb");
    const size_t n = j->k * (size_t)j->dim;
    if (fp == NULL || fwrite(pts, sizeof *pts, n, fp) != n || fclose(fp) != 0)
        return (double)NAN;
    fprintf(np_in, "%s %zu %d %zu %g\n", np_path, j->k, j->dim, j->freq, NUMPY_BUDGET);
    fflush(np_in);
    double s = 0.0;
    long done = 0, total = 0;
    if (fscanf(np_out, "%lf %ld %ld", &s, &done, &total) != 3 || done <= 0)
        return (double)NAN;
    *fraction = (double)done / (double)total;
    return s * (double)total / (double)done;
}

static void draw(const job *j, size_t round, double *pts)
{
    mcs_rng rng;
    (void)mcs_rng_seed(&rng, 24u, (uint64_t)round);
    for (size_t i = 0; i < j->k * (size_t)j->dim; ++i) {
        (void)mcs_rng_double(&rng, &pts[i]);
    }
}

static int run_job(const job *j, size_t rounds, int have_numpy)
{
    acc_t autop, direct;
    double *pts = malloc(j->k * (size_t)j->dim * sizeof *pts);
    if (pts == NULL || acc_new(j, MCS_POINTSET_PATH_AUTO, &autop) != 0 ||
        acc_new(j, MCS_POINTSET_PATH_DIRECT, &direct) != 0) {
        fprintf(stderr, "pointset_jobs: job %s: out of memory\n", j->name);
        return 1;
    }
    double t_auto[MAX_ROUNDS], t_direct[MAX_ROUNDS], t_np[MAX_ROUNDS];
    double r_direct[MAX_ROUNDS], r_np[MAX_ROUNDS], frac = 0.0;
    for (size_t r = 0; r < rounds; ++r) {
        draw(j, r, pts);
        for (size_t c = 0; c < 3u; ++c) {
            const size_t who = (c + r) % 3u;
            if (who == 0u)
                t_auto[r] = time_add(&autop, j->k, pts);
            else if (who == 1u)
                t_direct[r] = time_add(&direct, j->k, pts);
            else
                t_np[r] = have_numpy ? numpy_time(j, pts, &frac) : (double)NAN;
        }
        r_direct[r] = t_direct[r] / t_auto[r];
        r_np[r] = t_np[r] / t_auto[r];
    }
    mcs_pointset_path path = MCS_POINTSET_PATH_AUTO;
    if (j->dim == 2)
        (void)mcs_pointset2d_path_for(autop.obj, j->k, &path);
    else
        (void)mcs_pointset_path_for(autop.obj, j->k, &path);
    const double sets = (double)j->sets, ma = median(t_auto, rounds);
    const double md = median(t_direct, rounds), mr = median(r_direct, rounds);
    const double mn = have_numpy ? median(t_np, rounds) : (double)NAN;
    const double mrn = have_numpy ? median(r_np, rounds) : (double)NAN;
    const int ok_d = mr >= j->target_direct, ok_n = !have_numpy || mrn >= TARGET_NUMPY;
    printf("%-3s %dD %4zu x %6zu F=%-6zu | %9.3f %9.3f %10.1f | %7.1f %9.0f | >=%-4g %-4s "
           ">=%g %-4s    | %-6s %5.1f%% | %.1e\n",
           j->name, j->dim, j->sets, j->k, j->freq, sets * ma, sets * md, sets * mn, mr, mrn,
           j->target_direct, ok_d ? "ok" : "MISS", TARGET_NUMPY,
           !have_numpy ? "-" : ok_n ? "ok" : "MISS",
           path == MCS_POINTSET_PATH_NUFFT ? "NUFFT" : "DIRECT", 100.0 * frac,
           agreement(j, &autop, &direct));
    fflush(stdout);
    acc_free(&autop);
    acc_free(&direct);
    free(pts);
    return 0;
}

static void print_machine(void)
{
    char model[600] = "unknown";
    FILE *fp = fopen("/proc/cpuinfo", "r");
    char line[512];
    while (fp != NULL && fgets(line, sizeof line, fp) != NULL)
        if (strncmp(line, "model name", 10) == 0) {
            const char *c = strchr(line, ':');
            snprintf(model, sizeof model, "%s", c != NULL ? c + 2 : line);
            model[strcspn(model, "\n")] = '\0';
            break;
        }
    if (fp != NULL)
        fclose(fp);
    printf("machine: %s, %ld CPUs online\n", model, sysconf(_SC_NPROCESSORS_ONLN));
}

int main(int argc, char **argv)
{
    size_t rounds = 7u;
    const char *only = NULL, *python = "/usr/bin/python3";
    const char *script = "test/bench/src/pointset_jobs_numpy.py";
    for (int i = 1; i < argc; ++i) {
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(argv[i], "--quick") == 0)
            rounds = 3u;
        else if (strcmp(argv[i], "--rounds") == 0 && v != NULL && atoi(v) >= 1 &&
                 atoi(v) <= MAX_ROUNDS)
            rounds = (size_t)atoi(argv[++i]);
        else if (strcmp(argv[i], "--job") == 0 && v != NULL)
            only = argv[++i];
        else if (strcmp(argv[i], "--python") == 0 && v != NULL)
            python = argv[++i];
        else if (strcmp(argv[i], "--numpy-peer") == 0 && v != NULL)
            script = argv[++i];
        else {
            fprintf(stderr, "usage: %s [--quick] [--rounds R] [--job A|B|C|1D] [--python PATH] "
                    "[--numpy-peer SCRIPT]\n", argv[0]);
            return 2;
        }
    }
    const int have_numpy = numpy_start(python, script) == 0;
    printf("mcspec point-set jobs (issue 24): %zu interleaved rounds, one set per contender "
           "a round, thread CPU clock, medians\n", rounds);
    print_machine();
    printf("numpy peer: %s\n", have_numpy ? "batched exp of the phase matrix, chunks of 2^22 "
           "entries, timed up to 1 s a set and scaled to the set's wave vectors"
           : "not available (no python3 with numpy): its columns are empty");
    printf("\n%-31s|    AUTO s  DIRECT s    numpy s | DIRECT/    numpy/ | targets: DIRECT/, "
           "numpy/ | AUTO's  numpy | AUTO vs\n", "job");
    printf("%-31s| (whole job: sets x median set) |    AUTO      AUTO |%24s | path   timed | DIRECT\n",
           "", "");
    int rc = 0;
    for (size_t i = 0; i < NJOBS && rc == 0; ++i)
        if (only == NULL || strcmp(only, jobs[i].name) == 0)
            rc = run_job(&jobs[i], rounds, have_numpy);
    if (have_numpy) {
        fprintf(np_in, "\n");
        fclose(np_in);
        fclose(np_out);
        remove(np_path);
    }
    printf("\nagreement: the largest |P_AUTO - P_DIRECT| / max(P, 1) over every wave vector "
           "after the rounds (the NUFFT's promise: 1e-9)\n");
    return rc;
}
