/* Private to cli/record*.c: the operations of each record kind (record.c)
 * that the record files (record_file.c) use to load and save. */
#ifndef MCSPEC_CLI_RECORD_OPS_H
#define MCSPEC_CLI_RECORD_OPS_H

#include <stddef.h>
#include <stdint.h>

#include "mcspec.h"

typedef struct {
    mcs_io_kind kind;
    size_t size; /* the object; for the kinds over caller memory, its header */
    mcs_status (*init)(void *obj, const size_t *shape); /* NULL: not made here */
    mcs_status (*load)(void *obj, size_t len, const void *buf);
    mcs_status (*save)(const void *obj, size_t cap, void *buf, size_t *len);
    mcs_status (*merge)(void *dst, const void *src);
    /* The kinds whose arrays live in caller memory (pointset.h,
     * pointset2d.h, spectrum2d.h), NULL for the others: the buffer's size
     * for a shape, and init and load over a buffer. */
    mcs_status (*mem_size)(const size_t *shape, size_t *bytes);
    mcs_status (*init_mem)(void *obj, const size_t *shape, void *mem, size_t bytes);
    mcs_status (*load_mem)(void *obj, void *mem, size_t bytes, size_t len, const void *buf);
} kind_ops;

/* The operations of a kind, or NULL for one the command does not know. */
const kind_ops *cli_ops_of(uint32_t kind);

/* One block for an object over caller memory: its header, then its buffer
 * of `bytes` (*mem). NULL, after one line naming `what` (e.g. "--freq 4096")
 * and the bytes, where the size cannot be held: more than size_t counts,
 * than the machine's memory, or than malloc gives. */
void *cli_alloc_with_buffer(const char *cmd, const char *what, size_t header, size_t bytes,
                            mcs_status size_status, void **mem);

#endif /* MCSPEC_CLI_RECORD_OPS_H */
