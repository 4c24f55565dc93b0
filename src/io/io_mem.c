/* The save and load of the record kinds whose objects live over caller
 * memory (the point sets and 2D spectrum, io_points.c; the pair
 * correlation, io_pcf.c): the two walks of a load (io_internal.h), the
 * memory checks, and one save and one load for every such kind, told apart
 * by an io_mem_kind. */
#include "io_internal.h"
#include "core/internal.h"

#include <string.h>

mcs_status mcs_io_init_checked(void *obj, const uint64_t *shape)
{
    (void)obj;
    (void)shape;
    return MCS_IO_CHECKED;
}

mcs_status mcs_io_init_ready(void *obj, const uint64_t *shape)
{
    (void)obj;
    (void)shape;
    return MCS_OK; /* set up by the object's own init already */
}

/* The memory checks of a load once the record passed: the caller's buffer
 * (need bytes of it) against the object and the record, and those two
 * against each other. Six arguments: a seventh would be pushed, a frame gcc
 * calls dynamic (make stack). */
static mcs_status check_load_alias(const void *acc, size_t acc_bytes, const void *mem,
                                   size_t need, const void *buf, size_t len)
{
    if (mcs_overlap_(mem, need, acc, acc_bytes) || mcs_overlap_(mem, need, buf, len) ||
        mcs_overlap_(acc, acc_bytes, buf, len))
        return MCS_ERR_ALIAS;
    return MCS_OK;
}

/* A save's record buffer must not overlap the object it reads. */
static int save_overlaps(const void *acc, size_t acc_bytes, const void *mem, size_t bytes,
                         const void *buf, size_t cap)
{
    return buf != NULL && (mcs_overlap_(buf, cap, acc, acc_bytes) || mcs_overlap_(buf, cap, mem, bytes));
}

static uint64_t shape_word(const void *buf, size_t len, size_t i)
{
    mcs_io_info info;
    (void)mcs_io_peek(len, buf, &info); /* cannot fail: the record passed */
    return info.shape[i];
}

mcs_status mcs_io_save_mem(const io_mem_kind *m, const void *acc, size_t cap, void *buf,
                           size_t *len)
{
    uint64_t count = 0u;
    mcs_status st = acc == NULL || len == NULL ? MCS_ERR_NULL : m->count(acc, &count);
    const void *mem = NULL;
    size_t bytes = 0u;
    if (st == MCS_OK) { /* the object checked: its buffer is its own */
        memcpy(&mem, (const unsigned char *)acc + m->mem_at, sizeof mem);
        memcpy(&bytes, (const unsigned char *)acc + m->bytes_at, sizeof bytes);
    }
    if (st == MCS_OK && save_overlaps(acc, m->acc_size, mem, bytes, buf, cap))
        st = MCS_ERR_ALIAS;
    if (st != MCS_OK)
        return st;
    io_kind kind;
    m->table(&kind, acc);
    return mcs_io_save(&kind, m->state != NULL ? m->state(acc) : acc, cap, buf, len);
}

mcs_status mcs_io_load_mem(const io_mem_kind *m, void *acc, const io_mem_arg *arg, size_t len,
                           const void *buf)
{
    void *mem = arg->mem;
    const size_t bytes = arg->bytes;
    const unsigned flags = arg->flags;
    if (acc == NULL || mem == NULL || buf == NULL)
        return MCS_ERR_NULL;
    const uint64_t one[MCS_IO_MAX_SHAPE] = {1u, 1u, 1u, 1u, 1u, 1u, 1u, 1u};
    size_t need = 0u;
    if (m->size(one, flags, &need) == MCS_ERR_DOMAIN)
        return MCS_ERR_DOMAIN; /* a flag (only the point sets take flags) */
    io_kind k;
    m->table(&k, NULL);
    mcs_status st = mcs_io_load(&k, mem, len, buf); /* checks only */
    if (st != MCS_IO_CHECKED)
        return st;
    uint64_t shape[MCS_IO_MAX_SHAPE] = {0u};
    for (size_t i = 0; i < k.shape_len; ++i)
        shape[i] = shape_word(buf, len, i);
    (void)m->size(shape, flags, &need); /* cannot fail: the shape passed the kind's sizes */
    st = bytes < need ? MCS_ERR_SPACE : check_load_alias(acc, m->acc_size, mem, need, buf, len);
    if (st != MCS_OK)
        return st;
    (void)m->init(acc, shape, flags, mem, bytes); /* cannot fail: checked above */
    m->table(&k, acc);
    k.init = mcs_io_init_ready;
    return mcs_io_load(&k, m->state != NULL ? m->state(acc) : acc, len, buf);
}
