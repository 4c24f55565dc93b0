#!/bin/sh
# Command-line and output-format checks for the section examples (issue 4).
#
# usage: sh test/examples_check.sh [example binary ...]
#        (default: the binaries in $EXAMPLES, else build/examples/sec*;
#        TRIALS sets the trial count)
#
# For each binary:
#   --help exits 0 and prints a usage line to stdout;
#   bad options (unknown option, missing value, non-number, out-of-range
#   --n, --k, --trials) exit non-zero with a usage message on stderr and
#   nothing on stdout;
#   --csv prints exactly the required header line, then rows of exactly 15
#   fields whose n and k columns echo the options, whose verdict is one of
#   holds, limit, approx, fails or empty, and whose numeric fields parse as
#   numbers (or are empty);
#   the same seed gives byte-identical output (CSV and table), and a
#   different seed changes it;
#   sections 1-5 run above MCS_MAX_COV_N (--n 150) with every measured value
#   agreeing with the exact one and no nan, and every section runs at a
#   degenerate size (section 2: N = 50, K = 10 with zero variances; section
#   3: N = 1) without nan, absurd numbers or a false disagreement.
# Ends with a Unity-style summary ("N Tests F Failures 0 Ignored", then OK or
# FAIL), so test/run_tests.sh can count it as one more runner; exit status
# non-zero on failure.

TRIALS=${TRIALS:-400}
HEADER='section,quantity,equation,pattern,n,k,freq,freq2,closed_form,exact,measured,stderr,z_closed,z_exact,verdict'

if [ "$#" -eq 0 ]; then
    # shellcheck disable=SC2086 # a list of paths
    set -- ${EXAMPLES:-build/examples/sec*}
fi

