/* gnuplot figures of the mcspec command (see plot.h). */
#include "plot.h"
#include "atomic.h"
#include "cli.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <signal.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

extern char **environ;

#define PATH_LEN 4096

/* The files a rendering leaves in its temporary directory. */
static const char *const tmp_files[] = {"data.txt", "data2.txt", "plot.gp", "gnuplot.log",
                                         "figure"};

static const char *extension(const char *path)
{
    const char *dot = strrchr(path, '.');
    const char *slash = strrchr(path, '/');
    if (dot == NULL || (slash != NULL && dot < slash))
        return "";
    return dot + 1;
}

/* Full path of gnuplot on PATH into out; 0 if found. */
static int find_gnuplot(char *out, size_t size)
{
    const char *path = getenv("PATH");
    if (path == NULL || *path == '\0')
        return -1;
    while (*path != '\0') {
        const char *end = strchr(path, ':');
        size_t len = end != NULL ? (size_t)(end - path) : strlen(path);
        /* An empty PATH entry means the current directory. */
        int w = snprintf(out, size, "%.*s/gnuplot", (int)len, len != 0u ? path : ".");
        struct stat st;
        if (w > 0 && (size_t)w < size && stat(out, &st) == 0 && S_ISREG(st.st_mode) &&
            access(out, X_OK) == 0)
            return 0;
        path += len;
        if (*path == ':')
            ++path;
    }
    return -1;
}

static void dir_of(const char *path, char *dir, size_t size)
{
    const char *slash = strrchr(path, '/');
    if (slash == NULL)
        snprintf(dir, size, ".");
    else if (slash == path)
        snprintf(dir, size, "/");
    else
        snprintf(dir, size, "%.*s", (int)(slash - path), path);
}

int cli_plot_check_file(const char *cmd, const char *path)
{
    const char *ext = extension(path);
    if (strcmp(ext, "svg") != 0 && strcmp(ext, "png") != 0)
        return cli_fail(cmd, "--plot %s: the file name must end in .svg or .png", path);
    if (strlen(path) > PATH_LEN - 32)
        return cli_fail(cmd, "--plot: the file name is too long");
    char dir[PATH_LEN];
    dir_of(path, dir, sizeof dir);
    /* The figure is renamed onto path, as a record is (atomic.h). */
    const char *special = cli_not_regular(path);
    if (special != NULL)
        return cli_fail(cmd, "--plot %s: it is %s, not a regular file (give a regular file or a "
                        "new name)", path, special);
    if (access(dir, W_OK) != 0)
        return cli_fail(cmd, "--plot %s: cannot write in directory '%s': %s", path, dir,
                        strerror(errno));
    return 0;
}

int cli_plot_check_gnuplot(const char *cmd)
{
    char gp[PATH_LEN];
    if (find_gnuplot(gp, sizeof gp) != 0)
        return cli_fail(cmd, "--plot needs gnuplot, which is not on PATH (Debian: apt-get "
                        "install gnuplot-nox)");
    return 0;
}

int cli_plot_check(const char *cmd, const char *path)
{
    int rc = cli_plot_check_file(cmd, path);
    return rc != 0 ? rc : cli_plot_check_gnuplot(cmd);
}

int cli_plot_check_log(const char *cmd, int log, const char *plot)
{
    if (log && plot == NULL)
        return cli_fail(cmd, "--log sets the figure's y axis: give --plot FILE too");
    return 0;
}

int cli_check_outputs(const char *cmd, const char *save, const char *plot)
{
    if (save != NULL && cli_write_check(cmd, save) != 0)
        return CLI_EXIT_USAGE;
    return plot != NULL ? cli_plot_check(cmd, plot) : 0;
}

/* ---- Writing the data and the script ----------------------------------------- */

void cli_plot_value(FILE *fp, double x)
{
    /* gnuplot reads NaN as an undefined point and breaks the line there. */
    if (isnan(x))
        fputs(" NaN", fp);
    else
        fprintf(fp, " %.17g", x);
}

void cli_plot_string(FILE *fp, const char *s)
{
    fputc('"', fp);
    for (; *s != '\0'; ++s) {
        if (*s == '\\' || *s == '"')
            fputc('\\', fp);
        if ((unsigned char)*s >= 0x20u)
            fputc(*s, fp);
    }
    fputc('"', fp);
}

