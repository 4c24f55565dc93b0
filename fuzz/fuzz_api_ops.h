/* Operations of fuzz/fuzz_api.c: the read-outs of every accumulator and of
 * exact theory, generators (rng, importance, patterns, samplers), plans, the
 * closed forms of eq.h and the 2D and point-set read-outs. Included once by
 * fuzz_api.c, after the argument stream, the objects and the checks it uses. */
#ifndef FUZZ_API_OPS_H
#define FUZZ_API_OPS_H

/* ---- read-outs, by signature ---- */

typedef mcs_status (*r1_fn)(const void *, size_t, double *);
typedef mcs_status (*r2_fn)(const void *, size_t, double *, double *);
typedef mcs_status (*r3_fn)(const void *, size_t, size_t, double *, double *);
typedef mcs_status (*r4_fn)(const void *, size_t, size_t, double *);
typedef mcs_status (*r6_fn)(const void *, size_t, size_t, const double *, double *);
typedef mcs_status (*r7_fn)(const void *, size_t, size_t, const double *, const double *, double *);
#define R1(f, T) static mcs_status a_##f(const void *o, size_t a, double *v) { return mcs_##f((const T *)o, a, v); }
#define R2(f, T) static mcs_status a_##f(const void *o, size_t a, double *r, double *i) { return mcs_##f((const T *)o, a, r, i); }
#define R3(f, T) static mcs_status a_##f(const void *o, size_t a, size_t b, double *r, double *i) { return mcs_##f((const T *)o, a, b, r, i); }
#define R4(f, T) static mcs_status a_##f(const void *o, size_t a, size_t b, double *v) { return mcs_##f((const T *)o, a, b, v); }
#define R6(f, T) static mcs_status a_##f(const void *o, size_t n, size_t k, const double *f_, double *v) { return mcs_##f((const T *)o, n, k, f_, v); }
#define R7(f, T) static mcs_status a_##f(const void *o, size_t n, size_t k, const double *f_, const double *g, double *v) { return mcs_##f((const T *)o, n, k, f_, g, v); }
R1(spectrum_mean_stderr, mcs_spectrum) R1(spectrum_power, mcs_spectrum)
R1(spectrum_power_stderr, mcs_spectrum) R1(moment_bin_mean, mcs_moment) R1(moment_power, mcs_moment)
R1(theory_bin_mean, mcs_theory) R1(theory_power, mcs_theory) R1(pointset2d_radial, mcs_pointset2d)
R1(pointset2d_radial_stderr, mcs_pointset2d) R1(pointset2d_anisotropy, mcs_pointset2d)
R1(pointset2d_exact_radial, mcs_pattern2d) R1(pointset2d_exact_anisotropy, mcs_pattern2d)
R2(spectrum_mean, mcs_spectrum) R2(moment_mean, mcs_moment) R2(theory_mean, mcs_theory)
R2(importance_q, mcs_importance) R2(moment_cross_matrix, mcs_moment)
R2(moment_covariance_matrix, mcs_moment) R2(theory_cross_matrix, mcs_theory)
R2(theory_covariance_matrix, mcs_theory)
R3(moment_cross, mcs_moment) R3(moment_covariance, mcs_moment) R3(theory_cross, mcs_theory)
R3(theory_covariance, mcs_theory) R3(spectrum2d_mean, mcs_spectrum2d)
R4(moment_bin_second, mcs_moment) R4(theory_bin_second, mcs_theory)
R4(spectrum2d_power, mcs_spectrum2d) R4(spectrum2d_power_stderr, mcs_spectrum2d)
R4(spectrum2d_mean_stderr, mcs_spectrum2d)
R6(moment_estimator_mean, mcs_moment) R6(moment_variance, mcs_moment)
R6(theory_estimator_mean, mcs_theory) R6(theory_variance, mcs_theory) R6(eq13_variance, mcs_theory)
R7(moment_estimator_covariance, mcs_moment) R7(theory_estimator_covariance, mcs_theory)
R7(eq2_uncorrelated_variance, mcs_theory) R7(eq4_correlated_variance, mcs_theory)
R1(theory_spectrum_power, mcs_theory_spectrum) R2(theory_spectrum_mean, mcs_theory_spectrum)
R3(theory_spectrum_cross, mcs_theory_spectrum) R3(theory_spectrum_covariance, mcs_theory_spectrum)
R6(theory_spectrum_estimator_mean, mcs_theory_spectrum) R6(theory_spectrum_variance, mcs_theory_spectrum)
R7(theory_spectrum_estimator_covariance, mcs_theory_spectrum)

