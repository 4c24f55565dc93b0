/* A spectrum record's bytes depend on the data and the path only, not on the
 * build's capacities: the same trials give the same record at the default
 * MCS_MAX_N and at -DMCS_MAX_N=256 or 64 (the block-phase kernel's chunk of
 * samples, and the pair path's chunk of binned points, used to follow
 * MCS_MAX_N: 64 samples at the default, 16 below 1024, so records of a
 * forced path differed with more than 16 samples or non-zero bins). The
 * expected CRC-32s were computed at the default capacity; N = 61 is prime,
 * so its transforms are the direct sums over the library's own twiddle
 * table (no KissFFT), and small enough for every capacity.
 *
 * Every build of the same source runs this: the record CRCs hold wherever
 * the twiddle table (the platform's cos and sin) is glibc's to the last bit
 * (checked first: otherwise the test is ignored, its expectations being
 * glibc's), the FFT and pair paths with the KissFFT back end only (FFTW
 * builds, make FFT=fftw, transform by FFTW: the sparse path alone is
 * checked there); the pair path's batches are the same in every build.
 * docs/format.md, "Reproducibility across builds", says how far records of
 * other builds may differ. */
#include "mcspec.h"
#include "unity.h"

#include <stdio.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define N 61u

static mcs_spectrum acc;
static unsigned char record[1u << 14];
static size_t bins[128];
static double weights[128], points[128];

static uint32_t crc_of(const void *data, size_t len)
{
    uint32_t crc = 0u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_crc32(len, data, &crc));
    return crc;
}

/* The CRC-32 of the record of `trials` trials of k samples on the path,
 * from bins (input 0) or from points (1), with weights in [0.5, 1.5) drawn
 * as multiples of 2^-32. */
static uint32_t record_crc_of(mcs_spectrum_path path, size_t k, int input, int trials)
{
    mcs_rng rng;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, 2026u + k, 22u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc, N));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_set_path(&acc, path));
    for (int t = 0; t < trials; ++t) {
        for (size_t j = 0; j < k; ++j) {
            uint32_t u, v;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_u32(&rng, &u));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_u32(&rng, &v));
            points[j] = (double)u * 0x1p-32;
            bins[j] = (size_t)u % N;
            weights[j] = 0.5 + (double)v * 0x1p-32;
        }
        TEST_ASSERT_EQUAL_INT(MCS_OK, input == 0 ? mcs_spectrum_add_bins(&acc, k, bins, weights)
                                                 : mcs_spectrum_add_points(&acc, k, points, weights));
    }
    size_t len = 0u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_save_spectrum(&acc, sizeof record, record, &len));
    return crc_of(record, len - 4u); /* the record's own CRC-32 (its last 4 bytes) */
}

static uint32_t record_crc(mcs_spectrum_path path, size_t k, int input)
{
    return record_crc_of(path, k, input, 30);
}

/* Skips the test unless the twiddle table of N is the one the CRCs were
 * computed with. */
static void require_reference_twiddles(void)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc, N));
    const uint32_t c = crc_of(acc.plan.cos_table, N * sizeof(double));
    const uint32_t s = crc_of(acc.plan.sin_table, N * sizeof(double));
    if (c != 0xa1f46230u || s != 0xca190dfcu)
        TEST_IGNORE_MESSAGE("cos and sin here differ from glibc's in the last bit: the "
                            "expected record CRCs do not apply");
}

typedef struct {
    mcs_spectrum_path path;
    size_t k;
    int input;
    uint32_t crc;
} expected_record;

static const expected_record expected[] = {
    {MCS_SPECTRUM_PATH_SPARSE, 8u, 0, 0x555dfd83u},   {MCS_SPECTRUM_PATH_SPARSE, 40u, 0, 0xf940b8fau},
    {MCS_SPECTRUM_PATH_SPARSE, 100u, 1, 0x69e797d5u}, {MCS_SPECTRUM_PATH_FFT, 40u, 0, 0xa260ff9au},
    {MCS_SPECTRUM_PATH_FFT, 100u, 1, 0x43e63b82u},    {MCS_SPECTRUM_PATH_PAIR, 40u, 0, 0x34614678u},
    {MCS_SPECTRUM_PATH_PAIR, 40u, 1, 0x546bd259u},    {MCS_SPECTRUM_PATH_PAIR, 100u, 1, 0x8606d047u},
    {MCS_SPECTRUM_PATH_AUTO, 40u, 1, 0x546bd259u},    {MCS_SPECTRUM_PATH_AUTO, 100u, 0, 0xb0a4e387u}};

static void test_records_of_every_path_are_those_of_the_default_capacity(void)
{
    require_reference_twiddles();
    const int kiss = strcmp(mcs_dft_backend(), "kissfft") == 0;
    char msg[96];
    for (size_t i = 0; i < sizeof expected / sizeof expected[0]; ++i) {
        const expected_record *e = &expected[i];
        if (!kiss && e->path != MCS_SPECTRUM_PATH_SPARSE)
            continue;
        const uint32_t crc = record_crc(e->path, e->k, e->input);
        snprintf(msg, sizeof msg, "path %d, k %zu, input %d: CRC 0x%08x", (int)e->path, e->k,
                 e->input, (unsigned)crc);
        TEST_ASSERT_EQUAL_HEX32_MESSAGE(e->crc, crc, msg);
    }
}

/* The pair path closes a batch once its pairs pay for the close (rule (a),
 * spectrum.h), by a cost model whose constants are those of one reference
 * machine: they used to be this CPU's and back end's, so the same 1500
 * trials made 70 units with the AVX2 kernels, 60 without them and 52 with
 * FFTW, and records with other standard errors. */
static void test_pair_batches_are_the_same_on_every_cpu_and_back_end(void)
{
    const uint32_t crc = record_crc_of(MCS_SPECTRUM_PATH_PAIR, 40u, 0, 1500);
    uint64_t units = 0u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_units(&acc, &units));
    TEST_ASSERT_EQUAL_UINT64(70u, units);
    require_reference_twiddles();
    if (strcmp(mcs_dft_backend(), "kissfft") == 0)
        TEST_ASSERT_EQUAL_HEX32(0xab826025u, crc);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_records_of_every_path_are_those_of_the_default_capacity);
    RUN_TEST(test_pair_batches_are_the_same_on_every_cpu_and_back_end);
    return UNITY_END();
}
