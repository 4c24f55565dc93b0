/* The size query, init and copy of the objects over a caller buffer
 * (mcs_pointset, mcs_pointset2d, mcs_spectrum2d), each described by its
 * mcs_ps_kind (pointset_internal.h): the checks in the order their headers
 * give, then the header set up aside and stored whole. */
#include "pointset_internal.h"

#include <string.h>

/* Room for any of the headers: a copy sets dst up aside, since dst may be
 * src, whose statistics and settings it still reads. */
typedef union {
    mcs_pointset ps;
    mcs_pointset2d ps2d;
    mcs_spectrum2d sp2d;
} any_header;

mcs_status mcs_ps_size_(const mcs_ps_kind *kind, size_t a, size_t b, size_t *bytes)
{
    if (bytes == NULL)
        return MCS_ERR_NULL;
    mcs_ps_layout lay;
    mcs_status st = kind->layout(a, b, &lay);
    if (st == MCS_OK)
        *bytes = lay.total;
    return st;
}

/* *obj <- the header over mem for the checked layout lay: its statistics
 * zeroed under a new head (from NULL) or from's (a copy, like its source). */
static void set_up(const mcs_ps_kind *kind, void *obj, void *mem, const mcs_ps_layout *lay,
                   const void *like, const mcs_ps_view *from)
{
    any_header h;
    memset(&h, 0, sizeof h);
    kind->set_up(&h, mem, lay, like);
    unsigned char *base = mcs_ps_aligned(mem);
    if (from != NULL) {
        memcpy(base, from->state, lay->stats);
    } else {
        memset(base, 0, lay->stats);
        mcs_ps_head *head = (mcs_ps_head *)(void *)base;
        head->shape[0] = lay->shape[0];
        head->shape[1] = lay->shape[1];
    }
    memcpy(obj, &h, kind->hdr);
}

mcs_status mcs_ps_init_(const mcs_ps_kind *kind, void *acc, size_t a, size_t b, void *mem,
                        size_t bytes)
{
    if (acc == NULL || mem == NULL)
        return MCS_ERR_NULL;
    mcs_ps_layout lay;
    mcs_status st = kind->layout(a, b, &lay);
    if (st != MCS_OK)
        return st;
    if (bytes < lay.total)
        return MCS_ERR_SPACE;
    if (mcs_overlap_(mem, lay.total, acc, kind->hdr))
        return MCS_ERR_ALIAS;
    set_up(kind, acc, mem, &lay, NULL, NULL);
    return MCS_OK;
}

mcs_status mcs_ps_copy_(const mcs_ps_kind *kind, void *dst, void *mem, size_t bytes,
                        const void *src)
{
    if (dst == NULL || mem == NULL)
        return MCS_ERR_NULL;
    mcs_ps_view v;
    mcs_status st = kind->view(src, &v);
    if (st != MCS_OK)
        return st;
    mcs_ps_layout lay;
    (void)kind->layout(v.arg[0], v.arg[1], &lay); /* cannot fail: src passed init */
    if (bytes < lay.total)
        return MCS_ERR_SPACE;
    const size_t hdr = kind->hdr;
    if (mcs_overlap_(mem, lay.total, dst, hdr) || mcs_overlap_(mem, lay.total, src, hdr) ||
        mcs_overlap_(mem, lay.total, v.mem, v.bytes) ||
        (dst != src && mcs_overlap_(dst, hdr, src, hdr)))
        return MCS_ERR_ALIAS;
    set_up(kind, dst, mem, &lay, src, &v);
    return MCS_OK;
}