void cli_plot_title(FILE *fp, const cli_plot_info *info)
{
    char title[1024];
    snprintf(title, sizeof title, "%s%s%s", info->title, info->subtitle != NULL ? "\n" : "",
             info->subtitle != NULL ? info->subtitle : "");
    /* The newline between the two title lines must reach gnuplot as \n. */
    fputc('"', fp);
    for (const char *s = title; *s != '\0'; ++s) {
        if (*s == '\n')
            fputs("\\n", fp);
        else if (*s == '\\' || *s == '"')
            fprintf(fp, "\\%c", *s);
        else if ((unsigned char)*s >= 0x20u)
            fputc(*s, fp);
    }
    fputs("\" noenhanced", fp);
}

FILE *cli_plot_data(const char *tmp, const char *name)
{
    char file[PATH_LEN + 16];
    snprintf(file, sizeof file, "%s/%s", tmp, name);
    return fopen(file, "w");
}

void cli_plot_data_ref(FILE *fp, const char *tmp, const char *name)
{
    char file[PATH_LEN + 16];
    snprintf(file, sizeof file, "%s/%s", tmp, name);
    cli_plot_string(fp, file);
}

/* Below this fraction of the highest value, a value on a log axis is the
 * rounding residue of a zero (a comb's 1e-33), not a value to stretch the
 * axis over thirty decades for. */
#define LOG_FLOOR 1e-12

/* The values a row draws: power - se, power, power + se, exact, closed. */
static void drawn_values(const double in[4], double out[5])
{
    const double se = isnan(in[1]) ? 0.0 : in[1];
    out[0] = in[0] - se;
    out[1] = in[0];
    out[2] = in[0] + se;
    out[3] = in[2];
    out[4] = in[3];
}

/* [bottom, top] of a log axis over drawn values in [lo, hi]. */
static void log_range(cli_plot_axis *a)
{
    if (!(a->hi > 0.0) || !(a->lo > 0.0)) { /* nothing to draw: one decade either side of 1 */
        a->bottom = 0.1;
        a->top = 10.0;
        return;
    }
    const double lo = fmin(a->lo / 2.0, a->hi / 100.0);
    a->bottom = lo;
    a->top = lo * pow(a->hi / lo, 1.0 / 0.7);
}

void cli_plot_axis_init(cli_plot_axis *a, int log, const void *rows, size_t first, size_t n,
                        cli_plot_row_fn get)
{
    a->log = log;
    a->hi = a->scale = 0.0;
    a->lo = (double)INFINITY;
    double in[4], v[5];
    /* The highest value: of the rows drawn (the range), and of all of them,
     * row 0 too (S_0, P(0) = K), for the floor: a spectrum that is zero at
     * every k >= 1 is rounding residue everywhere, not a range to draw. */
    for (size_t i = 0; i < n; ++i) {
        get(rows, i, in);
        drawn_values(in, v);
        for (int j = 2; j < 5; ++j) { /* power + se, exact, closed */
            if (!isnan(v[j]) && v[j] > a->scale)
                a->scale = v[j];
            if (i >= first && !isnan(v[j]) && v[j] > a->hi)
                a->hi = v[j];
        }
    }
    /* The lowest value above the floor, now that the floor is known. */
    for (size_t i = first; log && i < n; ++i) {
        get(rows, i, in);
        drawn_values(in, v);
        for (int j = 0; j < 5; ++j)
            if (v[j] > LOG_FLOOR * a->scale && v[j] < a->lo)
                a->lo = v[j];
    }
    if (log && isinf(a->lo)) /* nothing above the floor: nothing on the axis */
        a->hi = 0.0;
    if (log) {
        log_range(a);
    } else {
        a->bottom = 0.0;
        a->top = 1.45 * (a->hi > 0.0 ? a->hi : 1.0);
    }
}

void cli_plot_axis_write(FILE *fp, const cli_plot_axis *a)
{
    if (a->log)
        fputs("set logscale y\nset format y '10^{%L}'\n", fp);
    fprintf(fp, "set yrange [%.17g:%.17g]\n", a->bottom, a->top);
}

/* Whether x is off a log axis: <= 0, or a rounding residue (NaN is not). */
static int below_axis(const cli_plot_axis *a, double x)
{
    return a->log && !isnan(x) && !(x > LOG_FLOOR * a->scale);
}