#define E(f, type, nn) {(void (*)(void))a_##f, type, nn, "mcs_" #f}
typedef struct {
    void (*f)(void);
    int type, nonneg;
    const char *name;
} readout;
static const readout r1s[] = {
    E(spectrum_mean_stderr, SPEC, 1), E(spectrum_power, SPEC, 1), E(spectrum_power_stderr, SPEC, 1),
    E(moment_bin_mean, MOM, 0), E(moment_power, MOM, 1), E(theory_bin_mean, TH, 0),
    E(theory_power, TH, 1), E(pointset2d_radial, PS2, 1), E(pointset2d_radial_stderr, PS2, 1),
    E(pointset2d_anisotropy, PS2, 0), E(pointset2d_exact_radial, P2D, 1),
    E(pointset2d_exact_anisotropy, P2D, 0), E(theory_spectrum_power, TS, 1)};
static const readout r2s[] = {E(spectrum_mean, SPEC, 0), E(moment_mean, MOM, 0),
                              E(theory_mean, TH, 0), E(importance_q, IMP, 0),
                              E(theory_spectrum_mean, TS, 0)};
static const readout r5s[] = {E(moment_cross_matrix, MOM, 1), E(moment_covariance_matrix, MOM, 1),
                              E(theory_cross_matrix, TH, 1), E(theory_covariance_matrix, TH, 1)};
static const readout r3s[] = {E(moment_cross, MOM, 1), E(moment_covariance, MOM, 1),
                              E(theory_cross, TH, 1), E(theory_covariance, TH, 1),
                              E(spectrum2d_mean, S2, 0), E(theory_spectrum_cross, TS, 1),
                              E(theory_spectrum_covariance, TS, 1)};
static const readout r4s[] = {E(moment_bin_second, MOM, 0), E(theory_bin_second, TH, 0),
                              E(spectrum2d_power, S2, 1), E(spectrum2d_power_stderr, S2, 1),
                              E(spectrum2d_mean_stderr, S2, 1)};
static const readout r6s[] = {E(moment_estimator_mean, MOM, 0), E(moment_variance, MOM, 1),
                              E(theory_estimator_mean, TH, 0), E(theory_variance, TH, 1),
                              E(eq13_variance, TH, 0), E(theory_spectrum_estimator_mean, TS, 0),
                              E(theory_spectrum_variance, TS, 1)};
static const readout r7s[] = {E(moment_estimator_covariance, MOM, 0),
                              E(theory_estimator_covariance, TH, 0),
                              E(eq2_uncorrelated_variance, TH, 1), E(eq4_correlated_variance, TH, 1),
                              E(theory_spectrum_estimator_covariance, TS, 0)};
#define PICK(table) (&table[byte() % (sizeof table / sizeof table[0])])

static void op_readout(unsigned which)
{
    const readout *r = which == 0 ? PICK(r1s) : which == 1 ? PICK(r2s) : which == 2 ? PICK(r3s)
                       : which == 3 ? PICK(r4s) : which == 4 ? PICK(r5s) : which == 5 ? PICK(r6s)
                                                                          : PICK(r7s);
    const void *o = obj_or_null(r->type);
    size_t a = size_any(), b = size_any(), len = a <= 64u ? a : 1u;
    double *re = dout[0], *im = dout[1];
    begin(r->name);
    reg(o, o ? obj_size[r->type] : 0u, 0u);
    mcs_status st = MCS_ERR_NULL;
    switch (which) {
    case 0:
        st = end(((r1_fn)r->f)(o, a, out(re, 1, 8)));
        vals(st, re, 1, r->nonneg);
        break;
    case 1:
        st = end(((r2_fn)r->f)(o, a, out(re, 1, 8), out(im, 1, 8)));
        vals(st, re, 1, 0);
        vals(st, im, 1, 0);
        break;
    case 2:
        st = end(((r3_fn)r->f)(o, a, b, out(re, 1, 8), out(im, 1, 8)));
        vals(st, re, 1, r->nonneg && a == b);
        vals(st, im, 1, 0);
        break;
    case 3:
        st = end(((r4_fn)r->f)(o, a, b, out(re, 1, 8)));
        vals(st, re, 1, r->nonneg);
        break;
    case 4: /* matrices: n = a, n * n entries each; the diagonal is a power or a variance */
        st = end(((r2_fn)r->f)(o, a, out(re, len * len, 8), out(im, len * len, 8)));
        vals(st, re, len * len, 0);
        for (size_t k = 0; st == MCS_OK && k < len; ++k)
            vals(st, &re[k * len + k], 1, 1);
        break;
    case 5:
        st = end(((r6_fn)r->f)(o, a, b, reg(darray(0, len), len * 8, 0), out(re, 1, 8)));
        vals(st, re, 1, r->nonneg);
        break;
    default:
        st = end(((r7_fn)r->f)(o, a, b, reg(darray(0, len), len * 8, 0), reg(darray(1, len), len * 8, 0),
                               out(re, 1, 8)));
        vals(st, re, 1, r->nonneg);
    }
}

