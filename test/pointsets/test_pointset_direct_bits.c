/* The direct path's bits, whatever the build (MCS_CONFIG_NUFFT, config.h):
 * an object of flags 0 on the DIRECT path gives the statistics of a
 * MCS_POINTSET_DIRECT_ONLY object byte for byte, in 1D and 2D, for double,
 * float and batched points. In a build without the NUFFT the flags-0 object
 * stays on AUTO, which must then be the direct sum. Each test also writes a
 * digest of its statistics to the file $MCS_DIGEST_OUT names, if set: make
 * test-nonufft runs this runner from both builds and compares the digests,
 * which proves the build without the NUFFT bit-identical to the default
 * build's direct path. */
#include "mcspec/pointset.h"
#include "mcspec/pointset2d.h"
#include "mcspec/rng.h"
#include "nufft_skip.h"
#include "unity.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

enum { F1 = 300, K1 = 2000, F2 = 24, K2 = 500, SETS = 3 };

static _Alignas(64) unsigned char mem_a[MCS_POINTSET2D_SIZE(F2) + MCS_POINTSET_SIZE(F1)];
static _Alignas(64) unsigned char mem_b[MCS_POINTSET2D_SIZE_DIRECT(F2) + MCS_POINTSET_SIZE_DIRECT(F1)];
static double pts[SETS * 2 * K1];
static float ptsf[SETS * 2 * K1];
static double read_a[2 * (2 * F2 + 1) * (2 * F2 + 1)], read_b[2 * (2 * F2 + 1) * (2 * F2 + 1)];

/* FNV-1a over bytes, continued from h. */
static uint64_t fnv(uint64_t h, const void *p, size_t n)
{
    const unsigned char *b = (const unsigned char *)p;
    for (size_t i = 0; i < n; ++i)
        h = (h ^ b[i]) * 1099511628211u;
    return h;
}

static void write_digest(const char *name, uint64_t h)
{
    const char *path = getenv("MCS_DIGEST_OUT");
    if (path == NULL || *path == '\0')
        return;
    FILE *f = fopen(path, "a");
    TEST_ASSERT_NOT_NULL(f);
    fprintf(f, "%s %016llx\n", name, (unsigned long long)h);
    TEST_ASSERT_EQUAL_INT(0, fclose(f));
}

static void draw(unsigned seed, size_t n)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, seed, 77u);
    for (size_t j = 0; j < n; ++j) {
        double u = 0.0;
        mcs_rng_double(&rng, &u);
        pts[j] = u;
        ptsf[j] = (float)u < 1.0f ? (float)u : 0.5f;
    }
}

/* The flags-0 object's path: DIRECT forced where the NUFFT exists, AUTO
 * (the direct sum) where it does not. */
static mcs_pointset_path first_path(void)
{
    return MCS_CONFIG_NUFFT ? MCS_POINTSET_PATH_DIRECT : MCS_POINTSET_PATH_AUTO;
}

static void test_a_1d_object_of_flags_0_gives_the_bits_of_a_direct_only_one(void)
{
    static mcs_pointset a, b;
    mcs_pointset_path p = MCS_POINTSET_PATH_NUFFT;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(&a, F1, 0u, mem_a, sizeof mem_a));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(&b, F1, MCS_POINTSET_DIRECT_ONLY, mem_b,
                                                    sizeof mem_b));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_set_path(&a, first_path()));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_path_for(&a, K1, &p));
    TEST_ASSERT_EQUAL_INT(MCS_POINTSET_PATH_DIRECT, p);
    draw(1u, SETS * K1);
    for (size_t t = 0; t < SETS; ++t) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add(&a, K1, pts + t * K1));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add(&b, K1, pts + t * K1));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add_f(&a, K1, ptsf + t * K1));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add_f(&b, K1, ptsf + t * K1));
    }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add_sets(&a, SETS, K1, pts));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add_sets(&b, SETS, K1, pts));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_read_all(&a, F1 + 1u, read_a, read_a + F1 + 1u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_read_all(&b, F1 + 1u, read_b, read_b + F1 + 1u));
    TEST_ASSERT_EQUAL_MEMORY(b.mean, a.mean, (F1 + 1u) * sizeof(double));
    TEST_ASSERT_EQUAL_MEMORY(b.m2, a.m2, (F1 + 1u) * sizeof(double));
    TEST_ASSERT_EQUAL_MEMORY(read_b, read_a, 2u * (F1 + 1u) * sizeof(double));
    write_digest("pointset", fnv(14695981039346656037u, read_a, 2u * (F1 + 1u) * sizeof(double)));
}

static void test_a_2d_object_of_flags_0_gives_the_bits_of_a_direct_only_one(void)
{
    enum { SIDE = 2 * F2 + 1 };
    static mcs_pointset2d a, b;
    mcs_pointset_path p = MCS_POINTSET_PATH_NUFFT;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_init(&a, F2, 0u, mem_a, sizeof mem_a));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_init(&b, F2, MCS_POINTSET_DIRECT_ONLY, mem_b,
                                                      sizeof mem_b));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_set_path(&a, first_path()));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_path_for(&a, K2, &p));
    TEST_ASSERT_EQUAL_INT(MCS_POINTSET_PATH_DIRECT, p);
    draw(2u, SETS * 2u * K2);
    for (size_t t = 0; t < SETS; ++t) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add(&a, K2, pts + 2u * t * K2));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add(&b, K2, pts + 2u * t * K2));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add_f(&a, K2, ptsf + 2u * t * K2));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add_f(&b, K2, ptsf + 2u * t * K2));
    }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add_sets(&a, SETS, K2, pts));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add_sets(&b, SETS, K2, pts));
    const size_t n = (size_t)SIDE * SIDE;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_read_all(&a, SIDE, read_a, read_a + n));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_read_all(&b, SIDE, read_b, read_b + n));
    TEST_ASSERT_EQUAL_MEMORY(read_b, read_a, 2u * n * sizeof(double));
    uint64_t h = fnv(14695981039346656037u, read_a, 2u * n * sizeof(double));
    const size_t r = F2 + 1u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_radial_all(&a, r, read_a, read_a + r, read_a + 2u * r));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_radial_all(&b, r, read_b, read_b + r, read_b + 2u * r));
    TEST_ASSERT_EQUAL_MEMORY(read_b, read_a, 3u * r * sizeof(double));
    write_digest("pointset2d", fnv(h, read_a, 3u * r * sizeof(double)));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_a_1d_object_of_flags_0_gives_the_bits_of_a_direct_only_one);
    RUN_TEST(test_a_2d_object_of_flags_0_gives_the_bits_of_a_direct_only_one);
    return UNITY_END();
}
