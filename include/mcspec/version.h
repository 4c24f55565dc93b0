/* mcspec version: the release this header belongs to, and the release of the
 * library actually linked (mcs_version), so a program can check that they
 * agree. Semantic versioning; while MAJOR is 0 a MINOR release may change
 * the API (CHANGELOG.md says how), a PATCH release never does. */
#ifndef MCSPEC_VERSION_H
#define MCSPEC_VERSION_H

#ifdef __cplusplus
extern "C" {
#endif

#define MCS_VERSION_MAJOR 0
#define MCS_VERSION_MINOR 2
#define MCS_VERSION_PATCH 0
#define MCS_VERSION_STRING "0.2.0"

/* MCS_VERSION_STRING of the library that was linked ("0.2.0"); never NULL.
 * A program built against this header sees MCS_VERSION_STRING here too
 * unless it runs with another libmcspec.so.MAJOR. */
const char *mcs_version(void);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_VERSION_H */
