/* Atomic file writes (see atomic.h). */
#include "atomic.h"
#include "cli.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

/* path + ".partXXXXXX" into out; 0, or -1 if it does not fit. */
static int part_name(const char *path, char *out, size_t size)
{
    int w = snprintf(out, size, "%s.partXXXXXX", path);
    return w > 0 && (size_t)w < size ? 0 : -1;
}

static int write_all(int fd, const unsigned char *p, size_t len)
{
    while (len > 0u) {
        ssize_t w = write(fd, p, len);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0)
            return -1;
        p += w;
        len -= (size_t)w;
    }
    return 0;
}

/* Flushes the directory holding path, so the rename itself survives a crash
 * (best effort: some file systems refuse fsync on a directory). */
static void sync_dir(const char *path)
{
    char dir[4096];
    const char *slash = strrchr(path, '/');
    if (slash == NULL)
        snprintf(dir, sizeof dir, ".");
    else if (slash == path)
        snprintf(dir, sizeof dir, "/");
    else
        snprintf(dir, sizeof dir, "%.*s", (int)(slash - path), path);
    int fd = open(dir, O_RDONLY);
    if (fd >= 0) {
        (void)fsync(fd);
        (void)close(fd);
    }
}

int cli_write_failed(const char *cmd, const char *path, int err, unsigned long long len)
{
    struct rlimit lim;
    if (err == EFBIG && getrlimit(RLIMIT_FSIZE, &lim) == 0 && lim.rlim_cur != RLIM_INFINITY)
        return cli_fail(cmd, "cannot write %s: its %llu bytes pass the file-size limit of %llu "
                        "bytes (ulimit -f)", path, len, (unsigned long long)lim.rlim_cur);
    if (err == EFBIG)
        return cli_fail(cmd, "cannot write %s: %s (its %llu bytes pass a file-size limit)", path,
                        strerror(err), len);
    return cli_fail(cmd, "cannot write %s: %s", path, strerror(err != 0 ? err : EIO));
}

const char *cli_not_regular(const char *path)
{
    struct stat st;
    /* lstat: a symbolic link is itself replaced by the rename, not written
     * through. */
    if (lstat(path, &st) != 0 || S_ISREG(st.st_mode))
        return NULL;
    if (S_ISDIR(st.st_mode))
        return "a directory";
    if (S_ISLNK(st.st_mode))
        return "a symbolic link";
    if (S_ISCHR(st.st_mode))
        return "a character device";
    if (S_ISBLK(st.st_mode))
        return "a block device";
    if (S_ISFIFO(st.st_mode))
        return "a FIFO";
    if (S_ISSOCK(st.st_mode))
        return "a socket";
    return "a special file";
}

/* The one line of a refused path; CLI_EXIT_USAGE. */
static int refuse_special(const char *cmd, const char *path, const char *what)
{
    return cli_fail(cmd, "cannot write %s: it is %s, not a regular file (give a regular file "
                    "or a new name)", path, what);
}

int cli_write_atomic(const char *cmd, const char *path, const void *buf, size_t len)
{
    char part[4096];
    if (part_name(path, part, sizeof part) != 0)
        return cli_fail(cmd, "cannot write %s: path too long", path);
    /* Again at the end: something else may have taken the name during the run. */
    const char *special = cli_not_regular(path);
    if (special != NULL)
        return refuse_special(cmd, path, special);
    int fd = mkstemp(part);
    if (fd < 0)
        return cli_fail(cmd, "cannot write %s: %s", path, strerror(errno));
    /* mkstemp makes the file 0600; a record gets the usual 0666 less umask. */
    mode_t mask = umask(0);
    umask(mask);
    int ok = write_all(fd, (const unsigned char *)buf, len) == 0 &&
             fchmod(fd, 0666 & ~mask) == 0 && fsync(fd) == 0;
    int err = errno;
    if (close(fd) != 0 && ok) { /* a delayed write error (NFS, quota) */
        err = errno;
        ok = 0;
    }
    if (ok && rename(part, path) != 0) {
        err = errno;
        ok = 0;
    }
    if (!ok) {
        unlink(part);
        return cli_write_failed(cmd, path, err, (unsigned long long)len);
    }
    sync_dir(path);
    return 0;
}

int cli_write_check(const char *cmd, const char *path)
{
    char part[4096];
    if (path[0] == '\0')
        return cli_fail(cmd, "an empty file name");
    if (part_name(path, part, sizeof part) != 0)
        return cli_fail(cmd, "cannot write %s: path too long", path);
    const char *special = cli_not_regular(path);
    if (special != NULL)
        return refuse_special(cmd, path, special);
    int fd = mkstemp(part);
    if (fd < 0)
        return cli_fail(cmd, "cannot write %s: %s", path, strerror(errno));
    (void)close(fd);
    (void)unlink(part);
    return 0;
}
