/* A renderer's pixel loop feeding its own samples to mcspec (issue 9).
 *
 * The samplers are written here as a renderer has them, not taken from
 * mcspec. Per pixel, K samples in three dimensions:
 *  - vdc-cp:     van der Corput (Halton base 2) by bit reversal, plus a
 *                per-pixel Cranley-Patterson offset from a pixel hash;
 *  - halton3-cp: Halton base 3, plus another per-pixel offset;
 *  - rng:        plain random from the renderer's own 32-bit generator.
 * Samples stay 0.32 fixed point up to the last step, (bits >> 8) 2^-24, so
 * the rotation is an exact wrapping add (mod 1) and every sample is exact in
 * float and in double; the buffer is float, as in a renderer. Each pixel's K
 * samples of one dimension are one trial: mcs_spectrum_add_points_f reads
 * them where the sampler wrote them, and mcs_estimate_points_f gives the
 * pixel's estimate of a 1D integrand: a
 * texture row of N texels looked up nearest, so the estimator is eq. 8's
 * binned one and mcspec's theory of it is exact.
 *
 * What each dimension reduces to: the first K = 2^m van der Corput points are
 * {j/K}, and {j/K + r} mod 1 = {(j + beta)/K} with beta = frac(K r): uniform
 * jitter, exactly. The generator is random. The first 2^m Halton base-3
 * points are no mcspec pattern: they are compared with jitter (what a
 * renderer might expect of a low-discrepancy dimension), and their exact
 * value is the average over the rotation of their fixed set,
 * mcs_theory_rotation (theory.h: with A_j = N a_j, the bin offset
 * n_j - n_j' of two rotated points is floor(D) or floor(D) + 1,
 * D = A_j - A_j', the latter with probability frac(D), and both read-outs
 * follow from that offset histogram). The same rotation average of the van
 * der Corput set must give mcspec's jitter theory: the example checks
 * that, two independent routes to the same exact numbers. */
#include "mcspec.h"
#include "measure.h"
#include "readout.h"
#include "report.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>

static const char help_text[] =
    "A renderer's pixel loop with its own samplers (issue 9): an image of T pixels,\n"
    "rows of 32, K samples per pixel in three dimensions, each written as a\n"
    "renderer writes it: van der Corput (bit reversal) and Halton base 3, each\n"
    "with a per-pixel Cranley-Patterson rotation from a pixel hash, and plain\n"
    "random from the renderer's own 32-bit generator. Each pixel's K samples of\n"
    "one dimension (float) are one trial for mcs_spectrum_add_points_f (read in\n"
    "place) and mcs_estimate_points_f, whose integrand is a texture row of N\n"
    "texels with the values of f(x) = 0.5 + 0.3 sin(2 pi x) + 0.4 [x >= 0.3]\n"
    "at the texel centres (nearest lookup). Printed per dimension: <|S_k|^2> at\n"
    "k in {1, K/2, K, K+1, 2K, N/2}, <I> and Var[I], beside the exact\n"
    "prediction of the pattern the dimension reduces to: a rotated van der Corput set of K = 2^m points is\n"
    "uniform jitter (closed: eq. 37, eq. 14 with eq. 37); random is random\n"
    "(closed: eq. 23, eq. 25). Halton base 3 with K = 2^m is not jitter: its\n"
    "closed column holds mcspec's exact jitter value (the comparison a renderer\n"
    "might make) and its exact column the rotation average of its fixed set,\n"
    "mcs_theory_rotation. --trials is the pixel count T, --k must be a\n"
    "power of 2, --n is the texture's texels and the spectrum's bins.\n";

#define WIDTH 32u   /* pixels per image row */
#define MAX_K 4096u /* samples per pixel */
#define SECTION "renderer"

enum { D_VDC, D_HALTON3, D_RANDOM, D_COUNT };
static const char *const dim_name[D_COUNT] = {"vdc-cp", "halton3-cp", "rng"};

/* The renderer's per-pixel sample buffer, in float as renderers keep it:
 * each dimension's K samples are contiguous, so one dimension of one pixel
 * is an array the _f calls read as is (no copy, no conversion pass). */
