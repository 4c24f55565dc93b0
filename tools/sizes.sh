#!/bin/sh
# sizeof every public struct (make sizes), without running anything: for each
# "typedef struct { ... } mcs_x;" in the public headers it compiles
# "char mcs_sizeof_x[sizeof(mcs_x)];" with each compiler and flag set given,
# and reads the sizes back with nm -S. So it works for cross compilers too.
#
#   tools/sizes.sh OUTDIR "label|cc|nm|flags" ...
set -eu
out=$1
shift
mkdir -p "$out"
names=$(awk '/^typedef struct/ { s = 1 } s && /^} mcs_[a-z0-9_]*;/ { n = $2; sub(/;.*/, "", n); print n; s = 0 }' \
    include/mcspec/*.h)
{
    echo '#include "mcspec.h"'
    for n in $names; do echo "char ${n}_sizeof_[sizeof(${n})];"; done
} >"$out/sizes.c"

i=0
header=$(printf '%-16s' struct)
for spec in "$@"; do
    i=$((i + 1))
    label=${spec%%|*}; rest=${spec#*|}
    cc=${rest%%|*}; rest=${rest#*|}
    nm=${rest%%|*}; flags=${rest#*|}
    # shellcheck disable=SC2086 # flags are a word list
    $cc -std=c11 -Iinclude $flags -fno-common -c "$out/sizes.c" -o "$out/sizes$i.o"
    "$nm" -S -P "$out/sizes$i.o" | awk '$1 ~ /_sizeof_$/ { n = $1; sub(/_sizeof_$/, "", n); printf "%s %d\n", n, ("0x" $4) + 0 }' \
        >"$out/sizes$i.txt"
    header="$header | $label"
done
echo "$header"
for n in $names; do
    line=$(printf '%-16s' "$n")
    j=1
    while [ $j -le $i ]; do
        v=$(awk -v n="$n" '$1 == n { print $2 }' "$out/sizes$j.txt")
        line="$line | $(printf '%s' "$v" | awk '{ if ($1 >= 10240) printf "%d (%.0f KiB)", $1, $1 / 1024; else printf "%d", $1 }')"
        j=$((j + 1))
    done
    echo "$line"
done
