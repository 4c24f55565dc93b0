/* The checks of the size query, init and copy of the objects over a
 * caller buffer (mcs_pointset, mcs_pointset2d, mcs_spectrum2d), in the
 * order their headers give, and the set-up of their statistics. */
#include "pointset_internal.h"

#include <string.h>

mcs_status mcs_ps_size_(mcs_status st, const mcs_ps_layout *lay, size_t *bytes)
{
    if (bytes == NULL)
        return MCS_ERR_NULL;
    if (st == MCS_OK)
        *bytes = lay->total;
    return st;
}

mcs_status mcs_ps_check_init_(const mcs_ps_span *to, mcs_status st, const mcs_ps_layout *lay)
{
    if (to->obj == NULL || to->mem == NULL)
        return MCS_ERR_NULL;
    if (st != MCS_OK)
        return st;
    if (to->bytes < lay->total)
        return MCS_ERR_SPACE;
    return mcs_overlap_(to->mem, lay->total, to->obj, to->hdr) ? MCS_ERR_ALIAS : MCS_OK;
}

mcs_status mcs_ps_check_copy_(const mcs_ps_span *to, const mcs_ps_span *from, mcs_status st,
                              const mcs_ps_layout *lay)
{
    st = mcs_ps_check_init_(to, st, lay);
    if (st != MCS_OK)
        return st;
    const void *mem = to->mem;
    const size_t need = lay->total, hdr = to->hdr;
    if (mcs_overlap_(mem, need, from->obj, hdr) || mcs_overlap_(mem, need, from->mem, from->bytes) ||
        (to->obj != from->obj && mcs_overlap_(to->obj, hdr, from->obj, hdr)))
        return MCS_ERR_ALIAS;
    return MCS_OK;
}

unsigned char *mcs_ps_set_up_stats_(void *mem, const mcs_ps_layout *lay, const void *stats)
{
    unsigned char *base = mcs_ps_aligned(mem);
    if (stats != NULL) {
        memcpy(base, stats, lay->stats);
    } else {
        memset(base, 0, lay->stats);
        mcs_ps_head *head = (mcs_ps_head *)(void *)base;
        head->shape[0] = lay->shape[0];
        head->shape[1] = lay->shape[1];
    }
    return base;
}
