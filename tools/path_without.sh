#!/bin/sh
# Runs a command with a PATH that lacks the optional tools, so that CI can
# show README's two commands need none of them (issue 23: `make test` once
# failed on a machine without gnuplot).
#
#   tools/path_without.sh DIR TOOL... -- COMMAND [ARG...]
#
# DIR is made afresh and filled with a symlink to every program of every
# folder on PATH except the TOOLs (first match wins, as PATH would have it);
# COMMAND then runs with PATH=DIR alone. Fails if a TOOL is still found.
set -eu
dir=$1
shift
drop=
while [ $# -gt 0 ] && [ "$1" != "--" ]; do drop="$drop $1"; shift; done
[ $# -gt 0 ] || { echo "usage: tools/path_without.sh DIR TOOL... -- COMMAND [ARG...]" >&2; exit 2; }
shift
rm -rf "$dir"
mkdir -p "$dir"
old_ifs=$IFS
IFS=:
for d in $PATH; do
    [ -d "$d" ] || continue
    for p in "$d"/*; do
        name=${p##*/}
        [ -x "$p" ] && [ ! -d "$p" ] || continue
        [ -e "$dir/$name" ] && continue
        case " $drop " in *" $name "*) continue ;; esac
        ln -s "$p" "$dir/$name"
    done
done
IFS=$old_ifs
for t in $drop; do
    if PATH=$dir command -v "$t" >/dev/null 2>&1; then
        echo "path_without: $t is still on the reduced PATH" >&2
        exit 1
    fi
done
echo "path_without: running '$*' without:$drop"
PATH=$dir exec "$@"
