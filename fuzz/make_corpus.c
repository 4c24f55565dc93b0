/* Writes the seed corpus of fuzz_load: small valid records of every kind,
 * from real accumulations with fixed seeds (so the bytes are the same on
 * every run and host), and a few with a provenance block (format version
 * 2). Usage: make_corpus DIR (make fuzz-corpus). */
#include <stdio.h>
#include <string.h>

#include "mcspec.h"

static unsigned char buf[1u << 16];
static mcs_spectrum spec;
static mcs_moment mom;
static mcs_autocorr ac;
static mcs_welford wf;
/* The point-set and 2D spectra over static buffers for the largest shape
 * below (F = 16; 16 x 17 bins). */
static mcs_pointset ps;
static mcs_pointset2d ps2;
static mcs_spectrum2d sp2;
static unsigned char ps_mem[MCS_POINTSET_SIZE(16u)], ps2_mem[MCS_POINTSET2D_SIZE(16u)],
    sp2_mem[MCS_SPECTRUM2D_SIZE(16u, 17u)];

static int write_file(const char *dir, const char *name, size_t len)
{
    char path[512];
    (void)snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "wb");
    if (f == NULL || fwrite(buf, 1u, len, f) != len || fclose(f) != 0) {
        fprintf(stderr, "make_corpus: cannot write %s\n", path);
        return 1;
    }
    return 0;
}

static int check(mcs_status st, const char *what)
{
    if (st != MCS_OK)
        fprintf(stderr, "make_corpus: %s: %s\n", what, mcs_status_str(st));
    return st != MCS_OK;
}

/* `trials` trials of a stratified pattern of k samples over n bins into the
 * binned accumulators, its points into the point-set spectra (cutoff n), and
 * points paired up as (x, y) into the 2D ones (2D cutoff and sides n), then
 * one file each. */
static int one_case(const char *dir, size_t n, size_t k, size_t trials, uint64_t seed)
{
    mcs_pattern pat;
    mcs_rng rng;
    size_t bins[64];
    double w[64], pts[64];
    char name[64];
    size_t len = 0u;
    int bad = check(mcs_pattern_init(&pat, MCS_PATTERN_STRATIFIED, n, k, NULL), "pattern");
    bad |= check(mcs_rng_seed(&rng, seed, 7u), "rng");
    bad |= check(mcs_spectrum_init(&spec, n), "spectrum");
    bad |= check(mcs_moment_init(&mom, n), "moment");
    bad |= check(mcs_autocorr_init(&ac, n), "autocorr");
    bad |= check(mcs_welford_init(&wf), "welford");
    bad |= check(mcs_pointset_init(&ps, n, 0u, ps_mem, sizeof ps_mem), "pointset");
    bad |= check(mcs_pointset2d_init(&ps2, n, 0u, ps2_mem, sizeof ps2_mem), "pointset2d");
    bad |= check(mcs_spectrum2d_init(&sp2, n, n + 1u, sp2_mem, sizeof sp2_mem), "spectrum2d");
    for (size_t t = 0; t < trials && !bad; ++t) {
        bad |= check(mcs_pattern_draw(&pat, &rng, k, bins, w, pts), "draw");
        bad |= check(mcs_pointset_add(&ps, k, pts), "pointset add");
        bad |= check(mcs_pointset2d_add(&ps2, k / 2u, pts), "pointset2d add");
        bad |= check(mcs_spectrum2d_add_points(&sp2, k / 2u, pts, NULL), "spectrum2d add");
        bad |= check(mcs_spectrum_add_bins(&spec, k, bins, w), "spectrum add");
        bad |= check(mcs_moment_add_bins(&mom, k, bins, w), "moment add");
        bad |= check(mcs_autocorr_add_bins(&ac, k, bins, w), "autocorr add");
        bad |= check(mcs_welford_add(&wf, w[0] * (double)bins[0]), "welford add");
    }
    if (bad)
        return 1;
    (void)snprintf(name, sizeof name, "spectrum-n%zu-t%zu.rec", n, trials);
    bad |= check(mcs_io_save_spectrum(&spec, sizeof buf, buf, &len), name) || write_file(dir, name, len);
    (void)snprintf(name, sizeof name, "moment-n%zu-t%zu.rec", n, trials);
    bad |= check(mcs_io_save_moment(&mom, sizeof buf, buf, &len), name) || write_file(dir, name, len);
    (void)snprintf(name, sizeof name, "autocorr-n%zu-t%zu.rec", n, trials);
    bad |= check(mcs_io_save_autocorr(&ac, sizeof buf, buf, &len), name) || write_file(dir, name, len);
    (void)snprintf(name, sizeof name, "welford-t%zu.rec", trials);
    bad |= check(mcs_io_save_welford(&wf, sizeof buf, buf, &len), name) || write_file(dir, name, len);
    (void)snprintf(name, sizeof name, "pointset-f%zu-t%zu.rec", n, trials);
    bad |= check(mcs_io_save_pointset(&ps, sizeof buf, buf, &len), name) || write_file(dir, name, len);
    (void)snprintf(name, sizeof name, "pointset2d-f%zu-t%zu.rec", n, trials);
    bad |= check(mcs_io_save_pointset2d(&ps2, sizeof buf, buf, &len), name) ||
           write_file(dir, name, len);
    (void)snprintf(name, sizeof name, "spectrum2d-n%zux%zu-t%zu.rec", n, n + 1u, trials);
    bad |= check(mcs_io_save_spectrum2d(&sp2, sizeof buf, buf, &len), name) ||
           write_file(dir, name, len);
    return bad;
}