tmp=$(mktemp -d "${TMPDIR:-/tmp}/examples_check.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' EXIT INT TERM

passed=0
failed=0
ok() { passed=$((passed + 1)); }
bad() { failed=$((failed + 1)); echo "FAIL $1"; }

for bin in "$@"; do
    name=$(basename "$bin")
    echo "== $bin"
    if [ ! -x "$bin" ]; then
        bad "$name: not an executable (build it first)"
        continue
    fi

    # --help
    if "$bin" --help >"$tmp/out" 2>"$tmp/err" && grep -q '^usage:' "$tmp/out"; then
        ok
    else
        bad "$name --help: non-zero exit or no usage line"
    fi

    # bad options: non-zero exit, usage on stderr, nothing on stdout
    for args in "--bogus" "--n" "--n abc" "--n 0" "--n 100000" "--k 0" "--k -3" \
                "--trials 1" "--seed x" "--trials=12junk" "stray"; do
        # shellcheck disable=SC2086 # word splitting of $args is intended
        if "$bin" $args >"$tmp/out" 2>"$tmp/err"; then
            bad "$name $args: exit status 0"
        elif ! grep -q 'usage' "$tmp/err"; then
            bad "$name $args: no usage message on stderr"
        elif [ -s "$tmp/out" ]; then
            bad "$name $args: wrote to stdout"
        else
            ok
        fi
    done

    # CSV format
    n=32
    k=4
    if ! "$bin" --csv --n "$n" --k "$k" --trials "$TRIALS" --seed 7 >"$tmp/csv1" 2>"$tmp/err"; then
        bad "$name --csv: non-zero exit ($(head -n 1 "$tmp/err"))"
        continue
    fi
    ok
    if [ "$(head -n 1 "$tmp/csv1")" = "$HEADER" ]; then ok; else bad "$name --csv: header differs"; fi
    rows=$(($(wc -l <"$tmp/csv1") - 1))
    if [ "$rows" -ge 1 ]; then ok; else bad "$name --csv: no rows"; fi
    problems=$(tail -n +2 "$tmp/csv1" | awk -F, -v n="$n" -v k="$k" '
        function num(s) { return s == "" || s ~ /^[-+]?(inf|nan|[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?)$/ }
        NF != 15 { printf "line %d: %d fields\n", NR + 1, NF; next }
        $5 != n || $6 != k { printf "line %d: n,k = %s,%s\n", NR + 1, $5, $6 }
        $15 != "" && $15 != "holds" && $15 != "limit" && $15 != "approx" && $15 != "fails" {
            printf "line %d: verdict \"%s\"\n", NR + 1, $15 }
        $7 !~ /^[0-9]*$/ || $8 !~ /^[0-9]*$/ { printf "line %d: freq fields\n", NR + 1 }
        { for (i = 9; i <= 14; ++i) if (!num($i)) printf "line %d: field %d \"%s\"\n", NR + 1, i, $i }
        $1 == "" || $2 == "" { printf "line %d: empty section or quantity\n", NR + 1 }')
    if [ -z "$problems" ]; then ok; else bad "$name --csv rows: $(echo "$problems" | head -n 3 | tr '\n' ';')"; fi

    # Determinism: same seed, same bytes (CSV and table); another seed differs.
    "$bin" --csv --n "$n" --k "$k" --trials "$TRIALS" --seed 7 >"$tmp/csv2" 2>/dev/null
    if cmp -s "$tmp/csv1" "$tmp/csv2"; then ok; else bad "$name --csv: same seed, different output"; fi
    "$bin" --n "$n" --k "$k" --trials "$TRIALS" --seed 7 >"$tmp/tab1" 2>/dev/null
    "$bin" --n "$n" --k "$k" --trials "$TRIALS" --seed 7 >"$tmp/tab2" 2>/dev/null
    if [ -s "$tmp/tab1" ] && cmp -s "$tmp/tab1" "$tmp/tab2"; then ok; else
        bad "$name table: same seed, different or empty output"; fi
    "$bin" --csv --n "$n" --k "$k" --trials "$TRIALS" --seed 8 >"$tmp/csv3" 2>/dev/null
    if cmp -s "$tmp/csv1" "$tmp/csv3"; then bad "$name --csv: seed has no effect"; else ok; fi

    # --opt=value spelling gives the same run as --opt value.
    "$bin" --csv --n="$n" --k="$k" --trials="$TRIALS" --seed=7 >"$tmp/csv4" 2>/dev/null
    if cmp -s "$tmp/csv1" "$tmp/csv4"; then ok; else bad "$name: --opt=value differs from --opt value"; fi

    # Any N: above MCS_MAX_COV_N (64 by default) the exact theory still
    # answers, every measured value agrees with it, and nothing prints nan.
    case $name in sec[1-5]_*)
        if "$bin" --n 150 --k 7 --trials "$TRIALS" --seed 3 >"$tmp/big" 2>"$tmp/err" &&
            ! grep -qi 'nan' "$tmp/big" && ! grep -q '^WARNING' "$tmp/big"; then ok; else
            bad "$name --n 150: failed, nan, or a disagreement ($(grep -i -m1 'nan\|^WARNING' "$tmp/big"))"
        fi ;;
    esac
    # Degenerate sizes: no nan, no absurd numbers (a z or a value of more
    # than 30 characters), no false disagreement. Section 2 at N = 50, K = 10
    # has zero-variance jitter and uniform rows; section 3 at N = 1 has no
    # frequency above 0.
    case $name in
    sec2_*) small="--n 50 --k 10" ;;
    sec3_*) small="--n 1 --k 3" ;;
    *) small="--n 1 --k 2" ;;
    esac
    # shellcheck disable=SC2086 # word splitting of $small is intended
    if "$bin" $small --trials "$TRIALS" >"$tmp/small" 2>"$tmp/err" &&
        ! grep -qi 'nan' "$tmp/small" && ! grep -q '^WARNING' "$tmp/small" &&
        ! grep -Eq '[0-9.e+-]{31,}' "$tmp/small"; then ok; else
        bad "$name $small: failed, nan, an absurd number or a false disagreement"
    fi
    if [ "$name" = sec2_fourier ]; then
        # no z beyond 1e6 on a row whose exact and measured values agree
        zs=$(awk '$1 == "Var[I]" && ($(NF-2) + 0 > 1e6 || $(NF-2) + 0 < -1e6)' "$tmp/small")
        if [ -z "$zs" ]; then ok; else bad "$name $small: absurd z_exact: $zs"; fi
    fi
done

echo "-----------------------"
echo "$((passed + failed)) Tests $failed Failures 0 Ignored"
if [ "$failed" -eq 0 ]; then echo "OK"; else echo "FAIL"; fi
[ "$failed" -eq 0 ]