static void op_welford_readout(void)
{
    const mcs_welford *o = obj_or_null(WEL);
    double *v = out(dout[0], 1, 8);
    const unsigned which = byte() % 4u;
    begin("welford read-out");
    reg(o, sizeof *o, 0u);
    mcs_status st = end(which == 0   ? mcs_welford_mean(o, v)
                        : which == 1 ? mcs_welford_variance(o, v)
                        : which == 2 ? mcs_welford_stderr(o, v)
                                     : mcs_welford_variance_stderr(o, v));
    vals(st, v, 1, which != 0);
    if (st == MCS_OK && which == 3 && *v == 0.0 && o->count >= 4u && o->m2 > 0.0)
        finding(6, cur_fn, "variance_stderr 0 with m2 = %g, m4 = %g", o->m2, o->m4);
}

/* ---- generators: rng, importance, patterns, samplers ---- */

static int unseeded(const mcs_rng *r) { return r != NULL && (r->inc & 1u) == 0u; }

static void op_rng(void)
{
    mcs_rng *r = obj_or_null(RNG);
    const unsigned which = byte() % 4u;
    const uint32_t bound = (uint32_t)word(byte() % 5u);
    begin("rng");
    inout(RNG, r);
    uint32_t *u = out(uout, 1, 4);
    double *d = out(dout[0], 1, 8);
    mcs_status st = which == 0   ? mcs_rng_seed(r, word(8), word(8))
                    : which == 1 ? mcs_rng_u32(r, u)
                    : which == 2 ? mcs_rng_bounded(r, bound, u)
                                 : mcs_rng_double(r, d);
    end(st);
    if (st == MCS_OK && which == 2 && *u >= bound)
        finding(0, cur_fn, "bounded(%u) gave %u", bound, *u);
    if (st == MCS_OK && which == 3 && !(*d >= 0.0 && *d < 1.0))
        finding(0, cur_fn, "double gave %g", *d);
    if (st == MCS_OK && which != 0 && unseeded(r))
        finding(3, cur_fn, "MCS_OK from an unseeded generator");
}

static void op_importance(void)
{
    mcs_importance *imp = obj_or_null(IMP);
    const size_t n = size_any(), len = n <= MAXLEN ? n : 1u;
    begin("importance");
    if (byte() % 2u == 0u) {
        mcs_status st = end(mcs_importance_init(inout(IMP, imp), n, reg(darray(0, len), len * 8, 0)));
        int full = 1; /* H <= 1 when every bin is in the support (a weight of 0 is not) */
        for (size_t b = 0; st == MCS_OK && b < n; ++b)
            full &= imp->p[b] > 0.0;
        if (st == MCS_OK &&
            !(imp->harmonic_mean > 0.0 && isfinite(imp->harmonic_mean) &&
              (imp->harmonic_mean <= 1.0 || !full)))
            finding(8, cur_fn, "harmonic mean %.17g outside (0, 1]", imp->harmonic_mean);
        return;
    }
    double *x = byte() % 4u ? out(dout[0], 1, 8) : NULL;
    size_t *bin = byte() % 4u ? out(zout, 1, sizeof(size_t)) : NULL;
    reg(imp, imp ? sizeof *imp : 0u, 0u);
    mcs_status st = end(mcs_importance_warp(imp, dbl(), x, bin));
    if (st == MCS_OK && ((x && !(*x >= 0.0 && *x < 1.0)) || (bin && *bin >= imp->n)))
        finding(0, cur_fn, "warp gave x = %g, bin %zu", x ? *x : 0.0, bin ? *bin : 0u);
}