/* The accumulators one_case left, saved with a provenance block (format
 * version 2): a pattern run of two seeds and three stream ranges, two point
 * files, a 2D run. */
static int provenance_cases(const char *dir)
{
    static mcs_io_provenance prov;
    size_t len = 0u;
    memset(&prov, 0, sizeof prov);
    prov.source = MCS_IO_SOURCE_PATTERN;
    prov.dim = 1u;
    (void)snprintf(prov.pattern, sizeof prov.pattern, "stratified");
    prov.n = spec.n;
    prov.k = 4u;
    prov.importance = 1u;
    prov.importance_crc = 0x5eed1234u;
    prov.streams = 6u;
    prov.trials = 30u;
    prov.nranges = 3u;
    prov.range[0] = (mcs_io_streams){3u, 0u, 1u};
    prov.range[1] = (mcs_io_streams){3u, 2u, 4u};
    prov.range[2] = (mcs_io_streams){5u, 1u, 6u};
    int bad = check(mcs_io_save_spectrum(&spec, sizeof buf, buf, &len), "spectrum") ||
              check(mcs_io_set_provenance(&prov, sizeof buf, buf, &len), "pattern provenance") ||
              write_file(dir, "spectrum-n7-t5-pattern.rec", len);
    (void)snprintf(prov.pattern, sizeof prov.pattern, "jittered");
    prov.dim = 2u;
    prov.n = 0u;
    prov.importance = 0u;
    prov.importance_crc = 0u;
    prov.nranges = 1u;
    bad |= check(mcs_io_save_pointset2d(&ps2, sizeof buf, buf, &len), "pointset2d") ||
           check(mcs_io_set_provenance(&prov, sizeof buf, buf, &len), "2D provenance") ||
           write_file(dir, "pointset2d-f7-t5-pattern.rec", len);
    memset(&prov, 0, sizeof prov);
    prov.source = MCS_IO_SOURCE_POINTS;
    prov.ninputs = 2u;
    prov.input[0] = (mcs_io_input){0x0badf00du, 123u, "a.txt"};
    prov.input[1] = (mcs_io_input){0xc0ffee00u, 4567u, "...very/long/path/b.txt"};
    bad |= check(mcs_io_save_pointset(&ps, sizeof buf, buf, &len), "pointset") ||
           check(mcs_io_set_provenance(&prov, sizeof buf, buf, &len), "points provenance") ||
           write_file(dir, "pointset-f7-t5-points.rec", len);
    return bad;
}

/* The measure accumulators (kinds 8 to 11): `sets` sets of k random 2D
 * points (the pcf in dim dimensions, of `bins` bins; the Gaussian kernel
 * for odd seeds), empty when sets is 0. */