void cli_plot_profile_row(FILE *fp, const cli_plot_axis *a, long x, double power,
                          double stderr_, double exact, double closed)
{
    const double in[4] = {power, stderr_, exact, closed};
    double v[5];
    drawn_values(in, v);
    /* Log: a line (the band's edges, exact, closed) at a zero runs down to
     * the bottom of the axis, as it would towards minus infinity, so a comb
     * still reads as one; a measured mean of zero is not drawn (a point on
     * the edge would read as that value); no band where even its upper edge
     * is zero. */
    if (below_axis(a, v[2]))
        v[0] = v[2] = (double)NAN;
    for (int j = 0; j < 5; ++j)
        if (below_axis(a, v[j]))
            v[j] = j == 1 ? (double)NAN : a->bottom;
    fprintf(fp, "%ld", x);
    cli_plot_value(fp, v[1]);
    cli_plot_value(fp, v[0]);
    cli_plot_value(fp, v[2]);
    cli_plot_value(fp, v[3]);
    cli_plot_value(fp, v[4]);
    fputc('\n', fp);
}

/* The measured power (k >= 1) with its band and the predictions. */
static int write_data(const char *tmp, const cli_plot_axis *axis, const cli_spectrum_row *rows,
                      size_t nrows)
{
    FILE *fp = cli_plot_data(tmp, "data.txt");
    if (fp == NULL)
        return -1;
    fputs("# k power power-stderr power+stderr exact closed\n", fp);
    for (size_t i = 0; i < nrows; ++i) {
        const cli_spectrum_row *r = &rows[i];
        if (r->freq != 0u)
            cli_plot_profile_row(fp, axis, (long)r->freq, r->power, r->power_stderr, r->exact,
                                 r->closed);
    }
    return fclose(fp) == 0 ? 0 : -1;
}

static int series_present(const cli_spectrum_row *rows, size_t nrows, int exact)
{
    for (size_t i = 1; i < nrows; ++i)
        if (!isnan(exact ? rows[i].exact : rows[i].closed))
            return 1;
    return 0;
}

/* cli_plot_row_fn of spectrum rows. */
static void spectrum_values(const void *rows, size_t i, double v[4])
{
    const cli_spectrum_row *r = (const cli_spectrum_row *)rows + i;
    v[0] = r->power;
    v[1] = r->power_stderr;
    v[2] = r->exact;
    v[3] = r->closed;
}

void cli_plot_style(FILE *fp)
{
    fputs("set key top right box opaque samplen 3 spacing 1.15\n"
          "set grid lc rgb '#dddddd'\n"
          "set border lw 1.2\n", fp);
}

void cli_plot_profile(FILE *fp, const cli_plot_series *s)
{
    fputs("plot ", fp);
    cli_plot_data_ref(fp, s->tmp, s->data);
    /* Band first, then the predictions, then the measured points on top. */
    fprintf(fp, " using 1:3:4 with filledcurves fc rgb '#9ecae1' fs solid 0.5 noborder "
                "title \"%s ± 1 standard error\" noenhanced", s->measured);
    if (s->exact_label != NULL) {
        fputs(", \\\n     '' using 1:5 with lines lw 3 lc rgb '#e6550d' title ", fp);
        cli_plot_string(fp, s->exact_label);
        fputs(" noenhanced", fp);
    }
    if (s->closed_label != NULL) {
        fputs(", \\\n     '' using 1:6 with lines lw 2 dt (6,4) lc rgb '#252525' title ", fp);
        cli_plot_string(fp, s->closed_label);
        fputs(" noenhanced", fp);
    }
    fprintf(fp, ", \\\n     '' using 1:2 with points pt 7 ps 0.55 lc rgb '#08519c' "
                "title \"%s (mean over trials)\" noenhanced\n", s->measured);
}

typedef struct {
    const cli_plot_info *info;
    const cli_spectrum_row *rows;
    size_t nrows;
} spectrum_figure;

