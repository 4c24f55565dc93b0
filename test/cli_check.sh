#!/bin/sh
# Checks of the mcspec command (issue 13).
#
# usage: sh test/cli_check.sh   ($MCSPEC names the binary, default
#                                build/bin/mcspec; $GOLDEN the golden files,
#                                default test/golden)
#
#   --help on the command and on every subcommand, no C suffixes in them;
#   --version and `mcspec version` print the library's version string;
#   bad usage (unknown command or option, missing or out-of-range values):
#   exit 2, one line on stderr, nothing on stdout (--save, merge and show are
#   test/record_check.sh's);
#   the golden point files: test/golden/hand_n4_weights.txt against the
#   spectrum worked out by hand in its header, and
#   test/golden/comb_k8_n64.txt (equally spaced points under a random
#   rotation) against the jitter comb of eq. 37, and against the exact
#   column of `mcspec pattern jitter` at the same N and K;
#   every subcommand's output: CSV headers exactly, row counts, field counts,
#   numbers or empty fields; table headers; the pattern's measurements within
#   5 standard errors of exact theory;
#   determinism: the same seed gives the same bytes, another seed differs,
#   --opt=value equals --opt value, a kind's variance does not depend on
#   which other kinds run (one stream per kind);
#   every malformed input (bad number, wrong column count, empty set, NaN,
#   infinity, out-of-range point, negative weight, a NUL byte, unreadable
#   file, empty input) gives exit 2, one line on stderr naming the line, nothing on
#   stdout, also when the error comes after many good sets; --wrap;
#   --plot: a missing gnuplot, a failing one (a fake on PATH), a bad file
#   name and an unwritable directory give exit 2 and no file; with gnuplot
#   (skipped, with a line saying so, when it is not installed), an SVG and a
#   PNG of the expected size with the expected series, and no temporary
#   files left behind; --log (a fake gnuplot keeps the script and data): a
#   log y axis over a positive range, no value <= 0 drawn, a comb still a
#   comb, the 2D image not on it;
#   progress: on a terminal it appears, with the time left and, for a
#   --stream run, that stream's share; never with --csv, never when stderr
#   is not a terminal (the terminal checks need util-linux `script`).
# Ends with a Unity-style summary ("N Tests F Failures 0 Ignored", then OK or
# FAIL) so test/run_tests.sh counts it; exit status non-zero on failure.