static float samples[D_COUNT][MAX_K];

static double texture[MCS_MAX_COV_N];  /* the integrand, one value per texel */
static mcs_spectrum spectrum[D_COUNT]; /* per dimension, pixels as trials */
static mcs_welford estimate[D_COUNT];  /* the pixel estimates I */
static mcs_theory jitter, random_th;   /* mcspec's exact moments */

/* <|S_freq|^2> from exact moments, EX_NA if the read-out fails. */
static double theory_power(const mcs_theory *th, size_t freq)
{
    double v = 0.0;
    return ex_or_na(mcs_theory_power(th, freq, &v), &v);
}
/* The rotation averages of the fixed vdc and halton3 sets (mcspec's exact
 * theory of a Cranley-Patterson rotated set), their h(d) in work. */
static mcs_theory_rotation rotation[2];
static double rotation_work[2][MCS_THEORY_ROTATION_LEN(MCS_MAX_COV_N)];
static double base_set[MAX_K];

/* The rotation average's <|S_freq|^2> and Var[I] of the texture, EX_NA if
 * the read-out fails. */
static double rotation_power(int s, size_t freq)
{
    double v = 0.0;
    return ex_or_na(mcs_theory_rotation_power(&rotation[s], freq, &v), &v);
}

static double rotation_variance(int s, size_t n, size_t k)
{
    double v = 0.0;
    return ex_or_na(mcs_theory_rotation_variance(&rotation[s], n, k, texture, &v), &v);
}

/* What the summary reads: per dimension the largest |z| against the closed
 * and the exact column, and the measured Var[I]; jitter's exact Var[I]. */
typedef struct {
    double z_closed[D_COUNT], z_exact[D_COUNT];
    double var_measured[D_COUNT], var_jitter;
} summary;

/* ---- the renderer's samplers ---- */

/* PCG's RXS-M-XS output permutation as a 32-bit hash (Jarzynski and Olano). */
static uint32_t pcg_hash(uint32_t v)
{
    uint32_t s = v * 747796405u + 2891336453u;
    uint32_t w = ((s >> ((s >> 28u) + 4u)) ^ s) * 277803737u;
    return (w >> 22u) ^ w;
}

static uint32_t hash2(uint32_t a, uint32_t b)
{
    return pcg_hash(a ^ pcg_hash(b));
}

/* The renderer's generator: an LCG step through the same permutation. */
static uint32_t tiny_next(uint32_t *state)
{
    *state = *state * 747796405u + 2891336453u;
    uint32_t s = *state;
    uint32_t w = ((s >> ((s >> 28u) + 4u)) ^ s) * 277803737u;
    return (w >> 22u) ^ w;
}

/* 0.32 fixed point to [0,1): the top 24 bits, exact in float (a 24-bit
 * integer times a power of 2), so widening it to double is exact too. */
static float unit(uint32_t bits)
{
    return (float)(bits >> 8u) * 0x1p-24f;
}

/* Radical inverse in base 2 as 0.32 fixed point: the bits of i reversed. */
static uint32_t vdc_bits(uint32_t i)
{
    i = (i << 16u) | (i >> 16u);
    i = ((i & 0x00ff00ffu) << 8u) | ((i & 0xff00ff00u) >> 8u);
    i = ((i & 0x0f0f0f0fu) << 4u) | ((i & 0xf0f0f0f0u) >> 4u);
    i = ((i & 0x33333333u) << 2u) | ((i & 0xccccccccu) >> 2u);
    return ((i & 0x55555555u) << 1u) | ((i & 0xaaaaaaaau) >> 1u);
}

/* Radical inverse in base 3 as 0.32 fixed point (truncated: r < 1, and the
 * scaling by 2^32 is exact, so the result fits). */
static uint32_t halton3_bits(uint32_t i)
{
    double r = 0.0, scale = 1.0 / 3.0;
    for (; i > 0u; i /= 3u, scale /= 3.0)
        r += (double)(i % 3u) * scale;
    return (uint32_t)(r * 4294967296.0);
}

/* One pixel's samples, dimension by dimension. The rotation is a wrapping
 * add of a hashed offset: addition mod 2^32 is addition mod 1. */
