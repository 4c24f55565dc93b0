/* Tests of the integrand families (integrand.h) against independent
 * references: integrals, integrals of f^2 and the per-cell integrals of the
 * jittered grid's exact MSE by quadrature (Simpson's rule for the smooth
 * families; for the indicators the exact length of each vertical chord,
 * integrated over x by the midpoint rule), the Fourier power by a DFT on a
 * fine grid (spectrally exact for the smooth periodic families) and, for
 * the disk, by the chord integral in closed form and J1 by its integral
 * (1/pi) int_0^pi cos(t - x sin t) dt; Parseval for the cosines; the draw's
 * ranges and reproducibility; bad input. */
#include "mcspec.h"
#include "unity.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define PI 3.14159265358979323846

static mcs_integrand draw(mcs_integrand_family fam, size_t dim, uint64_t seed)
{
    mcs_rng rng;
    mcs_integrand f;
    mcs_rng_seed(&rng, seed, 7u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrand_draw(&f, fam, dim, &rng));
    return f;
}

static double ev(const mcs_integrand *f, double x, double y)
{
    const double p[2] = {x, y};
    double v = NAN;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrand_eval(f, p, &v));
    return v;
}

static int smooth(const mcs_integrand *f)
{
    return f->family == MCS_INTEGRAND_GAUSSIAN || f->family == MCS_INTEGRAND_GAUSSIAN_PERIODIC ||
           f->family == MCS_INTEGRAND_COSINE;
}

/* Simpson weights over n (even) intervals of [a, b]. */
static double simpson_w(int i, int n, double h)
{
    return h / 3.0 * (i == 0 || i == n ? 1.0 : (i & 1) ? 4.0 : 2.0);
}

/* Length of [y0, y1] inside the indicator at abscissa x (independent of the
 * library: the half-plane solved for y, the disk's chords over its images). */
static double chord(const mcs_integrand *f, double x, double y0, double y1)
{
    if (f->family == MCS_INTEGRAND_HEAVISIDE) {
        const double u0 = f->normal[0], u1 = f->normal[1];
        const double a = (x - f->centre[0]) * u0 - f->centre[1] * u1; /* a + y u1 > 0 */
        if (fabs(u1) < 1e-300)
            return a > 0.0 ? y1 - y0 : 0.0;
        const double t = -a / u1;
        const double lo = u1 > 0.0 ? fmax(y0, t) : y0, hi = u1 > 0.0 ? y1 : fmin(y1, t);
        return hi > lo ? hi - lo : 0.0;
    }
    double len = 0.0;
    for (int nx = -1; nx <= 1; ++nx)
        for (int ny = -1; ny <= 1; ++ny) {
            const double dx = x - f->centre[0] - nx, r = f->width;
            if (fabs(dx) >= r)
                continue;
            const double h = sqrt(r * r - dx * dx), c = f->centre[1] + ny;
            const double lo = fmax(y0, c - h), hi = fmin(y1, c + h);
            len += hi > lo ? hi - lo : 0.0;
        }
    return len;
}

/* int over the cell of f (*i) and f^2 (*j), independently of the library. */
static void ref_cell(const mcs_integrand *f, double x0, double x1, double y0, double y1, double *i,
                     double *j)
{
    double si = 0.0, sj = 0.0;
    if (f->dim == 1u) {
        if (smooth(f)) {
            const int n = 4000;
            const double h = (x1 - x0) / n;
            for (int a = 0; a <= n; ++a) {
                const double v = ev(f, fmin(x0 + a * h, nextafter(1.0, 0.0)), 0.0);
                si += simpson_w(a, n, h) * v;
                sj += simpson_w(a, n, h) * v * v;
            }
        } else if (f->family == MCS_INTEGRAND_HEAVISIDE) {
            si = sj = fmax(0.0, fmin(x1, f->centre[0]) - x0);
        } else {
            for (int n = -1; n <= 1; ++n) {
                const double lo = fmax(x0, f->centre[0] - f->width + n);
                const double hi = fmin(x1, f->centre[0] + f->width + n);
                si += hi > lo ? hi - lo : 0.0;
            }
            sj = si;
        }
    } else if (smooth(f)) {
        const int n = x1 - x0 > 0.5 ? 600 : 160;
        const double hx = (x1 - x0) / n, hy = (y1 - y0) / n;
        for (int a = 0; a <= n; ++a)
            for (int b = 0; b <= n; ++b) {
                const double x = fmin(x0 + a * hx, nextafter(1.0, 0.0));
                const double y = fmin(y0 + b * hy, nextafter(1.0, 0.0));
                const double v = ev(f, x, y), w = simpson_w(a, n, hx) * simpson_w(b, n, hy);
                si += w * v;
                sj += w * v * v;
            }
    } else {
        const int n = 20000;
        const double h = (x1 - x0) / n;
        for (int a = 0; a < n; ++a)
            si += h * chord(f, x0 + (a + 0.5) * h, y0, y1);
        sj = si;
    }
    *i = si;
    *j = sj;
}