MCSPEC=${MCSPEC:-build/bin/mcspec}
GOLDEN=${GOLDEN:-test/golden}
case $MCSPEC in
/*) abs=$MCSPEC ;;
*) abs=$PWD/$MCSPEC ;;
esac

# shellcheck source=test/support/check.sh
. "$(dirname "$0")/support/check.sh"
check_start cli_check

if [ ! -x "$MCSPEC" ]; then
    bad "$MCSPEC is not an executable (make cli)"
    check_summary
    exit 1
fi

input() { printf '%b' "$1" >"$tmp/in"; } # backslash escapes (\n) in $1 are expanded

echo "== $MCSPEC"

# ---------------------------------------------------------------- --help
succeeds "mcspec --help" "$MCSPEC" --help && grep -q '^usage: mcspec COMMAND' "$tmp/out" && ok ||
    bad "mcspec --help: no usage line"
for c in spectrum pattern variance; do
    if succeeds "mcspec $c --help" "$MCSPEC" "$c" --help && grep -q "^usage: mcspec $c" "$tmp/out"
    then ok; else bad "mcspec $c --help: no usage line"; fi
done
"$MCSPEC" spectrum --help | grep -q 'freq,mean_re,mean_im,mean_stderr,power,power_stderr' && ok ||
    bad "spectrum --help does not give the CSV header"
"$MCSPEC" pattern --help | grep -q 'exact,closed,z_exact,z_closed' && ok ||
    bad "pattern --help does not give the CSV columns"
# --version and `version`: the library's version string, as version.h has it.
version=$(sed -n 's/^#define MCS_VERSION_STRING "\(.*\)"$/\1/p' "$(dirname "$0")/../include/mcspec/version.h")
[ -n "$version" ] && ok || bad "no MCS_VERSION_STRING in include/mcspec/version.h"
for v in --version version; do
    if succeeds "mcspec $v" "$MCSPEC" "$v" && [ "$(cat "$tmp/out")" = "mcspec $version" ]; then ok
    else bad "mcspec $v: '$(cat "$tmp/out")', expected 'mcspec $version'"; fi
done
succeeds "mcspec version --help" "$MCSPEC" version --help && grep -q '^usage: mcspec version' "$tmp/out" && ok ||
    bad "mcspec version --help: no usage line"
usage_error "version with an argument" "^mcspec version: unexpected argument 'x'" "$MCSPEC" version x
"$MCSPEC" --help | grep -q -- '--version' && ok || bad "mcspec --help does not mention --version"
# Numbers in the help texts as a user types them: no C suffix (1048576u).
for c in "" spectrum pattern variance merge show version; do
    # shellcheck disable=SC2086
    suffixed=$("$MCSPEC" $c --help | grep -E '[0-9]+[uUlL]+\b')
    if [ -z "$suffixed" ]; then ok; else bad "mcspec $c --help: a C suffix in '$suffixed'"; fi
done
# The exact column is filled at every N (mcs_theory_spectrum above
# MCS_MAX_COV_N): the help texts no longer say it is empty there.
for c in pattern variance; do
    if "$MCSPEC" "$c" --help | tr '\n' ' ' | grep -Eq 'empty (column|field) (elsewhere|for the other)'
    then bad "mcspec $c --help still says the exact column is empty above N = 64"
    elif "$MCSPEC" "$c" --help | tr '\n' ' ' | grep -q 'for every N, kind'; then ok
    else bad "mcspec $c --help does not say the exact values cover every N"; fi
done
# The 1D point-set spectrum in 1D terms: k x_j, k = 0..F; k.x_j and the axes
# are the 2D wording.
"$MCSPEC" spectrum --help | tr '\n' ' ' |
    grep -qF 'P(k) = |sum_j exp(-2 pi i k x_j)|^2 / K at the integer frequencies k = 0..F (--dim 1)' && ok ||
    bad "spectrum --help: the 1D periodogram is not in 1D terms"

# ------------------------------------------------------------- bad usage
usage_error "no command" 'which command' "$MCSPEC"
usage_error "unknown command" "unknown command 'bogus'" "$MCSPEC" bogus
usage_error "spectrum --n 0" '--n expects a whole number' "$MCSPEC" spectrum --n 0 -
usage_error "spectrum --n too big" '--n expects a whole number from 1 to' "$MCSPEC" spectrum --n 99999 -
usage_error "spectrum --n abc" "not 'abc'" "$MCSPEC" spectrum --n abc -
usage_error "spectrum --n (no value)" '--n needs a value' "$MCSPEC" spectrum --n
usage_error "spectrum --bogus" "unknown option '--bogus'" "$MCSPEC" spectrum --bogus -
usage_error "spectrum -x" "unknown option '-x'" "$MCSPEC" spectrum -x -
usage_error "spectrum two files" "unexpected argument" "$MCSPEC" spectrum a b
usage_error "spectrum --n twice" 'given twice' "$MCSPEC" spectrum --n 4 --n 8 -
usage_error "spectrum --csv=1" 'takes no value' "$MCSPEC" spectrum --csv=1 -
usage_error "pattern without KIND" 'which pattern' "$MCSPEC" pattern --n 16 --k 4
usage_error "pattern bogus KIND" "unknown pattern 'bogus'" "$MCSPEC" pattern bogus --n 16 --k 4
usage_error "pattern without --n" '--n N is required' "$MCSPEC" pattern random --k 4
usage_error "pattern without --k" '--k K is required' "$MCSPEC" pattern random --n 16
usage_error "pattern --k 0" '--k expects' "$MCSPEC" pattern random --n 16 --k 0
usage_error "pattern --trials 1" '--trials expects a whole number from 2' "$MCSPEC" pattern random --n 16 --k 4 --trials 1
usage_error "pattern --seed -1" "--seed expects.*not '-1'" "$MCSPEC" pattern random --n 16 --k 4 --seed -1
usage_error "pattern --trials=12junk" "not '12junk'" "$MCSPEC" pattern random --n 16 --k 4 --trials=12junk
usage_error "variance without --k" '--k K is required' "$MCSPEC" variance -
usage_error "variance --trials 3" '--trials expects a whole number from 4' "$MCSPEC" variance --k 2 --trials 3 -
usage_error "variance --kind bogus" "unknown pattern 'bogus'" "$MCSPEC" variance --k 2 --kind bogus -
usage_error "variance two stdins" "cannot both be read from '-'" "$MCSPEC" variance --k 2 --importance - -

# ------------------------------------------------ golden: hand-worked file
hand=$GOLDEN/hand_n4_weights.txt
if succeeds "spectrum of $hand" "$MCSPEC" spectrum --n 4 --weights --csv "$hand"; then
    # freq mean_re mean_im mean_stderr power power_stderr, as worked out in the file
    cat >"$tmp/want" <<'EOF'
0 0.875 0 0.625 1.15625 1.09375
1 0.25 -0.375 0.67314560089181297 0.65625 0.59375
2 -0.375 0 0.125 0.15625 0.09375
EOF
    problems=$(tail -n +2 "$tmp/out" | tr ',' ' ' | paste -d' ' - "$tmp/want" | awk '{
        for (i = 1; i <= 6; ++i) { d = $i - $(i + 6); if (d < 0) d = -d
            if (d > 1e-12) printf "k=%s column %d: %s, by hand %s; ", $1, i, $i, $(i + 6) } }
        END { if (NR != 3) printf "%d rows", NR }')
    if [ -z "$problems" ]; then ok; else bad "$hand: $problems"; fi
fi

# ------------------------------------------------ golden: rotated comb
comb=$GOLDEN/comb_k8_n64.txt
if succeeds "spectrum of $comb" "$MCSPEC" spectrum --n 64 --csv "$comb"; then
    cp "$tmp/out" "$tmp/comb.csv"
    csv_shape "spectrum --csv" "$tmp/comb.csv" 'freq,mean_re,mean_im,mean_stderr,power,power_stderr' 33 6
    problems=$(tail -n +2 "$tmp/comb.csv" | awk -F, '{
        want = ($1 % 8 == 0) ? 1 : 0; d = $5 - want; if (d < 0) d = -d
        if ($1 != NR - 1) printf "row %d has freq %s; ", NR, $1
        if (d > 1e-12) printf "k=%s power %s, comb %d; ", $1, $5, want
        if ($6 > 1e-12) printf "k=%s power_stderr %s; ", $1, $6 }')
    if [ -z "$problems" ]; then ok; else bad "$comb against eq. 37: $problems"; fi
    # The same comb is what mcspec predicts for jitter at N = 64, K = 8.
    if succeeds "pattern jitter --n 64 --k 8" "$MCSPEC" pattern jitter --n 64 --k 8 --trials 2 --csv; then
        tail -n +2 "$tmp/comb.csv" >"$tmp/comb.rows"
        problems=$(tail -n +2 "$tmp/out" | cut -d, -f7 | paste -d, "$tmp/comb.rows" - |
            awk -F, '{ d = $5 - $7; if (d < 0) d = -d; if ($7 == "" || d > 1e-12) printf "k=%s: %s vs exact %s; ", $1, $5, $7 }')
        if [ -z "$problems" ]; then ok; else bad "$comb against pattern jitter's exact column: $problems"; fi
    fi
fi
if succeeds "spectrum table of $comb" "$MCSPEC" spectrum --n 64 "$comb"; then
    if grep -q 'trials (point sets) 12, K per set: min 8, max 8' "$tmp/out" &&
       grep -Eq '^ *freq +mean_re +mean_im +mean_stderr +power +power_stderr$' "$tmp/out" &&
       [ "$(grep -Ec '^ *[0-9]+ ' "$tmp/out")" -eq 33 ]; then ok
    else bad "spectrum table: summary, header or 33 rows missing"; fi
fi
# Standard input, given as '-' or by no FILE, reads the same.
cp "$comb" "$tmp/in"
run "$MCSPEC" spectrum --n 64 --csv -
cmp -s "$tmp/out" "$tmp/comb.csv" && ok || bad "spectrum - (stdin) differs from the file"
run "$MCSPEC" spectrum --n 64 --csv
cmp -s "$tmp/out" "$tmp/comb.csv" && ok || bad "spectrum with no FILE differs from the file"
: >"$tmp/in"

# --wrap takes coordinates modulo 1.
input '1.0\n-0.25\n'
succeeds "spectrum --wrap" "$MCSPEC" spectrum --wrap --n 4 --csv && cp "$tmp/out" "$tmp/wrap.csv"
input '0\n0.75\n'
succeeds "spectrum, wrapped by hand" "$MCSPEC" spectrum --n 4 --csv
cmp -s "$tmp/out" "$tmp/wrap.csv" && ok || bad "--wrap differs from the points wrapped by hand"

# ------------------------------------------------------- malformed input
input '0.1\n0.2\nabc\n'
usage_error "bad number" 'line 3: .*not a number' "$MCSPEC" spectrum -
input '0.1\n0.2 0.3\n'
usage_error "two columns without --weights" 'line 2: expected 1 column, found 2' "$MCSPEC" spectrum -
input '0.1 1\n0.2\n'
usage_error "one column with --weights" 'line 2: expected 2 columns, found 1' "$MCSPEC" spectrum --weights -
input '0.1 1 2\n'
usage_error "three columns with --weights" 'line 1: expected 2 columns, found 3' "$MCSPEC" spectrum --weights -
input '0.1\n#\n\n#\n0.2\n'
usage_error "empty set" 'line 4: empty point set' "$MCSPEC" spectrum -
input '0.1\nnan\n'
usage_error "NaN point" "line 2: coordinate 'nan' is not a finite number" "$MCSPEC" spectrum -
input '0.1 inf\n'
usage_error "infinite weight" "line 1: weight 'inf' is not a finite number" "$MCSPEC" spectrum --weights -
input '0.5\n1.0\n'
usage_error "point 1.0" 'line 2: coordinate 1.0 is outside \[0,1\)' "$MCSPEC" spectrum -
input '-0.1\n'
usage_error "negative point" 'line 1: coordinate -0.1 is outside' "$MCSPEC" spectrum -
input '0.5 -2\n'
usage_error "negative weight" 'line 1: weight -2 is negative' "$MCSPEC" spectrum --weights -
input ''
usage_error "empty input" 'input is empty' "$MCSPEC" spectrum -
# Weights of one set summing above the spectrum's MCS_SPECTRUM_MAX_SUM = 2^100:
# the line where the sum passes it (it was exit 1, MCS_ERR_MAGNITUDE).
input '0.1 1\n#\n0.1 1e30\n0.2 1e30\n0.3 1\n'
usage_error "weights summing above 2^100" \
    '^mcspec spectrum: <stdin>: line 4: .*weights.* sum to 2e\+30.*above 1\.26765e\+30 = 2\^100' \
    "$MCSPEC" spectrum --n 4 --weights -
input '0.5 1.3e30\n'
usage_error "one weight above 2^100" '<stdin>: line 1: .*2\^100' "$MCSPEC" spectrum --n 4 --weights -
input '0.5 1e30\n0.25 2.6765060022822938e29\n#\n0.5 1\n'
succeeds "weights summing to 2^100 exactly" "$MCSPEC" spectrum --n 4 --weights --csv -
input '# header\n# only\n'
usage_error "only comments" 'line 2: end of input and no point read' "$MCSPEC" spectrum -
# A NUL byte anywhere in a text input is an error on its line: a C string
# ends there, so the rest of the line was lost (a leading NUL dropped the
# point, "0.2<NUL>9" read as 0.2).
printf '0.1\n\0000.7\n0.9\n' >"$tmp/in"
usage_error "NUL at the start of a line" '^mcspec spectrum: <stdin>: line 2: a NUL byte' \
    "$MCSPEC" spectrum --n 4 -
printf '0.1\n0.2\0009\n' >"$tmp/nul.txt"
usage_error "NUL inside a number" "nul.txt: line 2: a NUL byte at column 4" \
    "$MCSPEC" spectrum --n 4 "$tmp/nul.txt"
printf '# a header\000 with a NUL\n0.5\n' >"$tmp/in"
usage_error "NUL in a '#' line" '<stdin>: line 1: a NUL byte' "$MCSPEC" spectrum -
printf '0.1 0.2\n0.3 0.4\000\n' >"$tmp/in"
usage_error "2D: NUL after a point" '<stdin>: line 2: a NUL byte at column 8' \
    "$MCSPEC" spectrum --dim 2 --freq 2 -
printf '0.5 1\n0.25 \0002\n' >"$tmp/in"
usage_error "--weights: NUL before a weight" '<stdin>: line 2: a NUL byte' "$MCSPEC" spectrum --weights -
printf '1\n2\n\000\n3\n' >"$tmp/nul.txt"
usage_error "integrand with a NUL line" "^mcspec variance: .*nul.txt: line 3: a NUL byte" \
    "$MCSPEC" variance --k 2 "$tmp/nul.txt"
printf '1\n1\000\n' >"$tmp/nul.txt"
usage_error "importance with a NUL" "^mcspec pattern: .*nul.txt: line 2: a NUL byte" \
    "$MCSPEC" pattern random --n 2 --k 2 --importance "$tmp/nul.txt"
: >"$tmp/in"
usage_error "missing file" "cannot read '$tmp/nope.txt'" "$MCSPEC" spectrum "$tmp/nope.txt"
usage_error "a directory" "cannot read '$tmp': it is a directory" "$MCSPEC" spectrum "$tmp"
# Nothing partial: 200 good sets, then a bad line.
awk 'BEGIN { for (s = 0; s < 200; ++s) { print 0.25; print 0.5; print "#" } print "0.5 0.5" }' >"$tmp/in"
usage_error "error after 200 good sets" 'line 601: expected 1 column' "$MCSPEC" spectrum --n 8 -
: >"$tmp/in"
printf '1\n2\n3\n' >"$tmp/f3.txt"
printf '1\n0\n1\n' >"$tmp/g0.txt"
printf '1\n-1\n1\n' >"$tmp/gneg.txt"
printf '1\n1\n' >"$tmp/g2.txt"
printf '0.5\n0.25\nx\n' >"$tmp/fbad.txt"
usage_error "integrand bad number" "fbad.txt: line 3: integrand value 'x' is not a number" \
    "$MCSPEC" variance --k 2 "$tmp/fbad.txt"
usage_error "importance weight -1" "gneg.txt: line 2: importance weight -1 must be >= 0" \
    "$MCSPEC" variance --k 2 --importance "$tmp/gneg.txt" "$tmp/f3.txt"
run "$MCSPEC" variance --k 2 --importance "$tmp/g0.txt" "$tmp/f3.txt"
if [ "$rc" -ne 0 ]; then bad "importance weight 0 (a bin never drawn) refused: $(head -n 1 "$tmp/err")"
else ok; fi
usage_error "importance of the wrong length" 'holds 2 importance weights, but the integrand has 3' \
    "$MCSPEC" variance --k 2 --importance "$tmp/g2.txt" "$tmp/f3.txt"
usage_error "pattern importance of the wrong length" 'holds 2 importance weights, but --n is 3' \
    "$MCSPEC" pattern random --n 3 --k 2 --importance "$tmp/g2.txt"
usage_error "homogenized with importance" 'homogenized is not defined with an importance function' \
    "$MCSPEC" pattern homogenized --n 2 --k 2 --importance "$tmp/g2.txt"
usage_error "missing integrand file" "cannot read '$tmp/nope.txt'" "$MCSPEC" variance --k 2 "$tmp/nope.txt"

# ------------------------------------------------------- pattern output
header='freq,mean_re,mean_im,mean_stderr,power,power_stderr,exact,closed,z_exact,z_closed'
for kind in random stratified homogenized uniform jitter; do
    if succeeds "pattern $kind --csv" "$MCSPEC" pattern "$kind" --n 16 --k 4 --trials 50 --seed 3 --csv; then
        csv_shape "pattern $kind --csv" "$tmp/out" "$header" 9 10
        # N <= 64: an exact value at every frequency; K divides N: a closed form too.
        missing=$(tail -n +2 "$tmp/out" | awk -F, '$7 == "" || $8 == "" { printf "%s ", $1 }')
        if [ -z "$missing" ]; then ok; else bad "pattern $kind: no exact or closed value at k = $missing"; fi
    fi
done
# Above N = 64 (the N x N capacity), K not dividing N: exact values at every
# frequency from mcs_theory_spectrum, and the measurement within 5 standard errors.
if succeeds "pattern homogenized --n 100 --k 7" "$MCSPEC" pattern homogenized --n 100 --k 7 --trials 2000 --csv; then
    csv_shape "pattern --n 100 --csv" "$tmp/out" "$header" 51 10
    empty=$(tail -n +2 "$tmp/out" | awk -F, '$7 == "" { printf "%s ", $1 }')
    if [ -z "$empty" ]; then ok; else bad "pattern --n 100 --k 7: no exact value at k = $empty"; fi
    worst=$(tail -n +2 "$tmp/out" | awk -F, '{ z = $9 < 0 ? -$9 : $9; if (z > m) m = z } END { print m + 0 }')
    if awk -v z="$worst" 'BEGIN { exit !(z < 5) }'; then ok; else bad "pattern --n 100 --k 7: |z_exact| up to $worst"; fi
fi
# The measurements agree with exact theory (fixed seeds, 5 standard errors).
for kind in random stratified homogenized jitter; do
    run "$MCSPEC" pattern "$kind" --n 32 --k 4 --trials 4000 --seed 11 --csv
    worst=$(tail -n +2 "$tmp/out" | awk -F, '{ z = $9 < 0 ? -$9 : $9; if (z > m) m = z } END { print m + 0 }')
    if awk -v z="$worst" 'BEGIN { exit !(z < 5) }'; then ok; else bad "pattern $kind: |z_exact| up to $worst"; fi
done
if succeeds "pattern table" "$MCSPEC" pattern stratified --n 32 --k 4 --trials 100; then
    if head -n 1 "$tmp/out" | grep -q '^mcspec pattern stratified: N = 32 bins, K = 4 samples, 100 trials, seed 1' &&
       grep -Eq '^ *freq +mean_re .* exact +closed +z_exact +z_closed$' "$tmp/out" &&
       [ "$(grep -Ec '^ *[0-9]+ ' "$tmp/out")" -eq 17 ]; then ok
    else bad "pattern table: title, header or 17 rows missing"; fi
fi

# ------------------------------------------------------ variance output
vheader='kind,n,k,trials,mean,mean_stderr,variance,variance_stderr,exact,z_exact,bias,exact_mean,z_mean'
awk 'BEGIN { for (i = 0; i < 16; ++i) { x = (i + 0.5) / 16; print 0.5 + 0.3 * sin(6.283185307179586 * x) + (x >= 0.3 ? 0.4 : 0) } }' >"$tmp/f16.txt"
if succeeds "variance --csv" "$MCSPEC" variance --k 4 --trials 2000 --seed 5 --csv "$tmp/f16.txt"; then
    cp "$tmp/out" "$tmp/var1.csv"
    csv_shape "variance --csv" "$tmp/var1.csv" "$vheader" 5 13
    kinds=$(tail -n +2 "$tmp/var1.csv" | cut -d, -f1 | tr '\n' ' ')
    if [ "$kinds" = "random stratified homogenized uniform jitter " ]; then ok; else bad "variance kinds: $kinds"; fi
    worst=$(tail -n +2 "$tmp/var1.csv" | awk -F, '{ z = $10 < 0 ? -$10 : $10; if ($10 == "") z = 99; if (z > m) m = z } END { print m + 0 }')
    if awk -v z="$worst" 'BEGIN { exit !(z < 5) }'; then ok; else bad "variance: |z_exact| up to $worst"; fi
fi
run "$MCSPEC" variance --k 4 --trials 2000 --seed 5 --csv --kind stratified "$tmp/f16.txt"
if [ "$(tail -n +2 "$tmp/out")" = "$(grep '^stratified,' "$tmp/var1.csv")" ]; then ok
else bad "variance --kind stratified differs from its row in the all-kinds run"; fi
printf '1\n2\n1\n2\n1\n2\n1\n2\n1\n2\n1\n2\n1\n2\n1\n2\n' >"$tmp/g16.txt"
for kind in random stratified jitter; do
    run "$MCSPEC" pattern "$kind" --n 16 --k 4 --trials 4000 --seed 2 --importance "$tmp/g16.txt" --csv
    worst=$(tail -n +2 "$tmp/out" | awk -F, '{ z = $9 < 0 ? -$9 : $9; if ($9 == "") z = 99; if (z > m) m = z } END { print m + 0 }')
    if [ "$rc" -eq 0 ] && awk -v z="$worst" 'BEGIN { exit !(z < 5) }'; then ok
    else bad "pattern $kind --importance: status $rc, |z_exact| up to $worst"; fi
done
run "$MCSPEC" variance --k 4 --trials 100 --csv --importance "$tmp/g16.txt" "$tmp/f16.txt"
kinds=$(tail -n +2 "$tmp/out" | cut -d, -f1 | tr '\n' ' ')
if [ "$rc" -eq 0 ] && [ "$kinds" = "random stratified uniform jitter " ]; then ok
else bad "variance --importance: status $rc, kinds $kinds"; fi
# A bin of weight 0 is never drawn: every kind but uniform is biased by
# exactly -f_3 / 16 there, and its mean agrees with the exact mean (z_mean).
printf '1\n2\n1\n0\n1\n2\n1\n2\n1\n2\n1\n2\n1\n2\n1\n2\n' >"$tmp/g16z.txt"
if succeeds "variance, a bin of weight 0" "$MCSPEC" variance --k 4 --trials 4000 --seed 3 --csv \
    --importance "$tmp/g16z.txt" "$tmp/f16.txt"; then
    want=$(awk 'NR == 4 { printf "%.17g", -$1 / 16 }' "$tmp/f16.txt")
    problems=$(tail -n +2 "$tmp/out" | awk -F, -v want="$want" '
        $1 != "uniform" { d = $11 - want; if (d < 0) d = -d; if (d > 1e-15) printf "%s bias %s, want %s; ", $1, $11, want }
        { z = $13 < 0 ? -$13 : $13; if ($13 == "" || z >= 5) printf "%s z_mean %s; ", $1, $13 }')
    if [ -z "$problems" ]; then ok; else bad "variance with a zero weight: $problems"; fi
fi
# Above MCS_MAX_COV_N, every kind, with and without importance: an exact Var[I].
awk 'BEGIN { for (i = 0; i < 100; ++i) print sin(i / 10) }' >"$tmp/f100.txt"
awk 'BEGIN { for (i = 0; i < 100; ++i) print 1 + (i % 7) / 3 }' >"$tmp/g100.txt"
for imp in "" "--importance $tmp/g100.txt"; do
    # shellcheck disable=SC2086
    if succeeds "variance --n 100 $imp" "$MCSPEC" variance --k 7 --trials 100 --csv $imp "$tmp/f100.txt"; then
        empty=$(tail -n +2 "$tmp/out" | awk -F, '$9 == "" { printf "%s ", $1 }')
        rows=$(tail -n +2 "$tmp/out" | wc -l)
        if [ -z "$empty" ] && [ "$rows" -ge 4 ]; then ok
        else bad "variance at N = 100 $imp: no exact value for $empty($rows rows)"; fi
    fi
done
if succeeds "variance table" "$MCSPEC" variance --k 4 --trials 100 "$tmp/f16.txt"; then
    if grep -Eq '^kind +mean +mean_stderr +variance +var_stderr +exact +z_exact +bias +z_mean' "$tmp/out" &&
       [ "$(grep -Ec '^(random|stratified|homogenized|uniform|jitter) ' "$tmp/out")" -eq 5 ]; then ok
    else bad "variance table: header or 5 rows missing"; fi
fi

# ----------------------------------------------------------- determinism
run "$MCSPEC" pattern random --n 32 --k 4 --trials 300 --seed 7 --csv; cp "$tmp/out" "$tmp/p1"
run "$MCSPEC" pattern random --n 32 --k 4 --trials 300 --seed 7 --csv; cp "$tmp/out" "$tmp/p2"
run "$MCSPEC" pattern random --n 32 --k 4 --trials 300 --seed 8 --csv; cp "$tmp/out" "$tmp/p3"
run "$MCSPEC" pattern random --n=32 --k=4 --trials=300 --seed=7 --csv; cp "$tmp/out" "$tmp/p4"
cmp -s "$tmp/p1" "$tmp/p2" && ok || bad "pattern: the same seed gives different output"
cmp -s "$tmp/p1" "$tmp/p3" && bad "pattern: the seed has no effect" || ok
cmp -s "$tmp/p1" "$tmp/p4" && ok || bad "pattern: --opt=value differs from --opt value"
run "$MCSPEC" variance --k 4 --trials 300 --seed 7 --csv "$tmp/f16.txt"; cp "$tmp/out" "$tmp/v1"
run "$MCSPEC" variance --k 4 --trials 300 --seed 7 --csv "$tmp/f16.txt"; cp "$tmp/out" "$tmp/v2"
run "$MCSPEC" variance --k 4 --trials 300 --seed 9 --csv "$tmp/f16.txt"; cp "$tmp/out" "$tmp/v3"
cmp -s "$tmp/v1" "$tmp/v2" && ok || bad "variance: the same seed gives different output"
cmp -s "$tmp/v1" "$tmp/v3" && bad "variance: the seed has no effect" || ok

# ------------------------------------------------- point sets, 2D and 1D
"$MCSPEC" spectrum --help | grep -q 'kx,ky,power,power_stderr' &&
    "$MCSPEC" spectrum --help | grep -q 'radius,power,power_stderr,anisotropy_db' && ok ||
    bad "spectrum --help does not give the point-set CSV headers"
"$MCSPEC" pattern --help | grep -q 'kx,ky,power,power_stderr,exact,z_exact' && ok ||
    bad "pattern --help does not give the 2D CSV columns"
# --dim 2 without --freq takes the default F (test/spectrum_check.sh); empty input is still an error.
usage_error "spectrum --dim 2 without --freq, empty input" 'input is empty' "$MCSPEC" spectrum --dim 2 -
usage_error "spectrum --dim 3" '--dim expects a whole number from 1 to 2' "$MCSPEC" spectrum --dim 3 --freq 4 -
usage_error "spectrum --freq with --n" 'exclude each other' "$MCSPEC" spectrum --freq 4 --n 8 -
usage_error "spectrum --freq with --weights" 'needs binning' "$MCSPEC" spectrum --freq 4 --weights -
usage_error "spectrum --radial in 1D" '--radial needs --dim 2' "$MCSPEC" spectrum --freq 4 --radial -
usage_error "spectrum --radial binned" '--radial needs --dim 2 --freq' "$MCSPEC" spectrum --radial -
# --freq's range is the caps of the objects: MCS_POINTSET_MAX_FREQ in 1D,
# MCS_POINTSET2D_MAX_FREQ in 2D (read from --help, which prints the same
# macros), not SIZE_MAX; within them, what the machine's memory holds.
cap1=$("$MCSPEC" spectrum --help | sed -n 's/.*F = 1\.\.\([0-9][0-9]*\) in 1D.*/\1/p')
cap2=$("$MCSPEC" spectrum --help | sed -n 's/.* 1\.\.\([0-9][0-9]*\) in 2D.*/\1/p')
if [ -n "$cap1" ] && [ -n "$cap2" ]; then ok; else bad "spectrum --help gives no --freq range ('$cap1', '$cap2')"; fi
usage_error "spectrum --freq 0" "^mcspec spectrum: --freq expects a whole number from 1 to $cap1 for --dim 1 \(MCS_POINTSET_MAX_FREQ\), not '0'$" \
    "$MCSPEC" spectrum --freq 0 -
