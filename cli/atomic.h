/* Atomic file writes for the mcspec command: the bytes go to a temporary
 * file in the destination's directory, are flushed to the disk (fsync), and
 * only then take the final name (rename, atomic within a file system). An
 * interrupted or failed run leaves the old file, or none, under the final
 * name, never a truncated one; at worst a PATH.partXXXXXX beside it. Only a
 * regular file is replaced: a device node, FIFO, socket, directory or
 * symbolic link under the final name is refused, and left as it is. */
#ifndef MCSPEC_CLI_ATOMIC_H
#define MCSPEC_CLI_ATOMIC_H

#include <stddef.h>

/* Writes buf[len] to path atomically, mode 0666 less the umask; path must be
 * a regular file or nothing (cli_not_regular). Returns 0, or CLI_EXIT_USAGE
 * after one line on stderr naming path and the reason. */
int cli_write_atomic(const char *cmd, const char *path, const void *buf, size_t len);

/* Checks, before any work, that path is a regular file or nothing
 * (cli_not_regular) and that its directory takes a new file (so a long run
 * does not fail at its end). Returns 0 or CLI_EXIT_USAGE after a message. */
int cli_write_check(const char *cmd, const char *path);

/* The one line of a failed write of len bytes to path, errno err: "cannot
 * write PATH: REASON", where EFBIG names the file-size limit (ulimit -f) it
 * passed. Returns CLI_EXIT_USAGE. */
int cli_write_failed(const char *cmd, const char *path, int err, unsigned long long len);

/* What path is when it exists and is not a regular file: "a directory", "a
 * character device", "a FIFO", "a symbolic link", ...; NULL for a regular
 * file or nothing there (or a path lstat cannot reach: the write reports
 * that). The rename of an atomic write would replace such a path by a
 * regular file, so every writer refuses it. */
const char *cli_not_regular(const char *path);

#endif /* MCSPEC_CLI_ATOMIC_H */
