/* Tests of utk's integrand families, blinn_phong and gaussian_mixture
 * (integrand.h), against independent references: the integrals I and
 * Q = int f^2 kept by the draw against composite Gauss-Legendre sums over
 * fine grids that never use the library's quadrature (the mixture through
 * mcs_integrand_eval on a grid whose lines hold every box edge, so each
 * cell is smooth; the Blinn-Phong lobe in the area form over the quad light
 * itself, int fr cos cos_q / r^2 dA, with a grid line on the horizon, which
 * checks the spherical-rectangle map too); a plain midpoint sum of the
 * Blinn-Phong estimate over [0,1)^2; the MSE of random sets against
 * Var[f] / K in standard errors, with a check that 10 % off would fail;
 * the draw's ranges, reproducibility and refusals. */
#include "mcspec.h"
#include "unity.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define PI 3.14159265358979323846
#define GL_N 10

static double gl_x[GL_N], gl_w[GL_N]; /* Gauss-Legendre on [-1, 1], by Newton */

static void gl_nodes(void)
{
    for (int i = 0; i < GL_N; ++i) {
        double x = cos(PI * (i + 0.75) / (GL_N + 0.5)), dp = 1.0;
        for (int it = 0; it < 100; ++it) {
            double p0 = 1.0, p1 = x;
            for (int n = 2; n <= GL_N; ++n) {
                const double p2 = ((2.0 * n - 1.0) * x * p1 - (n - 1.0) * p0) / n;
                p0 = p1;
                p1 = p2;
            }
            dp = GL_N * (x * p1 - p0) / (x * x - 1.0);
            const double dx = p1 / dp;
            x -= dx;
            if (fabs(dx) < 1e-16)
                break;
        }
        gl_x[i] = x;
        gl_w[i] = 2.0 / ((1.0 - x * x) * dp * dp);
    }
}

static mcs_integrand draw(mcs_integrand_family fam, size_t dim, mcs_rng *rng)
{
    mcs_integrand f;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrand_draw(&f, fam, dim, rng));
    return f;
}

static void moments(const mcs_integrand *f, double *i1, double *q)
{
    double v;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrand_integral(f, i1));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrand_variance(f, &v));
    *q = v + *i1 * *i1;
}

/* ---- gaussian_mixture: the grid on the box edges ---------------------------------- */

static int cmp_d(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* The nodes and weights of a composite rule on [0, 1] over the cuts (sorted),
 * each piece split in `split`. Returns the count. */
static size_t axis_rule(double *cuts, size_t nc, int split, double *x, double *w)
{
    qsort(cuts, nc, sizeof *cuts, cmp_d);
    size_t n = 0;
    for (size_t c = 0; c + 1 < nc; ++c)
        for (int s = 0; s < split; ++s) {
            const double a = cuts[c] + (cuts[c + 1] - cuts[c]) * s / split;
            const double b = cuts[c] + (cuts[c + 1] - cuts[c]) * (s + 1) / split;
            if (!(b > a))
                continue;
            for (int i = 0; i < GL_N; ++i) {
                x[n] = 0.5 * (a + b) + 0.5 * (b - a) * gl_x[i];
                w[n++] = 0.5 * (b - a) * gl_w[i];
            }
        }
    return n;
}

static double ax[4000], aw[4000], bx[4000], bw[4000];

static void mixture_grid(const mcs_integrand *f, double *i1, double *q)
{
    double cx[20] = {0.0, 1.0}, cy[20] = {0.0, 1.0};
    size_t n = 2;
    for (size_t b = 0; b < f->boxes; ++b, n += 2) {
        cx[n] = f->box_lo[b][0];
        cx[n + 1] = f->box_hi[b][0];
        cy[n] = f->box_lo[b][1];
        cy[n + 1] = f->box_hi[b][1];
    }
    const size_t nx = axis_rule(cx, n, f->dim == 1u ? 64 : 4, ax, aw);
    const size_t ny = f->dim == 1u ? 1u : axis_rule(cy, n, 4, bx, bw);
    double s = 0.0, s2 = 0.0;
    for (size_t i = 0; i < nx; ++i)
        for (size_t j = 0; j < ny; ++j) {
            const double p[2] = {ax[i], f->dim == 1u ? 0.0 : bx[j]};
            const double w = aw[i] * (f->dim == 1u ? 1.0 : bw[j]);
            double v;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrand_eval(f, p, &v));
            s += w * v;
            s2 += w * v * v;
        }
    *i1 = s;
    *q = s2;
}

