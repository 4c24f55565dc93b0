#!/bin/sh
# Run-time half of make check-alloc: runs the tests (and the section
# examples' command-line checks, if test/examples_check.sh exists) and every
# example with its defaults, all built against the counting archive (see
# tools/ar_counted.sh, tools/malloc_count.c), then checks that every program
# reported a count and that every count is zero.
#
#   tools/check_alloc_run.sh LOG TEST... -- EXAMPLE...
# $EXAMPLES: the section examples for test/examples_check.sh.
set -u
log=$1
shift
tests=
while [ $# -gt 0 ] && [ "$1" != "--" ]; do tests="$tests $1"; shift; done
[ $# -gt 0 ] && shift
examples=$*
out=$(dirname "$log")
rm -f "$log"
export MCS_MALLOC_LOG="$log"
rc=0

checker=
[ -f test/examples_check.sh ] && [ -n "${EXAMPLES:-}" ] && checker=test/examples_check.sh
# shellcheck disable=SC2086 # lists of paths
if ! sh test/run_tests.sh $tests $checker >"$out/tests.out" 2>&1; then
    rc=1
    cat "$out/tests.out"
    echo "check-alloc: tests failed in the counting build"
fi
tail -n 1 "$out/tests.out"
for b in $examples; do
    if ! "$b" >"$b.out" 2>&1; then
        rc=1
        cat "$b.out"
        echo "check-alloc: $b failed in the counting build"
    fi
done

# Every test and example must have reported at least once (a program that
# does not link the counter, or dies before exit, would not).
missing=0
for b in $tests $examples; do
    abs=$(cd "$(dirname "$b")" && pwd)/$(basename "$b")
    if ! awk -v p="$abs" '$2 == p { found = 1 } END { exit !found }' "$log" 2>/dev/null; then
        echo "check-alloc FAILED: $b reported no count"
        missing=1
    fi
done
[ "$missing" -eq 0 ] || rc=1
if [ -f "$log" ]; then
    awk '{ runs++; s += $1; prog[$2] = 1
           if ($1 > 0) print "check-alloc FAILED: " $2 ": " $1 " allocator call(s) from library code" }
         END { n = 0; for (p in prog) n++
               if (s > 0) exit 1
               printf "check-alloc OK at run time: %d runs of %d programs, 0 allocator calls from library code\n", runs, n }' \
        "$log" || rc=1
fi
exit "$rc"
