#!/bin/sh
# What make bench (mk/bench.mk) needs besides the library: libfftw3-dev for
# the FFTW peer and a python3 that imports numpy for the numpy peer. Debian's
# python3-numpy installs for /usr/bin/python3, which need not be the python3
# first on PATH, so every candidate interpreter is asked.
#
#   tools/bench_deps.sh install CC   apt-get what is missing (root, or sudo
#                                    without a password); apt-get update once first
#   tools/bench_deps.sh fftw CC      print 1 if CC compiles and links a fftw3
#                                    program, else 0
#   tools/bench_deps.sh python       print the first interpreter that imports
#                                    numpy, or nothing
set -u

fftw_ok() {
    probe=$(mktemp -d) || return 1
    printf '#include <fftw3.h>\nint main(void) { fftw_cleanup(); return 0; }\n' >"$probe/p.c"
    # $1 may carry words (CC="ccache gcc"): split on purpose.
    # shellcheck disable=SC2086
    $1 "$probe/p.c" -o "$probe/p" -lfftw3 >/dev/null 2>&1
    rc=$?
    rm -rf "$probe"
    return $rc
}

numpy_python() {
    candidates=/usr/bin/python3
    old_ifs=$IFS
    IFS=:
    for dir in $PATH; do
        [ -n "$dir" ] && [ -x "$dir/python3" ] && candidates="$candidates $dir/python3"
    done
    IFS=$old_ifs
    for py in $candidates; do
        if [ -x "$py" ] && "$py" -c 'import numpy' >/dev/null 2>&1; then
            echo "$py"
            return 0
        fi
    done
    return 1
}

install() {
    missing=
    fftw_ok "$1" || missing=" libfftw3-dev"
    numpy_python >/dev/null || missing="$missing python3-numpy"
    [ -n "$missing" ] || return 0
    if [ "$(id -u)" -eq 0 ]; then
        sudo=
    elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
        sudo=sudo
    else
        echo "bench: missing$missing; not root, so the peers that need them are skipped"
        return 0
    fi
    echo "bench: installing$missing with apt-get"
    # shellcheck disable=SC2086
    if ! { DEBIAN_FRONTEND=noninteractive $sudo apt-get update -qq &&
           DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends \
               $missing >/dev/null; }; then
        echo "bench: apt-get failed; the peers that need$missing are skipped"
    fi
    return 0
}

case "${1:-}" in
install) install "${2:-cc}" ;;
fftw) if fftw_ok "${2:-cc}"; then echo 1; else echo 0; fi ;;
python) numpy_python || true ;;
*) echo "usage: $0 install CC | fftw CC | python" >&2; exit 2 ;;
esac