static void test_mixture_integrals_match_a_grid_on_the_box_edges(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 25u, 1u);
    double worst = 0.0;
    for (size_t d = 1; d <= 2; ++d)
        for (int t = 0; t < (d == 1u ? 20 : 4); ++t) {
            const mcs_integrand f = draw(MCS_INTEGRAND_GAUSSIAN_MIXTURE, d, &rng);
            double i1, q, gi, gq;
            moments(&f, &i1, &q);
            mixture_grid(&f, &gi, &gq);
            const double e = fmax(fabs(i1 - gi) / gi, fabs(q - gq) / gq);
            worst = fmax(worst, e);
            TEST_ASSERT_TRUE_MESSAGE(e < 1e-12, "gaussian_mixture I or Q off the grid by 1e-12");
        }
    printf("gaussian_mixture: I and Q against the grid, largest relative error %.2e\n", worst);
}

/* ---- blinn_phong: the area form over the quad ------------------------------------- */

/* At the quad point (x, 0, z) seen from p: fr(o, l) cos(l) and the solid angle
 * per area, cos_q / r^2 = |p_y| / r^3 (the quad's normal is e_y). */
static void area_point(const mcs_integrand *f, double x, double z, double *lobe, double *jac)
{
    const double *p = f->shading, *o = f->view;
    const double lx = x - p[0], ly = -p[1], lz = z - p[2];
    const double r = sqrt(lx * lx + ly * ly + lz * lz);
    *jac = -p[1] / (r * r * r);
    *lobe = 0.0;
    if (lz <= 0.0)
        return;
    const double hx = o[0] + lx / r, hy = o[1] + ly / r, hz = o[2] + lz / r;
    const double ch = hz / sqrt(hx * hx + hy * hy + hz * hz);
    if (ch <= 0.0)
        return;
    const double a = f->exponent;
    *lobe = (a + 8.0) / (8.0 * PI) * pow(ch, a) * (lz / r);
}

/* Adaptive Gauss-Legendre (the test's own): a panel is kept when its rule
 * and the sum over its halves agree to tol. */
typedef double (*fn1)(void *ctx, double x);

static double gl_panel(fn1 fn, void *ctx, double a, double b)
{
    double s = 0.0;
    for (int i = 0; i < GL_N; ++i)
        s += gl_w[i] * fn(ctx, 0.5 * (a + b) + 0.5 * (b - a) * gl_x[i]);
    return 0.5 * (b - a) * s;
}

static double gl_adapt(fn1 fn, void *ctx, double a, double b, double whole, double tol, int depth)
{
    const double m = 0.5 * (a + b), l = gl_panel(fn, ctx, a, m), r = gl_panel(fn, ctx, m, b);
    if (depth >= 30 || fabs(l + r - whole) <= tol)
        return l + r;
    return gl_adapt(fn, ctx, a, m, l, tol, depth + 1) + gl_adapt(fn, ctx, m, b, r, tol, depth + 1);
}

typedef struct {
    const mcs_integrand *f;
    double x, tol;
    int what; /* 0: the solid angle, 1: fr cos, 2: (fr cos)^2, per d omega */
} area_ctx;

static double area_z(void *ctx, double z)
{
    const area_ctx *c = ctx;
    double lobe, jac;
    area_point(c->f, c->x, z, &lobe, &jac);
    return jac * (c->what == 0 ? 1.0 : c->what == 1 ? lobe : lobe * lobe);
}