usage_error "spectrum --dim 2 --freq 0" "--freq expects a whole number from 1 to $cap2 for --dim 2 \(MCS_POINTSET2D_MAX_FREQ\), not '0'" \
    "$MCSPEC" spectrum --dim 2 --freq 0 -
usage_error "spectrum --freq too big" "--freq expects a whole number from 1 to $cap1 for --dim 1 .*not '$((cap1 + 1))'" \
    "$MCSPEC" spectrum --freq "$((cap1 + 1))" -
usage_error "spectrum --dim 2 --freq too big" "from 1 to $cap2 for --dim 2 .*not '99999999999999999999'" \
    "$MCSPEC" spectrum --freq 99999999999999999999 --dim 2 -
usage_error "spectrum --freq x" "--freq expects a whole number from 1 to $cap1 .*not 'x'" "$MCSPEC" spectrum --freq x -
# The issue's sizes: F = 65536 in 1D, 2048 in 2D (its annuli: the plane's
# 16.8 million rows are not made for --radial).
input '0.5\n0.25\n'
succeeds "spectrum --freq 65536" "$MCSPEC" spectrum --freq 65536 --csv -
input '0.5 0.5\n0.25 0.75\n'
succeeds "spectrum --dim 2 --freq 2048 --radial" "$MCSPEC" spectrum --dim 2 --freq 2048 --radial --csv -
# The 2D cap's buffer (about 70 GB) is more than a test machine's memory:
# refused up front with the bytes it needs, nothing allocated.
usage_error "spectrum --dim 2 --freq at the 2D cap" "^mcspec spectrum: --freq $cap2 needs [0-9]+ bytes, more than " \
    "$MCSPEC" spectrum --dim 2 --freq "$cap2" --csv -
