#!/bin/sh
# Archiver for the check-alloc runtime build (mk/embedded.mk passes it as AR):
# runs ar as asked, then renames every allocator reference in the archive to
# the counting versions in tools/malloc_count.c (malloc -> mcs_count_malloc,
# ...). Only the library's objects are renamed, so only allocations made by
# library code are counted.
#   usage: tools/ar_counted.sh rcs ARCHIVE OBJECT...
set -eu
: "${REAL_AR:=ar}"
: "${OBJCOPY:=objcopy}"
"$REAL_AR" "$@"
archive=$2
redefs=
for s in malloc calloc realloc reallocarray free aligned_alloc posix_memalign memalign valloc \
         strdup strndup; do
    redefs="$redefs --redefine-sym $s=mcs_count_$s"
done
# shellcheck disable=SC2086 # word splitting of the option list is intended
"$OBJCOPY" $redefs "$archive"