static double area_x(void *ctx, double x)
{
    area_ctx *c = ctx;
    c->x = x;
    const double pz = c->f->shading[2], lo = c->what == 0 ? 0.0 : fmax(pz, 0.0);
    double s = 0.0;
    if (c->what == 0 && pz > 0.0 && pz < 1.0) /* the solid angle below the horizon too */
        s += gl_adapt(area_z, c, 0.0, pz, gl_panel(area_z, c, 0.0, pz), c->tol, 0);
    const double a = c->what == 0 && pz > 0.0 && pz < 1.0 ? pz : lo;
    if (a < 1.0)
        s += gl_adapt(area_z, c, a, 1.0, gl_panel(area_z, c, a, 1.0), c->tol, 0);
    return s;
}

static double area_integral(const mcs_integrand *f, int what, double scale)
{
    area_ctx c = {f, 0.0, 1e-15 * scale, what};
    return gl_adapt(area_x, &c, -1.0, 1.0, gl_panel(area_x, &c, -1.0, 1.0), 1e-14 * scale, 0);
}

static void blinn_area(const mcs_integrand *f, double i1, double q, double *ai, double *aq)
{
    const double omega = area_integral(f, 0, f->frame[0]);
    *ai = area_integral(f, 1, i1);       /* int fr cos d omega = int over [0,1)^2 of S fr cos */
    *aq = omega * area_integral(f, 2, q / omega); /* int (S fr cos)^2 du = S int (fr cos)^2 d omega */
}

static void test_blinn_phong_integrals_match_the_area_form_over_the_quad(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 25u, 2u);
    double worst = 0.0;
    for (int t = 0; t < 8; ++t) {
        const mcs_integrand f = draw(MCS_INTEGRAND_BLINN_PHONG, 2u, &rng);
        double i1, q, ai, aq;
        moments(&f, &i1, &q);
        blinn_area(&f, i1, q, &ai, &aq);
        const double e = fmax(fabs(i1 - ai) / ai, fabs(q - aq) / aq);
        worst = fmax(worst, e);
        TEST_ASSERT_TRUE_MESSAGE(e < 1e-12, "blinn_phong I or Q off the area form by 1e-12");
    }
    printf("blinn_phong: I and Q against the area form, largest relative error %.2e\n", worst);
}

/* The estimate itself, as the points see it: a midpoint sum over [0,1)^2. */
static void test_blinn_phong_midpoint_sum_of_the_estimate_is_its_integral(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 25u, 3u);
    enum { G = 600 };
    for (int t = 0; t < 3; ++t) {
        const mcs_integrand f = draw(MCS_INTEGRAND_BLINN_PHONG, 2u, &rng);
        double i1, q, s = 0.0, s2 = 0.0;
        moments(&f, &i1, &q);
        for (int i = 0; i < G; ++i)
            for (int j = 0; j < G; ++j) {
                const double p[2] = {(i + 0.5) / G, (j + 0.5) / G};
                double v;
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrand_eval(&f, p, &v));
                s += v;
                s2 += v * v;
            }
        s /= (double)G * G;
        s2 /= (double)G * G;
        /* O(h^2) with h = 1/600: 1e-5 to 1e-4 (the lobe can be sharp) */
        TEST_ASSERT_DOUBLE_WITHIN(5e-4 * i1, i1, s);
        TEST_ASSERT_DOUBLE_WITHIN(5e-4 * q, q, s2);
    }
}

/* ---- The MSE of random sets ------------------------------------------------------- */

