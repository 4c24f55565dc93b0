/* Adversarial table: records and their provenance (io.h) and exact spectra
 * at any N (mcs_theory_spectrum, theory.h). */
#include "adv_table.h"

#include <stdio.h>
#include <string.h>

/* A successful save must load back (io.h: "every record save writes loads
 * back"); the record is loaded into a scratch object of the same type. */
static int loads_back(int st, int type, const void *buf, const size_t *len)
{
    static _Alignas(64) unsigned char scratch[sizeof(mcs_spectrum)];
    static adv_pointset ps;
    static adv_pointset2d ps2;
    static adv_spectrum2d s2;
    static struct {
        mcs_pcf acc;
        _Alignas(64) unsigned char mem[MCS_PCF_SIZE(8)];
    } pcf;
    if (st != MCS_OK || buf == NULL)
        return st;
    int back;
    switch (type) {
    case T_WELFORD: back = mcs_io_load_welford((void *)scratch, *len, buf); break;
    case T_SPECTRUM: back = mcs_io_load_spectrum((void *)scratch, *len, buf); break;
    case T_MOMENT: back = mcs_io_load_moment((void *)scratch, *len, buf); break;
    case T_AUTOCORR: back = mcs_io_load_autocorr((void *)scratch, *len, buf); break;
    case T_POINTSET:
        back = mcs_io_load_pointset(&ps.acc, 0u, ps.mem, sizeof ps.mem, *len, buf);
        break;
    case T_POINTSET2D:
        back = mcs_io_load_pointset2d(&ps2.acc, 0u, ps2.mem, sizeof ps2.mem, *len, buf);
        break;
    case T_PCF: back = mcs_io_load_pcf(&pcf.acc, pcf.mem, sizeof pcf.mem, *len, buf); break;
    case T_INTEGRATE: back = mcs_io_load_integrate((void *)scratch, *len, buf); break;
    case T_DISC: back = mcs_io_load_discrepancy((void *)scratch, *len, buf); break;
    case T_SPACING: back = mcs_io_load_spacing((void *)scratch, *len, buf); break;
    default: back = mcs_io_load_spectrum2d(&s2.acc, s2.mem, sizeof s2.mem, *len, buf); break;
    }
    if (back == MCS_OK)
        return MCS_OK;
    snprintf(adv_note, sizeof adv_note, "the saved record does not load back (%s)",
             mcs_status_str((mcs_status)back));
    return ADV_BROKEN;
}