static void pixel_samples(uint32_t pixel_seed, size_t k)
{
    uint32_t rot_vdc = hash2(pixel_seed, 0x9e3779b9u);
    uint32_t rot_h3 = hash2(pixel_seed, 0x7f4a7c15u);
    uint32_t rng = hash2(pixel_seed, 0x85ebca6bu);
    for (uint32_t j = 0; j < (uint32_t)k; ++j) {
        samples[D_VDC][j] = unit(vdc_bits(j) + rot_vdc);
        samples[D_HALTON3][j] = unit(halton3_bits(j) + rot_h3);
        samples[D_RANDOM][j] = unit(tiny_next(&rng));
    }
}

/* The integrand as the renderer shades it: a nearest texel lookup, the
 * index clamped below n as a texture unit does (x n may round up to n). */
static double texel(double x, void *ctx)
{
    const size_t n = *(const size_t *)ctx;
    size_t t = (size_t)(x * (double)n);
    return texture[t < n ? t : n - 1u];
}

/* ---- the pixel loop ---- */

/* Renders the image: per pixel, its samples, then each dimension's K samples
 * to mcspec as one trial and the pixel's estimate to a Welford accumulator. */
static mcs_status render(const ex_options *opt)
{
    const uint32_t frame = (uint32_t)(opt->seed ^ (opt->seed >> 32u));
    size_t texels = opt->n;
    mcs_status st = MCS_OK;
    for (int d = 0; d < D_COUNT && st == MCS_OK; ++d) {
        st = mcs_spectrum_init(&spectrum[d], opt->n);
        if (st == MCS_OK)
            st = mcs_welford_init(&estimate[d]);
    }
    for (unsigned long p = 0; p < opt->trials && st == MCS_OK; ++p) {
        uint32_t px = (uint32_t)(p % WIDTH), py = (uint32_t)(p / WIDTH);
        pixel_samples(hash2(px, hash2(py, frame)), opt->k);
        for (int d = 0; d < D_COUNT && st == MCS_OK; ++d) {
            double pixel_value = 0.0;
            st = mcs_spectrum_add_points_f(&spectrum[d], opt->k, samples[d], NULL);
            if (st == MCS_OK)
                st = mcs_estimate_points_f(opt->k, texel, &texels, samples[d], NULL,
                                           &pixel_value);
            if (st == MCS_OK)
                st = mcs_welford_add(&estimate[d], pixel_value);
        }
    }
    return st;
}

/* ---- predictions ---- */

/* mcspec's theory of jitter and random, and of the two rotated sets
 * (their unrotated points from the samplers above). */
static mcs_status predict(const ex_options *opt)
{
    mcs_pattern pat;
    ex_integrand_bins(opt->n, texture);
    mcs_status st = mcs_pattern_init(&pat, MCS_PATTERN_JITTER, opt->n, opt->k, NULL);
    if (st == MCS_OK)
        st = mcs_theory_init(&jitter, &pat);
    if (st == MCS_OK)
        st = mcs_pattern_init(&pat, MCS_PATTERN_RANDOM, opt->n, opt->k, NULL);
    if (st == MCS_OK)
        st = mcs_theory_init(&random_th, &pat);
    for (int s = 0; s < 2 && st == MCS_OK; ++s) {
        for (uint32_t j = 0; j < (uint32_t)opt->k; ++j)
            base_set[j] = (double)unit(s == 0 ? vdc_bits(j) : halton3_bits(j));
        st = mcs_theory_rotation_init(&rotation[s], opt->n, opt->k, base_set,
                                      rotation_work[s], MCS_THEORY_ROTATION_LEN(MCS_MAX_COV_N));
    }
    return st;
}

/* ---- table sections ---- */

/* Prints a row and keeps the largest |z| of dimension d. */
static void print_row(const ex_options *opt, summary *sum, int d, const ex_row *r)
{
    ex_row_print(opt, r);
    double zc = fabs(ex_z(r->measured, r->closed_form, r->stderr_, r->abs_floor));
    double ze = fabs(ex_z(r->measured, r->exact, r->stderr_, r->abs_floor));
    if (!isnan(zc))
        sum->z_closed[d] = fmax(sum->z_closed[d], zc);
    if (!isnan(ze))
        sum->z_exact[d] = fmax(sum->z_exact[d], ze);
}