static void random_mse(mcs_integrand_family fam, size_t dim, uint64_t seed, int T)
{
    enum { M = 4, K = 16 };
    mcs_rng rng;
    mcs_rng_seed(&rng, seed, 4u);
    mcs_integrand fs[M];
    for (int i = 0; i < M; ++i)
        fs[i] = draw(fam, dim, &rng);
    mcs_integrate acc;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrate_init(&acc, fam, dim));
    double pts[K * 2];
    for (int t = 0; t < T; ++t) {
        for (size_t j = 0; j < K * dim; ++j)
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_double(&rng, &pts[j]));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrate_add(&acc, M, fs, K, pts,
                                                        MCS_INTEGRATE_RANDOM, 0u, 0u));
    }
    double mse, se, ex;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrate_mse(&acc, &mse));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrate_mse_stderr(&acc, &se));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrate_exact(&acc, &ex));
    const double z = (mse - ex) / se;
    printf("%s %zuD, K = %d, %d sets: mse %.5g exact %.5g z %.2f; at Var 10 %% off: z %.1f, %.1f\n",
           mcs_integrand_family_str(fam), dim, K, T, mse, ex, z, (mse - 1.1 * ex) / se,
           (mse - 0.9 * ex) / se);
    TEST_ASSERT_TRUE(fabs(z) < 5.0);
    TEST_ASSERT_TRUE(fabs(mse - 1.1 * ex) > 5.0 * se); /* the bound sees a 10 % error */
    TEST_ASSERT_TRUE(fabs(mse - 0.9 * ex) > 5.0 * se);
}

static void test_random_sets_have_mse_var_over_k_within_5_standard_errors(void)
{
    random_mse(MCS_INTEGRAND_BLINN_PHONG, 2u, 31u, 12000); /* the heavier tail */
    random_mse(MCS_INTEGRAND_GAUSSIAN_MIXTURE, 2u, 32u, 6000);
    random_mse(MCS_INTEGRAND_GAUSSIAN_MIXTURE, 1u, 33u, 6000);
}

/* ---- The 1D mixture's stratified (jittered) MSE ------------------------------------ */

/* sum over the m cells of K int_C f^2 - (K int_C f)^2, over K^2, each cell's
 * integrals by 10-point Gauss-Legendre on its pieces between box edges. */
static double strata_reference(const mcs_integrand *f, size_t m)
{
    double sum = 0.0;
    for (size_t a = 0; a < m; ++a) {
        double cuts[20] = {(double)a / m, (a + 1.0) / m};
        size_t n = 2;
        for (size_t b = 0; b < f->boxes; ++b)
            for (int e = 0; e < 2; ++e) {
                const double x = e ? f->box_hi[b][0] : f->box_lo[b][0];
                if (x > cuts[0] && x < cuts[1])
                    cuts[n++] = x;
            }
        const size_t nx = axis_rule(cuts, n, 2, ax, aw);
        double i1 = 0.0, j = 0.0;
        for (size_t i = 0; i < nx; ++i) {
            const double p[1] = {ax[i]};
            double v;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrand_eval(f, p, &v));
            i1 += aw[i] * v;
            j += aw[i] * v * v;
        }
        const double k = (double)m, var = k * j - (k * i1) * (k * i1);
        sum += var > 0.0 ? var : 0.0;
    }
    return sum / ((double)m * (double)m);
}