/* Draws and bins of 1D patterns; the outputs feed nothing (op_add makes trials). */
static void op_pattern(void)
{
    mcs_pattern *pat = obj_or_null(PAT);
    const unsigned which = byte() % 5u;
    const size_t n = size_any(), k = len_arg();
    const mcs_importance *imp = byte() % 2u ? obj_or_null(IMP) : NULL;
    mcs_rng *r = obj_or_null(RNG);
    const int with_x = byte() % 4u != 0u;
    begin("pattern");
    size_t *bins = which < 3 ? out(zout, k, sizeof(size_t)) : NULL;
    double *w = which < 3 ? out(dout[0], k, 8) : NULL, *x = which == 1 && with_x ? out(dout[1], k, 8) : NULL;
    mcs_status st;
    if (which == 0) {
        st = end(mcs_pattern_init(inout(PAT, pat), (mcs_pattern_kind)(byte() % 7u) - 1, n,
                                  byte() % 16u ? k : size_any(), reg(imp, imp ? sizeof *imp : 0u, 0u)));
        return;
    }
    if (which == 1) {
        reg(pat, pat ? sizeof *pat : 0u, 0u);
        st = end(mcs_pattern_draw(pat, inout(RNG, r), k, bins, w, x));
    } else if (which == 2) {
        const double *x2 = darray(2, k);
        const mcs_importance *ip = reg(imp, imp ? sizeof *imp : 0u, 0u);
        const float *xf = k % 2u ? reg(as_floats(x2, k), k * 4, 0) : NULL;
        st = end(xf != NULL ? mcs_pattern_bin_points_f(n, k, ip, xf, bins, w)
                            : mcs_pattern_bin_points(n, k, ip, reg(x2, k * 8, 0), bins, w));
    } else {
        const size_t nn = n <= MAXLEN ? n : 1u;
        double *s = out(dout[1], nn, 8);
        st = end(mcs_pattern_dense(n, k, reg(zarray(k, nn), k * sizeof(size_t), 0),
                                   reg(darray(0, k), k * 8, 0), s));
        vals(st, s, nn, 1);
        return;
    }
    vals(st, w, k, 1);
    for (size_t j = 0; st == MCS_OK && which == 1 && x != NULL && j < k; ++j)
        if (!(x[j] >= 0.0 && x[j] < 1.0))
            finding(0, cur_fn, "point %g outside [0, 1)", x[j]);
}

static double integrand(double x, void *ctx) { return x * *(const double *)ctx; }

/* mcs_estimate_points, or its float twin for odd k. */
static mcs_status estimate_points(size_t k, double *scale, double *v)
{
    mcs_estimate_integrand f = byte() % 16u ? integrand : NULL;
    const double *x = darray(2, k);
    const double *w = byte() % 4u ? reg(darray(1, k), k * 8, 0) : NULL;
    return k % 2u ? mcs_estimate_points_f(k, f, scale, reg(as_floats(x, k), k * 4, 0), w, v)
                  : mcs_estimate_points(k, f, scale, reg(x, k * 8, 0), w, v);
}

static void op_estimate(void)
{
    /* f[n] is read at every bin below n: n is a real length (no maximum to test). */
    const size_t n = len_arg(), k = len_arg(), nn = n;
    double scale = dbl();
    begin("estimate");
    double *v = out(dout[0], 1, 8);
    mcs_status st = byte() % 2u
                        ? mcs_estimate_bins(n, k, reg(darray(0, nn), nn * 8, 0),
                                            reg(zarray(k, nn), k * sizeof(size_t), 0),
                                            reg(darray(1, k), k * 8, 0), v)
                        : estimate_points(k, &scale, v);
    vals(end(st), v, 1, 0);
}

static void op_sampler_pattern2d(void)
{
    const unsigned which = byte() % 6u;
    mcs_sampler *smp = obj_or_null(SMP);
    mcs_pattern2d *p2 = obj_or_null(P2D);
    mcs_rng *r = obj_or_null(RNG);
    size_t k = len_arg() / 2u;
    const size_t a = size_any(), b = size_any();
    const int kind = (int)(byte() % (MCS_SAMPLER_KIND_COUNT + 2u)) - 1;
    begin(which < 3 ? "sampler" : "pattern2d");
    /* a sampler writes k dim doubles (dim up to MCS_SAMPLER_MAX_DIM): the
     * output holds that many, k cut so they fit (the call then refuses a k
     * that is not the sampler's) */
    const size_t dim = which < 3 && smp != NULL && smp->dim >= 1u &&
                               smp->dim <= MCS_SAMPLER_MAX_DIM ? smp->dim : 2u;
    if (k * dim > MAXLEN)
        k = MAXLEN / dim;
    double *pts = out(dout[0], k * dim, 8);
    mcs_status st = MCS_OK;
    switch (which) {
    case 0: end(mcs_sampler_init(inout(SMP, smp), (mcs_sampler_kind)kind, a, byte() % 8u ? k : b)); return;
    case 1: reg(smp, smp ? sizeof *smp : 0u, 0u); st = end(mcs_sampler_draw(smp, inout(RNG, r), k, pts)); break;
    case 2: reg(smp, smp ? sizeof *smp : 0u, 0u); st = end(mcs_sampler_base_points(smp, k, pts)); break;
    case 3: end(mcs_pattern2d_init(inout(P2D, p2), (mcs_pattern2d_kind)kind, byte() % 8u ? k : b, a % 16u, b % 16u)); return;
    case 4: reg(p2, p2 ? sizeof *p2 : 0u, 0u); st = end(mcs_pattern2d_draw(p2, inout(RNG, r), k, pts)); break;
    default: {
        const uint32_t l = (uint32_t)word(byte() % 3u), p = (uint32_t)word(4);
        const uint32_t i = (uint32_t)word(byte() % 3u), v = mcs_pattern2d_permute(i, l, p);
        if ((i < l && v >= l) || (i >= l && v != 0u))
            finding(101, "mcs_pattern2d_permute", "permute(%u, %u, %u) = %u", i, l, p, v);
        return;
    }
    }
    for (size_t j = 0; st == MCS_OK && j < k * dim; ++j)
        if (!(pts[j] >= 0.0 && pts[j] < 1.0))
            finding(0, cur_fn, "coordinate %g outside [0, 1)", pts[j]);
}

