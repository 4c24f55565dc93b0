#!/bin/sh
# The naming rule and the link-safety rule on the public API (make lint,
# make check-install).
#
#   tools/check_api.sh [-c 'CC CPPFLAGS'] [-d INCLUDE_DIR] [-n NM] [-p PENDING]
#                      [-o 'OBJECT...'] [LIBRARY...]
#
# 1. Names. Every function or object declared in INCLUDE_DIR/mcspec/<m>.h is
#    named mcs_<m>_... or exactly mcs_<m> (mcs_version in version.h); the
#    closed forms of eq.h may also carry their equation number, mcs_eq<NN>_...
#    PENDING (default: none) lists names allowed to break the rule for now,
#    one per line; an entry that no longer breaks it is an error too, so the
#    list can only shrink.
# 2. Objects (-o: the library's objects before the archive step). Every
#    global symbol they define starts with mcs_: even a build that skips the
#    localisation step (a copy of the sources) cannot clash with another
#    library's names. KissFFT's names are renamed by the build (KISS_RENAME).
# 3. Libraries (a .a or a .so). The symbols each one exports are exactly the
#    public API of step 1: none without a declaration in a public header
#    (so nothing without the mcs_ prefix either), and none of the API missing.
# 4. The adversarial table (-t: test/api/test_adversarial's program). Every
#    function the first library exports (nm type T) has rows in the table
#    (ADVERSARIAL_LIST=1 prints the functions it covers), so a new public
#    function cannot land without its adversarial rows.
# Prints one line per failure and a summary; exit status 1 on any failure.
set -eu
# shellcheck source=tools/common.sh
. "$(dirname "$0")/common.sh"
USAGE="usage: $0 [-c 'cc flags'] [-d dir] [-n nm] [-p pending] [-o 'objects'] [-t table] [library...]"

CPP='cc -Iinclude'
DIR=include
NM='nm'
PENDING=
OBJECTS=
TABLE=
opts_parse "c=CPP d=DIR n=NM p=PENDING o=OBJECTS t=TABLE" "$@"
shift $((OPTIND - 1))

make_tmp
fail=0
here=$(dirname "$0")

sh "$here/api.sh" -c "$CPP" -d "$DIR" list >"$tmp/api"
awk '{ print $2 }' "$tmp/api" | sort -u >"$tmp/names"
if [ -n "$PENDING" ]; then
    sed -e 's/#.*//' -e 's/[[:space:]]//g' -e '/^$/d' "$PENDING" | sort -u >"$tmp/pending"
else
    : >"$tmp/pending"
fi

# 1. The prefix of each name against the header that declares it.
awk '
    FILENAME == ARGV[1] { pending[$1] = 1; next }
    {
        m = $1; name = $2
        ok = (name == "mcs_" m || index(name, "mcs_" m "_") == 1)
        if (!ok && m == "eq" && name ~ /^mcs_eq[0-9]+[a-z]*_/) ok = 1
        if (ok && (name in pending)) { print "names: " name " in " m ".h follows the rule: drop it from the pending list"; bad++ }
        if (!ok && !(name in pending)) { print "names: " name " is declared in " m ".h, so it must be named mcs_" m "_..."; bad++ }
        seen[name] = 1
    }
    END {
        for (p in pending) if (!(p in seen)) { print "names: pending " p " is not declared in any public header"; bad++ }
        exit bad > 0
    }' "$tmp/pending" "$tmp/api" || fail=1
n_api=$(wc -l <"$tmp/names")
n_pending=$(wc -l <"$tmp/pending")

# 2. Global definitions of the raw objects.
if [ -n "$OBJECTS" ]; then
    # shellcheck disable=SC2086 # a list of paths
    "$NM" -P -g --defined-only $OBJECTS | awk '
        /:$/ { obj = $1; sub(/:$/, "", obj); next }
        NF >= 2 && $1 !~ /^mcs_/ { print "objects: " obj " defines the global " $1 " (type " $2 "), not prefixed mcs_"; bad++ }
        END { exit bad > 0 }' || fail=1
fi

# 3. What each library exports, against the API.
for lib in "$@"; do
    case $lib in
    *.so | *.so.*) "$NM" -D -P --defined-only "$lib" ;;
    *) "$NM" -P -g --defined-only "$lib" ;;
    esac | awk 'NF >= 2 && $1 !~ /:$/ { print $1 }' | sort -u >"$tmp/exported"
    comm -23 "$tmp/exported" "$tmp/names" | sed "s|^|exports: $lib exports |; s|$|, which no public header declares|"
    comm -13 "$tmp/exported" "$tmp/names" | sed "s|^|exports: $lib lacks |; s|$|, declared in a public header|"
    if ! cmp -s "$tmp/exported" "$tmp/names"; then fail=1; fi
done

# 4. Every exported function against the adversarial table.
n_table=
if [ -n "$TABLE" ] && [ $# -ge 1 ]; then
    case $1 in
    *.so | *.so.*) "$NM" -D -P --defined-only "$1" ;;
    *) "$NM" -P -g --defined-only "$1" ;;
    esac | awk 'NF >= 2 && $1 !~ /:$/ && $2 == "T" { print $1 }' | sort -u >"$tmp/functions"
    ADVERSARIAL_LIST=1 "$TABLE" | sort -u >"$tmp/table"
    comm -23 "$tmp/functions" "$tmp/table" |
        sed 's|^|table: |; s|$| has no rows in the adversarial table (test/support/adv_table_*.c)|'
    comm -13 "$tmp/functions" "$tmp/table" |
        sed 's|^|table: the adversarial table has rows for |; s|$|, which the library does not export|'
    if ! cmp -s "$tmp/functions" "$tmp/table"; then fail=1; fi
    n_table=$(wc -l <"$tmp/functions")
fi

if [ "$fail" -ne 0 ]; then
    echo "check-api FAILED"
    exit 1
fi
echo "check-api OK: $n_api public names named after their header ($n_pending pending rename)${OBJECTS:+, every global of the objects prefixed mcs_}${1:+, exported exactly by $*}${n_table:+, each of the $n_table functions with adversarial rows}"