: >"$tmp/in"
usage_error "pattern --dim 2 --freq 0" "--freq expects a whole number from 1 to $cap2, not '0'" \
    "$MCSPEC" pattern jittered --dim 2 --k 16 --freq 0
usage_error "pattern 2D KIND without --dim 2" "unknown pattern 'jittered'.*--dim 2" "$MCSPEC" pattern jittered --n 16 --k 4
usage_error "pattern --dim 2 without --freq" '--freq F is required' "$MCSPEC" pattern jittered --dim 2 --k 16
usage_error "pattern --dim 2 without --k" '--k K is required' "$MCSPEC" pattern jittered --dim 2 --freq 4
usage_error "pattern --dim 2 bogus KIND" "unknown 2D pattern 'bogus'" "$MCSPEC" pattern bogus --dim 2 --k 16 --freq 4
usage_error "pattern --dim 2 --n" 'takes no --n' "$MCSPEC" pattern random --dim 2 --k 16 --freq 4 --n 8
usage_error "pattern --freq in 1D" '--freq and --radial are for --dim 2' "$MCSPEC" pattern random --n 16 --k 4 --freq 4
# Malformed 2D input: the line and what was wrong.
input '0.1 0.2\n0.3\n'
usage_error "2D: one column" 'line 2: expected 2 columns, found 1' "$MCSPEC" spectrum --dim 2 --freq 2 -
input '0.1 0.2\n#\n0.3 0.4 0.5\n'
usage_error "2D: three columns" 'line 3: expected 2 columns, found 3' "$MCSPEC" spectrum --dim 2 --freq 2 -
input '0.1 0.2\n0.3 1.5\n'
usage_error "2D: y outside [0,1)" 'line 2: coordinate 1.5 is outside' "$MCSPEC" spectrum --dim 2 --freq 2 -
input '0.1 0.2\n0.3 x\n'
usage_error "2D: bad number" "line 2: coordinate 'x' is not a number" "$MCSPEC" spectrum --dim 2 --freq 2 -
input '0.5 0.5\n#\n#\n0.2 0.2\n'
usage_error "2D: empty set" 'line 3: empty point set' "$MCSPEC" spectrum --dim 2 --freq 2 -
awk 'BEGIN { for (s = 0; s < 100; ++s) { print "0.25 0.5"; print "0.5 0.75"; print "#" } print "0.5" }' >"$tmp/in"
usage_error "2D: error after 100 good sets" 'line 301: expected 2 columns, found 1' "$MCSPEC" spectrum --dim 2 --freq 2 -
: >"$tmp/in"