#define SAVE_THUNK(sfx, T)                                                          \
    static int t_io_save_##sfx(const adv_val *a)                                    \
    {                                                                               \
        return loads_back(mcs_io_save_##sfx(a[0].p, a[1].z, a[2].p, a[3].p), T, a[2].p, a[3].p); \
    }
#define LOAD_THUNK(sfx) \
    static int t_io_load_##sfx(const adv_val *a) { return mcs_io_load_##sfx(a[0].p, a[1].z, a[2].p); }
SAVE_THUNK(spectrum, T_SPECTRUM) SAVE_THUNK(moment, T_MOMENT) SAVE_THUNK(autocorr, T_AUTOCORR)
SAVE_THUNK(welford, T_WELFORD) SAVE_THUNK(pointset, T_POINTSET)
SAVE_THUNK(pointset2d, T_POINTSET2D) SAVE_THUNK(spectrum2d, T_SPECTRUM2D)
SAVE_THUNK(pcf, T_PCF) SAVE_THUNK(integrate, T_INTEGRATE) SAVE_THUNK(discrepancy, T_DISC)
SAVE_THUNK(spacing, T_SPACING)
LOAD_THUNK(spectrum) LOAD_THUNK(moment) LOAD_THUNK(autocorr) LOAD_THUNK(welford)
LOAD_THUNK(integrate) LOAD_THUNK(discrepancy) LOAD_THUNK(spacing)
static int t_io_load_pcf(const adv_val *a)
{
    return mcs_io_load_pcf(a[0].p, a[1].p, a[2].z, a[3].z, a[4].p);
}
static int t_io_load_pointset(const adv_val *a)
{
    return mcs_io_load_pointset(a[0].p, a[1].u32, a[2].p, a[3].z, a[4].z, a[5].p);
}
static int t_io_load_pointset2d(const adv_val *a)
{
    return mcs_io_load_pointset2d(a[0].p, a[1].u32, a[2].p, a[3].z, a[4].z, a[5].p);
}
static int t_io_load_spectrum2d(const adv_val *a)
{
    return mcs_io_load_spectrum2d(a[0].p, a[1].p, a[2].z, a[3].z, a[4].p);
}
static int t_io_load_size(const adv_val *a) { return mcs_io_load_size(a[0].z, a[1].p, a[2].u32, a[3].p); }

static int t_io_peek(const adv_val *a) { return mcs_io_peek(a[0].z, a[1].p, a[2].p); }
static int t_io_crc32(const adv_val *a) { return mcs_io_crc32(a[0].z, a[1].p, a[2].p); }
static int t_io_kind_str(const adv_val *a)
{
    const char *s = mcs_io_kind_str(a[0].u32);
    int known = a[0].u32 >= MCS_IO_KIND_SPECTRUM && a[0].u32 <= MCS_IO_KIND_SPACING;
    return s != NULL && known == (strcmp(s, "unknown") != 0) ? MCS_OK : ADV_BROKEN;
}
static int t_theory_spectrum_init(const adv_val *a) { return mcs_theory_spectrum_init(a[0].p, a[1].p); }
static int t_theory_spectrum_mean(const adv_val *a) { return mcs_theory_spectrum_mean(a[0].p, a[1].z, a[2].p, a[3].p); }
static int t_theory_spectrum_power(const adv_val *a) { return mcs_theory_spectrum_power(a[0].p, a[1].z, a[2].p); }
static int t_theory_power_spectrum(const adv_val *a) { return mcs_theory_power_spectrum(a[0].p, a[1].z, a[2].p); }
static int t_theory_spectrum_cross(const adv_val *a) { return mcs_theory_spectrum_cross(a[0].p, a[1].z, a[2].z, a[3].p, a[4].p); }
static int t_theory_spectrum_covariance(const adv_val *a) { return mcs_theory_spectrum_covariance(a[0].p, a[1].z, a[2].z, a[3].p, a[4].p); }
static int t_theory_spectrum_estimator_mean(const adv_val *a) { return mcs_theory_spectrum_estimator_mean(a[0].p, a[1].z, a[2].z, a[3].p, a[4].p); }
static int t_theory_spectrum_variance(const adv_val *a) { return mcs_theory_spectrum_variance(a[0].p, a[1].z, a[2].z, a[3].p, a[4].p); }
static int t_theory_spectrum_estimator_covariance(const adv_val *a)
{
    return mcs_theory_spectrum_estimator_covariance(a[0].p, a[1].z, a[2].z, a[3].p, a[4].p, a[5].p);
}

/* ---- provenance ---- */

/* A provenance read or made by a call passes mcs_io_provenance_bytes. */
static int prov_sound(int st, const mcs_io_provenance *prov)
{
    size_t bytes = 0;
    if (st != MCS_OK || prov == NULL)
        return st;
    if (mcs_io_provenance_bytes(prov, &bytes) == MCS_OK)
        return MCS_OK;
    snprintf(adv_note, sizeof adv_note, "the provenance made breaks the rules");
    return ADV_BROKEN;
}

static int t_io_peek_provenance(const adv_val *a)
{
    return prov_sound(mcs_io_peek_provenance(a[0].z, a[1].p, a[2].p), a[2].p);
}
/* The block's bytes as docs/format.md lays it out: an 8-byte head, then 80
 * bytes an input, or 56 more and 24 a stream range. */
static int t_io_provenance_bytes(const adv_val *a)
{
    const mcs_io_provenance *p = a[0].p;
    int st = mcs_io_provenance_bytes(p, a[1].p);
    if (st != MCS_OK)
        return st;
    const size_t want = p->source == MCS_IO_SOURCE_NONE     ? 0u
                        : p->source == MCS_IO_SOURCE_POINTS ? 8u + 80u * p->ninputs
                                                            : 64u + 24u * p->nranges;
    if (*(size_t *)a[1].p == want)
        return MCS_OK;
    snprintf(adv_note, sizeof adv_note, "%zu bytes, the layout says %zu", *(size_t *)a[1].p, want);
    return ADV_BROKEN;
}
/* The record made reads back the provenance set and loads (a spectrum's). */
static int t_io_set_provenance(const adv_val *a)
{
    static mcs_io_provenance back;
    int st = mcs_io_set_provenance(a[0].p, a[1].z, a[2].p, a[3].p);
    if (st != MCS_OK)
        return st;
    const size_t len = *(size_t *)a[3].p;
    if (mcs_io_peek_provenance(len, a[2].p, &back) != MCS_OK ||
        memcmp(&back, a[0].p, sizeof back) != 0) {
        snprintf(adv_note, sizeof adv_note, "the record does not read back the provenance set");
        return ADV_BROKEN;
    }
    return loads_back(st, T_SPECTRUM, a[2].p, a[3].p);
}
static int t_io_provenance_merge(const adv_val *a)
{
    return prov_sound(mcs_io_provenance_merge(a[0].p, a[1].p), a[0].p);
}

static const uint8_t pattern_vars[9] = {0, 1, 2, 3, 4, 5, 6, 7, 8};
/* A provenance of a pattern run and of point sets; for a record the source
 * set on it with a block of that source, and on a version 1 record. */
static const uint8_t source_vars[2] = {0, 1};
static const uint8_t record_vars[4] = {0, 1, 2, 3};

#define INFO_LEN {.op = L_CONST, .c = sizeof(mcs_io_info)}
#define CAP 16384u /* holds the record of every baseline object */
#define SAVE(sfx, T)                                                                       \
    FN(io_save_##sfx, EF_NONE, 1, 0, OBJ_IN("acc", T, 0), SZ_LEN("cap", CAP),              \
       AOUT("buf", E_U8, O_RAW, LEN(L_SLOT, 1), F_NULLOK), OUT("len", E_Z, O_RAW, 0))
#define LOAD(sfx, T)                                                                        \
    FN(io_load_##sfx, EF_NONE, 1, 0, OBJ_OUT("acc", T),                                     \
       {.name = "len", .kind = K_SIZE, .role = Z_REC, .type = T},                           \
       AIN("buf", E_U8, R_RECORD, LEN(L_REC, T), 0))
/* The loads of the objects over caller memory: the caller's buffer too. */
#define REC_LEN(T) {.name = "len", .kind = K_SIZE, .role = Z_REC, .type = T}
#define REC_BUF(T) AIN("buf", E_U8, R_RECORD, LEN(L_REC, T), 0)
#define LOAD_MEM(sfx, T, bytes)                                                            \
    FN(io_load_##sfx, EF_NONE, 1, 0, OBJ_OUT("acc", T), FLAGS, MEM(3), SZ_LEN("bytes", bytes), \
       REC_LEN(T), REC_BUF(T))
#define TS_IN OBJ_IN("ts", T_TSPEC, 0)
#define TS_SIZED OBJ_IN("ts", T_TSPEC, F_SIZED)
#define FREQ(nm, b) SZ_INDEX(nm, b, 0, BN - 1u, F_OKIN)
#define OUT_VAL(nm) OUT(nm, E_D, O_VAL, 0)
#define OUT_NN(nm) OUT(nm, E_D, O_NN, 0)
#define N_MATCH SZ_MATCH("n", BN, MCS_MAX_N)
#define K_MATCH SZ_MATCH("k", BK, SIZE_MAX)
#define F_OF(nm) AIN(nm, E_D, R_F, LEN(L_SLOT, 1), 0)

const adv_fn adv_fns_io[] = {
    SAVE(spectrum, T_SPECTRUM), SAVE(moment, T_MOMENT), SAVE(autocorr, T_AUTOCORR),
    SAVE(welford, T_WELFORD), SAVE(pointset, T_POINTSET), SAVE(pointset2d, T_POINTSET2D),
    SAVE(spectrum2d, T_SPECTRUM2D),
    LOAD(spectrum, T_SPECTRUM), LOAD(moment, T_MOMENT), LOAD(autocorr, T_AUTOCORR),
    LOAD(welford, T_WELFORD), LOAD_MEM(pointset, T_POINTSET, PS_MEM),
    LOAD_MEM(pointset2d, T_POINTSET2D, P2_MEM),
    FN(io_load_spectrum2d, EF_NONE, 1, 0, OBJ_OUT("acc", T_SPECTRUM2D), MEM(2),
       SZ_LEN("bytes", S2_MEM), REC_LEN(T_SPECTRUM2D), REC_BUF(T_SPECTRUM2D)),
    FN(io_load_size, EF_NONE, 1, 0, REC_LEN(T_POINTSET2D), REC_BUF(T_POINTSET2D), FLAGS,
       OUT("bytes", E_Z, O_RAW, 0)),
    SAVE(pcf, T_PCF), SAVE(integrate, T_INTEGRATE), SAVE(discrepancy, T_DISC),
    SAVE(spacing, T_SPACING),
    LOAD(integrate, T_INTEGRATE), LOAD(discrepancy, T_DISC), LOAD(spacing, T_SPACING),
    FN(io_load_pcf, EF_NONE, 1, 0, OBJ_OUT("acc", T_PCF), MEM(2), SZ_LEN("bytes", MCS_PCF_SIZE(8)),
       REC_LEN(T_PCF), REC_BUF(T_PCF)),
    FN(io_peek, EF_NONE, 1, 0, {.name = "len", .kind = K_SIZE, .role = Z_REC, .type = T_SPECTRUM},
       AIN("buf", E_U8, R_RECORD, LEN(L_REC, T_SPECTRUM), 0),
       AOUT("info", E_U8, O_RAW, INFO_LEN, 0)),
    FN(io_crc32, EF_NONE, 1, 0, {.name = "len", .kind = K_SIZE, .role = Z_LEN, .base = 64u, .hi = SIZE_MAX},
       AIN("data", E_U8, R_NONE, LEN(L_SLOT, 0), 0),
       OUT("crc", E_U32, O_RAW, 0)),
    FN(io_kind_str, EF_NONE, 1, 0, U32("kind", 1, 0, UINT32_MAX, F_FREE)),
    FN(io_peek_provenance, EF_NONE, 1, 0,
       {.name = "len", .kind = K_SIZE, .role = Z_REC, .type = T_RECORD},
       AIN("buf", E_U8, R_RECORD, LEN(L_REC, T_RECORD), 0), OBJ_OUT("prov", T_PROV)),
    FNV(io_provenance_bytes, EF_NONE, source_vars, 0, OBJ_IN("prov", T_PROV, F_ZEROOK),
        OUT("bytes", E_Z, O_RAW, 0)),
    FNV(io_set_provenance, EF_NONE, record_vars, 0, OBJ_IN("prov", T_PROV, F_ZEROOK),
        {.name = "cap", .kind = K_SIZE, .role = Z_LEN, .base = ADV_RECORD_CAP, .lo = 1, .hi = SIZE_MAX},
        OBJ_IO("buf", T_RECORD, F_SIZED), OBJ_IO("len", T_RECLEN, F_SIZED)),
    FNV(io_provenance_merge, EF_NONE, source_vars, 0, OBJ_IO("dst", T_PROV, 0),
        OBJ_IN("src", T_PROV, F_SIZED)),
    FNV(theory_spectrum_init, EF_NONE, pattern_vars, 1, OBJ_OUT("ts", T_TSPEC), OBJ_IN("pat", T_PAT, 0)),
    FN(theory_spectrum_mean, EF_NONE, 1, 0, TS_IN, FREQ("freq", 1), OUT_VAL("re"), OUT_VAL("im")),
    FN(theory_spectrum_power, EF_NONE, 1, 0, TS_IN, FREQ("freq", 1), OUT_NN("out")),
    FN(theory_power_spectrum, EF_NONE, 1, 0, TS_SIZED, N_MATCH,
       AOUT("power", E_D, O_NN, LEN(L_SLOT, 1), 0)),
    FN(theory_spectrum_cross, EF_NONE, 1, 0, TS_IN, FREQ("freq_k", 1), FREQ("freq_l", 2),
       OUT_VAL("re"), OUT_VAL("im")),
    FN(theory_spectrum_covariance, EF_NONE, 1, 0, TS_IN, FREQ("freq_k", 1), FREQ("freq_l", 2),
       OUT_VAL("re"), OUT_VAL("im")),
    FN(theory_spectrum_estimator_mean, EF_NONE, 1, 0, TS_SIZED, N_MATCH, K_MATCH, F_OF("f"),
       OUT_VAL("out")),
    FN(theory_spectrum_variance, EF_NONE, 1, 0, TS_SIZED, N_MATCH, K_MATCH, F_OF("f"),
       OUT_NN("out")),
    FN(theory_spectrum_estimator_covariance, EF_NONE, 1, 0, TS_SIZED, N_MATCH, K_MATCH,
       F_OF("f"), F_OF("g"), OUT_VAL("out")),
};
const size_t adv_fns_io_count = sizeof adv_fns_io / sizeof adv_fns_io[0];

/* ---- provenance rules (a scenario: a row has one bad state per slot) ----
 * Each rule of io.h broken alone: mcs_io_provenance_bytes, set_provenance
 * and merge (either side) refuse with MCS_ERR_FORMAT and change nothing;
 * and a record whose block breaks one under a right CRC is refused by
 * peek, peek_provenance and load, changing nothing. */

static void prov_valid(int points, mcs_io_provenance *p)
{
    memset(p, 0, sizeof *p);
    if (points) {
        p->source = MCS_IO_SOURCE_POINTS;
        p->ninputs = 2u;
        p->input[0].crc = 0x100u;
        p->input[1].crc = 0x200u;
        memcpy(p->input[0].name, "a.txt", 5);
        return;
    }
    p->source = MCS_IO_SOURCE_PATTERN;
    p->dim = 1u;
    memcpy(p->pattern, "jitter", 6);
    p->n = 12u;
    p->k = 6u;
    p->streams = 8u;
    p->trials = 80u;
    p->nranges = 2u;
    p->range[0] = (mcs_io_streams){7u, 0u, 2u};
    p->range[1] = (mcs_io_streams){7u, 4u, 8u};
}

/* Rule e broken in *p; 0 past the last. */
static int prov_break(int e, mcs_io_provenance *p)
{
    prov_valid(e >= 20, p);
    switch (e) {
    case 0: p->source = 3u; break;
    case 1: p->dim = 0u; break;
    case 2: p->dim = 3u; break;
    case 3: p->n = 0u; break;
    case 4: p->k = 0u; break;
    case 5: p->importance = 2u; break;
    case 6: p->importance_crc = 1u; break; /* a CRC without importance */
    case 7: p->streams = 0u; break;
    case 8: p->trials = p->streams - 1u; break;
    case 9: p->nranges = 0u; break;
    case 10: p->nranges = MCS_IO_PROV_MAX_RANGES + 1u; break;
    case 11: p->range[0].end = p->range[0].first; break;
    case 12: p->range[1].end = p->streams + 1u; break;
    case 13: p->range[1].first = 1u; break; /* overlaps the first */
    case 14: p->range[1].first = 2u; break; /* touches it: one range */
    case 15: p->range[1].seed = 6u; break;  /* out of order */
    case 16: memset(p->pattern, 0, sizeof p->pattern); break;
    case 17: memset(p->pattern, 'x', sizeof p->pattern); break; /* no NUL */
    case 18: p->pattern[2] = ' '; break;
    case 19: p->pattern[2] = (char)0x80; break;
    case 20: p->ninputs = 0u; break;
    case 21: p->ninputs = MCS_IO_PROV_MAX_INPUTS + 1u; break;
    case 22: p->input[1].crc = p->input[0].crc; break;
    case 23: p->input[1].crc = 0x50u; break;
    case 24: memset(p->input[1].name, 'y', sizeof p->input[1].name); break;
    default: return 0;
    }
    return 1;
}

#define PROV_REC_CAP 2048u

static int prov_refused(int e, const char *what, int st, int kept)
{
    if (st == MCS_ERR_FORMAT && kept)
        return MCS_OK;
    snprintf(adv_note, sizeof adv_note, "rule %d, %s: %s%s", e, what, mcs_status_str((mcs_status)st),
             kept ? "" : ", and it changed");
    return ADV_BROKEN;
}

int io_provenances_breaking_a_rule_are_refused_unchanged(const adv_val *a)
{
    static mcs_io_provenance bad, good, copy;
    static unsigned char rec[PROV_REC_CAP], before[PROV_REC_CAP];
    static _Alignas(64) unsigned char acc[sizeof(mcs_spectrum)], acc_before[sizeof(mcs_spectrum)];
    const size_t len1 = adv_record_size(T_SPECTRUM);
    int st;
    (void)a;
    for (int e = 0; prov_break(e, &bad); ++e) {
        size_t bytes = 7u, len = len1;
        prov_valid(e >= 20, &good);
        if ((st = prov_refused(e, "bytes", mcs_io_provenance_bytes(&bad, &bytes), bytes == 7u)))
            return st;
        memset(rec, 0, sizeof rec);
        adv_record(T_SPECTRUM, rec);
        memcpy(before, rec, sizeof rec);
        st = mcs_io_set_provenance(&bad, sizeof rec, rec, &len);
        if ((st = prov_refused(e, "set", st, len == len1 && memcmp(rec, before, sizeof rec) == 0)))
            return st;
        copy = bad;
        st = mcs_io_provenance_merge(&copy, &good);
        if ((st = prov_refused(e, "merge into it", st, memcmp(&copy, &bad, sizeof copy) == 0)))
            return st;
        copy = good;
        st = mcs_io_provenance_merge(&copy, &bad);
        if ((st = prov_refused(e, "merge it in", st, memcmp(&copy, &good, sizeof copy) == 0)))
            return st;
    }
    /* A block written, then one byte of it made to break a rule and the CRC
     * made right again: the name of the pattern, then its dim. */
    for (int e = 0; e < 2; ++e) {
        size_t len = len1, at = len1 - MCS_IO_CRC_BYTES + (e == 0 ? 18u : 8u);
        uint32_t crc = 0;
        memset(rec, 0, sizeof rec);
        adv_record(T_SPECTRUM, rec);
        prov_valid(0, &good);
        if (mcs_io_set_provenance(&good, sizeof rec, rec, &len) != MCS_OK)
            return ADV_BROKEN;
        rec[at] = e == 0 ? ' ' : 3u;
        (void)mcs_io_crc32(len - MCS_IO_CRC_BYTES, rec, &crc);
        for (int b = 0; b < 4; ++b)
            rec[len - MCS_IO_CRC_BYTES + (size_t)b] = (unsigned char)(crc >> (8 * b));
        memcpy(before, rec, sizeof rec);
        mcs_io_info info;
        memset(&info, 0x5A, sizeof info);
        const mcs_io_info info_before = info;
        st = mcs_io_peek(len, rec, &info);
        if ((st = prov_refused(e, "peek", st, memcmp(&info, &info_before, sizeof info) == 0)))
            return st;
        copy = bad;
        st = mcs_io_peek_provenance(len, rec, &copy);
        if ((st = prov_refused(e, "peek_provenance", st, memcmp(&copy, &bad, sizeof copy) == 0)))
            return st;
        memset(acc, 0x3C, sizeof acc);
        memcpy(acc_before, acc, sizeof acc);
        st = mcs_io_load_spectrum((mcs_spectrum *)(void *)acc, len, rec);
        if ((st = prov_refused(e, "load", st, memcmp(acc, acc_before, sizeof acc) == 0 &&
                                                  memcmp(rec, before, sizeof rec) == 0)))
            return st;
    }
    return MCS_OK;
}