static const mcs_integrand_family families[] = {
    MCS_INTEGRAND_GAUSSIAN, MCS_INTEGRAND_GAUSSIAN_PERIODIC, MCS_INTEGRAND_HEAVISIDE,
    MCS_INTEGRAND_DISK, MCS_INTEGRAND_COSINE};
#define NFAM (sizeof families / sizeof families[0])

static void test_integral_and_variance_match_quadrature(void)
{
    for (size_t d = 1; d <= 2; ++d)
        for (size_t fi = 0; fi < NFAM; ++fi)
            for (uint64_t seed = 1; seed <= 3; ++seed) {
                const mcs_integrand f = draw(families[fi], d, seed);
                double i = NAN, v = NAN, ri, rj;
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrand_integral(&f, &i));
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrand_variance(&f, &v));
                ref_cell(&f, 0.0, 1.0, 0.0, 1.0, &ri, &rj);
                const double tol = smooth(&f) ? 1e-9 : 2e-6; /* the midpoint rule at the chord ends: h^1.5 */
                char msg[64];
                snprintf(msg, sizeof msg, "%s d=%zu seed %d", mcs_integrand_family_str(f.family), d,
                         (int)seed);
                TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(tol * fmax(1.0, ri), ri, i, msg);
                TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(tol * fmax(1.0, rj), rj - ri * ri, v, msg);
                if (families[fi] == MCS_INTEGRAND_COSINE)
                    TEST_ASSERT_EQUAL_DOUBLE(1.0, i);
            }
}

/* The jittered MSE of grids with few cells, from the reference cell integrals. */
static void test_jittered_mse_matches_cell_quadrature(void)
{
    const size_t shapes[][2] = {{1, 1}, {3, 2}, {4, 4}, {2, 5}};
    for (size_t d = 1; d <= 2; ++d)
        for (size_t fi = 0; fi < NFAM; ++fi)
            for (size_t si = 0; si < 4; ++si) {
                const size_t mx = shapes[si][0], my = d == 1u ? 1u : shapes[si][1];
                const mcs_integrand f = draw(families[fi], d, 10u + si);
                const double k = (double)(mx * my);
                double sum = 0.0, got = NAN;
                for (size_t b = 0; b < my; ++b)
                    for (size_t a = 0; a < mx; ++a) {
                        double i, j;
                        ref_cell(&f, (double)a / mx, (double)(a + 1) / mx, (double)b / my,
                                 (double)(b + 1) / my, &i, &j);
                        sum += k * j - k * k * i * i;
                    }
                const double want = sum / (k * k);
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrand_jittered_mse(&f, mx, my, &got));
                char msg[96];
                snprintf(msg, sizeof msg, "%s d=%zu %zux%zu", mcs_integrand_family_str(f.family), d,
                         mx, my);
                TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(1e-6 * want + 1e-12, want, got, msg);
            }
}

/* A 1x1 grid is one random point: the jittered MSE is the variance. */
static void test_one_cell_jittered_is_the_variance(void)
{
    for (size_t d = 1; d <= 2; ++d)
        for (size_t fi = 0; fi < NFAM; ++fi) {
            const mcs_integrand f = draw(families[fi], d, 99u);
            double v = NAN, j = NAN;
            mcs_integrand_variance(&f, &v);
            mcs_integrand_jittered_mse(&f, 1u, 1u, &j);
            TEST_ASSERT_DOUBLE_WITHIN(1e-12 * fmax(v, 1e-3), v, j);
        }
}