/* ---- plans, theory, closed forms, 2D ---- */

static void op_dft_autocorr(void)
{
    const unsigned which = byte() % 5u;
    mcs_dft *plan = obj_or_null(DFT);
    const mcs_autocorr *ac = obj_or_null(AC);
    const size_t n = size_any(), len = n <= MAXLEN ? n : 1u;
    begin(which < 3 ? "dft" : "autocorr read-out");
    double *re = out(dout[0], len, 8), *im = byte() % 4u ? out(dout[1], len, 8) : NULL;
    mcs_status st;
    switch (which) {
    case 0: st = end(byte() % 2u ? mcs_dft_init(inout(DFT, plan), n) : mcs_dft_check(plan, n)); return;
    case 1:
    case 2: {
        const double *s = reg(darray(0, len), len * 8, 0);
        st = end(which == 1 ? mcs_dft_real(inout(DFT, plan), n, s, re, im)
                            : mcs_dft_real_half(inout(DFT, plan), n, s, re, im));
        break;
    }
    case 3:
        reg(ac, ac ? sizeof *ac : 0u, 0u);
        st = end(mcs_autocorr_mean(ac, inout(DFT, plan), n, re, im ? im : dout[1]));
        break;
    default:
        reg(ac, ac ? sizeof *ac : 0u, 0u);
        st = end(mcs_autocorr_power(ac, inout(DFT, plan), n, re));
        vals(st, re, len, 1);
        return;
    }
    vals(st, re, which == 2 ? len / 2u + 1u : len, 0);
    if (im != NULL)
        vals(st, im, which == 2 ? len / 2u + 1u : len, 0);
}

/* Exact moments (N x N) or exact spectra (any N) of a pattern; the power
 * spectrum of the latter. */
static void op_theory_init(void)
{
    const unsigned which = byte() % 3u;
    void *th = obj_or_null(which == 0 ? TH : TS);
    const mcs_pattern *pat = obj_or_null(PAT);
    const size_t n = size_any(), len = n <= MAXLEN ? n : 1u;
    begin(which == 0 ? "mcs_theory_init" : which == 1 ? "mcs_theory_spectrum_init" : "mcs_theory_power_spectrum");
    if (which == 2) {
        double *power = out(dout[0], len, 8);
        reg(th, th ? sizeof(mcs_theory_spectrum) : 0u, 0u);
        vals(end(mcs_theory_power_spectrum(th, n, power)), power, len, 1);
        return;
    }
    reg(pat, pat ? sizeof *pat : 0u, 0u);
    end(which == 0 ? mcs_theory_init(inout(TH, th), pat) : mcs_theory_spectrum_init(inout(TS, th), pat));
}

/* A probe read-out of an accumulator, to compare an object with its reload. */
static mcs_status probe(int type, const void *o, size_t f, double *v)
{
    switch (type) {
    case WEL: return mcs_welford_variance(o, v);
    case SPEC: return mcs_spectrum_power(o, f, v);
    case MOM: return mcs_moment_power(o, f, v);
    case PS: return mcs_pointset_power(o, (long)f, v);
    case PS2: return mcs_pointset2d_radial(o, f, v);
    case S2: return mcs_spectrum2d_power(o, f, 0u, v);
    default: *v = 0.0; return MCS_OK; /* autocorr: its read-outs need a plan */
    }
}