static int write_spectrum(FILE *fp, const char *tmp, const void *ctx)
{
    const spectrum_figure *fig = ctx;
    /* k >= 1: row 0 (S_0 = K / sqrt N) is not drawn. */
    cli_plot_axis axis;
    cli_plot_axis_init(&axis, fig->info->log_y, fig->rows, 1u, fig->nrows, spectrum_values);
    if (write_data(tmp, &axis, fig->rows, fig->nrows) != 0)
        return -1;
    fputs("set title ", fp);
    cli_plot_title(fp, fig->info);
    fputs("\nset xlabel \"frequency k\"\nset ylabel ", fp);
    cli_plot_string(fp, fig->info->ylabel != NULL ? fig->info->ylabel
                                                  : "⟨|S_k|^2⟩   (power spectrum, mean over trials)");
    fputc('\n', fp);
    cli_plot_style(fp);
    /* Head room above the highest value for the key, so it never hides data. */
    cli_plot_axis_write(fp, &axis);
    /* A little room right of k = N/2 so a comb tooth there is not cut by the border. */
    size_t last = fig->nrows > 1u ? fig->nrows - 1u : 1u;
    fprintf(fp, "set xrange [0:%.17g]\n", (double)last * 1.02 + 0.5);
    const int exact = fig->info->exact_label != NULL && series_present(fig->rows, fig->nrows, 1);
    const int closed = fig->info->closed_label != NULL && series_present(fig->rows, fig->nrows, 0);
    const cli_plot_series s = {tmp, "data.txt", "measured", exact ? fig->info->exact_label : NULL,
                               closed ? fig->info->closed_label : NULL};
    cli_plot_profile(fp, &s);
    return 0;
}

/* ---- Running gnuplot and moving the figure into place ------------------------ */

/* First line of the log, for the one-line message. */
static void first_log_line(const char *tmp, char *out, size_t size)
{
    char file[PATH_LEN + 16];
    snprintf(file, sizeof file, "%s/gnuplot.log", tmp);
    snprintf(out, size, "no message");
    FILE *fp = fopen(file, "r");
    if (fp == NULL)
        return;
    char line[512];
    while (fgets(line, sizeof line, fp) != NULL) {
        line[strcspn(line, "\r\n")] = '\0';
        if (line[strspn(line, " \t^")] != '\0') {
            snprintf(out, size, "%s", line + strspn(line, " \t"));
            break;
        }
    }
    fclose(fp);
}

static int run_gnuplot(const char *cmd, const char *tmp)
{
    char gp[PATH_LEN], script[PATH_LEN + 16], log[PATH_LEN + 16];
    if (find_gnuplot(gp, sizeof gp) != 0)
        return cli_fail(cmd, "--plot needs gnuplot, which is not on PATH");
    snprintf(script, sizeof script, "%s/plot.gp", tmp);
    snprintf(log, sizeof log, "%s/gnuplot.log", tmp);
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, log, O_WRONLY | O_CREAT | O_TRUNC, 0600);
    posix_spawn_file_actions_adddup2(&fa, STDOUT_FILENO, STDERR_FILENO);
    /* gnuplot gets SIGXFSZ back at its default (the command ignores it, and
     * an ignored signal stays ignored across exec). */
    posix_spawnattr_t attr;
    posix_spawnattr_init(&attr);
    sigset_t def;
    sigemptyset(&def);
    sigaddset(&def, SIGXFSZ);
    posix_spawnattr_setsigdefault(&attr, &def);
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGDEF);
    char *argv[] = {gp, script, NULL};
    pid_t pid;
    int rc = posix_spawn(&pid, gp, &fa, &attr, argv, environ);
    posix_spawn_file_actions_destroy(&fa);
    posix_spawnattr_destroy(&attr);
    if (rc != 0)
        return cli_fail(cmd, "cannot run %s: %s", gp, strerror(rc));
    int status = 0;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR)
            return cli_fail(cmd, "waiting for gnuplot: %s", strerror(errno));
    if (WIFSIGNALED(status))
        return cli_fail(cmd, "gnuplot was killed by signal %d%s", WTERMSIG(status),
                        WTERMSIG(status) == SIGXFSZ ? " (SIGXFSZ: the file-size limit, ulimit -f)"
                                                     : "");
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        char msg[512];
        first_log_line(tmp, msg, sizeof msg);
        return cli_fail(cmd, "gnuplot failed: %s", msg);
    }
    return 0;
}

static int copy_fd(int in, int out)
{
    char buf[65536];
    ssize_t got;
    while ((got = read(in, buf, sizeof buf)) > 0) {
        for (ssize_t done = 0; done < got;) {
            ssize_t w = write(out, buf + done, (size_t)(got - done));
            if (w < 0 && errno == EINTR)
                continue;
            if (w <= 0)
                return -1;
            done += w;
        }
    }
    return got < 0 ? -1 : 0;
}

