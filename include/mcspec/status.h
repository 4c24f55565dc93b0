/* mcspec status codes: every fallible call returns one. */
#ifndef MCSPEC_STATUS_H
#define MCSPEC_STATUS_H

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    MCS_OK = 0,                   /* success */
    MCS_ERR_NULL = -1,            /* a required pointer argument is NULL */
    MCS_ERR_N_RANGE = -2,         /* bin count n is 0 or above the capacity */
    MCS_ERR_K_RANGE = -3,         /* sample count k is 0 or above a capacity */
    MCS_ERR_NOT_FINITE = -4,      /* a weight or value is NaN or infinite */
    MCS_ERR_NEGATIVE = -5,        /* a weight is negative */
    MCS_ERR_ZERO_WEIGHT = -6,     /* every importance weight is 0, or one is positive but too small next to the total to be
                                     sampled as asked (below MCS_IMPORTANCE_MIN_G of it) */
    MCS_ERR_BIN_RANGE = -7,       /* a bin index is outside [0, n) */
    MCS_ERR_POINT_RANGE = -8,     /* a point is outside [0, 1) */
    MCS_ERR_KIND = -9,            /* unknown pattern kind, or kind not defined with importance */
    MCS_ERR_MISMATCH = -10,       /* objects of different n (or shape) combined */
    MCS_ERR_BOUND = -11,          /* random bound of 0 */
    MCS_ERR_EMPTY = -12,          /* too few trials for the quantity asked (e.g. variance of < 2) */
    MCS_ERR_DOMAIN = -13,         /* closed form asked outside the domain where the note defines it */
    MCS_ERR_FREQ_RANGE = -14,     /* a frequency index is outside [0, n) */
    MCS_ERR_UNINIT = -15,         /* object was not initialised by its init function */
    MCS_ERR_SPACE = -16,          /* caller buffer smaller than the record to save, or than the work memory asked for */
    MCS_ERR_TRUNCATED = -17,      /* saved record shorter than its header says (or than a header) */
    MCS_ERR_MAGIC = -18,          /* bytes do not start with the mcspec record magic */
    MCS_ERR_VERSION = -19,        /* record format version this build does not read */
    MCS_ERR_CHECKSUM = -20,       /* record CRC-32 does not match its bytes */
    MCS_ERR_FORMAT = -21,         /* record shape or lengths not what its kind needs, or bytes after it */
    MCS_ERR_INVARIANT = -22,      /* values no adds produce: negative M2, data with no trials, count > 2^53 */
    MCS_ERR_MAGNITUDE = -23,      /* a finite value above the largest magnitude the call accepts
                                     (its square or 4th power could overflow a sum; see the header) */
    MCS_ERR_COUNT = -24,          /* an add or merge would take a count past MCS_MAX_COUNT */
    MCS_ERR_ALIAS = -25           /* arrays overlap where the call cannot work in place */
} mcs_status;

/* Name of a status code as a static string ("MCS_OK", ...); never NULL. */
const char *mcs_status_str(mcs_status status);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_STATUS_H */