# The hand-worked file: every wave vector, and the annuli recomputed from
# the two sets' periodograms as its header gives them.
hand2=$GOLDEN/hand2d_two_sets.txt
if succeeds "spectrum --dim 2 of $hand2" "$MCSPEC" spectrum --dim 2 --freq 3 --csv "$hand2"; then
    csv_shape "spectrum --dim 2 --csv" "$tmp/out" 'kx,ky,power,power_stderr' 49 4
    problems=$(tail -n +2 "$tmp/out" | awk -F, '{
        odd = ($1 % 2 != 0); yodd = ($2 % 2 != 0)
        m = odd ? 1 : (yodd ? 0 : 2); se = odd ? 1 : 0
        d = $3 - m; e = $4 - se; if (d < 0) d = -d; if (e < 0) e = -e
        if (d > 1e-12 || e > 1e-12) printf "k=(%s,%s): %s +- %s, by hand %s +- %s; ", $1, $2, $3, $4, m, se }')
    if [ -z "$problems" ]; then ok; else bad "$hand2: $problems"; fi
fi
if succeeds "spectrum --radial of $hand2" "$MCSPEC" spectrum --dim 2 --freq 3 --radial --csv "$hand2"; then
    csv_shape "spectrum --radial --csv" "$tmp/out" 'radius,power,power_stderr,anisotropy_db' 4 4
    problems=$(tail -n +2 "$tmp/out" | awk -F, 'BEGIN {
        for (ky = -3; ky <= 3; ++ky) for (kx = -3; kx <= 3; ++kx) {
            r = int(sqrt(kx * kx + ky * ky) + 1e-9); if (r > 3) continue
            a = ((kx + ky) % 2 == 0) ? 2 : 0; b = (ky % 2 == 0) ? 2 : 0
            sa[r] += a; sb[r] += b; n[r]++; v[r, n[r]] = (a + b) / 2 }
        for (r = 0; r <= 3; ++r) {
            A = sa[r] / n[r]; B = sb[r] / n[r]; mean[r] = (A + B) / 2; se[r] = (A > B ? A - B : B - A) / 2
            ss = 0; for (i = 1; i <= n[r]; ++i) ss += (v[r, i] - mean[r]) ^ 2
            db[r] = (n[r] > 1 && ss > 0) ? 10 * log(ss / (n[r] - 1) / mean[r] ^ 2) / log(10) : "" } }
        { d = $2 - mean[$1]; e = $3 - se[$1]; if (d < 0) d = -d; if (e < 0) e = -e
          f = ($4 == "" || db[$1] == "") ? ($4 != db[$1]) : ($4 - db[$1]) ^ 2 > 1e-18
          if (d > 1e-12 || e > 1e-12 || f) printf "r=%s: %s +- %s, %s dB; by hand %s +- %s, %s dB; ", $1, $2, $3, $4, mean[$1], se[$1], db[$1] }')
    if [ -z "$problems" ]; then ok; else bad "$hand2 --radial: $problems"; fi