static void spectrum_section(const ex_options *opt, summary *sum)
{
    const size_t n = opt->n, k = opt->k;
    const size_t cand[6] = {1u, k / 2u, k, k + 1u, 2u * k, n / 2u};
    size_t freqs[6];
    size_t nfreq = ex_pick_freqs(n, cand, 6u, freqs);
    const double floor_ = 1e-10 * (double)k * (double)k / (double)n;
    ex_heading(opt, "power spectra <|S_k|^2> per sampler dimension, pixels as trials");
    for (int d = 0; d < D_COUNT; ++d)
        for (size_t i = 0; i < nfreq; ++i) {
            size_t q = freqs[i];
            double v = 0.0, closed, exact, se;
            double meas = ex_spectrum_power(&spectrum[d], q, &se);
            const char *eq = "eq. 37";
            if (d == D_VDC) {
                closed = ex_or_na(mcs_eq37_jitter_power(n, k, q, &v), &v);
                exact = theory_power(&jitter, q);
            } else if (d == D_RANDOM) {
                eq = "eq. 23";
                closed = ex_or_na(mcs_eq23_random_power(n, k, q, &v), &v);
                exact = theory_power(&random_th, q);
            } else {
                eq = "as jitter";
                closed = theory_power(&jitter, q);
                exact = rotation_power(1, q);
            }
            ex_row r = ex_row_of(SECTION, "<|S_k|^2>", eq, dim_name[d], (long)q, EX_NO_FREQ,
                                 closed, exact, meas, se, floor_);
            print_row(opt, sum, d, &r);
        }
}

static void estimator_section(const ex_options *opt, summary *sum)
{
    const size_t n = opt->n, k = opt->k;
    double pw[MCS_MAX_COV_N] = {0.0}, v = 0.0, fbar = 0.0;
    int ok37 = mcs_eq11_unbiased_mean(n, texture, &fbar) == MCS_OK;
    for (size_t q = 1; q < n && ok37; ++q)
        ok37 = mcs_eq37_jitter_power(n, k, q, &pw[q]) == MCS_OK;
    double eq14 = ok37 ? ex_or_na(mcs_eq14_variance(n, k, texture, pw, &v), &v) : EX_NA;
    double eq25 = ex_or_na(mcs_eq25_random_variance(n, k, texture, &v), &v);
    double var_jitter = ex_or_na(mcs_theory_variance(&jitter, n, k, texture, &v), &v);
    double var_random = ex_or_na(mcs_theory_variance(&random_th, n, k, texture, &v), &v);
    double mean_jitter = ex_or_na(mcs_theory_estimator_mean(&jitter, n, k, texture, &v), &v);
    double mean_random = ex_or_na(mcs_theory_estimator_mean(&random_th, n, k, texture, &v), &v);
    const double closed_var[D_COUNT] = {eq14, var_jitter, eq25};
    const double exact_var[D_COUNT] = {var_jitter, rotation_variance(1, n, k), var_random};
    const double exact_mean[D_COUNT] = {mean_jitter, fbar, mean_random};
    const char *const eq_var[D_COUNT] = {"eq. 14+37", "as jitter", "eq. 25"};
    ex_heading(opt, "the pixel estimate I = (1/K) sum_j f(x_j): mean (eq. 11) and variance");
    for (int d = 0; d < D_COUNT; ++d) {
        double se, meas = ex_mean(&estimate[d], &se);
        ex_row r = ex_row_of(SECTION, "<I>", "eq. 11", dim_name[d], EX_NO_FREQ, EX_NO_FREQ, fbar,
                             exact_mean[d], meas, se, 1e-12);
        print_row(opt, sum, d, &r);
        meas = ex_variance(&estimate[d], &se);
        sum->var_measured[d] = meas;
        r = ex_row_of(SECTION, "Var[I]", eq_var[d], dim_name[d], EX_NO_FREQ, EX_NO_FREQ,
                      closed_var[d], exact_var[d], meas, se, 1e-12);
        print_row(opt, sum, d, &r);
    }
    sum->var_jitter = var_jitter;
}

