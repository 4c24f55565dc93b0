/* mcspec-mpi: one pattern run split over MPI ranks (docs/scaling.md), or
 * the point-set spectrum of many point files.
 *
 *   mpirun -np P mcspec-mpi pattern KIND --n N --k K --trials T --seed S --save FILE
 *   mpirun -np P mcspec-mpi spectrum [mcspec spectrum's options] FILE...
 *
 * spectrum: every rank runs `mcspec spectrum` on the same arguments
 * (cli/psets.h), so all parse the same options and read the same sets in the
 * same order; rank r transforms the sets m with m mod P = r, each alone into
 * a one-trial object, and sends it as a record to rank 0, which receives
 * them in the order of the sets and merges each into the run's accumulator
 * exactly as one process merges its own: the CSV, the table and the --save
 * record are the bytes of `mcspec spectrum` with the same arguments. Only
 * rank 0 prints; the other ranks' messages would repeat rank 0's (the same
 * input), so they go to /dev/null, and a rank whose transform fails says so
 * to rank 0 in its message head instead (rank 0 then prints and writes
 * nothing, and every rank exits 1).
 *
 * Rank i runs stream i of the stream rule (cli/streams.h): PCG32 seeded
 * (S, i), floor(T/P) trials and one more for i < T mod P. The spectra are
 * reduced to rank 0 by a binomial tree: at level j = 0, 1, ..., a rank r with
 * r mod 2^(j+1) = 2^j saves its accumulator (docs/format.md) and sends the
 * bytes to r - 2^j, which loads them (every check of the loader) and merges
 * them into its own. That is the merge tree of cli/record.h, so the file
 * rank 0 writes has the bytes `mcspec pattern ... --streams P --save FILE`
 * writes, provenance included: each rank's record says it holds stream i of
 * the run, and every merge takes the union (mcs_io_provenance_merge), so
 * rank 0's says streams 0..P-1, as the single process's does. Every message
 * carries a status: a rank that fails (bad input, a
 * library error, a corrupt message) sends its failure up instead of data,
 * rank 0 writes nothing, and every rank exits with status 1 (2 for bad
 * usage). A rank that dies makes mpirun end the job; the file is written
 * atomically (cli/atomic.h), so no run leaves a partial FILE. */
#include "atomic.h"
#include "cli.h"
#include "input.h"
#include "psets.h"
#include "record.h"
#include "streams.h"
#include "trials.h"

#include "mcspec.h"

#include <mpi.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CMD "mcspec-mpi"
#define DEFAULT_SEED 1u
#define TAG_HEAD 1
#define TAG_BYTES 2

static const char help[] =
    "usage: mpirun -np P mcspec-mpi pattern KIND --n N --k K --trials T [--seed S]\n"
    "                                [--importance FILE] --save FILE [--timing]\n"
    "       mpirun -np P mcspec-mpi spectrum [mcspec spectrum's point-set options]\n"
    "                                FILE...\n"
    "\n"
    "spectrum: the point-set spectrum (--freq F, or --dim 2) of the sets of\n"
    "FILE..., rank r transforming the sets m with m mod P = r and rank 0 merging\n"
    "them in order: the output and --save record are the bytes of `mcspec\n"
    "spectrum` with the same arguments (see mcspec spectrum --help).\n"
    "\n"
    "Draws T trials of the pattern KIND (random, stratified, homogenized, uniform,\n"
    "jitter) over P MPI ranks and saves the merged spectrum accumulator to FILE\n"
    "(docs/format.md; read it with mcspec show, merge it with mcspec merge).\n"
    "\n"
    "Rank i runs stream i of mcspec pattern's stream rule: PCG32 seeded\n"
    "(initstate S, initseq i), floor(T/P) trials, one more for the first T mod P\n"
    "ranks. The accumulators are reduced to rank 0 by a tree of merges (log2 P\n"
    "levels; at each, half the remaining ranks send their saved accumulator to a\n"
    "partner, which merges it), in the order of mcspec merge, so FILE holds the\n"
    "bytes of `mcspec pattern KIND ... --streams P --save FILE` and of\n"
    "`mcspec merge` of the P files of `--streams P --stream I --save FILE_I`.\n"
    "\n"
    "Options:\n"
    "  --n N              bins N, 1.." CLI_STR(MCS_MAX_N) " (required)\n"
    "  --k K              samples per trial K, 1.." CLI_STR(CLI_MAX_K) " (required)\n"
    "  --trials T         trials in all, at least P (required)\n"
    "  --seed S           PCG32 seed (initstate; default 1)\n"
    "  --importance FILE  warp the samples through the importance function whose N\n"
    "                     weights (> 0, one per line) are in FILE (read by rank 0)\n"
    "  --save FILE        where rank 0 writes the merged record (required), atomically:\n"
    "                     a temporary file beside FILE, flushed, then renamed\n"
    "  --timing           rank 0 prints to stderr the trials per second of the\n"
    "                     slowest and fastest rank and the time of the reduction\n"
    "  --help             this text\n"
    "\n"
    "Exit status: 0 when FILE was written; 2 on bad usage (rank 0 says what to\n"
    "fix); 1 when any rank failed (each failing rank prints why, rank 0 says FILE\n"
    "was not written). For testing the failure paths, the environment variable\n"
    "MCSPEC_MPI_FAIL_RANK=r makes rank r report a failure instead of its data,\n"
    "and MCSPEC_MPI_ABORT_RANK=r makes rank r die (abort) after its trials.\n";

