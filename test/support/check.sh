# shellcheck shell=sh
# Shell helpers shared by the check scripts under test/ (cli_check.sh,
# record_check.sh, renderer_check.sh); each sources this file with
#   . "$(dirname "$0")/support/check.sh"
# then calls check_start NAME once and check_summary last.

# check_start NAME: the scratch directory $tmp (removed however the script
# ends), an empty $tmp/in for run's stdin, and the counters.
check_start() {
    tmp=$(mktemp -d "${TMPDIR:-/tmp}/$1.XXXXXX") || exit 1
    trap 'rm -rf "$tmp"' EXIT INT TERM
    : >"$tmp/in"
    passed=0
    failed=0
}

ok() { passed=$((passed + 1)); }
bad() { failed=$((failed + 1)); echo "FAIL $1"; }
skip() { echo "skip $1"; }

# run CMD...: stdout, stderr and status into $tmp/out, $tmp/err, $rc; stdin
# from $tmp/in (empty unless a check writes it).
run() { "$@" <"$tmp/in" >"$tmp/out" 2>"$tmp/err"; rc=$?; }

# succeeds LABEL CMD...: exit 0, nothing on stderr.
succeeds() {
    label=$1
    shift
    run "$@"
    if [ "$rc" -ne 0 ]; then bad "$label: exit status $rc: $(head -n 2 "$tmp/err")"; return 1; fi
    if [ -s "$tmp/err" ]; then bad "$label: wrote to stderr: $(head -n 2 "$tmp/err")"; return 1; fi
    ok
}

# usage_error LABEL PATTERN CMD...: exit 2, nothing on stdout, exactly one
# line on stderr matching the extended regular expression PATTERN.
usage_error() {
    label=$1 pattern=$2
    shift 2
    run "$@"
    if [ "$rc" -ne 2 ]; then bad "$label: exit status $rc, expected 2"
    elif [ -s "$tmp/out" ]; then bad "$label: wrote to stdout"
    elif [ "$(wc -l <"$tmp/err")" -ne 1 ]; then bad "$label: $(wc -l <"$tmp/err") lines on stderr"
    elif ! grep -Eq -- "$pattern" "$tmp/err"; then bad "$label: message '$(cat "$tmp/err")' lacks /$pattern/"
    else ok; fi
}

# csv_shape LABEL FILE HEADER ROWS FIELDS: the header line exactly, then ROWS
# rows of FIELDS fields, each field after the first a number or empty.
csv_shape() {
    if [ "$(head -n 1 "$2")" = "$3" ]; then ok; else bad "$1: header '$(head -n 1 "$2")'"; fi
    problems=$(tail -n +2 "$2" | awk -F, -v rows="$4" -v fields="$5" '
        function num(s) { return s == "" || s ~ /^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$/ }
        NF != fields { printf "row %d: %d fields; ", NR, NF }
        { for (i = 2; i <= NF; ++i) if (!num($i)) printf "row %d field %d \"%s\"; ", NR, i, $i }
        END { if (NR != rows) printf "%d rows, expected %d", NR, rows }')
    if [ -z "$problems" ]; then ok; else bad "$1: $problems"; fi
}

# The Unity-style summary test/run_tests.sh counts ("N Tests F Failures 0
# Ignored", then OK or FAIL); the status is non-zero on any failure.
check_summary() {
    echo "-----------------------"
    echo "$((passed + failed)) Tests $failed Failures 0 Ignored"
    if [ "$failed" -eq 0 ]; then echo "OK"; else echo "FAIL"; fi
    [ "$failed" -eq 0 ]
}
