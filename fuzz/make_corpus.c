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
    return bad;
}
