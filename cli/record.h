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

/* An accumulator of any kind the record format knows, heap-allocated. Its
 * provenance, which is about the trials and not the statistics, travels
 * beside it: the calls that read and write records take it apart. */
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

/* "a spectrum record of N = 64" and the like for a record's header. */
const char *cli_record_describe(const mcs_io_info *info, char *buf, size_t size);

/* Reads the record file path into a new accumulator. Every failure is one
 * line naming the file and what is wrong with it ("truncated", "checksum
 * mismatch", ...). Returns 0 or CLI_EXIT_USAGE. */
int cli_acc_read(const char *cmd, const char *path, cli_acc *acc);

/* cli_acc_read that also gives the record's provenance (source
 * MCS_IO_SOURCE_NONE for a version 1 record) and its CRC-32 (as
 * cli_record_peek); prov and crc may be NULL. */
int cli_acc_read_with(const char *cmd, const char *path, cli_acc *acc, mcs_io_provenance *prov,
                      uint32_t *crc);

/* What the record file path holds without loading its values: its header,
 * its provenance (source MCS_IO_SOURCE_NONE in a version 1 record) and its
 * CRC-32 (the record's last 4 bytes, which change with any byte of it). The
 * framing, the checksum and the kind (one this build knows) are checked,
 * failures said as cli_acc_read says them. Returns 0 or CLI_EXIT_USAGE. */
int cli_record_peek(const char *cmd, const char *path, mcs_io_info *info,
                    mcs_io_provenance *prov, uint32_t *crc);

/* acc as a record in a new buffer (*buf, *len; the caller frees *buf).
 * Returns 0 or an exit status. */
int cli_acc_save(const char *cmd, const cli_acc *acc, unsigned char **buf, size_t *len);

/* cli_acc_save with the provenance prov (version 2; NULL or source
 * MCS_IO_SOURCE_NONE: none, version 1). */
int cli_acc_save_with(const char *cmd, const cli_acc *acc, const mcs_io_provenance *prov,
                      unsigned char **buf, size_t *len);

/* The record of acc written to path atomically (atomic.h). */
int cli_acc_write(const char *cmd, const char *path, const cli_acc *acc);

/* cli_acc_write with the provenance prov (as cli_acc_save_with). */
int cli_acc_write_with(const char *cmd, const char *path, const cli_acc *acc,
                       const mcs_io_provenance *prov);

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

/* cli_tree_push of a leaf that stands for `weight` leaves of the tree (the
 * streams a merged record holds): two subtrees merge when they weigh the
 * same, so the aligned pieces of a run (streams [0, 2), [2, 4)) merge as
 * their streams would have. */
int cli_tree_push_weighted(const char *cmd, cli_merge_tree *tree, cli_acc *acc, uint64_t weight,
                           const char *what);

/* ---- --save of the measure commands (pcf, integrate, discrepancy, stats) ---- */

/* Where a measure command's record goes and what its sets were read from. */
typedef struct {
    const char *save;  /* --save FILE, or NULL: nothing saved (every call below does nothing) */
    const char *input; /* the point file; NULL or "-": standard input */
    uint32_t crc;      /* standard input's CRC-32 and length, kept by cli_save_begin */
    uint64_t bytes;
} cli_save_target;

/* Before any work: --save FILE must be a regular file or a new name
 * (cli_write_check, as mcspec spectrum --save); reading standard input, its
 * bytes are kept in a temporary file that becomes standard input, for the
 * record's provenance (cli_ps_checksum_stdin). Returns 0 or an exit status. */
int cli_save_begin(const char *cmd, cli_save_target *t);

/* After the report: the object of kind (mcs_pcf, ...) saved atomically to
 * t->save, its provenance the input file (name, CRC-32, bytes). */
int cli_save_points(const char *cmd, const cli_save_target *t, mcs_io_kind kind, void *obj);

/* mcspec show of a pcf, integrate, discrepancy or spacing record: the CSV
 * (csv) or table its command prints, under title and origin lines (not with
 * csv); prov is the record's (the pcf's exact column for a pattern run).
 * Returns 0 or an exit status (record_show.c). */
int cli_show_measure(int csv, const cli_acc *acc, const mcs_io_provenance *prov,
                     const char *title, const char *origin);

/* ---- Provenance (docs/format.md) ------------------------------------------ */

/* What identifies a pattern run; with the streams a record holds, its
 * provenance. */
typedef struct {
    unsigned dim;            /* 1 or 2 */
    const char *pattern;     /* its name, as mcs_pattern_kind_str or cli/source2d.h spell it */
    uint64_t n, k;           /* N (0 in 2D), K */
    int importance;          /* warped by an importance function ... */
    uint32_t importance_crc; /* ... whose weights have this cli_weights_crc */
    uint64_t seed, streams, trials;
} cli_run;

/* cli_save_points for sets drawn from a named pattern: the provenance of
 * run's whole stream range (one stream, P = 1). */
int cli_save_drawn(const char *cmd, const char *save, const cli_run *run, mcs_io_kind kind,
                   void *obj);

/* The provenance of streams [first, end) of run into *prov. */
void cli_run_provenance(const cli_run *run, uint64_t first, uint64_t end,
                        mcs_io_provenance *prov);

/* CRC-32 of n weights, each as little-endian binary64: the importance
 * function's checksum in a provenance. */
uint32_t cli_weights_crc(size_t n, const double *weights);

/* crc (0 to start) continued over data[len]: the CRC-32 of mcs_io_crc32
 * computed piece by piece, for inputs read in blocks. */
uint32_t cli_crc32_update(uint32_t crc, const void *data, size_t len);

/* A one-input provenance: the input named name (shortened to its last 60
 * bytes after "..." when it does not fit), crc and bytes. */
void cli_input_provenance(const char *name, uint32_t crc, uint64_t bytes,
                          mcs_io_provenance *prov);

/* "stratified, N = 48 bins, K = 5 samples, seed 9, streams 0..3 of 4" and
 * the like for a pattern provenance; "a.txt (1234 bytes, CRC-32 0x...)" or
 * "3 inputs: a.txt, b.txt, c.txt" for points; into buf, returned. */
const char *cli_provenance_describe(const mcs_io_provenance *prov, char *buf, size_t size);

/* Merges what is left into *out (the caller frees it) and empties the tree.
 * Returns 0 or an exit status (then the tree is emptied and *out cleared). */
int cli_tree_finish(const char *cmd, cli_merge_tree *tree, cli_acc *out);

/* Frees whatever the tree holds (after a failure elsewhere). */
void cli_tree_free(cli_merge_tree *tree);

#endif /* MCSPEC_CLI_RECORD_H */