/* J1 by its integral, trapezoid over a period (spectrally exact). */
static double j1_ref(double x)
{
    const int n = 600;
    double s = 0.0;
    for (int i = 0; i < n; ++i) {
        const double t = PI * (i + 0.5) / n;
        s += cos(t - x * sin(t));
    }
    return s / n;
}

static void test_fourier_power_matches_a_dft_and_bessel(void)
{
    enum { N = 128 };
    for (size_t d = 1; d <= 2; ++d) {
        const mcs_integrand_family smooth_periodic[2] = {MCS_INTEGRAND_GAUSSIAN_PERIODIC,
                                                         MCS_INTEGRAND_COSINE};
        for (int fi = 0; fi < 2; ++fi) {
            const mcs_integrand f = draw(smooth_periodic[fi], d, 5u + (uint64_t)fi);
            for (long kx = -5; kx <= 5; ++kx)
                for (long ky = d == 1u ? 0 : -3; ky <= (d == 1u ? 0 : 3); ++ky) {
                    double re = 0.0, im = 0.0;
                    for (int a = 0; a < N; ++a)
                        for (int b = 0; b < (d == 1u ? 1 : N); ++b) {
                            const double x = (double)a / N, y = (double)b / N;
                            const double v = ev(&f, x, y), ph = -2.0 * PI * (kx * x + ky * y);
                            re += v * cos(ph);
                            im += v * sin(ph);
                        }
                    const double norm = d == 1u ? N : (double)N * N;
                    const double want = (re * re + im * im) / (norm * norm);
                    double got = NAN;
                    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrand_power(&f, kx, ky, &got));
                    TEST_ASSERT_DOUBLE_WITHIN(1e-10 * want + 1e-14, want, got);
                }
        }
    }
    /* The disk: J1 against its integral, and the chord integral of e^{-2 pi i k.x}. */
    for (double x = 0.01; x < 160.0; x *= 1.37) {
        const mcs_integrand f = draw(MCS_INTEGRAND_DISK, 2u, 3u);
        const double r = f.width, rho = x / (2.0 * PI * r);
        (void)rho;
        double got = NAN;
        /* a wave vector (q, 0) with 2 pi r q near x */
        const long q = (long)floor(x / (2.0 * PI * r)) + 1;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrand_power(&f, q, 0, &got));
        const double j = j1_ref(2.0 * PI * r * (double)q), want = r * j / q * (r * j / q);
        TEST_ASSERT_DOUBLE_WITHIN(1e-11 * r * r, want, got);
    }
    const mcs_integrand disk = draw(MCS_INTEGRAND_DISK, 2u, 4u);
    const long ks[][2] = {{0, 0}, {1, 0}, {1, 2}, {-3, 1}, {4, 4}};
    for (int t = 0; t < 5; ++t) {
        const int n = 40000;
        double re = 0.0, im = 0.0;
        /* on the torus the periodic disk's coefficient is the single disk's over the plane */
        const double r = disk.width;
        for (int a = 0; a < n; ++a) {
            const double x = disk.centre[0] - r + 2.0 * r * (a + 0.5) / n, dx = x - disk.centre[0];
            const double h = sqrt(r * r - dx * dx), lo = disk.centre[1] - h, hi = disk.centre[1] + h;
            double cr, ci;
            if (ks[t][1] == 0) {
                cr = hi - lo;
                ci = 0.0;
            } else {
                const double w = -2.0 * PI * ks[t][1];
                cr = (sin(w * hi) - sin(w * lo)) / w;
                ci = -(cos(w * hi) - cos(w * lo)) / w;
            }
            const double ph = -2.0 * PI * ks[t][0] * x, dw = 2.0 * r / n;
            re += (cr * cos(ph) - ci * sin(ph)) * dw;
            im += (cr * sin(ph) + ci * cos(ph)) * dw;
        }
        double got = NAN;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrand_power(&disk, ks[t][0], ks[t][1], &got));
        TEST_ASSERT_DOUBLE_WITHIN(1e-6, re * re + im * im, got);
    }
    const mcs_integrand arc = draw(MCS_INTEGRAND_DISK, 1u, 4u);
    for (long k = 0; k <= 6; ++k) {
        const int n = 200000;
        double re = 0.0, im = 0.0, got = NAN;
        for (int a = 0; a < n; ++a) {
            const double x = (a + 0.5) / n, v = ev(&arc, x, 0.0);
            re += v * cos(2.0 * PI * k * x) / n;
            im -= v * sin(2.0 * PI * k * x) / n;
        }
        mcs_integrand_power(&arc, k, 0, &got);
        TEST_ASSERT_DOUBLE_WITHIN(2e-5, re * re + im * im, got);
    }
}