/* Copies the figure next to path under a temporary name, then renames it. */
static int install_figure(const char *cmd, const char *tmp, const char *path)
{
    char src[PATH_LEN + 16], part[PATH_LEN + 32];
    snprintf(src, sizeof src, "%s/figure", tmp);
    snprintf(part, sizeof part, "%s.partXXXXXX", path);
    const char *special = cli_not_regular(path);
    if (special != NULL)
        return cli_fail(cmd, "--plot %s: it is %s, not a regular file", path, special);
    int in = open(src, O_RDONLY);
    struct stat st;
    if (in < 0 || fstat(in, &st) != 0 || st.st_size == 0) {
        if (in >= 0)
            close(in);
        return cli_fail(cmd, "gnuplot wrote no figure");
    }
    int out = mkstemp(part);
    if (out < 0) {
        close(in);
        return cli_fail(cmd, "cannot write %s: %s", path, strerror(errno));
    }
    /* mkstemp makes the file 0600; a figure gets the usual 0666 less umask. */
    mode_t mask = umask(0);
    umask(mask);
    int ok = copy_fd(in, out) == 0 && fchmod(out, 0666 & ~mask) == 0;
    int err = errno;
    if (close(out) != 0 && ok) {
        err = errno;
        ok = 0;
    }
    close(in);
    if (ok && rename(part, path) != 0) {
        err = errno;
        ok = 0;
    }
    if (!ok) {
        unlink(part);
        return cli_write_failed(cmd, path, err, (unsigned long long)st.st_size);
    }
    return 0;
}

static void remove_tmp(const char *tmp)
{
    char file[PATH_LEN + 16];
    for (size_t i = 0; i < sizeof tmp_files / sizeof tmp_files[0]; ++i) {
        snprintf(file, sizeof file, "%s/%s", tmp, tmp_files[i]);
        unlink(file);
    }
    rmdir(tmp);
}

/* The terminal of the figure's format and its output in tmp, then the
 * figure's own script from write. */
static int write_script(const char *tmp, const char *ext, cli_plot_writer write, const void *ctx)
{
    char file[PATH_LEN + 16];
    snprintf(file, sizeof file, "%s/plot.gp", tmp);
    FILE *fp = fopen(file, "w");
    if (fp == NULL)
        return -1;
    if (strcmp(ext, "svg") == 0)
        fprintf(fp, "set terminal svg size %d,%d fixed enhanced font 'Sans,13' "
                    "background rgb 'white'\n", CLI_PLOT_WIDTH, CLI_PLOT_HEIGHT);
    else
        fprintf(fp, "set terminal pngcairo size %d,%d enhanced font 'Sans,12' "
                    "background rgb 'white'\n", CLI_PLOT_WIDTH, CLI_PLOT_HEIGHT);
    fputs("set encoding utf8\nset output ", fp);
    cli_plot_data_ref(fp, tmp, "figure");
    fputc('\n', fp);
    int rc = write(fp, tmp, ctx);
    return fclose(fp) == 0 ? rc : -1;
}

int cli_plot_render(const char *cmd, const char *path, cli_plot_writer write, const void *ctx)
{
    const char *base = getenv("TMPDIR");
    char tmp[PATH_LEN];
    snprintf(tmp, sizeof tmp, "%s/mcspec-plot.XXXXXX", base != NULL && *base != '\0' ? base : "/tmp");
    if (mkdtemp(tmp) == NULL)
        return cli_fail(cmd, "cannot make a temporary directory in %s: %s",
                        base != NULL && *base != '\0' ? base : "/tmp", strerror(errno));
    int rc = 0;
    if (write_script(tmp, extension(path), write, ctx) != 0)
        rc = cli_fail(cmd, "cannot write the plot data in %s: %s", tmp, strerror(errno));
    if (rc == 0)
        rc = run_gnuplot(cmd, tmp);
    if (rc == 0)
        rc = install_figure(cmd, tmp, path);
    remove_tmp(tmp);
    return rc;
}

int cli_plot_spectrum(const char *cmd, const char *path, const cli_plot_info *info,
                      const cli_spectrum_row *rows, size_t nrows)
{
    const spectrum_figure fig = {info, rows, nrows};
    return cli_plot_render(cmd, path, write_spectrum, &fig);
}
