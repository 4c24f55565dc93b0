/* Sizes and alignments of the public structs (abi.h): what a binding that
 * holds the objects as opaque bytes needs, read from this build's own
 * declarations (the public headers; no private header, no call). */
#include "mcspec/abi.h"
#include "mcspec.h"


typedef struct {
    size_t size, align;
} abi_entry;

#define ABI_ENTRY(t) {sizeof(t), _Alignof(t)}

/* Indexed by mcs_abi_type. */
static const abi_entry abi_table[MCS_ABI_TYPE_COUNT] = {
    ABI_ENTRY(mcs_rng),          ABI_ENTRY(mcs_importance),      ABI_ENTRY(mcs_pattern),
    ABI_ENTRY(mcs_pattern2d),    ABI_ENTRY(mcs_sampler),         ABI_ENTRY(mcs_welford),
    ABI_ENTRY(mcs_dft),          ABI_ENTRY(mcs_spectrum),        ABI_ENTRY(mcs_moment),
    ABI_ENTRY(mcs_autocorr),     ABI_ENTRY(mcs_pointset),        ABI_ENTRY(mcs_pointset2d),
    ABI_ENTRY(mcs_spectrum2d),   ABI_ENTRY(mcs_theory),          ABI_ENTRY(mcs_theory_spectrum),
    ABI_ENTRY(mcs_discrepancy),  ABI_ENTRY(mcs_spacing),         ABI_ENTRY(mcs_io_provenance),
    ABI_ENTRY(mcs_pcf),          ABI_ENTRY(mcs_integrand),       ABI_ENTRY(mcs_integrate),
    ABI_ENTRY(mcs_projections),  ABI_ENTRY(mcs_projections_pair), ABI_ENTRY(mcs_bluenoise_params),
};

mcs_status mcs_abi_sizeof(mcs_abi_type type, size_t *size, size_t *align)
{
    if (size == NULL && align == NULL)
        return MCS_ERR_NULL;
    /* as unsigned: a negative value is huge, and short-enum targets (the
     * enum an unsigned char) get no always-false comparison */
    const unsigned t = (unsigned)type;
    if (t >= (unsigned)MCS_ABI_TYPE_COUNT)
        return MCS_ERR_KIND;
    if (size != NULL && align != NULL && (void *)size == (void *)align)
        return MCS_ERR_ALIAS;
    if (size != NULL)
        *size = abi_table[t].size;
    if (align != NULL)
        *align = abi_table[t].align;
    return MCS_OK;
}
