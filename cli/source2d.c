/* The named 2D point sources (see source2d.h). */
#include "source2d.h"
#include "cli.h"
#include "output.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The 2D pattern kind named name, or -1. */
static int pattern_kind(const char *name)
{
    for (int i = 0; i < MCS_PATTERN2D_KIND_COUNT; ++i)
        if (strcmp(name, mcs_pattern2d_kind_str((mcs_pattern2d_kind)i)) == 0)
            return i;
    return -1;
}

/* The sampler kind named name that exists in 2D, or -1. */
static int sampler_kind(const char *name)
{
    for (int i = 0; i < MCS_SAMPLER_KIND_COUNT; ++i)
        if (strcmp(name, mcs_sampler_kind_str((mcs_sampler_kind)i)) == 0 &&
            mcs_sampler_has_dim((mcs_sampler_kind)i, 2u))
            return i;
    return -1;
}

int cli_source2d_known(const char *name)
{
    return pattern_kind(name) >= 0 || sampler_kind(name) >= 0;
}

/* Only rotated or shifted samplers have a fixed periodogram (Sobol points
 * are Owen-scrambled, permuted Halton digits and padded pairs are not
 * rotations): mcs_sampler_base_is_exact. */
static int has_base(const cli_source2d *src)
{
    return src->is_sampler && mcs_sampler_base_is_exact(src->sampler.kind);
}

/* One trial of the unrandomised set into src->base, over a buffer of its
 * own (src->base_mem), AUTO picking the path as for the trials. */
static int measure_base(const char *cmd, cli_source2d *src, size_t freq)
{
    size_t bytes = 0u;
    mcs_status st = mcs_pointset2d_size(freq, 0u, &bytes);
    if (st != MCS_OK)
        return cli_internal(cmd, "the unrandomised %s set: %s", src->name, mcs_status_str(st));
    double *pts = cli_alloc(cmd, 2u * src->k, sizeof *pts);
    src->base = cli_alloc(cmd, 1, sizeof *src->base);
    src->base_mem = cli_alloc(cmd, 1, bytes);
    if (pts == NULL || src->base == NULL || src->base_mem == NULL) {
        free(pts);
        return CLI_EXIT_FAIL;
    }
    st = mcs_sampler_base_points(&src->sampler, src->k, pts);
    if (st == MCS_OK)
        st = mcs_pointset2d_init(src->base, freq, 0u, src->base_mem, bytes);
    if (st == MCS_OK)
        st = mcs_pointset2d_add(src->base, src->k, pts);
    free(pts);
    if (st != MCS_OK)
        return cli_internal(cmd, "the unrandomised %s set: %s", src->name, mcs_status_str(st));
    return 0;
}

/* Owen's exact theory for a nested-scrambled sampler: Sobol at K = 2^m by
 * the (0,m,2)-net route, else the pair counts of its unscrambled points
 * (bases 2, 2 for Sobol, 2, 3 for Halton); nothing (no exact column) above
 * CLI_OWEN_MAX_K points. */
static int setup_owen(const char *cmd, cli_source2d *src)
{
    mcs_owen_theory t = MCS_OWEN_THEORY_NONE;
    if (!src->is_sampler || mcs_owen_theory_of(src->sampler.kind, 2u, &t) != MCS_OK ||
        t != MCS_OWEN_THEORY_NESTED)
        return 0;
    const int sobol = src->sampler.kind == MCS_SAMPLER_SOBOL ||
                      src->sampler.kind == MCS_SAMPLER_SOBOL_ND;
    if (sobol && (src->k & (src->k - 1u)) == 0u) {
        size_t m = 0;
        while (((size_t)1 << m) < src->k)
            ++m;
        src->net_m = m + 1u;
        return 0;
    }
    if (src->k > CLI_OWEN_MAX_K)
        return 0;
    const size_t axes[2] = {0u, 1u};
    const unsigned bases[2] = {2u, sobol ? 2u : 3u};
    size_t len = 0;
    mcs_status st = mcs_owen_len(2u, bases, &len);
    double *pts = cli_alloc(cmd, 2u * src->k, sizeof *pts);
    src->owen = cli_alloc(cmd, 1, sizeof *src->owen);
    src->owen_work = cli_alloc(cmd, len > 0u ? len : 1u, sizeof *src->owen_work);
    if (pts == NULL || src->owen == NULL || src->owen_work == NULL) {
        free(pts);
        return CLI_EXIT_FAIL;
    }
    if (st == MCS_OK)
        st = mcs_sampler_base_points(&src->sampler, src->k, pts);
    if (st == MCS_OK)
        st = mcs_owen_init(src->owen, src->k, 2u, pts, 2u, axes, bases, src->owen_work, len);
    free(pts);
    if (st != MCS_OK)
        return cli_internal(cmd, "Owen's theory for %s: %s", src->name, mcs_status_str(st));
    return 0;
}

