/* For the tests of a library built with or without the NUFFT
 * (MCS_CONFIG_NUFFT, config.h; make test-nonufft builds the second):
 * MCS_TEST_NEEDS_NUFFT() skips a test of the NUFFT itself with a printed
 * reason in the build without it, and MCS_TEST_LAST_PATH is the last path a
 * loop over DIRECT..NUFFT can take there. */
#ifndef MCSPEC_TEST_NUFFT_SKIP_H
#define MCSPEC_TEST_NUFFT_SKIP_H

#include "mcspec/config.h"
#include "mcspec/pointset.h"
#include "unity.h"

#if MCS_CONFIG_NUFFT
#define MCS_TEST_NEEDS_NUFFT() ((void)0)
#define MCS_TEST_LAST_PATH MCS_POINTSET_PATH_NUFFT
#else
#define MCS_TEST_NEEDS_NUFFT()                                                             \
    TEST_IGNORE_MESSAGE("library built with MCS_CONFIG_NUFFT 0: no NUFFT to test")
#define MCS_TEST_LAST_PATH MCS_POINTSET_PATH_DIRECT
#endif

#endif /* MCSPEC_TEST_NUFFT_SKIP_H */