static int measure_case(const char *dir, size_t dim, size_t bins, size_t k, size_t sets,
                        uint64_t seed)
{
    static mcs_pcf pcf;
    static _Alignas(64) unsigned char pcf_mem[MCS_PCF_SIZE(16u)];
    static mcs_integrate in;
    static mcs_discrepancy di;
    static mcs_spacing sp;
    static double pts[2u * 64u];
    static unsigned char work[MCS_DISCREPANCY_STAR_WORK_SIZE(64) + MCS_PCF_WORK_SIZE(64)];
    mcs_rng rng;
    mcs_integrand fs[2];
    const mcs_pcf_estimator est = seed % 2u ? MCS_PCF_GAUSSIAN : MCS_PCF_RDF;
    int bad = check(mcs_rng_seed(&rng, seed, 11u), "rng") ||
              check(mcs_pcf_init(&pcf, dim, est, bins, 1.5, 0.125, pcf_mem, sizeof pcf_mem), "pcf") ||
              check(mcs_integrate_init(&in, MCS_INTEGRAND_GAUSSIAN, 2u), "integrate") ||
              check(mcs_discrepancy_init(&di, 2u), "discrepancy") ||
              check(mcs_spacing_init(&sp, 2u), "spacing");
    for (size_t t = 0; t < sets && !bad; ++t) {
        for (size_t i = 0; i < 2u * k; ++i)
            bad |= check(mcs_rng_double(&rng, &pts[i]), "rng");
        for (size_t i = 0; i < 2u; ++i)
            bad |= check(mcs_integrand_draw(&fs[i], MCS_INTEGRAND_GAUSSIAN, 2u, &rng), "draw");
        bad |= check(mcs_pcf_add(&pcf, k, pts, work, sizeof work), "pcf add") ||
               check(mcs_integrate_add(&in, 2u, fs, k, pts, t % 2u ? MCS_INTEGRATE_RANDOM
                                                                  : MCS_INTEGRATE_NONE, 0u, 0u),
                     "integrate add") ||
               check(mcs_discrepancy_add(&di, k, pts, t % 2u ? work : NULL, sizeof work),
                     "discrepancy add") ||
               check(mcs_spacing_add(&sp, k, pts, work, sizeof work), "spacing add");
    }
    char name[96];
    size_t len = 0u;
    (void)snprintf(name, sizeof name, "pcf-d%zu-b%zu-k%zu-t%zu.rec", dim, bins, k, sets);
    bad |= check(mcs_io_save_pcf(&pcf, sizeof buf, buf, &len), name) || write_file(dir, name, len);
    (void)snprintf(name, sizeof name, "integrate-k%zu-t%zu.rec", k, sets);
    bad |= check(mcs_io_save_integrate(&in, sizeof buf, buf, &len), name) ||
           write_file(dir, name, len);
    (void)snprintf(name, sizeof name, "discrepancy-k%zu-t%zu.rec", k, sets);
    bad |= check(mcs_io_save_discrepancy(&di, sizeof buf, buf, &len), name) ||
           write_file(dir, name, len);
    (void)snprintf(name, sizeof name, "spacing-k%zu-t%zu.rec", k, sets);
    bad |= check(mcs_io_save_spacing(&sp, sizeof buf, buf, &len), name) ||
           write_file(dir, name, len);
    return bad;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: make_corpus DIR\n");
        return 2;
    }
    /* Empty, one trial (no spread yet) and a few trials; odd and even N. */
    int bad = one_case(argv[1], 1u, 2u, 0u, 1u);
    bad |= one_case(argv[1], 2u, 3u, 1u, 2u);
    bad |= one_case(argv[1], 7u, 4u, 5u, 3u);
    bad |= provenance_cases(argv[1]);
    bad |= one_case(argv[1], 16u, 6u, 20u, 4u);
    /* AUTO takes the PAIR path here: 2 closed batches of 16 and an open one
     * of 8, so the spectrum record has units with spread and open sums. */
    bad |= one_case(argv[1], 16u, 6u, 40u, 5u);
    bad |= measure_case(argv[1], 2u, 4u, 16u, 0u, 6u);
    bad |= measure_case(argv[1], 2u, 8u, 64u, 3u, 8u);
    bad |= measure_case(argv[1], 1u, 16u, 32u, 5u, 7u);
    return bad;
}