/* Save an accumulator, load the record into the other object of its type:
 * a record save writes must load, and the loaded object must read out like
 * the saved one (io.h). */
static void op_save_load(void)
{
    static unsigned char rec[(1u << 18) + GUARD];
    const int type = acc_types[byte() % 7u];
    const unsigned i = byte();
    void *src = obj(type, i), *dst = obj(type, i + 1u);
    const size_t room = 1u << 18, cap = byte() % 8u ? room : size_any() % room, f = byte() % 8u;
    size_t *len = out(zout, 1, sizeof(size_t));
    begin("mcs_io_save");
    reg(src, obj_size[type], 0u);
    mcs_status st;
    switch (type) {
    case WEL: st = mcs_io_save_welford(src, cap, out(rec, cap, 1), len); break;
    case SPEC: st = mcs_io_save_spectrum(src, cap, out(rec, cap, 1), len); break;
    case MOM: st = mcs_io_save_moment(src, cap, out(rec, cap, 1), len); break;
    case AC: st = mcs_io_save_autocorr(src, cap, out(rec, cap, 1), len); break;
    case PS: st = mcs_io_save_pointset(src, cap, out(rec, cap, 1), len); break;
    case PS2: st = mcs_io_save_pointset2d(src, cap, out(rec, cap, 1), len); break;
    default: st = mcs_io_save_spectrum2d(src, cap, out(rec, cap, 1), len); break;
    }
    if (end(st) != MCS_OK)
        return;
    begin("mcs_io_load");
    reg(rec, *len, 0u);
    switch (type) {
    case WEL: st = mcs_io_load_welford(inout(type, dst), *len, rec); break;
    case SPEC: st = mcs_io_load_spectrum(inout(type, dst), *len, rec); break;
    case MOM: st = mcs_io_load_moment(inout(type, dst), *len, rec); break;
    case AC: st = mcs_io_load_autocorr(inout(type, dst), *len, rec); break;
    case PS: {
        fz_pointset *d = inout(type, dst);
        st = mcs_io_load_pointset(&d->acc, 0u, d->mem, sizeof d->mem, *len, rec);
        break;
    }
    case PS2: {
        fz_pointset2d *d = inout(type, dst);
        st = mcs_io_load_pointset2d(&d->acc, 0u, d->mem, sizeof d->mem, *len, rec);
        break;
    }
    default: {
        fz_spectrum2d *d = inout(type, dst);
        st = mcs_io_load_spectrum2d(&d->acc, d->mem, sizeof d->mem, *len, rec);
        break;
    }
    }
    if (end(st) != MCS_OK)
        finding(0, cur_fn, "a record save wrote does not load (%s)", mcs_status_str(st));
    double a = 0.0, b = 0.0;
    const mcs_status sa = probe(type, src, f, &a), sb = probe(type, dst, f, &b);
    if (sa != sb || (sa == MCS_OK && !(fabs(a - b) <= 1e-12 * fabs(a) + 1e-300)))
        finding(type == MOM ? 103 : 0, cur_fn, "read-out %zu: saved %.17g (%s), loaded %.17g (%s)", f,
                a, mcs_status_str(sa), b, mcs_status_str(sb));
}