/* The rotation-average formula on the van der Corput set against mcspec's
 * jitter theory: two independent routes to the same exact numbers. */
static void check_section(const ex_options *opt)
{
    const size_t n = opt->n, k = opt->k;
    double worst = 0.0, v = 0.0;
    for (size_t q = 0; q < n; ++q)
        worst = fmax(worst, fabs(rotation_power(0, q) - theory_power(&jitter, q)));
    double vj = ex_or_na(mcs_theory_variance(&jitter, n, k, texture, &v), &v);
    double gap_var = ex_rel_gap(rotation_variance(0, n, k), vj, 1e-300);
    ex_heading(opt, "check: the rotation average of the fixed van der Corput set is jitter");
    ex_notef(opt,
             "over all k, |rotation average - mcspec jitter theory| <= %.2g K^2/N in "
             "<|S_k|^2>; relative gap %.2g in Var[I]",
             worst / ((double)k * (double)k / (double)n), gap_var);
}

static void summary_section(const ex_options *opt, const summary *sum)
{
    ex_heading(opt, "summary (computed from the rows above)");
    for (int d = 0; d < D_COUNT; ++d) {
        const char *against = d == D_HALTON3 ? "its rotation average" : d == D_VDC ? "jitter"
                                                                                   : "random";
        ex_notef(opt, "%-10s largest |z| against %s: %.2f (%s)", dim_name[d], against,
                 sum->z_exact[d], sum->z_exact[d] <= EX_Z_REJECT ? "agrees" : "DISAGREES");
    }
    ex_notef(opt,
             "halton3-cp is not jitter: largest |z| against jitter %.1f (%s at %.0f stderr)",
             sum->z_closed[D_HALTON3],
             sum->z_closed[D_HALTON3] > EX_Z_REJECT ? "separated" : "not separated",
             EX_Z_REJECT);
    if (sum->var_jitter > 0.0)
        ex_notef(opt, "halton3-cp's measured Var[I] %.3g is %.3g times jitter's exact %.3g",
                 sum->var_measured[D_HALTON3], sum->var_measured[D_HALTON3] / sum->var_jitter,
                 sum->var_jitter);
    else
        ex_notef(opt, "halton3-cp's measured Var[I] %.3g; jitter's exact is %.3g",
                 sum->var_measured[D_HALTON3], sum->var_jitter);
}

/* --k must be a power of 2: only then is the rotated van der Corput set jitter. */
static int k_is_power_of_two(const char *prog, size_t k)
{
    if ((k & (k - 1u)) == 0u)
        return 1;
    fprintf(stderr, "%s: --k must be a power of 2 (got %zu)\n\nusage: %s [options] (--help)\n",
            prog, k, prog);
    return 0;
}

int main(int argc, char **argv)
{
    ex_options opt = {64u, 16u, WIDTH * WIDTH, 1u, 0};
    int rc = ex_parse_options(argc, argv, &opt, MCS_MAX_COV_N, MAX_K, help_text);
    if (rc != EX_PARSE_OK)
        return rc;
    if (!k_is_power_of_two(argv[0], opt.k))
        return EX_PARSE_ERROR;
    mcs_status st = predict(&opt);
    if (st == MCS_OK)
        st = render(&opt);
    if (st != MCS_OK) {
        fprintf(stderr, "%s: %s\n", argv[0], mcs_status_str(st));
        return 1;
    }
    summary sum = {{0.0}, {0.0}, {0.0}, 0.0};
    ex_begin(&opt, "A renderer's own samplers, pixels as trials (issue 9)");
    ex_notef(&opt, "%lu pixels (rows of %u), K = %zu samples per pixel, N = %zu bins and texels",
             opt.trials, WIDTH, opt.k, opt.n);
    spectrum_section(&opt, &sum);
    estimator_section(&opt, &sum);
    check_section(&opt);
    summary_section(&opt, &sum);
    ex_end(&opt);
    return 0;
}
