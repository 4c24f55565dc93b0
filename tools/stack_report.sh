#!/bin/sh
# Stack report for the library (make stack).
#
#   tools/stack_report.sh [-l LIMIT] [-d DEPTH] [-n N] [-p PUBLIC_HEADERS_DIR] [-e ROOTS] DIR
#
# Reads every .su (gcc -fstack-usage) and .ci (gcc -fcallgraph-info=su) file
# under DIR. Prints the largest frames and, for every public function (a name
# declared in the headers under PUBLIC_HEADERS_DIR, default include/mcspec),
# the deepest static call chain: its own frame plus the worst chain of its
# callees, summed along the call graph of all library objects. -e names the
# roots instead (comma-separated, e.g. Reset_Handler for a firmware image).
# - Calls to functions outside the library (libm, memset) add nothing: their
#   stack is the C library's, outside this check; they are listed as "+ext".
# - Calls through a function pointer (a caller's integrand) are not followed.
# - A recursive call (KissFFT's kf_work, once per radix stage) counts its
#   cycle DEPTH times (default 8: N <= 4096 factors into at most 7 stages).
# Fails (exit 1) if any frame exceeds LIMIT bytes (default 1024) or is
# dynamic (alloca or VLA), or if there are no .su files.
set -eu
# shellcheck source=tools/common.sh
. "$(dirname "$0")/common.sh"
USAGE="usage: $0 [-l limit] [-d depth] [-n top] [-p headers-dir] [-e roots] dir"

LIMIT=1024
DEPTH=8
TOP=8
HDRS=include/mcspec
ROOTS=
opts_parse "l=LIMIT d=DEPTH n=TOP p=HDRS e=ROOTS" "$@"
shift $((OPTIND - 1))
[ $# -eq 1 ] || usage_exit
dir=$1

su_files=$(find "$dir" -name '*.su' | sort)
[ -n "$su_files" ] || fail_exit 1 "stack: no .su files under $dir"
ci_files=$(find "$dir" -name '*.ci' | sort)

make_tmp

# Roots: every mcs_xxx( in the public headers, or the -e list.
if [ -n "$ROOTS" ]; then
    echo "$ROOTS" | tr ',' '\n' >"$tmp/public"
else
    grep -ho 'mcs_[a-z0-9_]*[[:space:]]*(' "$HDRS"/*.h 2>/dev/null | sed 's/[[:space:]]*($//' |
        sort -u >"$tmp/public"
fi

# Frames: "bytes qualifiers function file:line".
# shellcheck disable=SC2086 # file list
cat $su_files | awk -F '\t' '{
    n = split($1, a, ":"); fn = a[n]; loc = a[1] ":" a[2]
    sub(/^.*\//, "", loc)
    print $2, $3, fn, loc }' | sort -k1,1nr >"$tmp/frames"

echo "Largest stack frames (bytes, gcc -fstack-usage):"
head -n "$TOP" "$tmp/frames" | awk '{ printf "  %6d  %-34s %s%s\n", $1, $3, $4, ($2 == "static" ? "" : "  (" $2 ")") }'

# Call graph from the .ci files: nodes with a frame size, edges caller callee.
: >"$tmp/graph"
if [ -n "$ci_files" ]; then
    # shellcheck disable=SC2086 # file list
    cat $ci_files | awk '
        /^node:/ {
            t = $0; sub(/.*title: "/, "", t); sub(/".*/, "", t)
            l = $0; sub(/.*label: "/, "", l); sub(/".*/, "", l)
            bytes = -1
            if (match(l, /\\n[0-9]+ bytes/)) { b = substr(l, RSTART + 2, RLENGTH - 2); sub(/ bytes/, "", b); bytes = b + 0 }
            print "N", t, bytes
        }
        /^edge:/ {
            s = $0; sub(/.*sourcename: "/, "", s); sub(/".*/, "", s)
            d = $0; sub(/.*targetname: "/, "", d); sub(/".*/, "", d)
            print "E", s, d
        }' >"$tmp/graph"
fi

awk -v depth="$DEPTH" -v limit="$LIMIT" -v top="$TOP" '
    FILENAME == ARGV[1] { public[$1] = 1; next }
    $1 == "N" { if ($3 >= 0) frame[$2] = $3; else if (!($2 in frame)) ext[$2] = 1; next }
    $1 == "E" { ne[$2]++; edge[$2, ne[$2]] = $3; next }
    function name(t) { sub(/^.*:/, "", t); return t }
    # Deepest chain from f; onstack marks the current path for cycles.
    function worst(f,    i, c, w, best, bestc, own) {
        if (f in memo) return memo[f]
        if (!(f in frame)) { hasext[f] = 1; return 0 }
        onstack[f] = 1
        own = frame[f]; best = 0; bestc = ""
        for (i = 1; i <= ne[f]; i++) {
            c = edge[f, i]
            if (c == f || (c in onstack)) {
                recursive[c] = 1
                w = frame[c] * (depth - 1)
                if (w > best) { best = w; bestc = c " (recursion x" depth - 1 ")" }
                continue
            }
            w = worst(c)
            if (w > best) { best = w; bestc = (chain[c] != "") ? name(c) " > " chain[c] : name(c) (c in frame ? "" : " +ext") }
        }
        delete onstack[f]
        memo[f] = own + best
        chain[f] = bestc
        return memo[f]
    }
    END {
        for (f in frame) {
            if (!(f in public)) continue
            w = worst(f)
            printf "%d\t%s\t%s\n", w, f, chain[f] > "'"$tmp"'/chains"
            np++
        }
        close("'"$tmp"'/chains")
        if (np == 0) { print "stack: no public function found in the call graph" > "/dev/stderr" }
    }
' "$tmp/public" "$tmp/graph"

if [ -s "$tmp/chains" ]; then
    if [ -n "$ROOTS" ]; then what="of $ROOTS"; else what="of public functions"; fi
    echo "Deepest static call chain $what (bytes; own frame + callees):"
    sort -k1,1nr "$tmp/chains" | head -n "$TOP" | awk -F '\t' '{
        printf "  %6d  %s%s\n", $1, $2, ($3 == "" ? "" : " > " $3) }'
    sort -k1,1nr "$tmp/chains" | head -n 1 | awk -F '\t' '{
        printf "Deepest: %s, %d bytes\n", $2, $1 }'
fi

awk -v limit="$LIMIT" '
    $1 > limit { printf "stack FAILED: %s at %s uses %d bytes (limit %d)\n", $3, $4, $1, limit; bad = 1 }
    $2 ~ /dynamic/ { printf "stack FAILED: %s at %s has a dynamic frame (%s): alloca or VLA\n", $3, $4, $2; bad = 1 }
    END { if (bad) exit 1 }
' "$tmp/frames"
max=$(head -n 1 "$tmp/frames" | awk '{ print $1 " bytes (" $3 ")" }')
echo "stack OK: largest frame $max, limit $LIMIT bytes, no dynamic frames"