fi

# The shifted-grid comb, measured from the file and predicted by pattern.
comb2=$GOLDEN/comb2d_k16.txt
if succeeds "spectrum --dim 2 of $comb2" "$MCSPEC" spectrum --dim 2 --freq 8 --csv "$comb2"; then
    cp "$tmp/out" "$tmp/comb2.csv"
    problems=$(tail -n +2 "$tmp/comb2.csv" | awk -F, '{
        want = ($1 % 4 == 0 && $2 % 4 == 0) ? 16 : 0; d = $3 - want; if (d < 0) d = -d
        if (d > 1e-12 * 16 || $4 > 1e-12 * 16) printf "k=(%s,%s): %s +- %s, comb %d; ", $1, $2, $3, $4, want }')
    if [ -z "$problems" ]; then ok; else bad "$comb2 against the comb: $problems"; fi
    if succeeds "pattern shifted-grid --dim 2" "$MCSPEC" pattern shifted-grid --dim 2 --k 16 --freq 8 --trials 2 --csv; then
        tail -n +2 "$tmp/comb2.csv" >"$tmp/comb2.rows"
        problems=$(tail -n +2 "$tmp/out" | cut -d, -f5 | paste -d, "$tmp/comb2.rows" - |
            awk -F, '{ d = $3 - $5; if (d < 0) d = -d; if ($5 == "" || d > 1e-12 * 16) printf "k=(%s,%s): %s vs exact %s; ", $1, $2, $3, $5 }')
        if [ -z "$problems" ]; then ok; else bad "$comb2 against pattern shifted-grid's exact column: $problems"; fi
    fi
fi
# 1D without binning: the rotated 8-point comb of the 1D golden file.
if succeeds "spectrum --freq 20 table of $comb" "$MCSPEC" spectrum --freq 20 "$comb"; then
    if head -n 1 "$tmp/out" | grep -qF 'point sets in 1D, no binning: P(k) = |sum_j exp(-2 pi i k x_j)|^2 / K, k = 0..F, F = 20' &&
       ! grep -Eq 'per axis|k\.x_j|kx' "$tmp/out"; then ok
    else bad "spectrum --freq 20 table: 2D wording in 1D: $(head -n 1 "$tmp/out")"; fi
fi
if succeeds "spectrum --dim 2 table of $hand2" "$MCSPEC" spectrum --dim 2 --freq 3 "$hand2"; then
    head -n 1 "$tmp/out" | grep -qF 'point sets in 2D, no binning: P(k) = |sum_j exp(-2 pi i k.x_j)|^2 / K, |kx|, |ky| <= F = 3' &&
        ok || bad "spectrum --dim 2 table: $(head -n 1 "$tmp/out")"
fi
if succeeds "spectrum --freq 20 of $comb" "$MCSPEC" spectrum --freq 20 --csv "$comb"; then
    csv_shape "spectrum --freq --csv" "$tmp/out" 'freq,power,power_stderr' 21 3
    problems=$(tail -n +2 "$tmp/out" | awk -F, '{
        want = ($1 % 8 == 0) ? 8 : 0; d = $2 - want; if (d < 0) d = -d
        if (d > 1e-12 * 8 || $3 > 1e-12 * 8) printf "f=%s: %s +- %s, comb %d; ", $1, $2, $3, want }')
    if [ -z "$problems" ]; then ok; else bad "$comb --freq 20 against the comb: $problems"; fi
fi

# Every 2D kind: the CSV shapes, exact values where theory exists, and the
# measurement within 5 standard errors of them (fixed seed).
h2d='kx,ky,power,power_stderr,exact,z_exact'
hrad='radius,power,power_stderr,anisotropy_db,exact,z_exact'
for kind in random jittered grid shifted-grid n-rooks multi-jittered cmj halton hammersley sobol-owen kronecker; do
    case $kind in multi-jittered | cmj) theory=0 ;; *) theory=1 ;; esac # sobol-owen: Owen's theory
    if succeeds "pattern $kind --dim 2 --csv" "$MCSPEC" pattern "$kind" --dim 2 --k 16 --freq 5 --trials 2000 --seed 4 --csv; then
        csv_shape "pattern $kind --dim 2 --csv" "$tmp/out" "$h2d" 121 6
        filled=$(tail -n +2 "$tmp/out" | awk -F, '$5 != "" { n++ } END { print n + 0 }')
        worst=$(tail -n +2 "$tmp/out" | awk -F, '$6 != "" { z = $6 < 0 ? -$6 : $6; if (z > m) m = z } END { print m + 0 }')
        if [ "$theory" -eq 1 ] && [ "$filled" -eq 121 ] && awk -v z="$worst" 'BEGIN { exit !(z < 5) }'; then ok
        elif [ "$theory" -eq 0 ] && [ "$filled" -eq 0 ]; then ok
        else bad "pattern $kind --dim 2: $filled exact values, |z_exact| up to $worst"; fi
    fi
    if succeeds "pattern $kind --dim 2 --radial --csv" "$MCSPEC" pattern "$kind" --dim 2 --k 16 --freq 5 --trials 2000 --seed 4 --radial --csv; then
        csv_shape "pattern $kind --radial --csv" "$tmp/out" "$hrad" 6 6
        worst=$(tail -n +2 "$tmp/out" | awk -F, '$6 != "" { z = $6 < 0 ? -$6 : $6; if (z > m) m = z } END { print m + 0 }')
        awk -v z="$worst" 'BEGIN { exit !(z < 5) }' && ok || bad "pattern $kind --radial: |z_exact| up to $worst"
    fi
done
if succeeds "pattern --dim 2 table" "$MCSPEC" pattern jittered --dim 2 --k 16 --freq 3 --trials 100 --radial; then
    if head -n 1 "$tmp/out" | grep -q '^mcspec pattern jittered: 2D, 4 x 4 strata, K = 16 points, F = 3, 100 trials, seed 1' &&
       grep -Eq '^ *radius +power +power_stderr +anisotropy_db +exact +z_exact$' "$tmp/out" &&
       [ "$(grep -Ec '^ *[0-9]+ ' "$tmp/out")" -eq 4 ]; then ok
    else bad "pattern --dim 2 table: title, header or 4 rows missing"; fi