/* Closed forms of eq.h without objects: (n, k, freq[, freq]) and (n, k, f). */
static void op_eq_plain(void)
{
    const size_t n = size_any(), k = size_any(), a = size_any(), b = size_any();
    const size_t len = n <= MAXLEN ? n : 1u;
    double *re = out(dout[0], 1, 8), *im = out(dout[1], 1, 8);
    const unsigned which = byte() % 15u;
    static const char *const names[15] = {
        "mcs_eq23_random_power", "mcs_eq31_stratified_delta_printed", "mcs_eq32_stratified_delta",
        "mcs_eq33_stratified_power_exact", "mcs_eq33_stratified_power_limit", "mcs_eq37_jitter_power",
        "mcs_eq30_stratified_delta_printed", "mcs_eq30_stratified_delta_corrected",
        "mcs_eq30_stratified_cross", "mcs_eq34_uniform_spectrum", "mcs_eq35_jitter_mean",
        "mcs_eq11_unbiased_mean", "mcs_eq14_variance", "mcs_eq24_random_variance",
        "mcs_eq25_random_variance"};
    begin(names[which]);
    const double *f = reg(darray(0, len), len * 8, 0), *g = reg(darray(1, len), len * 8, 0);
    mcs_status st;
    switch (which) {
    case 0: st = mcs_eq23_random_power(n, k, a, re); break;
    case 1: st = mcs_eq31_stratified_delta_printed(n, k, a, re); break;
    case 2: st = mcs_eq32_stratified_delta(n, k, a, re); break;
    case 3: st = mcs_eq33_stratified_power_exact(n, k, a, re); break;
    case 4: st = mcs_eq33_stratified_power_limit(n, k, a, re); break;
    case 5: st = mcs_eq37_jitter_power(n, k, a, re); break;
    case 6: st = mcs_eq30_stratified_delta_printed(n, k, a, b, re, im); break;
    case 7: st = mcs_eq30_stratified_delta_corrected(n, k, a, b, re, im); break;
    case 8: st = mcs_eq30_stratified_cross(n, k, a, b, re, im); break;
    case 9: st = mcs_eq34_uniform_spectrum(n, k, a, re, im); break;
    case 10: st = mcs_eq35_jitter_mean(n, k, a, re, im); break;
    case 11: st = mcs_eq11_unbiased_mean(n, f, re); break;
    case 12: st = mcs_eq14_variance(n, k, f, g, re); break;
    case 13: st = mcs_eq24_random_variance(n, k, f, re); break;
    default: st = mcs_eq25_random_variance(n, k, f, re); break;
    }
    vals(end(st), re, 1, which == 0 || which == 3 || which == 4 || which == 5 || which >= 13);
    if (which >= 6 && which <= 10)
        vals(st, im, 1, 0);
}

/* Closed forms of the importance section (eq. 41-58). */
static void op_eq_importance(void)
{
    const mcs_importance *imp = byte() % 16u ? obj(IMP, byte()) : NULL;
    const size_t k = size_any(), a = size_any(), b = size_any();
    const size_t len = imp != NULL && imp->n <= MAXLEN ? imp->n : 1u;
    double *re = out(dout[0], 1, 8), *im = out(dout[1], 1, 8);
    const unsigned which = byte() % 11u;
    static const char *const names[11] = {
        "mcs_eq41_importance_second", "mcs_eq43_importance_cross", "mcs_eq45_importance_power",
        "mcs_eq46_importance_power0", "mcs_eq49_importance_stratified_cross",
        "mcs_eq50_importance_stratified_power", "mcs_eq52_variance_printed",
        "mcs_eq52_variance_corrected", "mcs_eq55_variance_convolution", "mcs_eq58_bound_printed",
        "mcs_eq58_bound_corrected"};
    begin(names[which]);
    reg(imp, imp ? sizeof *imp : 0u, 0u);
    const double *f = reg(darray(0, len), len * 8, 0);
    mcs_status st;
    switch (which) {
    case 0: st = mcs_eq41_importance_second(imp, k, a, b, re); break;
    case 1: st = mcs_eq43_importance_cross(imp, k, a, b, re, im); break;
    case 2: st = mcs_eq45_importance_power(imp, k, a, re); break;
    case 3: st = mcs_eq46_importance_power0(imp, k, re); break;
    case 4: st = mcs_eq49_importance_stratified_cross(imp, k, a, b, re, im); break;
    case 5: st = mcs_eq50_importance_stratified_power(imp, k, a, re); break;
    case 6: st = mcs_eq52_variance_printed(imp, k, f, re); break;
    case 7: st = mcs_eq52_variance_corrected(imp, k, f, re); break;
    case 8: st = mcs_eq55_variance_convolution(imp, k, f, re); break;
    case 9: st = mcs_eq58_bound_printed(imp, k, f, re); break;
    default: st = mcs_eq58_bound_corrected(imp, k, f, re); break;
    }
    vals(end(st), re, 1, which == 0 || which == 2 || which == 3 || which == 7 || which >= 9);
    if (which == 1 || which == 4)
        vals(st, im, 1, 0);
}

