#!/bin/sh
# Static half of the allocation-free claim: every external symbol an archive
# (or object, or linked image) references must be on an allow-list.
#
#   tools/check_alloc.sh [-n NM] [-a ALLOWLIST] [-r RUNTIME_LIB] [-l LABEL] FILE...
#
# A symbol referenced (nm -u) by a member of FILE and defined by no member of
# any FILE is "external". It passes if it is listed in ALLOWLIST (default
# tools/alloc_allowlist.txt) or, with -r, defined by RUNTIME_LIB (the
# compiler's libgcc: soft-float and division helpers such as __aeabi_dmul).
# Allocation, stdio, process exit and similar names fail even if RUNTIME_LIB
# happens to define them. Each failure names the symbol and the object that
# references it; the exit status is 1 if there is any.
set -eu
# shellcheck source=tools/common.sh
. "$(dirname "$0")/common.sh"
USAGE="usage: $0 [-n nm] [-a allowlist] [-r runtime-lib] [-l label] file..."

NM='nm'
ALLOW="$(dirname "$0")/alloc_allowlist.txt"
RUNTIME=
LABEL=
opts_parse "n=NM a=ALLOW r=RUNTIME l=LABEL" "$@"
shift $((OPTIND - 1))
[ $# -ge 1 ] || fail_exit 2 "check_alloc: no input file"
for f in "$@"; do
    [ -r "$f" ] || fail_exit 2 "check_alloc: cannot read $f"
done
[ -n "$LABEL" ] || LABEL=$*

make_tmp

# Defined anywhere in the inputs (any type but U/w/v-undefined).
"$NM" -A -P --defined-only "$@" 2>/dev/null | awk '{ print $2 }' | sort -u >"$tmp/defined"
# Undefined references, as "object symbol".
"$NM" -A -P -u "$@" 2>/dev/null | awk '{
    obj = $1; sub(/:$/, "", obj)
    if (match(obj, /\[[^]]*\]$/)) obj = substr(obj, RSTART + 1, RLENGTH - 2)
    print obj, $2 }' | sort -u >"$tmp/refs"
sed -e 's/#.*//' -e 's/[[:space:]]//g' -e '/^$/d' "$ALLOW" | sort -u >"$tmp/allow"
if [ -n "$RUNTIME" ]; then
    "$NM" -P --defined-only "$RUNTIME" 2>/dev/null | awk 'NF >= 2 && $2 ~ /^[TtWwDdRrBbVv]$/ { print $1 }' |
        sort -u >"$tmp/runtime"
else
    : >"$tmp/runtime"
fi

awk -v label="$LABEL" '
    FILENAME == ARGV[1] { defined[$1] = 1; next }
    FILENAME == ARGV[2] { allow[$1] = 1; next }
    FILENAME == ARGV[3] { runtime[$1] = 1; next }
    {
        obj = $1; sym = $2
        if (sym in defined) next
        forbidden = (sym ~ /^_*(malloc|calloc|realloc|reallocarray|free|cfree|alloca|aligned_alloc|posix_memalign|memalign|valloc|pvalloc|strdup|strndup|sbrk|_sbrk|brk|mmap|abort|exit|_exit|_Exit|quick_exit|atexit|at_quick_exit|assert|__assert_fail|__assert_func|__assert|raise|signal|longjmp|setjmp|system|getenv|errno|__errno|__errno_location|__stack_chk_fail)(_r)?$/ ||
                     sym ~ /^_*(v?[fsd]?n?printf|v?[fs]?scanf|f?puts|f?putc|putchar|getchar|f?getc|fgets|fopen|fclose|fflush|fread|fwrite|fseek|ftell|perror|setvbuf|setbuf|stdin|stdout|stderr|__printf_chk|__fprintf_chk|__sprintf_chk|__snprintf_chk|_impure_ptr|_reent|_global_impure_ptr)(_r)?$/ ||
                     sym ~ /_malloc_r$|_free_r$|_calloc_r$|_realloc_r$/)
        if (forbidden) { bad[++nbad] = sym " (forbidden: allocation, I/O or process control) referenced by " obj; next }
        if (sym in allow) { used[sym] = 1; next }
        if (sym in runtime) { helper[sym] = 1; next }
        bad[++nbad] = sym " (not on the allow-list) referenced by " obj
    }
    END {
        n = 0; list = ""
        for (s in used) names[++n] = s
        for (i = 2; i <= n; i++) {          # insertion sort: stable output
            v = names[i]; j = i - 1
            while (j > 0 && names[j] > v) { names[j + 1] = names[j]; j-- }
            names[j + 1] = v
        }
        for (i = 1; i <= n; i++) list = list " " names[i]
        h = 0; for (s in helper) h++
        if (nbad > 0) {
            printf "check-alloc FAILED for %s:\n", label
            for (i = 1; i <= nbad; i++) printf "  %s\n", bad[i]
            exit 1
        }
        printf "check-alloc OK for %s: %d allowed external symbols (%s )", label, n, list
        if (h > 0) printf ", %d compiler runtime helpers", h
        printf "\n"
    }
' "$tmp/defined" "$tmp/allow" "$tmp/runtime" "$tmp/refs"