fi

# --save: the record shows the same numbers; streams merge like 1D runs.
if succeeds "spectrum --dim 2 --save" "$MCSPEC" spectrum --dim 2 --freq 3 --csv --save "$tmp/h2.rec" "$hand2"; then
    cp "$tmp/out" "$tmp/h2.csv"
    succeeds "show the 2D spectrum record" "$MCSPEC" show "$tmp/h2.rec" --csv &&
        { cmp -s "$tmp/out" "$tmp/h2.csv" && ok || bad "show of the saved 2D spectrum differs from spectrum --csv"; }
fi
if succeeds "spectrum --freq --save" "$MCSPEC" spectrum --freq 20 --csv --save "$tmp/c1.rec" "$comb"; then
    cp "$tmp/out" "$tmp/c1.csv"
    succeeds "show the 1D point-set record" "$MCSPEC" show "$tmp/c1.rec" --csv &&
        { cmp -s "$tmp/out" "$tmp/c1.csv" && ok || bad "show of the saved 1D point-set spectrum differs"; }
fi
run "$MCSPEC" pattern n-rooks --dim 2 --k 9 --freq 4 --trials 301 --seed 6 --radial --csv --save "$tmp/p2.rec"
cut -d, -f1-4 "$tmp/out" >"$tmp/p2.csv"
succeeds "show --radial of a pattern --dim 2 record" "$MCSPEC" show "$tmp/p2.rec" --radial --csv &&
    { cmp -s "$tmp/out" "$tmp/p2.csv" && ok || bad "show --radial differs from pattern --dim 2 --radial"; }
run "$MCSPEC" pattern n-rooks --dim 2 --k 9 --freq 4 --trials 301 --seed 6 --radial --csv; cp "$tmp/out" "$tmp/q1"
run "$MCSPEC" pattern n-rooks --dim 2 --k 9 --freq 4 --trials 301 --seed 7 --radial --csv; cp "$tmp/out" "$tmp/q2"
cut -d, -f1-4 "$tmp/q1" | cmp -s - "$tmp/p2.csv" && ok ||
    bad "pattern --dim 2: the same seed gives different output"
cmp -s "$tmp/q1" "$tmp/q2" && bad "pattern --dim 2: the seed has no effect" || ok
run "$MCSPEC" pattern cmj --dim 2 --k 12 --freq 3 --trials 101 --seed 2 --streams 3 --save "$tmp/s3.rec"
for i in 0 1 2; do
    run "$MCSPEC" pattern cmj --dim 2 --k 12 --freq 3 --trials 101 --seed 2 --streams 3 --stream "$i" --save "$tmp/s3_$i.rec"
done
if succeeds "merge of the --stream files" "$MCSPEC" merge "$tmp/s3_0.rec" "$tmp/s3_1.rec" "$tmp/s3_2.rec" -o "$tmp/s3m.rec"; then
    cmp -s "$tmp/s3.rec" "$tmp/s3m.rec" && ok || bad "pattern --dim 2 --streams 3 differs from the merge of its streams"
fi

# ----------------------------------------------------------------- plots
usage_error "--plot x.pdf" 'must end in .svg or .png' "$MCSPEC" pattern random --n 16 --k 4 --plot "$tmp/x.pdf"
usage_error "--plot in a missing directory" 'cannot write in directory' \
    "$MCSPEC" pattern random --n 16 --k 4 --plot "$tmp/no/such/dir/x.svg"
usage_error "--plot without gnuplot" 'needs gnuplot, which is not on PATH' \
    env PATH=/nonexistent "$abs" pattern random --n 16 --k 4 --plot "$tmp/nognuplot.svg"
[ -e "$tmp/nognuplot.svg" ] && bad "--plot without gnuplot left a file" || ok
if command -v gnuplot >/dev/null 2>&1; then
    mkdir -p "$tmp/gptmp"
    succeeds "pattern --plot x.svg" \
        env TMPDIR="$tmp/gptmp" "$MCSPEC" pattern stratified --n 32 --k 4 --trials 200 --plot "$tmp/p.svg"
    svg=$(tr '\n' ' ' <"$tmp/p.svg" | sed -n 's/.*<svg\([^>]*\)>.*/\1/p')
    case $svg in
    *'width="960"'*'height="600"'*) ok ;;
    *) bad "--plot SVG root element: $svg" ;;
    esac
    for s in 'measured ± 1 standard error' 'measured (mean over trials)' 'exact: mcs_theory' 'closed form: eq. 33'; do
        grep -qF "<text>$s" "$tmp/p.svg" && ok || bad "--plot SVG has no legend entry '$s'"
    done
    succeeds "spectrum --plot x.png" env TMPDIR="$tmp/gptmp" "$MCSPEC" spectrum --n 64 --plot "$tmp/s.png" "$comb"
    sig=$(od -An -tx1 -N24 "$tmp/s.png" | tr -d ' \n')
    [ "$sig" = "89504e470d0a1a0a0000000d49484452000003c000000258" ] && ok ||
        bad "--plot PNG: not a 960 x 600 PNG ($sig)"
    [ -z "$(ls -A "$tmp/gptmp")" ] && ok || bad "--plot left temporary files: $(ls -A "$tmp/gptmp")"
    succeeds "pattern --dim 2 --plot x.svg" \
        env TMPDIR="$tmp/gptmp" "$MCSPEC" pattern jittered --dim 2 --k 16 --freq 6 --trials 200 --plot "$tmp/p2d.svg"
    grep -q "<image .*data:image/png;base64," "$tmp/p2d.svg" && ok || bad "--dim 2 --plot SVG has no image"
    for s in 'measured ± 1 standard error' 'measured (mean over trials)' 'exact: closed form'; do
        grep -qF "<text>$s" "$tmp/p2d.svg" && ok || bad "--dim 2 --plot SVG has no legend entry '$s'"
    done
    succeeds "show --plot of a pointset2d record" env TMPDIR="$tmp/gptmp" "$MCSPEC" show "$tmp/p2.rec" --plot "$tmp/s2d.png"
    sig=$(od -An -tx1 -N24 "$tmp/s2d.png" | tr -d ' \n')
    [ "$sig" = "89504e470d0a1a0a0000000d49484452000003c000000258" ] && ok ||
        bad "show --plot of a pointset2d record: not a 960 x 600 PNG ($sig)"
else
    skip "--plot rendering (SVG and PNG files, their size and legends): gnuplot not installed"
fi
# A gnuplot that fails: exit 2 with its message, no figure, nothing on
# stdout. A fake one, first on PATH: no real gnuplot needed.
mkdir -p "$tmp/fakebin" "$tmp/gptmp"
printf '#!/bin/sh\necho "fake gnuplot: cannot draw" >&2\nexit 1\n' >"$tmp/fakebin/gnuplot"
chmod +x "$tmp/fakebin/gnuplot"
usage_error "--plot with a failing gnuplot" 'gnuplot failed: fake gnuplot: cannot draw' \
    env PATH="$tmp/fakebin:$PATH" TMPDIR="$tmp/gptmp" "$abs" pattern random --n 16 --k 4 --plot "$tmp/f.svg"
[ ! -e "$tmp/f.svg" ] && [ -z "$(ls -A "$tmp/gptmp")" ] && ok ||
    bad "--plot with a failing gnuplot left files behind"

