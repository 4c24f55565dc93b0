#!/bin/sh
# The public API of mcspec, read from the public headers.
#
#   tools/api.sh [-c 'CC CPPFLAGS'] [-d INCLUDE_DIR] list|names
#
# Each header INCLUDE_DIR/mcspec/*.h (default include) is run through the
# preprocessor (default 'cc -Iinclude'; pass the library's own flags, so that
# macros such as config.h's capacity tag expand as in the library build).
# The declarations that come from the header itself (found by the line
# markers, not from the headers it includes) are split into top-level
# statements; typedefs, static functions and struct bodies are skipped, and
# what is left is a function (the first mcs_ name followed by "(") or an
# extern object (an extern statement ending in an mcs_ name).
#   list   one line per declaration: "<header basename> <name>"
#   names  the names alone, sorted (the archive's keep list, the .so's
#          version script)
# Exit status 1 if a header fails to preprocess or if no declaration at all
# is found (a parser that silently found nothing would let every check
# downstream pass).
set -eu

CPP='cc -Iinclude'
DIR=include
while getopts c:d: opt; do
    case $opt in
    c) CPP=$OPTARG ;;
    d) DIR=$OPTARG ;;
    *) echo "usage: $0 [-c 'cc flags'] [-d include-dir] list|names" >&2; exit 2 ;;
    esac
done
shift $((OPTIND - 1))
mode=${1:-list}
case $mode in list | names) ;; *) echo "$0: unknown mode $mode" >&2; exit 2 ;; esac

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM
: >"$tmp/list"
for h in "$DIR"/mcspec/*.h; do
    base=$(basename "$h" .h)
    # shellcheck disable=SC2086 # CPP is a command and its flags
    $CPP -E -x c "$h" >"$tmp/pp" || { echo "$0: cannot preprocess $h" >&2; exit 1; }
    awk -v hdr="$base" -v want="$(basename "$h")" '
        # Line markers: # <line> "<file>" [flags]. Keep text of this header only.
        /^# [0-9]+ "/ {
            f = $3; gsub(/"/, "", f); n = split(f, parts, "/")
            inside = (parts[n] == want && f ~ /mcspec\//)
            text = text " "        # a statement never spans an #include
            next
        }
        inside { text = text " " $0 }
        function emit(stmt,    name) {
            gsub(/[ \t]+/, " ", stmt); sub(/^ /, "", stmt); sub(/ $/, "", stmt)
            if (stmt == "" || stmt ~ /^(typedef|static)[^A-Za-z0-9_]/) return
            if (match(stmt, /mcs_[A-Za-z0-9_]*[ ]*\(/)) {
                name = substr(stmt, RSTART, RLENGTH); sub(/[ ]*\($/, "", name)
                print hdr, name; return
            }
            if (stmt ~ /^extern / && match(stmt, /mcs_[A-Za-z0-9_]*[ ]*(\[[^]]*\])?$/)) {
                name = substr(stmt, RSTART, RLENGTH); sub(/[ ]*\[.*$/, "", name)
                print hdr, name
            }
        }
        END {
            depth = 0; stmt = ""
            len = length(text)
            for (i = 1; i <= len; i++) {
                c = substr(text, i, 1)
                if (c == "{") {
                    # A function body at top level ends the declaration before it.
                    if (depth == 0 && stmt ~ /\)[ ]*$/ && stmt !~ /^[ ]*(typedef|struct|union|enum)[^A-Za-z0-9_]/) {
                        emit(stmt); stmt = ""; skipbody = 1
                    }
                    depth++; continue
                }
                if (c == "}") {
                    depth--
                    if (depth == 0 && skipbody) { skipbody = 0; stmt = "" }
                    continue
                }
                if (depth > 0) continue
                if (c == ";") { emit(stmt); stmt = ""; continue }
                stmt = stmt c
            }
            emit(stmt)
        }' "$tmp/pp" >>"$tmp/list"
done
[ -s "$tmp/list" ] || { echo "$0: no declaration found under $DIR/mcspec" >&2; exit 1; }
if [ "$mode" = list ]; then
    sort -u "$tmp/list"
else
    awk '{ print $2 }' "$tmp/list" | sort -u
fi
