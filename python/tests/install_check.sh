#!/bin/sh
# make check-install-python (part of make check-install): the package as
# users get it. Run from the repository root; MAKE may be set.
#  1. make install PREFIX=<tmp>: the package lands in
#     <tmp>/lib/python3/dist-packages/mcspec, and from another directory,
#     with that PYTHONPATH and no MCSPEC_LIBRARY, it imports and loads
#     <tmp>/lib/libmcspec.so.0 ("the installation prefix's lib");
#  2. README's Python quick start (the ```python block after the marker
#     <!-- python-quickstart -->) runs there and writes radial.png (skipped,
#     saying so, without matplotlib);
#  3. pip install ./python --no-build-isolation --no-index (into a
#     temporary prefix, from a copy of python/) imports with
#     MCSPEC_LIBRARY naming the installed library;
#  4. make uninstall leaves no file of the package.
# Prints one line per check and "N passed, N failed"; exit 1 on a failure.
set -u
: "${MAKE:=make}"
root=$(pwd)
py=$(sh python/find_python.sh) || { echo "check-install-python: skipped: no python3 that imports numpy"; exit 0; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/mcspec-python.XXXXXX")
trap 'rm -rf "$tmp"' EXIT INT TERM
passed=0 failed=0
check() {
    label=$1; shift
    if "$@" >"$tmp/log" 2>&1; then passed=$((passed + 1)); echo "ok   $label"
    else failed=$((failed + 1)); echo "FAIL $label"; sed 's/^/     | /' "$tmp/log" | tail -n 15; fi
}
prefix=$tmp/prefix
site=$prefix/lib/python3/dist-packages
check "make install PREFIX=$prefix" $MAKE --no-print-directory install PREFIX="$prefix"
mkdir -p "$tmp/run"
imports() (
    cd "$tmp/run" && env -u MCSPEC_LIBRARY PYTHONPATH="$site" "$py" -c '
import sys, mcspec
assert mcspec.__file__.startswith(sys.argv[1]), mcspec.__file__
assert mcspec.library_source == "the installation prefix'"'"'s lib", mcspec.library_source
assert mcspec.library_path.startswith(sys.argv[2]), mcspec.library_path
print(mcspec.__version__, mcspec.library_path)' "$site" "$prefix/lib"
)
check "the installed package imports and loads the prefix's library" imports
sed -n '/<!-- python-quickstart -->/,/^```$/p' README.md | sed '1,2d;$d' >"$tmp/run/quickstart.py"
quickstart() (
    [ -s "$tmp/run/quickstart.py" ] || { echo "no quick start block in README.md"; return 1; }
    cd "$tmp/run" && env -u MCSPEC_LIBRARY PYTHONPATH="$site" MPLBACKEND=Agg "$py" quickstart.py &&
        [ -s radial.png ]
)
if "$py" -c "import matplotlib" >/dev/null 2>&1; then
    check "README's Python quick start writes radial.png" quickstart
else
    echo "skip README's Python quick start: no matplotlib for $py"
fi
pip_install() (
    cp -r "$root/python" "$tmp/src" && cd "$tmp/src" &&
        "$py" -m pip install . --no-build-isolation --no-index --no-deps --prefix "$tmp/pip" -q &&
        sp=$(dirname "$(dirname "$(find "$tmp/pip" -path '*mcspec/__init__.py' | head -n 1)")") &&
        cd "$tmp/run" && PYTHONPATH=$sp MCSPEC_LIBRARY=$prefix/lib/libmcspec.so.0 "$py" -c '
import sys, mcspec
assert mcspec.__file__.startswith(sys.argv[1]) and mcspec.library_source == "MCSPEC_LIBRARY"
print(mcspec.periodogram(mcspec.sample("random", 2, 8, sets=2), 1).mean)' "$sp"
)
if "$py" -m pip --version >/dev/null 2>&1; then
    check "pip install ./python --no-build-isolation imports with MCSPEC_LIBRARY" pip_install
else
    echo "skip pip install: no pip for $py"
fi
gone() (
    $MAKE --no-print-directory uninstall PREFIX="$prefix" && [ ! -e "$site" ] &&
        [ ! -e "$prefix/lib/python3" ]
)
check "make uninstall removes the package" gone
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
