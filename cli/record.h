/* Saved accumulators for the mcspec command (docs/format.md): reading a
 * record file into an accumulator of whatever kind it holds, merging
 * accumulators in a fixed tree order, saving one atomically.
 *
 * The tree order: leaves 0, 1, 2, ... are merged as a binary counter would
 * carry, (0+1), (2+3), ((0+1)+(2+3)), ..., and what is left at the end right
 * to left, the left operand always the destination. That is exactly the
 * binomial tree mcspec-mpi reduces over its ranks (rank r receives from
 * r + 2^j at level j), so `mcspec pattern --streams P`, `mcspec merge` of the
 * P `--stream I` files and `mpirun -np P mcspec-mpi` do the same floating-point
 * operations in the same order and give the same bytes. Memory: one
 * accumulator per level, log2 P + 1 of them. */
#ifndef MCSPEC_CLI_RECORD_H
#define MCSPEC_CLI_RECORD_H

#include <stddef.h>
#include <stdint.h>

#include "mcspec.h"

/* An accumulator of any kind the record format knows, heap-allocated. */
typedef struct {
    mcs_io_kind kind;
    void *obj; /* the object of that kind: mcs_spectrum, ..., mcs_spectrum2d */
} cli_acc;

/* A new, empty accumulator of kind (spectrum, pointset, pointset2d or
 * spectrum2d) and shape (N; F; F; N1, N2). Returns 0 or an exit status. */
int cli_acc_new(const char *cmd, mcs_io_kind kind, const size_t shape[2], cli_acc *acc);

/* A new spectrum accumulator for n bins. Returns 0 or an exit status. */
int cli_acc_new_spectrum(const char *cmd, size_t n, cli_acc *acc);

/* Copies the object of acc over obj, an object of the same kind. */
void cli_acc_copy_to(const cli_acc *acc, void *obj);

/* Frees acc->obj (NULL is fine) and clears acc. */
void cli_acc_free(cli_acc *acc);

/* Trials (values, for welford) acc holds. */
uint64_t cli_acc_count(const cli_acc *acc);

/* The shape of acc: N (spectrum, moment, autocorr), F (pointset,
 * pointset2d) or N1, N2 (spectrum2d); unused words 0. */
void cli_acc_shape(const cli_acc *acc, size_t shape[2]);

/* "a spectrum record of N = 64" and the like, into buf; returns buf. */
const char *cli_acc_describe(const cli_acc *acc, char *buf, size_t size);

/* Non-zero when a and b have the same kind and shape (so they merge). */
int cli_acc_same(const cli_acc *a, const cli_acc *b);

/* Reads the record file path into a new accumulator. Every failure is one
 * line naming the file and what is wrong with it ("truncated", "checksum
 * mismatch", ...). Returns 0 or CLI_EXIT_USAGE. */
int cli_acc_read(const char *cmd, const char *path, cli_acc *acc);

/* acc as a record in a new buffer (*buf, *len; the caller frees *buf).
 * Returns 0 or an exit status. */
int cli_acc_save(const char *cmd, const cli_acc *acc, unsigned char **buf, size_t *len);

/* The record of acc written to path atomically (atomic.h). */
int cli_acc_write(const char *cmd, const char *path, const cli_acc *acc);

/* dst <- dst merged with src (same kind and shape, else a message naming
 * `what`, the source). Returns 0 or an exit status. */
int cli_acc_merge(const char *cmd, cli_acc *dst, const cli_acc *src, const char *what);

/* The merge tree (see above). Zero it to start. */
typedef struct {
    cli_acc level[65];
    uint64_t leaves[65];
    size_t depth;
} cli_merge_tree;

/* Adds the next leaf; the tree takes acc over (acc is cleared), also on
 * failure. `what` names the leaf in messages. Returns 0 or an exit status. */
int cli_tree_push(const char *cmd, cli_merge_tree *tree, cli_acc *acc, const char *what);

/* Merges what is left into *out (the caller frees it) and empties the tree.
 * Returns 0 or an exit status (then the tree is emptied and *out cleared). */
int cli_tree_finish(const char *cmd, cli_merge_tree *tree, cli_acc *out);

/* Frees whatever the tree holds (after a failure elsewhere). */
void cli_tree_free(cli_merge_tree *tree);

#endif /* MCSPEC_CLI_RECORD_H */