# --log: the y axis of the figure's spectrum (2D: its profile) in log scale.
# A fake gnuplot, first on PATH, keeps the script and data it is given.
usage_error "--log without --plot" "^mcspec pattern: --log sets the figure's y axis: give --plot FILE too" \
    "$MCSPEC" pattern random --n 16 --k 4 --log
usage_error "spectrum --log without --plot" "--log sets the figure's y axis" "$MCSPEC" spectrum --n 4 --log -
usage_error "show --log without --plot" "--log sets the figure's y axis" "$MCSPEC" show x.rec --log
mkdir -p "$tmp/capbin"
# shellcheck disable=SC2016 # $1 and $d are the fake's own, expanded when it runs
printf '#!/bin/sh\nd=$(dirname "$1")\nrm -rf "%s" && mkdir "%s" && cp "$d"/plot.gp "$d"/data*.txt "%s/" &&\n    echo figure >"$d/figure"\n' \
    "$tmp/cap" "$tmp/cap" "$tmp/cap" >"$tmp/capbin/gnuplot"
chmod +x "$tmp/capbin/gnuplot"
# log_figure LABEL: the script sets a log y axis over a positive range, and
# the drawn columns (2-6) of the profile's data hold no value <= 0.
log_figure() {
    range=$(sed -n 's/^set yrange \[\([^:]*\):.*/\1/p' "$tmp/cap/plot.gp" | tail -n 1)
    if ! grep -qx 'set logscale y' "$tmp/cap/plot.gp"; then bad "$1: no 'set logscale y'"
    elif ! awk -v r="$range" 'BEGIN { exit !(r > 0) }'; then bad "$1: y range from '$range'"
    elif ! awk '!/^#/ { for (i = 2; i <= 6; ++i) if ($i != "NaN" && !($i > 0)) exit 1 }' "$tmp/cap/data.txt"
    then bad "$1: a value <= 0 on the log axis: $(grep -v '^#' "$tmp/cap/data.txt" | head -n 3 | tr '\n' ';')"
    else ok; fi
}
# The jitter comb: exact powers 0 between the teeth, measured 0 (or rounding).
succeeds "pattern jitter --plot --log" env PATH="$tmp/capbin:$PATH" \
    "$abs" pattern jitter --n 64 --k 8 --trials 50 --plot "$tmp/log.svg" --log
log_figure "pattern jitter --log"
# ... whose exact line still reads as a comb: teeth at k = 8, 16, 24, 32 and
# the bottom of the axis between them.
teeth=$(awk -v b="$range" '!/^#/ && $5 != "NaN" && $5 > b { printf "%s ", $1 }' "$tmp/cap/data.txt")
[ "$teeth" = "8 16 24 32 " ] && ok || bad "pattern jitter --log: exact teeth at '$teeth'"
succeeds "pattern jitter --plot, linear" env PATH="$tmp/capbin:$PATH" \
    "$abs" pattern jitter --n 64 --k 8 --trials 50 --plot "$tmp/log.svg"
grep -q 'logscale' "$tmp/cap/plot.gp" && bad "--plot without --log sets a log scale" || ok
grep -q '^set yrange \[0:' "$tmp/cap/plot.gp" && ok || bad "--plot without --log: y range not from 0"
succeeds "spectrum --plot --log of the comb" env PATH="$tmp/capbin:$PATH" \
    "$abs" spectrum --n 64 --plot "$tmp/log.png" --log "$comb"
log_figure "spectrum --log"
succeeds "spectrum --freq --plot --log of the comb" env PATH="$tmp/capbin:$PATH" \
    "$abs" spectrum --freq 20 --plot "$tmp/log.png" --log "$comb"
log_figure "spectrum --freq --log"
# Zero at every k >= 1 (uniform, K = N): nothing on the axis, a range still.
succeeds "pattern uniform K = N --plot --log" env PATH="$tmp/capbin:$PATH" \
    "$abs" pattern uniform --n 16 --k 16 --trials 10 --plot "$tmp/log.svg" --log
log_figure "pattern uniform K = N --log"
# 2D: the profile panel is logarithmic, the image before it is not.
succeeds "pattern --dim 2 --plot --log" env PATH="$tmp/capbin:$PATH" \
    "$abs" pattern grid --dim 2 --k 16 --freq 6 --trials 20 --plot "$tmp/log.svg" --log
log_figure "pattern --dim 2 --log"
order=$(grep -n 'with image\|^set logscale y' "$tmp/cap/plot.gp" | cut -d: -f2 | cut -c1-4 | tr '\n' ' ')
[ "$order" = "plot set  " ] && ok || bad "pattern --dim 2 --log: the image is on the log axis ($order)"
succeeds "show --plot --log of a pointset record" env PATH="$tmp/capbin:$PATH" \
    "$abs" show "$tmp/c1.rec" --plot "$tmp/log.svg" --log
log_figure "show --log"
if command -v gnuplot >/dev/null 2>&1; then
    for a in "pattern jitter --n 64 --k 8 --trials 50" "pattern uniform --n 16 --k 16 --trials 10" \
             "pattern jittered --dim 2 --k 16 --freq 6 --trials 50"; do
        # shellcheck disable=SC2086
        succeeds "$a --plot x.svg --log (gnuplot)" env TMPDIR="$tmp/gptmp" "$MCSPEC" $a --plot "$tmp/l.svg" --log &&
            { grep -q '<svg' "$tmp/l.svg" && ok || bad "$a --log: no SVG"; }
    done
else
    skip "--plot --log rendering: gnuplot not installed"
fi

# -------------------------------------------------------------- progress
run env MCSPEC_PROGRESS_DELAY=0 "$MCSPEC" pattern random --n 64 --k 8 --trials 3000
[ "$rc" -eq 0 ] && [ ! -s "$tmp/err" ] && ok || bad "progress on a stderr that is not a terminal"
if command -v script >/dev/null 2>&1 && script -qec true /dev/null >/dev/null 2>&1; then
    # Under script(1) stderr is a terminal; stdout goes to a file.
    MCSPEC_PROGRESS_DELAY=0 script -qec "'$abs' pattern random --n 64 --k 8 --trials 3000 >/dev/null" \
        /dev/null >"$tmp/tty" 2>&1
    grep -q 'of 3000 trials' "$tmp/tty" && ok || bad "no progress on a terminal"
    # ... with the time taken and an estimate of the time left.
    grep -Eq '% \([0-9]+ of 3000 trials, [0-9]+ s, about [0-9]+ (s|min [0-9]+ s|h [0-9]+ min) left\)' "$tmp/tty" &&
        ok || bad "progress without the time left: $(tr '\r' '\n' <"$tmp/tty" | grep -m 1 trials | cat -v)"
    # A --stream run counts its own share: stream 2 of 3 runs 1000 of the 3000.
    MCSPEC_PROGRESS_DELAY=0 script -qec "'$abs' pattern random --n 64 --k 8 --trials 3000 --streams 3 --stream 2 >/dev/null" \
        /dev/null >"$tmp/tty" 2>&1
    grep -Eq '\([0-9]+ of 1000 trials, .* left\)' "$tmp/tty" && ok ||
        bad "progress of --stream 2 of 3: $(tr '\r' '\n' <"$tmp/tty" | grep -m 1 trials | cat -v)"
    MCSPEC_PROGRESS_DELAY=0 script -qec "'$abs' pattern random --n 64 --k 8 --trials 3000 --csv >/dev/null" \
        /dev/null >"$tmp/tty" 2>&1
    [ ! -s "$tmp/tty" ] && ok || bad "progress with --csv: $(od -c "$tmp/tty" | head -n 2)"
else
    skip "progress on a terminal: util-linux script not available"
fi

check_summary