static void test_mixture_1d_stratified_mse_matches_cells_and_sets(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 25u, 5u);
    double worst = 0.0;
    for (int t = 0; t < 6; ++t) {
        const mcs_integrand f = draw(MCS_INTEGRAND_GAUSSIAN_MIXTURE, 1u, &rng);
        const size_t ms[3] = {1u, 7u, 64u};
        for (int i = 0; i < 3; ++i) {
            double v;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrand_jittered_mse(&f, ms[i], 1u, &v));
            const double r = strata_reference(&f, ms[i]);
            worst = fmax(worst, fabs(v - r) / r);
            TEST_ASSERT_DOUBLE_WITHIN(1e-10 * r, r, v);
        }
        double var;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrand_variance(&f, &var));
        double one;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrand_jittered_mse(&f, 1u, 1u, &one));
        TEST_ASSERT_DOUBLE_WITHIN(1e-12 * var, var, one); /* one stratum: random */
    }
    /* stratified sets of K = 16 against it, and 10 % off seen */
    enum { M = 4, K = 16, T = 6000 };
    mcs_integrand fs[M];
    for (int i = 0; i < M; ++i)
        fs[i] = draw(MCS_INTEGRAND_GAUSSIAN_MIXTURE, 1u, &rng);
    mcs_integrate acc;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrate_init(&acc, MCS_INTEGRAND_GAUSSIAN_MIXTURE, 1u));
    double pts[K];
    for (int t = 0; t < T; ++t) {
        for (int j = 0; j < K; ++j) {
            double u;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_double(&rng, &u));
            pts[j] = (j + u) / K;
            if (pts[j] >= 1.0)
                pts[j] = nextafter(1.0, 0.0);
        }
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrate_add(&acc, M, fs, K, pts,
                                                        MCS_INTEGRATE_JITTERED, K, 1u));
    }
    double mse, se, ex;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrate_mse(&acc, &mse));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrate_mse_stderr(&acc, &se));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrate_exact(&acc, &ex));
    printf("gaussian_mixture 1D strata: cells against quadrature %.2e; K = %d, %d sets: mse %.5g "
           "exact %.5g z %.2f; 10 %% off: z %.1f, %.1f\n", worst, K, T, mse, ex, (mse - ex) / se,
           (mse - 1.1 * ex) / se, (mse - 0.9 * ex) / se);
    TEST_ASSERT_TRUE(fabs(mse - ex) < 5.0 * se);
    TEST_ASSERT_TRUE(fabs(mse - 1.1 * ex) > 5.0 * se);
    TEST_ASSERT_TRUE(fabs(mse - 0.9 * ex) > 5.0 * se);
}

/* ---- Draws and refusals ---------------------------------------------------------------- */

static void test_draws_are_reproducible_in_range_and_blinn_phong_is_2d_only(void)
{
    TEST_ASSERT_EQUAL_INT(0, mcs_integrand_has_dim(MCS_INTEGRAND_BLINN_PHONG, 1u));
    TEST_ASSERT_EQUAL_INT(1, mcs_integrand_has_dim(MCS_INTEGRAND_BLINN_PHONG, 2u));
    TEST_ASSERT_EQUAL_INT(1, mcs_integrand_has_dim(MCS_INTEGRAND_GAUSSIAN_MIXTURE, 1u));
    TEST_ASSERT_EQUAL_INT(0, mcs_integrand_has_dim(MCS_INTEGRAND_FAMILIES, 2u));
    TEST_ASSERT_EQUAL_STRING("blinn_phong", mcs_integrand_family_str(MCS_INTEGRAND_BLINN_PHONG));
    TEST_ASSERT_EQUAL_STRING("gaussian_mixture",
                             mcs_integrand_family_str(MCS_INTEGRAND_GAUSSIAN_MIXTURE));
    mcs_rng a, b;
    mcs_rng_seed(&a, 9u, 1u);
    b = a;
    mcs_integrand f;
    memset(&f, 0x5a, sizeof f);
    const mcs_integrand g0 = f;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_integrand_draw(&f, MCS_INTEGRAND_BLINN_PHONG, 1u, &a));
    TEST_ASSERT_EQUAL_MEMORY(&g0, &f, sizeof f);
    TEST_ASSERT_EQUAL_MEMORY(&b, &a, sizeof a);
    size_t seen[9] = {0};
    for (int t = 0; t < 200; ++t) {
        const mcs_integrand_family fam = t & 1 ? MCS_INTEGRAND_BLINN_PHONG
                                               : MCS_INTEGRAND_GAUSSIAN_MIXTURE;
        const size_t d = t & 1 ? 2u : 1u + (size_t)(t & 2) / 2u;
        const mcs_integrand x = draw(fam, d, &a), y = draw(fam, d, &b);
        TEST_ASSERT_EQUAL_MEMORY(&x, &y, sizeof x);
        TEST_ASSERT_TRUE(x.error < 1e-12); /* the quadrature's estimate */
        if (fam == MCS_INTEGRAND_BLINN_PHONG) {
            TEST_ASSERT_TRUE(x.shading[1] <= -0.01 && x.view[0] >= 0.0 && x.view[1] <= 0.0);
            TEST_ASSERT_TRUE(x.exponent >= 10.0 && x.exponent <= 100.0);
            TEST_ASSERT_TRUE(x.integral > 0.0);
        } else {
            TEST_ASSERT_TRUE(x.boxes >= 2u * d && x.boxes <= 2u * d * d);
            seen[x.boxes]++;
        }
        double v;
        TEST_ASSERT_EQUAL_INT(0, mcs_integrand_is_periodic(fam));
        TEST_ASSERT_EQUAL_INT(d == 2u ? MCS_ERR_DOMAIN : MCS_OK, /* 1D mixture: by erf */
                              mcs_integrand_jittered_mse(&x, 2u, d == 2u ? 2u : 1u, &v));
        TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_integrand_power(&x, 1, 0, &v));
    }
    for (size_t n = 4; n <= 8; ++n)
        TEST_ASSERT_TRUE(seen[n] > 0u); /* every box count of 2D is drawn */
}