/* What rank 0 parses and every rank needs. */
typedef struct {
    uint64_t n, k, trials, seed, kind, importance, timing;
    int64_t status; /* 0, or the exit status every rank returns at once */
} run_params;

/* Rank 0: the command line into *prm and, with --importance, the weights
 * into *weights. Returns 0, -1 after --help, or an exit status. */
static int parse(int argc, char **argv, int nranks, run_params *prm, const char **save,
                 double **weights)
{
    size_t n = 0u, k = 0u;
    int timing = 0;
    const char *importance = NULL;
    cli_opt opts[] = {
        {"n", CLI_OPT_SIZE, &n, 1, MCS_MAX_N, 0},
        {"k", CLI_OPT_SIZE, &k, 1, CLI_MAX_K, 0},
        {"trials", CLI_OPT_U64, &prm->trials, 1, UINT64_MAX / 2u, 0},
        {"seed", CLI_OPT_U64, &prm->seed, 0, UINT64_MAX, 0},
        {"importance", CLI_OPT_STRING, &importance, 0, 0, 0},
        {"save", CLI_OPT_STRING, save, 0, 0, 0},
        {"timing", CLI_OPT_FLAG, &timing, 0, 0, 0},
    };
    const char *args[2] = {NULL, NULL};
    cli_parser p = {CMD, help, opts, CLI_COUNT(opts), args, CLI_COUNT(args), 0u, NULL};
    int rc = cli_parse(&p, argc, argv);
    if (rc != CLI_PARSED)
        return rc;
    if (p.nargs < 1u || strcmp(args[0], "pattern") != 0)
        return cli_fail(CMD, "the commands are pattern and spectrum: mcspec-mpi pattern KIND "
                        "..., mcspec-mpi spectrum ... FILE...");
    if (p.nargs < 2u || cli_pattern_kind(args[1]) < 0)
        return cli_fail(CMD, "which pattern? give KIND: random, stratified, homogenized, "
                        "uniform or jitter");
    for (int i = 0; i < 3; ++i)
        if (!opts[i].given)
            return cli_fail(CMD, "--%s is required (see %s --help)", opts[i].name, CMD);
    if (*save == NULL)
        return cli_fail(CMD, "--save FILE is required: where the merged spectrum goes");
    if (prm->trials < (uint64_t)nranks)
        return cli_fail(CMD, "--trials %llu is fewer than the %d ranks: every rank needs a trial",
                        (unsigned long long)prm->trials, nranks);
    prm->n = n;
    prm->k = k;
    prm->kind = (uint64_t)cli_pattern_kind(args[1]);
    prm->timing = (uint64_t)timing;
    prm->importance = importance != NULL;
    if (importance != NULL) {
        size_t count = 0u;
        rc = cli_read_values(CMD, importance, "importance weight", 1, MCS_MAX_N, weights, &count);
        if (rc == 0 && count != n)
            rc = cli_fail(CMD, "%s holds %zu importance weights, but --n is %zu",
                          cli_input_name(importance), count, n);
        if (rc != 0)
            return rc;
    }
    return cli_write_check(CMD, *save);
}

