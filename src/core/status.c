#include "mcspec/status.h"

const char *mcs_status_str(mcs_status status)
{
    switch (status) {
    case MCS_OK: return "MCS_OK";
    case MCS_ERR_NULL: return "MCS_ERR_NULL";
    case MCS_ERR_N_RANGE: return "MCS_ERR_N_RANGE";
    case MCS_ERR_K_RANGE: return "MCS_ERR_K_RANGE";
    case MCS_ERR_NOT_FINITE: return "MCS_ERR_NOT_FINITE";
    case MCS_ERR_NEGATIVE: return "MCS_ERR_NEGATIVE";
    case MCS_ERR_ZERO_WEIGHT: return "MCS_ERR_ZERO_WEIGHT";
    case MCS_ERR_BIN_RANGE: return "MCS_ERR_BIN_RANGE";
    case MCS_ERR_POINT_RANGE: return "MCS_ERR_POINT_RANGE";
    case MCS_ERR_KIND: return "MCS_ERR_KIND";
    case MCS_ERR_MISMATCH: return "MCS_ERR_MISMATCH";
    case MCS_ERR_BOUND: return "MCS_ERR_BOUND";
    case MCS_ERR_EMPTY: return "MCS_ERR_EMPTY";
    case MCS_ERR_DOMAIN: return "MCS_ERR_DOMAIN";
    case MCS_ERR_FREQ_RANGE: return "MCS_ERR_FREQ_RANGE";
    case MCS_ERR_UNINIT: return "MCS_ERR_UNINIT";
    case MCS_ERR_SPACE: return "MCS_ERR_SPACE";
    case MCS_ERR_TRUNCATED: return "MCS_ERR_TRUNCATED";
    case MCS_ERR_MAGIC: return "MCS_ERR_MAGIC";
    case MCS_ERR_VERSION: return "MCS_ERR_VERSION";
    case MCS_ERR_CHECKSUM: return "MCS_ERR_CHECKSUM";
    case MCS_ERR_FORMAT: return "MCS_ERR_FORMAT";
    case MCS_ERR_INVARIANT: return "MCS_ERR_INVARIANT";
    case MCS_ERR_MAGNITUDE: return "MCS_ERR_MAGNITUDE";
    case MCS_ERR_COUNT: return "MCS_ERR_COUNT";
    case MCS_ERR_ALIAS: return "MCS_ERR_ALIAS";
    }
    return "MCS_ERR_UNKNOWN";
}
