#!/bin/sh
# Checks of examples/renderer_sampler beyond the command-line and CSV format
# that test/examples_check.sh checks for every example (issue 9).
#
# usage: sh test/renderer_check.sh   ($RENDERER names the binary, default
#                                     build/examples/renderer_sampler)
#
#   --k that is not a power of 2 (the rotated van der Corput set is jitter
#   only for K = 2^m): exit 2, usage on stderr, nothing on stdout;
#   at the defaults and at two other (N, K, pixels, seed): every row's
#   measurement within 5 standard errors of its exact prediction (mcspec's
#   jitter and random theory, the rotation average for Halton base 3);
#   the van der Corput and random rows' closed forms equal the exact values
#   (verdict holds) wherever the closed form exists;
#   the Halton base-3 rows separate it from jitter: its Var[I] row's verdict
#   is "fails" (jitter refuted, rotation average confirmed) at the defaults;
#   the table ends with the line saying every measurement agrees.
# Ends with a Unity-style summary ("N Tests F Failures 0 Ignored", then OK or
# FAIL) so test/run_tests.sh counts it; exit status non-zero on failure.

RENDERER=${RENDERER:-build/examples/renderer_sampler}

# shellcheck source=test/support/check.sh
. "$(dirname "$0")/support/check.sh"
check_start renderer_check

echo "== $RENDERER"
if [ ! -x "$RENDERER" ]; then
    bad "$RENDERER: not an executable (build it first)"
else
    for k in 3 6 12 1000; do
        "$RENDERER" --k "$k" >"$tmp/out" 2>"$tmp/err"
        rc=$?
        if [ "$rc" -eq 2 ] && grep -q 'usage' "$tmp/err" && grep -q 'power of 2' "$tmp/err" &&
            [ ! -s "$tmp/out" ]; then
            ok
        else
            bad "--k $k: want exit 2, usage on stderr only (got $rc)"
        fi
    done

    for args in "" "--n 40 --k 8 --trials 2048 --seed 3" "--n 64 --k 128 --trials 600 --seed 11"; do
        # shellcheck disable=SC2086 # word splitting of $args is intended
        if ! "$RENDERER" --csv $args >"$tmp/csv" 2>"$tmp/err"; then
            bad "--csv $args: non-zero exit ($(head -n 1 "$tmp/err"))"
            continue
        fi
        far=$(tail -n +2 "$tmp/csv" | awk -F, '
            function abs(v) { return v < 0 ? -v : v }
            $14 == "" || abs($14) > 5 { printf "%s %s k=%s z_exact=%s; ", $4, $2, $7, $14 }')
        if [ -z "$far" ]; then ok; else bad "$args: rows far from exact: $far"; fi
        notexact=$(tail -n +2 "$tmp/csv" | awk -F, '
            $4 != "halton3-cp" && $9 != "" && $15 != "holds" {
                printf "%s %s k=%s %s; ", $4, $2, $7, $15 }')
        if [ -z "$notexact" ]; then ok; else bad "$args: closed form not exact: $notexact"; fi
        rows=$(tail -n +2 "$tmp/csv" | awk -F, '{ c[$4]++ }
            END { print c["vdc-cp"] + 0, c["halton3-cp"] + 0, c["rng"] + 0 }')
        # shellcheck disable=SC2086 # split into three counts
        set -- $rows
        if [ "$1" -ge 3 ] && [ "$1" = "$2" ] && [ "$2" = "$3" ]; then ok; else
            bad "$args: rows per dimension $rows"; fi
        # shellcheck disable=SC2086
        "$RENDERER" $args >"$tmp/table" 2>/dev/null
        if tail -n 1 "$tmp/table" | grep -q '^Every measured value agrees'; then ok; else
            bad "$args table: last line: $(tail -n 1 "$tmp/table")"; fi
    done

    "$RENDERER" --csv >"$tmp/csv" 2>/dev/null
    v=$(awk -F, '$4 == "halton3-cp" && $2 == "Var[I]" { print $15 }' "$tmp/csv")
    if [ "$v" = "fails" ]; then ok; else
        bad "halton3-cp Var[I] against jitter: verdict \"$v\", want fails"; fi
fi

check_summary