/* Every rank: the pattern of prm (importance weights already everywhere). */
static int make_pattern(const char *cmd, const run_params *prm, const double *weights,
                        mcs_importance *imp, mcs_pattern *pat)
{
    const mcs_importance *g = NULL;
    mcs_status st = MCS_OK;
    if (prm->importance) {
        st = mcs_importance_init(imp, (size_t)prm->n, weights);
        g = imp;
    }
    if (st == MCS_OK)
        st = mcs_pattern_init(pat, (mcs_pattern_kind)prm->kind, (size_t)prm->n,
                              (size_t)prm->k, g);
    if (st != MCS_OK)
        return cli_fail(cmd, "cannot set up the pattern: %s", mcs_status_str(st));
    return 0;
}

/* A rank's state in the reduction. failed counts failed ranks in its
 * subtree; first_failed is the lowest of them. */
typedef struct {
    int rank, nranks;
    const char *cmd;
    cli_acc acc;
    mcs_io_provenance *prov; /* the streams acc holds */
    uint64_t failed, first_failed;
} node;

static void mark_failed(node *me, uint64_t count, uint64_t first)
{
    if (count == 0u)
        return;
    me->first_failed = me->failed == 0u || first < me->first_failed ? first : me->first_failed;
    me->failed += count;
}

/* Sends this subtree's result to parent: a head {failed, first_failed,
 * bytes}, then the record when nothing failed. */
static void send_up(node *me, int parent)
{
    unsigned char *buf = NULL;
    size_t len = 0u;
    if (me->failed == 0u && cli_acc_save_with(me->cmd, &me->acc, me->prov, &buf, &len) != 0)
        mark_failed(me, 1u, (uint64_t)me->rank);
    uint64_t head[3] = {me->failed, me->first_failed, me->failed == 0u ? (uint64_t)len : 0u};
    MPI_Send(head, 3, MPI_UINT64_T, parent, TAG_HEAD, MPI_COMM_WORLD);
    if (head[0] == 0u)
        MPI_Send(buf, (int)len, MPI_BYTE, parent, TAG_BYTES, MPI_COMM_WORLD);
    free(buf);
}

