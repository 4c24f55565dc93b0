#!/bin/sh
# The Python package's tests, as `make test` runs them: pytest over
# python/tests with the build tree's library (MCSPEC_LIBRARY) and command
# (MCSPEC), under the first interpreter that imports numpy and pytest
# (python/find_python.sh). Without one, or under SAN=1 (an instrumented
# libmcspec.so cannot load into an uninstrumented python), it prints one line
# saying the tests were skipped and why, and succeeds.
#   sh python/tests/run.sh LIBRARY MCSPEC [SAN]
lib=$1 cli=$2 san=${3:-}
here=$(dirname "$0")
if [ "$san" = 1 ]; then
    echo "python: tests skipped: SAN=1 builds an instrumented libmcspec.so that python cannot load"
    exit 0
fi
py=$(sh "$here/../find_python.sh" pytest) || {
    echo "python: tests skipped: no python3 that imports numpy and pytest (tried \$PYTHON, python3 on PATH, /usr/bin/python3; Debian: apt-get install python3-numpy python3-pytest)"
    exit 0
}
echo "== python/tests ($py, $lib)"
MCSPEC_LIBRARY=$lib MCSPEC=$cli PYTHONPATH="$here/..${PYTHONPATH:+:$PYTHONPATH}" \
    PYTHONDONTWRITEBYTECODE=1 "$py" -m pytest -q -p no:cacheprovider "$here"