int cli_source2d_init(const char *cmd, const char *name, size_t k, size_t freq,
                      cli_source2d *src)
{
    memset(src, 0, sizeof *src);
    src->name = name;
    src->k = k;
    const int pk = pattern_kind(name), sk = sampler_kind(name);
    mcs_status st = MCS_ERR_KIND;
    if (pk >= 0) {
        st = mcs_pattern2d_init(&src->pattern, (mcs_pattern2d_kind)pk, k, 0u, 0u);
    } else if (sk >= 0) {
        src->is_sampler = 1;
        st = mcs_sampler_init(&src->sampler, (mcs_sampler_kind)sk, 2u, k);
    }
    if (st == MCS_ERR_KIND)
        return cli_fail(cmd, "unknown 2D pattern '%s' (%s)", name, CLI_SOURCE2D_NAMES);
    if (st != MCS_OK)
        return cli_fail(cmd, "cannot set up %s with K = %zu: %s", name, k, mcs_status_str(st));
    return has_base(src) ? measure_base(cmd, src, freq) : setup_owen(cmd, src);
}

void cli_source2d_free(cli_source2d *src)
{
    free(src->base);
    free(src->base_mem);
    free(src->owen);
    free(src->owen_work);
    src->base = NULL;
    src->base_mem = NULL;
    src->owen = NULL;
    src->owen_work = NULL;
}

static int has_owen(const cli_source2d *src) { return src->net_m != 0u || src->owen != NULL; }

const char *cli_source2d_exact_source(const cli_source2d *src)
{
    if (has_base(src))
        return "unrandomised set";
    if (has_owen(src))
        return src->net_m != 0u ? "Owen scrambling, (0,m,2)-net counts (docs/owen.md)"
                                : "Owen scrambling, pair counts of the unscrambled set (docs/owen.md)";
    if (src->is_sampler || src->pattern.kind == MCS_PATTERN2D_MULTI_JITTERED ||
        src->pattern.kind == MCS_PATTERN2D_CMJ)
        return "";
    return "closed form";
}

int cli_source2d_uses_strata(const cli_source2d *src)
{
    return !src->is_sampler && src->pattern.kind != MCS_PATTERN2D_RANDOM &&
           src->pattern.kind != MCS_PATTERN2D_NROOKS;
}

static double exact_at(const void *ctx, long kx, long ky)
{
    const cli_source2d *src = ctx;
    double v = 0.0;
    if (has_base(src))
        return cli_or_nan(mcs_pointset2d_power(src->base, kx, ky, &v), &v);
    if (src->net_m != 0u)
        return cli_or_nan(mcs_owen_net_power(2u, src->net_m - 1u, kx, ky, &v), &v);
    if (src->owen != NULL)
        return cli_or_nan(mcs_owen_power(src->owen, kx, ky, &v), &v);
    if (src->is_sampler)
        return (double)NAN;
    return cli_or_nan(mcs_pointset2d_exact_power(&src->pattern, kx, ky, &v), &v);
}

static double exact_radial(const void *ctx, size_t r)
{
    const cli_source2d *src = ctx;
    double v = 0.0;
    if (has_base(src))
        return cli_or_nan(mcs_pointset2d_radial(src->base, r, &v), &v);
    if (has_owen(src)) { /* the mean of the exact P over the annulus r <= |k| < r + 1 */
        const long lo = (long)r * (long)r, hi = ((long)r + 1) * ((long)r + 1), rr = (long)r + 1;
        double sum = 0.0;
        size_t n = 0;
        for (long ky = -rr; ky <= rr; ++ky)
            for (long kx = -rr; kx <= rr; ++kx) {
                const long q = kx * kx + ky * ky;
                if (q >= lo && q < hi) {
                    sum += exact_at(ctx, kx, ky);
                    ++n;
                }
            }
        return n > 0u ? sum / (double)n : (double)NAN;
    }
    if (src->is_sampler)
        return (double)NAN;
    return cli_or_nan(mcs_pointset2d_exact_radial(&src->pattern, r, &v), &v);
}

void cli_source2d_exact(const cli_source2d *src, cli_exact2d *out)
{
    out->ctx = src;
    out->at = exact_at;
    out->radial = exact_radial;
    out->scale = (double)src->k;
}

int cli_source2d_run(const char *cmd, const void *source, uint64_t seed, uint64_t stream,
                     uint64_t first, uint64_t last, void *acc, cli_progress *progress)
{
    const cli_source2d *src = source;
    double *pts = cli_alloc(cmd, 2u * src->k, sizeof *pts);
    if (pts == NULL)
        return CLI_EXIT_FAIL;
    mcs_rng rng;
    mcs_status st = mcs_rng_seed(&rng, seed, stream);
    for (uint64_t t = first; st == MCS_OK && t < last; ++t) {
        st = src->is_sampler ? mcs_sampler_draw(&src->sampler, &rng, src->k, pts)
                             : mcs_pattern2d_draw(&src->pattern, &rng, src->k, pts);
        if (st == MCS_OK)
            st = mcs_pointset2d_add(acc, src->k, pts);
        if (progress != NULL)
            cli_progress_update(progress, t + 1u);
    }
    free(pts);
    if (st != MCS_OK)
        return cli_internal(cmd, "a trial failed: %s", mcs_status_str(st));
    return 0;
}