static void test_a_tampered_integrand_is_refused_and_writes_nothing(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 10u, 1u);
    const mcs_integrand bp = draw(MCS_INTEGRAND_BLINN_PHONG, 2u, &rng);
    const mcs_integrand gm = draw(MCS_INTEGRAND_GAUSSIAN_MIXTURE, 2u, &rng);
    double out = 42.0;
    mcs_integrand f = bp;
    f.shading[0] += 1e-9; /* p no longer of unit length and the frame not its own */
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_integrand_integral(&f, &out));
    f = bp;
    f.frame[0] *= 1.5;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_integrand_integral(&f, &out));
    f = bp;
    f.dim = 1u;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_integrand_integral(&f, &out));
    f = bp;
    f.square = f.integral * f.integral * 0.5; /* below I^2 */
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_integrand_variance(&f, &out));
    f = gm;
    f.boxes = 9u;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_integrand_integral(&f, &out));
    f = gm;
    f.precision[0][0] = 1000.0; /* a variance below 0.01 */
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_integrand_integral(&f, &out));
    f = gm;
    f.mean[1][0] = f.box_hi[1][0] + 0.01;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_integrand_integral(&f, &out));
    f = gm;
    f.integral = NAN;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_integrand_integral(&f, &out));
    TEST_ASSERT_EQUAL_DOUBLE(42.0, out);
}

/* A jittered reference has no exact value for these families: the add
 * still counts the set, the exact column stays empty. */
static void test_a_jittered_reference_leaves_the_exact_column_empty(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 11u, 1u);
    const mcs_integrand f = draw(MCS_INTEGRAND_GAUSSIAN_MIXTURE, 2u, &rng);
    mcs_integrate acc;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrate_init(&acc, MCS_INTEGRAND_GAUSSIAN_MIXTURE, 2u));
    const double pts[8] = {0.1, 0.2, 0.6, 0.3, 0.2, 0.7, 0.8, 0.9};
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrate_add(&acc, 1u, &f, 4u, pts, MCS_INTEGRATE_JITTERED,
                                                    2u, 2u));
    double v;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrate_mse(&acc, &v));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_integrate_exact(&acc, &v));
}

int main(void)
{
    gl_nodes();
    UNITY_BEGIN();
    RUN_TEST(test_mixture_integrals_match_a_grid_on_the_box_edges);
    RUN_TEST(test_blinn_phong_integrals_match_the_area_form_over_the_quad);
    RUN_TEST(test_blinn_phong_midpoint_sum_of_the_estimate_is_its_integral);
    RUN_TEST(test_random_sets_have_mse_var_over_k_within_5_standard_errors);
    RUN_TEST(test_mixture_1d_stratified_mse_matches_cells_and_sets);
    RUN_TEST(test_draws_are_reproducible_in_range_and_blinn_phong_is_2d_only);
    RUN_TEST(test_a_tampered_integrand_is_refused_and_writes_nothing);
    RUN_TEST(test_a_jittered_reference_leaves_the_exact_column_empty);
    return UNITY_END();
}
