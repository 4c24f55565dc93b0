/* Atomic file writes for the mcspec command: the bytes go to a temporary
 * file in the destination's directory, are flushed to the disk (fsync), and
 * only then take the final name (rename, atomic within a file system). An
 * interrupted or failed run leaves the old file, or none, under the final
 * name, never a truncated one; at worst a PATH.partXXXXXX beside it. */
#ifndef MCSPEC_CLI_ATOMIC_H
#define MCSPEC_CLI_ATOMIC_H

#include <stddef.h>

/* Writes buf[len] to path atomically, mode 0666 less the umask. Returns 0, or
 * CLI_EXIT_USAGE after one line on stderr naming path and the reason. */
int cli_write_atomic(const char *cmd, const char *path, const void *buf, size_t len);

/* Checks, before any work, that path's directory takes a new file (so a long
 * run does not fail at its end). Returns 0 or CLI_EXIT_USAGE after a message. */
int cli_write_check(const char *cmd, const char *path);

#endif /* MCSPEC_CLI_ATOMIC_H */
