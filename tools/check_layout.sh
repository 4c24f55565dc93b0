#!/bin/sh
# The library's layout (CONTRIBUTING.md): sources in one folder per family,
# families in the order of the data flow, and every dependency pointing down.
#
#   tools/check_layout.sh [-n NM] [OBJECT...]
#
# Fails (exit 1, one line per finding) when
#   - a .c or .h file sits directly under src/, or a folder of src/ is not a
#     family listed below (vendored code stays under src/vendor/);
#   - a file includes a private header of a family above its own
#     ("family/name.h" names another family; a bare "name.h" must be in the
#     file's own folder), or a private header that does not exist;
#   - the file-level include graph has a cycle;
#   - given the library's objects, a file calls a function defined in a file
#     of a family above its own, or the file-level call graph has a cycle.
# The families, lowest first: a family may use the ones before it.
FAMILIES="core random dft patterns accumulators pointsets measures theory io"
set -u
export LC_ALL=C
nm_cmd=nm
if [ "${1:-}" = "-n" ]; then nm_cmd=$2; shift 2; fi
cd "$(dirname "$0")/.." || exit 1
fail=0
finding() { echo "check-layout: $*"; fail=1; }

rank() {
    r=0
    for f in $FAMILIES; do
        [ "$f" = "$1" ] && { echo "$r"; return; }
        r=$((r + 1))
    done
    echo -1
}

for f in src/*.c src/*.h; do
    [ -e "$f" ] && finding "$f: sources live in their family's folder (src/<family>/), not directly under src/"
done
for d in src/*/; do
    fam=$(basename "$d")
    [ "$fam" = vendor ] && continue
    [ "$(rank "$fam")" -ge 0 ] || finding "src/$fam/: not a family of this script's list ($FAMILIES); add it in its place there and in CONTRIBUTING.md"
done

# Include edges, one "from to" per line (paths under src/); an include names
# a private header as "family/name.h" or, in its own family, "name.h".
# MCS_SIMD_BODY names a kernel body that core/simd_clones.h includes.
edges=$(mktemp)
calls=$(mktemp)
trap 'rm -f "$edges" "$calls"' EXIT
for file in src/*/*.c src/*/*.h; do
    case $file in src/vendor/*) continue ;; esac
    fam=${file#src/}; fam=${fam%%/*}
    sed -n 's/^[ \t]*#[ \t]*include[ \t]*"\([^"]*\)".*/\1/p; s/^[ \t]*#[ \t]*define[ \t]*MCS_SIMD_BODY[ \t]*"\([^"]*\)".*/\1/p' "$file" |
        while read -r inc; do
            case $inc in
            mcspec/* | mcspec.h | kiss_fft.h | kiss_fft.c | kiss_fftr.h) continue ;;
            */*) target=src/$inc ;;
            *) target=src/$fam/$inc ;;
            esac
            if [ ! -f "$target" ]; then
                echo "MISSING $file $inc"
                continue
            fi
            echo "$file $target"
        done
done >"$edges"
grep '^MISSING ' "$edges" | while read -r _ file inc; do
    echo "check-layout: $file includes \"$inc\", which is no private header: name another family's header as \"family/name.h\""
done | grep . && fail=1
sed -i '/^MISSING /d' "$edges"

# Direction: the target's family must not rank above the includer's.
check_direction() {  # $1: what the edges are ("includes", "calls into")
    while read -r from to; do
        ff=${from#src/}; ff=${ff%%/*}
        tf=${to#src/}; tf=${tf%%/*}
        if [ "$(rank "$tf")" -gt "$(rank "$ff")" ]; then
            echo "check-layout: $from ($ff) $1 $to ($tf), a family above its own"
        fi
    done
}
bad=$(check_direction includes <"$edges")
[ -n "$bad" ] && { echo "$bad"; fail=1; }

# Cycles: tsort fails on a loop and names the files on it.
if ! tsort "$edges" >/dev/null 2>"$edges.err"; then
    finding "the include graph has a cycle:"
    sed 's/^/    /' "$edges.err"
fi
rm -f "$edges.err"

# Calls between files, from the objects' symbols: an undefined symbol of one
# object defined by another (static helpers are not visible, and need not be).
if [ $# -gt 0 ]; then
    defs=$(mktemp)
    for o in "$@"; do
        src=$(echo "$o" | sed -n 's,.*/obj/\(src/[a-z0-9_]*/[a-z0-9_]*\)\.o$,\1.c,p')
        [ -n "$src" ] || continue
        case $src in src/vendor/*) continue ;; esac
        "$nm_cmd" --defined-only "$o" | awk -v s="$src" 'NF == 3 && $2 ~ /^[TDRB]$/ {print $3, s}'
    done | sort -u >"$defs"
    for o in "$@"; do
        src=$(echo "$o" | sed -n 's,.*/obj/\(src/[a-z0-9_]*/[a-z0-9_]*\)\.o$,\1.c,p')
        [ -n "$src" ] || continue
        case $src in src/vendor/*) continue ;; esac
        "$nm_cmd" -u "$o" | awk '{print $NF}' | sort -u | join - "$defs" |
            awk -v s="$src" '$2 != s {print s, $2}'
    done | sort -u >"$calls"
    rm -f "$defs"
    bad=$(check_direction "calls into" <"$calls")
    [ -n "$bad" ] && { echo "$bad"; fail=1; }
    if ! tsort "$calls" >/dev/null 2>"$calls.err"; then
        finding "the call graph between files has a cycle:"
        sed 's/^/    /' "$calls.err"
    fi
    rm -f "$calls.err"
fi

if [ "$fail" -eq 0 ]; then
    n_inc=$(wc -l <"$edges")
    n_call=$(wc -l <"$calls")
    echo "check-layout OK: $(echo "$FAMILIES" | wc -w) families ($FAMILIES), $n_inc private includes and $n_call calls between files, all downward or within a family, no cycle"
fi
exit "$fail"