static void test_parseval_holds_for_the_cosines(void)
{
    for (size_t d = 1; d <= 2; ++d) {
        const mcs_integrand f = draw(MCS_INTEGRAND_COSINE, d, 21u);
        double sum = 0.0, i, v;
        for (long kx = -4; kx <= 4; ++kx)
            for (long ky = d == 1u ? 0 : -4; ky <= (d == 1u ? 0 : 4); ++ky) {
                double p;
                mcs_integrand_power(&f, kx, ky, &p);
                sum += p;
            }
        mcs_integrand_integral(&f, &i);
        mcs_integrand_variance(&f, &v);
        TEST_ASSERT_DOUBLE_WITHIN(1e-15, v + i * i, sum);
    }
}

static void test_draws_are_reproducible_and_in_range(void)
{
    for (size_t fi = 0; fi < NFAM; ++fi)
        for (size_t d = 1; d <= 2; ++d) {
            mcs_rng a, b;
            mcs_rng_seed(&a, 5u, 1u);
            mcs_rng_seed(&b, 5u, 1u);
            for (int t = 0; t < 200; ++t) {
                mcs_integrand f, g;
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrand_draw(&f, families[fi], d, &a));
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrand_draw(&g, families[fi], d, &b));
                TEST_ASSERT_EQUAL_MEMORY(&f, &g, sizeof f);
                double i;
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrand_integral(&f, &i));
                TEST_ASSERT_TRUE(i > 0.0 || families[fi] == MCS_INTEGRAND_HEAVISIDE);
            }
        }
}

static void test_bad_input_is_refused_and_writes_nothing(void)
{
    mcs_rng rng, unseeded;
    memset(&unseeded, 0, sizeof unseeded);
    mcs_rng_seed(&rng, 1u, 2u);
    mcs_integrand f, g;
    memset(&f, 0x5a, sizeof f);
    g = f;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_integrand_draw(NULL, MCS_INTEGRAND_DISK, 2u, &rng));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_integrand_draw(&f, MCS_INTEGRAND_FAMILIES, 2u, &rng));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_integrand_draw(&f, MCS_INTEGRAND_DISK, 3u, &rng));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_integrand_draw(&f, MCS_INTEGRAND_DISK, 2u, &unseeded));
    TEST_ASSERT_EQUAL_MEMORY(&g, &f, sizeof f);
    double out = 42.0, x[2] = {0.5, 1.0};
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_integrand_integral(&f, &out));
    f = draw(MCS_INTEGRAND_GAUSSIAN, 2u, 1u);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_integrand_eval(&f, x, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_integrand_power(&f, 1, 0, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_integrand_jittered_mse(&f, 0u, 2u, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_integrand_estimate(&f, 0u, x, &out));
    f.width = NAN;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_integrand_variance(&f, &out));
    TEST_ASSERT_EQUAL_DOUBLE(42.0, out);
    f = draw(MCS_INTEGRAND_DISK, 1u, 1u);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE, mcs_integrand_power(&f, 1, 1, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_integrand_jittered_mse(&f, 4u, 2u, &out));
    TEST_ASSERT_EQUAL_DOUBLE(42.0, out);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_integral_and_variance_match_quadrature);
    RUN_TEST(test_jittered_mse_matches_cell_quadrature);
    RUN_TEST(test_one_cell_jittered_is_the_variance);
    RUN_TEST(test_fourier_power_matches_a_dft_and_bessel);
    RUN_TEST(test_parseval_holds_for_the_cosines);
    RUN_TEST(test_draws_are_reproducible_and_in_range);
    RUN_TEST(test_bad_input_is_refused_and_writes_nothing);
    return UNITY_END();
}