/* The 2D spectrum's transform and variances, and the exact 2D and point-set read-outs. */
static void op_2d(void)
{
    const unsigned which = byte() % 9u;
    const mcs_spectrum2d *s2 = obj_or_null(S2);
    const mcs_pattern2d *p2 = obj_or_null(P2D);
    const size_t nx = size_any(), ny = size_any(), a = size_any(), b = size_any();
    const size_t plane = s2 != NULL && s2->n_x * s2->n_y <= MAXLEN ? s2->n_x * s2->n_y : 1u;
    const size_t eplane = nx <= 64u && ny <= 64u ? nx * ny : 1u, len = which < 2 ? plane : eplane;
    double *re = out(dout[0], which == 0 ? plane : 1u, 8), *im = out(dout[1], which == 0 ? plane : 1u, 8);
    const long fx = (long)word(byte() % 9u), fy = (long)word(byte() % 9u);
    begin("2d");
    reg(which < 2 ? (const void *)s2 : (const void *)p2, which < 2 ? (s2 ? sizeof *s2 : 0u) : (p2 ? sizeof *p2 : 0u), 0u);
    const double *f = reg(darray(0, len), len * 8, 0), *g = reg(darray(1, len), len * 8, 0);
    mcs_status st;
    switch (which) {
    case 0: st = mcs_spectrum2d_transform(s2, f, re, im); break;
    case 1: st = mcs_spectrum2d_variance14(s2, a, f, g, re); break;
    case 2: st = mcs_spectrum2d_exact_mean(p2, nx, ny, a, b, re, im); break;
    case 3: st = mcs_spectrum2d_exact_power(p2, nx, ny, a, b, re); break;
    case 4: st = mcs_spectrum2d_exact_covariance(p2, nx, ny, a, b, a % 7u, b % 5u, re, im); break;
    case 5: st = mcs_spectrum2d_exact_variance(p2, nx, ny, f, g, re); break;
    case 6: st = mcs_spectrum2d_exact_variance14(p2, nx, ny, f, g, re); break;
    case 7: st = mcs_pointset2d_exact_power(p2, fx, fy, re); break;
    default: st = mcs_pointset_exact_power((mcs_pattern_kind)(byte() % 7u) - 1, a, fx, re); break;
    }
    end(st);
    vals(st, re, which == 0 ? plane : 1u, which == 1 || which == 3 || which >= 5);
    if (which == 0 || which == 2 || which == 4)
        vals(st, im, which == 0 ? plane : 1u, 0);
}

/* Point-set read-outs at signed frequencies, the spectrum's path, and the
 * calls without a status (names, version, sampler helpers, ring size). */
static void op_misc(void)
{
    const unsigned which = byte() % 8u;
    const long fx = (long)word(byte() % 9u), fy = (long)word(byte() % 9u);
    const size_t a = size_any();
    const int e = (int)word(byte() % 5u);
    double *v = out(dout[0], 1, 8);
    begin("misc");
    mcs_status st = MCS_OK;
    switch (which) {
    case 0:
    case 1: {
        const mcs_pointset *ps = obj_or_null(PS);
        reg(ps, ps ? obj_size[PS] : 0u, 0u);
        st = end(which == 0 ? mcs_pointset_power(ps, fx, v) : mcs_pointset_power_stderr(ps, fx, v));
        break;
    }
    case 2:
    case 3: {
        const mcs_pointset2d *ps2 = obj_or_null(PS2);
        reg(ps2, ps2 ? obj_size[PS2] : 0u, 0u);
        st = end(which == 2 ? mcs_pointset2d_power(ps2, fx, fy, v)
                            : mcs_pointset2d_power_stderr(ps2, fx, fy, v));
        break;
    }
    case 4: {
        mcs_spectrum *sp = obj_or_null(SPEC);
        end(mcs_spectrum_set_path(inout(SPEC, sp), (mcs_spectrum_path)e));
        return;
    }
    case 5: {
        size_t *n = out(zout, 1, sizeof(size_t));
        end(mcs_pointset2d_ring_size(a, n));
        return;
    }
    case 6: {
        const char *names[5] = {mcs_status_str((mcs_status)e), mcs_pattern_kind_str((mcs_pattern_kind)e),
                                mcs_sampler_kind_str((mcs_sampler_kind)e),
                                mcs_pattern2d_kind_str((mcs_pattern2d_kind)e), mcs_version()};
        for (int i = 0; i < 5; ++i)
            if (names[i] == NULL || strlen(names[i]) > 64u)
                finding(0, "names", "a name function returned NULL or a long string");
        return;
    }
    default: {
        const int h = mcs_sampler_has_dim((mcs_sampler_kind)e, a);
        const uint32_t x = (uint32_t)word(4), seed = (uint32_t)word(4);
        const uint32_t r0 = mcs_sampler_owen_scramble(x, seed), r1 = mcs_sampler_owen_scramble(x ^ 0xFFFFu, seed);
        if (h != 0 && h != 1)
            finding(0, "mcs_sampler_has_dim", "returned %d", h);
        if ((r0 ^ r1) >> 16 != 0u)
            finding(0, "mcs_sampler_owen_scramble", "low bits changed the top 16 bits");
        return;
    }
    }
    vals(st, v, 1, 1);
}

#endif /* FUZZ_API_OPS_H */