/* Receives a child's subtree and merges it in (or takes over its failure). */
static void receive_from(node *me, int child)
{
    uint64_t head[3];
    MPI_Recv(head, 3, MPI_UINT64_T, child, TAG_HEAD, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (head[0] != 0u) {
        mark_failed(me, head[0], head[1]);
        return;
    }
    unsigned char *buf = cli_alloc(me->cmd, 1, (size_t)head[2]);
    mcs_spectrum *other = cli_alloc(me->cmd, 1, sizeof *other);
    mcs_io_provenance *prov = cli_alloc(me->cmd, 1, sizeof *prov);
    /* Receive even when out of memory, into nothing, so the sender is not left waiting. */
    MPI_Recv(buf, buf != NULL ? (int)head[2] : 0, MPI_BYTE, child, TAG_BYTES, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
    mcs_status st = buf != NULL && other != NULL && prov != NULL
                        ? mcs_io_load_spectrum(other, head[2], buf)
                        : MCS_ERR_NULL;
    if (st == MCS_OK)
        st = mcs_io_peek_provenance(head[2], buf, prov);
    if (st != MCS_OK)
        cli_internal(me->cmd, "the record from rank %d is unusable: %s", child,
                     mcs_status_str(st));
    /* The union of the streams, which must be disjoint pieces of one run. */
    mcs_status union_st = st == MCS_OK && me->failed == 0u
                              ? mcs_io_provenance_merge(me->prov, prov)
                              : MCS_OK;
    if (union_st != MCS_OK)
        cli_internal(me->cmd, "the streams of rank %d do not join this rank's: %s", child,
                     mcs_status_str(union_st));
    cli_acc theirs = {MCS_IO_KIND_SPECTRUM, other};
    char what[48];
    snprintf(what, sizeof what, "the record of rank %d", child);
    if (st != MCS_OK || union_st != MCS_OK ||
        (me->failed == 0u && cli_acc_merge(me->cmd, &me->acc, &theirs, what) != 0))
        mark_failed(me, 1u, (uint64_t)me->rank);
    free(prov);
    free(other);
    free(buf);
}

/* The binomial tree: at level j, ranks r = m 2^(j+1) receive from r + 2^j. */
static void reduce(node *me)
{
    for (int step = 1; step < me->nranks; step *= 2) {
        if (me->rank % (2 * step) == step) {
            send_up(me, me->rank - step);
            return;
        }
        if (me->rank % (2 * step) == 0 && me->rank + step < me->nranks)
            receive_from(me, me->rank + step);
    }
}

/* This rank's trials into me->acc; marks the rank failed on any error. */
static void run_rank(node *me, const run_params *prm, const double *weights, double *seconds)
{
    mcs_importance *imp = cli_alloc(me->cmd, 1, sizeof *imp);
    mcs_pattern pat;
    const char *inject = getenv("MCSPEC_MPI_FAIL_RANK");
    const char *die = getenv("MCSPEC_MPI_ABORT_RANK");
    int rc = imp != NULL ? 0 : CLI_EXIT_FAIL;
    if (rc == 0)
        rc = make_pattern(me->cmd, prm, weights, imp, &pat);
    if (rc == 0)
        rc = cli_acc_new_spectrum(me->cmd, (size_t)prm->n, &me->acc);
    if (rc == 0 && me->prov == NULL)
        rc = CLI_EXIT_FAIL; /* said by main's cli_alloc */
    if (rc == 0) {
        const cli_run run = {1u, mcs_pattern_kind_str((mcs_pattern_kind)prm->kind), prm->n,
                             prm->k, prm->importance != 0u,
                             prm->importance ? cli_weights_crc((size_t)prm->n, weights) : 0u,
                             prm->seed, (uint64_t)me->nranks, prm->trials};
        cli_run_provenance(&run, (uint64_t)me->rank, (uint64_t)me->rank + 1u, me->prov);
    }
    const double t0 = MPI_Wtime();
    if (rc == 0)
        rc = cli_run_streams(me->cmd, &pat, prm->seed, prm->trials, (uint64_t)me->nranks,
                             (uint64_t)me->rank, me->acc.obj, NULL);
    *seconds = MPI_Wtime() - t0;
    if (die != NULL && atoi(die) == me->rank)
        abort();
    if (rc == 0 && inject != NULL && atoi(inject) == me->rank)
        rc = cli_internal(me->cmd, "failing as MCSPEC_MPI_FAIL_RANK asks");
    if (rc != 0)
        mark_failed(me, 1u, (uint64_t)me->rank);
    free(imp);
}

/* Rank 0 after the reduction: the file, or why not. Returns the exit status. */
static int finish(node *me, const char *save, const run_params *prm, double reduce_s,
                  const double *rank_s)
{
    if (me->failed != 0u)
        return cli_internal(CMD, "%llu rank%s failed (first: rank %llu); %s not written",
                            (unsigned long long)me->failed, me->failed == 1u ? "" : "s",
                            (unsigned long long)me->first_failed, save);
    int rc = cli_acc_write_with(CMD, save, &me->acc, me->prov);
    if (rc != 0)
        return CLI_EXIT_FAIL;
    printf("%s: spectrum record, N = %llu, %llu trials from %d rank%s\n", save,
           (unsigned long long)prm->n, (unsigned long long)cli_acc_count(&me->acc),
           me->nranks, me->nranks == 1 ? "" : "s");
    if (prm->timing) {
        double lo = rank_s[0], hi = rank_s[0];
        for (int r = 1; r < me->nranks; ++r) {
            lo = rank_s[r] < lo ? rank_s[r] : lo;
            hi = rank_s[r] > hi ? rank_s[r] : hi;
        }
        const double share = (double)(prm->trials / (uint64_t)me->nranks);
        int levels = 0;
        for (int step = 1; step < me->nranks; step *= 2)
            ++levels;
        fprintf(stderr, "%s: trials per second per rank %.4g (slowest) .. %.4g (fastest); "
                "reduction %.3g ms over %d level%s\n", CMD, share / hi, share / lo,
                1e3 * reduce_s, levels, levels == 1 ? "" : "s");
    }
    return 0;
}


/* ---- spectrum ------------------------------------------------------------------ */

/* A rank's state in a spectrum run. */
typedef struct {
    int rank, nranks;
    int failed;           /* this rank's transform failed: it sends failure heads */
    uint64_t bad_sets;    /* rank 0: sets that failed on some rank */
    uint64_t first_bad;   /* ... the first of them */
    int first_bad_rank;
    int inject;           /* MCSPEC_MPI_FAIL_RANK names this rank */
} spec_node;

static void spec_mark(spec_node *me, uint64_t set, int rank)
{
    if (me->bad_sets == 0u) {
        me->first_bad = set;
        me->first_bad_rank = rank;
    }
    ++me->bad_sets;
}

/* Rank 0: the one-trial record of set `set` from rank `owner` into the
 * scratch, then merged. */
static void spec_receive(spec_node *me, cli_ps_sink *sink, uint64_t set, int owner)
{
    uint64_t head[2];
    MPI_Recv(head, 2, MPI_UINT64_T, owner, TAG_HEAD, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (head[0] != 0u) {
        spec_mark(me, set, owner);
        return;
    }
    unsigned char *buf = cli_alloc(sink->cmd, 1, (size_t)head[1]);
    MPI_Recv(buf, buf != NULL ? (int)head[1] : 0, MPI_BYTE, owner, TAG_BYTES, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
    mcs_status st = MCS_ERR_NULL;
    if (buf != NULL && sink->dim == 2u) {
        mcs_pointset2d *o = sink->one.obj;
        st = mcs_io_load_pointset2d(o, 0u, o->mem, o->bytes, (size_t)head[1], buf);
    } else if (buf != NULL) {
        mcs_pointset *o = sink->one.obj;
        st = mcs_io_load_pointset(o, 0u, o->mem, o->bytes, (size_t)head[1], buf);
    }
    free(buf);
    if (st != MCS_OK) {
        cli_internal(sink->cmd, "the record of set %llu from rank %d is unusable: %s",
                     (unsigned long long)set, owner, mcs_status_str(st));
        spec_mark(me, set, owner);
    } else if (me->bad_sets == 0u && cli_ps_sink_absorb(sink, sink->one.obj) != 0) {
        spec_mark(me, set, 0);
    }
}

/* Rank r != 0: set `set` transformed and sent to rank 0 (or a failure head). */
static void spec_send(spec_node *me, cli_ps_sink *sink, size_t k, const double *pts)
{
    unsigned char *buf = NULL;
    size_t len = 0u;
    if (!me->failed && me->inject)
        me->failed = cli_internal(sink->cmd, "failing as MCSPEC_MPI_FAIL_RANK asks") != 0;
    if (!me->failed)
        me->failed = cli_ps_sink_transform(sink, k, pts) != 0 ||
                     cli_acc_save(sink->cmd, &sink->one, &buf, &len) != 0;
    uint64_t head[2] = {(uint64_t)me->failed, me->failed ? 0u : (uint64_t)len};
    MPI_Send(head, 2, MPI_UINT64_T, 0, TAG_HEAD, MPI_COMM_WORLD);
    if (!me->failed)
        MPI_Send(buf, (int)len, MPI_BYTE, 0, TAG_BYTES, MPI_COMM_WORLD);
    free(buf);
}

/* cli_ps_driver.set: every rank sees every set; each does its part. Always
 * 0, so every rank reads on in step; failures travel in the heads. */
static int spec_set(void *ctx, cli_ps_sink *sink, uint64_t set, size_t k, const double *pts)
{
    spec_node *me = ctx;
    const int owner = (int)(set % (uint64_t)me->nranks);
    if (me->rank != 0) {
        if (owner == me->rank)
            spec_send(me, sink, k, pts);
        return 0;
    }
    if (owner != 0) {
        spec_receive(me, sink, set, owner);
        return 0;
    }
    if (me->bad_sets == 0u && (cli_ps_sink_transform(sink, k, pts) != 0 ||
                               cli_ps_sink_absorb(sink, sink->one.obj) != 0))
        spec_mark(me, set, 0);
    return 0;
}

/* cli_ps_driver.start: a rank that could not set up (memory) stops them all. */
static int spec_start(void *ctx, int rc)
{
    (void)ctx;
    int worst = rc;
    MPI_Allreduce(&rc, &worst, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    return worst;
}

/* cli_ps_driver.finish: rank 0's verdict, shared by every rank. rc is the
 * reading's status, the same on every rank (the same files). */
static int spec_finish(void *ctx, cli_ps_sink *sink, int rc)
{
    spec_node *me = ctx;
    int status = rc;
    if (me->rank == 0 && rc == 0 && me->bad_sets != 0u)
        status = cli_internal(sink->cmd, "%llu set%s failed (first: set %llu, on rank %d); "
                              "nothing printed or written", (unsigned long long)me->bad_sets,
                              me->bad_sets == 1u ? "" : "s", (unsigned long long)me->first_bad,
                              me->first_bad_rank);
    MPI_Bcast(&status, 1, MPI_INT, 0, MPI_COMM_WORLD);
    return status;
}

/* mcspec-mpi spectrum ...: argv[0] is "spectrum". */
static int spectrum_main(int argc, char **argv, int rank, int nranks)
{
    char cmd[64];
    snprintf(cmd, sizeof cmd, "%s spectrum%s", CMD, nranks > 1 ? ": rank 0" : "");
    if (rank != 0 && (freopen("/dev/null", "w", stderr) == NULL ||
                      freopen("/dev/null", "w", stdout) == NULL))
        return CLI_EXIT_FAIL;
    const char *inject = getenv("MCSPEC_MPI_FAIL_RANK");
    spec_node me = {rank, nranks, 0, 0u, 0u, 0, inject != NULL && atoi(inject) == rank};
    const cli_ps_driver drv = {rank == 0 ? cmd : CMD " spectrum", rank == 0, &me, spec_start,
                               spec_set, spec_finish};
    return cli_spectrum_run(argc, argv, &drv);
}

int main(int argc, char **argv)
{
    static double weights_buf[MCS_MAX_N];
    int rank = 0, nranks = 1;
    /* As in mcspec: a file-size limit makes the save fail with EFBIG, which
     * the atomic writer reports and cleans up after, instead of SIGXFSZ. */
    signal(SIGXFSZ, SIG_IGN);
    MPI_Init(&argc, &argv);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &nranks);
    if (argc > 1 && strcmp(argv[1], "spectrum") == 0) {
        const int status = spectrum_main(argc - 1, argv + 1, rank, nranks);
        fflush(stdout);
        MPI_Finalize();
        return status;
    }
    run_params prm = {0u, 0u, 0u, DEFAULT_SEED, 0u, 0u, 0u, 0};
    const char *save = NULL;
    if (rank == 0) {
        double *weights = NULL;
        int rc = parse(argc, argv, nranks, &prm, &save, &weights);
        prm.status = rc < 0 ? -1 : rc;
        if (rc == 0 && weights != NULL)
            memcpy(weights_buf, weights, (size_t)prm.n * sizeof weights_buf[0]);
        free(weights);
    }
    /* Bad usage stops every rank at once, with rank 0's one message. */
    MPI_Bcast(&prm, (int)sizeof prm, MPI_BYTE, 0, MPI_COMM_WORLD);
    if (prm.status != 0) {
        MPI_Finalize();
        return prm.status < 0 ? CLI_EXIT_OK : (int)prm.status;
    }
    if (prm.importance)
        MPI_Bcast(weights_buf, (int)prm.n, MPI_DOUBLE, 0, MPI_COMM_WORLD);
    char cmd[64];
    snprintf(cmd, sizeof cmd, "%s: rank %d", CMD, rank);
    node me = {rank, nranks, cmd, {MCS_IO_KIND_SPECTRUM, NULL},
               cli_alloc(cmd, 1, sizeof(mcs_io_provenance)), 0u, 0u};
    double trial_s = 0.0;
    run_rank(&me, &prm, weights_buf, &trial_s);
    /* Time the reduction alone, not the wait for the slowest rank's trials. */
    MPI_Barrier(MPI_COMM_WORLD);
    const double t0 = MPI_Wtime();
    reduce(&me);
    const double reduce_s = MPI_Wtime() - t0;
    double *rank_s = rank == 0 ? cli_alloc(cmd, (size_t)nranks, sizeof *rank_s) : NULL;
    static double ignored;
    MPI_Gather(&trial_s, 1, MPI_DOUBLE, rank_s != NULL ? rank_s : &ignored, 1, MPI_DOUBLE, 0,
               MPI_COMM_WORLD);
    int status = 0;
    if (rank == 0)
        status = rank_s != NULL ? finish(&me, save, &prm, reduce_s, rank_s) : CLI_EXIT_FAIL;
    MPI_Bcast(&status, 1, MPI_INT, 0, MPI_COMM_WORLD);
    free(rank_s);
    free(me.prov);
    cli_acc_free(&me.acc);
    fflush(stdout);
    MPI_Finalize();
    return status;
}
