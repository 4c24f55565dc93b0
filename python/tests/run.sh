#!/bin/sh
# The Python package's tests, as `make test` runs them: pytest over
# python/tests with the build tree's library (MCSPEC_LIBRARY) and command
# (MCSPEC), under the first interpreter that imports numpy and pytest
# (python/find_python.sh). Without one, or under SAN=1 (an instrumented
# libmcspec.so cannot load into an uninstrumented python), it prints one line
# saying the tests were skipped and why, and succeeds.
# It ends with a Unity-style summary ("N Tests F Failures 0 Ignored") so that
# test/run_tests.sh counts its tests in make test's one total line.
#   sh python/tests/run.sh [LIBRARY [MCSPEC [SAN]]]
# (defaults: $MCSPEC_LIBRARY, $MCSPEC, $SAN from the environment)
lib=${1:-${MCSPEC_LIBRARY:-}} cli=${2:-${MCSPEC:-}} san=${3:-${SAN:-}}
here=$(dirname "$0")
skipped() {
    echo "python: tests skipped: $1"
    echo "0 Tests 0 Failures 0 Ignored"
    exit 0
}
[ "$san" != 1 ] || skipped "SAN=1 builds an instrumented libmcspec.so that python cannot load"
py=$(sh "$here/../find_python.sh" pytest) ||
    skipped "no python3 that imports numpy and pytest (tried \$PYTHON, python3 on PATH, /usr/bin/python3; Debian: apt-get install python3-numpy python3-pytest)"
echo "== python/tests ($py, $lib)"
out=$(MCSPEC_SCRIBBLE=1 MCSPEC_LIBRARY=$lib MCSPEC=$cli PYTHONPATH="$here/..${PYTHONPATH:+:$PYTHONPATH}" \
    PYTHONDONTWRITEBYTECODE=1 "$py" -m pytest -q -p no:cacheprovider "$here" 2>&1)
rc=$?
printf '%s\n' "$out"
line=$(printf '%s\n' "$out" | tail -n 1)
count() { printf '%s\n' "$line" | grep -o "[0-9][0-9]* $1" | grep -o '^[0-9]*'; }
passed=$(count passed) failed=$(count failed) errors=$(count error)
passed=${passed:-0} failed=$((${failed:-0} + ${errors:-0}))
[ "$rc" -eq 0 ] || [ "$failed" -gt 0 ] || failed=1 # pytest failed without a count
echo "$((passed + failed)) Tests $failed Failures 0 Ignored"
[ "$failed" -eq 0 ] && echo OK || echo FAIL
exit "$rc"
