#include "peer_numpy.h"

#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include "mcspec/pattern.h"

typedef struct {
    pid_t pid;
    FILE *to;   /* commands to the co-process */
    FILE *from; /* its replies */
    size_t batch;
    char describe[256];
} numpy_peer;

static numpy_peer peer = {-1, NULL, NULL, 0u, "not available"};

/* Child side: stdin from to_child, stdout to from_child, then exec. */
static void exec_child(const char *python, const char *script, int to_child[2],
                       int from_child[2])
{
    dup2(to_child[0], STDIN_FILENO);
    dup2(from_child[1], STDOUT_FILENO);
    close(to_child[0]);
    close(to_child[1]);
    close(from_child[0]);
    close(from_child[1]);
    execl(python, python, script, (char *)NULL);
    _exit(127);
}

static int read_line(char *buf, size_t len)
{
    if (peer.from == NULL || fgets(buf, (int)len, peer.from) == NULL)
        return BENCH_FAILED;
    buf[strcspn(buf, "\n")] = '\0';
    return BENCH_OK;
}

static int handshake(const char *python)
{
    char line[256], numpy_version[64], python_version[64];
    if (read_line(line, sizeof line) != BENCH_OK ||
        sscanf(line, "ready %63s %63s", numpy_version, python_version) != 2)
        return BENCH_UNAVAILABLE;
    snprintf(peer.describe, sizeof peer.describe, "numpy %s (Python %s, %s)", numpy_version,
             python_version, python);
    return BENCH_OK;
}

/* Parses a reply "KEYWORD A [B]" into values[0..count); BENCH_OK only if the
 * keyword matches and each value is a complete number token. */
static int parse_reply(const char *line, const char *keyword, double *values, size_t count)
{
    size_t len = strlen(keyword);
    if (strncmp(line, keyword, len) != 0 || line[len] != ' ')
        return BENCH_FAILED;
    const char *p = line + len;
    for (size_t i = 0; i < count; ++i) {
        char *end;
        values[i] = strtod(p, &end);
        if (end == p || (*end != ' ' && *end != '\0'))
            return BENCH_FAILED;
        p = end;
    }
    return *p == '\0' ? BENCH_OK : BENCH_FAILED;
}

/* Sends one command line and reads the reply into buf. */
static int command(char *buf, size_t len, const char *cmd)
{
    if (peer.to == NULL || fputs(cmd, peer.to) == EOF || fflush(peer.to) != 0)
        return BENCH_FAILED;
    return read_line(buf, len);
}

static int choose_clock(int wall)
{
    char line[64];
    double zero;
    if (command(line, sizeof line, wall ? "clock wall\n" : "clock cpu\n") != BENCH_OK)
        return BENCH_FAILED;
    return parse_reply(line, "ok", &zero, 1u);
}

int bench_numpy_start(const char *python, const char *script, int wall)
{
    int to_child[2], from_child[2];
    if (python == NULL || python[0] == '\0' || script == NULL)
        return BENCH_UNAVAILABLE;
    if (pipe(to_child) != 0)
        return BENCH_UNAVAILABLE;
    if (pipe(from_child) != 0) {
        close(to_child[0]);
        close(to_child[1]);
        return BENCH_UNAVAILABLE;
    }
    signal(SIGPIPE, SIG_IGN); /* a dead peer must give an error, not kill the bench */
    pid_t pid = fork();
    if (pid == 0)
        exec_child(python, script, to_child, from_child);
    close(to_child[0]);
    close(from_child[1]);
    if (pid < 0) {
        close(to_child[1]);
        close(from_child[0]);
        return BENCH_UNAVAILABLE;
    }
    peer.pid = pid;
    peer.to = fdopen(to_child[1], "w");
    peer.from = fdopen(from_child[0], "r");
    if (peer.to == NULL || peer.from == NULL || handshake(python) != BENCH_OK ||
        choose_clock(wall) != BENCH_OK) {
        fprintf(stderr, "bench: numpy peer did not start with %s\n", python);
        bench_numpy_stop();
        return BENCH_UNAVAILABLE;
    }
    return BENCH_OK;
}

void bench_numpy_stop(void)
{
    if (peer.to != NULL) {
        fprintf(peer.to, "quit\n");
        fclose(peer.to);
    }
    if (peer.from != NULL)
        fclose(peer.from);
    if (peer.pid > 0)
        waitpid(peer.pid, NULL, 0);
    peer.to = peer.from = NULL;
    peer.pid = -1;
    snprintf(peer.describe, sizeof peer.describe, "not available");
}

const char *bench_numpy_describe(void)
{
    return peer.describe;
}

size_t bench_numpy_batch(void)
{
    return peer.batch;
}

static int numpy_prepare(void *ctx, const bench_cell *cell)
{
    (void)ctx;
    if (peer.to == NULL)
        return BENCH_UNAVAILABLE;
    char cmd[128], line[128];
    snprintf(cmd, sizeof cmd, "cell %zu %zu %s %llu\n", cell->n, cell->k,
             mcs_pattern_kind_str((mcs_pattern_kind)cell->kind), (unsigned long long)cell->seed);
    double batch;
    if (command(line, sizeof line, cmd) != BENCH_OK ||
        parse_reply(line, "ok", &batch, 1u) != BENCH_OK)
        return BENCH_FAILED;
    peer.batch = (size_t)batch;
    return BENCH_OK;
}

static int numpy_slice(void *ctx, double seconds, bench_slice *out)
{
    (void)ctx;
    char cmd[64], line[128];
    snprintf(cmd, sizeof cmd, "slice %.6f\n", seconds);
    double v[2];
    if (command(line, sizeof line, cmd) != BENCH_OK || parse_reply(line, "done", v, 2u) != BENCH_OK)
        return BENCH_FAILED;
    out->trials = v[0];
    out->seconds = v[1];
    return BENCH_OK;
}

static int numpy_readout(void *ctx, size_t freq, double *value, double *stderr_out)
{
    (void)ctx;
    char cmd[64], line[128];
    snprintf(cmd, sizeof cmd, "read %zu\n", freq);
    double v[2];
    if (command(line, sizeof line, cmd) != BENCH_OK ||
        parse_reply(line, "power", v, 2u) != BENCH_OK)
        return BENCH_FAILED;
    *value = v[0];
    *stderr_out = v[1];
    return BENCH_OK;
}

bench_contender bench_numpy_contender(void)
{
    bench_contender c = {"numpy", NULL, 1u, numpy_prepare, NULL, numpy_slice, numpy_readout, 0.0, 0u};
    return c;
}
