#!/bin/sh
# Checks of the command mcspec integrate (issue 25).
#
# usage: sh test/integrate_check.sh   ($MCSPEC names the binary, default
#                                      build/bin/mcspec)
#
#   --help; the CSV: header exactly, one row per family and K, numbers or
#   empty fields (exact empty for point files, predicted empty for the
#   families that are not periodic); hand-made sets against values worked
#   out by hand: one point at x = 1/2 and the 1D step [x < p], p uniform,
#   E (1[x < p] - p)^2 = x^3/3 + (1 - x)^3/3 = 1/12; one point in 2D and the
#   disk on the torus, E (1[inside] - pi r^2)^2 = E pi r^2 (1 - pi r^2) over
#   r uniform on [0.1, 0.4] = 0.07 pi - 0.00682 pi^2 (E r^2 = 0.07,
#   E r^4 = 0.00682); both within 5 standard errors;
#   named patterns: random and jittered in 2D, random and stratified in 1D,
#   every family's mse within 5 standard errors of exact, and for the
#   periodic families predicted - 5 se <= mse <= predicted + tail + 5 se;
#   convergence slopes over K = 64..4096 within 0.1 of the published rate
#   (random -1; jittered -2 smooth, -1.5 discontinuous); utk's families
#   (blinn_phong, 2D only, and gaussian_mixture) on their own, as their
#   quadratures cost about a millisecond per integrand: random sets and
#   1D strata within 5 se of exact, no 2D jittered exact and no prediction,
#   blinn_phong's slopes,
#   blinn_phong absent on 1D points and refused there by --family, and a
#   --family list; the same bytes for
#   the same seed and different ones for another; standard input; files
#   grouped by K; a figure (when gnuplot is there);
#   every bad usage and input: exit 2, one line on stderr, nothing on stdout.
# Ends with a Unity-style summary so test/run_tests.sh counts it.

MCSPEC=${MCSPEC:-build/bin/mcspec}

# shellcheck source=test/support/check.sh
. "$(dirname "$0")/support/check.sh"
check_start integrate_check

if [ ! -x "$MCSPEC" ]; then
    bad "$MCSPEC is not an executable (make cli)"
    check_summary
    exit 1
fi

HEADER='family,k,mse,mse_stderr,exact,predicted,predicted_tail,freq,sets,slope,rate_random,rate_jittered'

# csv_shape LABEL FILE ROWS: the header exactly, ROWS rows of 12 fields,
# fields 2.. numbers or empty.
csv_shape() {
    if [ "$(head -n 1 "$2")" = "$HEADER" ]; then ok; else bad "$1: header '$(head -n 1 "$2")'"; fi
    problems=$(tail -n +2 "$2" | awk -F, -v rows="$3" '
        function num(s) { return s == "" || s ~ /^[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?$/ }
        NF != 12 { printf "row %d: %d fields; ", NR, NF }
        { for (i = 2; i <= NF; ++i) if (!num($i)) printf "row %d field %d \"%s\"; ", NR, i, $i }
        END { if (NR != rows) printf "%d rows, expected %d", NR, rows }')
    if [ -z "$problems" ]; then ok; else bad "$1: $problems"; fi
}

# within LABEL FILE: every row with an exact value has |mse - exact| < 5 se,
# every row with a prediction pred - 5 se <= mse <= pred + tail + 5 se.
within() {
    problems=$(awk -F, 'NR > 1 {
        if ($5 != "" && ($3 - $5 > 5 * $4 || $5 - $3 > 5 * $4)) printf "%s K=%s: mse %s exact %s se %s; ", $1, $2, $3, $5, $4
        if ($6 != "" && ($3 < $6 - 5 * $4 || $3 > $6 + $7 + 5 * $4)) printf "%s K=%s: mse %s predicted %s tail %s se %s; ", $1, $2, $3, $6, $7, $4
    }' "$2")
    if [ -z "$problems" ]; then ok; else bad "$1: $problems"; fi
}

# column_is LABEL FILE FAMILY COL WHAT: COL of FAMILY's rows is empty
# (WHAT = empty) or not (WHAT = set).
column_is() {
    problems=$(awk -F, -v fam="$3" -v col="$4" -v what="$5" 'NR > 1 && $1 == fam {
        if ((what == "empty") != ($col == "")) printf "K=%s col %d \"%s\"; ", $2, col, $col }' "$2")
    if [ -z "$problems" ]; then ok; else bad "$1: $problems"; fi
}

echo "== $MCSPEC integrate"

# ---------------------------------------------------------------- --help
if succeeds "--help" "$MCSPEC" integrate --help && grep -q '^usage: mcspec integrate' "$tmp/out" &&
    grep -q "$HEADER" "$tmp/out"; then ok; else bad "--help: no usage line or CSV header"; fi

# ------------------------------------------------------------- bad usage
printf '0.5 0.5\n' >"$tmp/one"
printf '0.1 0.2 0.3\n' >"$tmp/three"
printf '0.1 0.2\n0.5 x\n' >"$tmp/nan"
printf '0.1 0.2\n1.5 0.2\n' >"$tmp/outside"
: >"$tmp/empty"
usage_error "unknown option" "unknown option '--bogus'" "$MCSPEC" integrate --bogus "$tmp/one"
usage_error "unknown kind" "unknown pattern 'blue'" "$MCSPEC" integrate blue --k 16
usage_error "a 1D kind in 2D" "'stratified' is a 1D pattern: give --dim 1" "$MCSPEC" integrate stratified --k 16
usage_error "a 2D kind in 1D" "'jittered' is a 2D pattern: give --dim 2" "$MCSPEC" integrate jittered --dim 1 --k 16
usage_error "--k without a kind" "--k needs a KIND" "$MCSPEC" integrate --k 16
usage_error "a kind without --k" "'random' is a pattern: give --k K" "$MCSPEC" integrate random
usage_error "--k 0" "--k expects a whole number from 1" "$MCSPEC" integrate random --k 0
usage_error "a sample kind without 1D" "pmj02 has dimensions 2 only" "$MCSPEC" integrate pmj02 --dim 1 --k 16
# the kinds of mcspec sample that mcspec pattern does not draw: no exact column
if succeeds "integrate poisson-disk" "$MCSPEC" integrate poisson-disk --k 64 --sets 4 --family disk --csv &&
    awk -F, 'NR == 2 && $1 == "disk" && $3 != "" && $5 == "" { g = 1 } END { exit !g || NR != 2 }' "$tmp/out"
then ok; else bad "integrate poisson-disk: not one disk row with an mse and no exact"; fi
usage_error "--k twice" "--k 16 given twice" "$MCSPEC" integrate random --k 16 --k 16
usage_error "--k with no value" "--k needs a value" "$MCSPEC" integrate random --k
usage_error "--k with files" "give one KIND with --k, not files" "$MCSPEC" integrate random jittered --k 16
usage_error "unknown family" "unknown family 'bump'" "$MCSPEC" integrate random --k 16 --family bump
usage_error "unknown family in a list" "unknown family 'bump'" "$MCSPEC" integrate random --k 16 --family disk,bump
usage_error "blinn_phong in 1D" "family blinn_phong has no 1D integrands" "$MCSPEC" integrate random --dim 1 --k 16 --family blinn_phong
printf '0.5\n#\n' >"$tmp/one1"
usage_error "blinn_phong on a 1D file" "family blinn_phong has no 1D integrands" "$MCSPEC" integrate --family disk,blinn_phong "$tmp/one1"
usage_error "--sets with files" "--sets is for a named pattern" "$MCSPEC" integrate --sets 4 "$tmp/one"
usage_error "--sets 0" "--sets expects" "$MCSPEC" integrate random --k 16 --sets 0
usage_error "--integrands 0" "--integrands expects" "$MCSPEC" integrate random --k 16 --integrands 0
usage_error "--dim 3" "--dim expects a whole number from 1 to 2" "$MCSPEC" integrate random --dim 3 --k 16
usage_error "--freq too high in 2D" "--freq: at most 1024 in 2D" "$MCSPEC" integrate random --k 16 --freq 2000
usage_error "--freq too high for a 2D file" "--freq: at most 1024 in 2D" "$MCSPEC" integrate --freq 2000 "$tmp/one"
usage_error "--exact with a kind" "--exact is for point files" "$MCSPEC" integrate random --k 16 --exact random
usage_error "--exact bogus" "--exact takes random, jittered or stratified, not 'blue'" "$MCSPEC" integrate --exact blue "$tmp/one"
usage_error "--wrap with a kind" "--wrap is for point files" "$MCSPEC" integrate random --k 16 --wrap
usage_error "--plot .txt" "must end in .svg or .png" "$MCSPEC" integrate random --k 16 --plot "$tmp/f.txt"
usage_error "three coordinates" "3 coordinates; the integrands take 1 or 2" "$MCSPEC" integrate "$tmp/three"
usage_error "not a number" "nan.*line 2" "$MCSPEC" integrate "$tmp/nan"
usage_error "outside [0,1)" "outside.*line 2" "$MCSPEC" integrate "$tmp/outside"
usage_error "empty file" "empty|no point" "$MCSPEC" integrate "$tmp/empty"
usage_error "missing file" "no-such-file" "$MCSPEC" integrate "$tmp/no-such-file"

# ------------------------------------------- hand-made: one point, by hand
# 16 sets of the single point 1/2 (1D) and (1/2, 1/2) (2D), 4096 integrands each.
awk 'BEGIN { for (i = 0; i < 16; ++i) print "0.5\n#" }' >"$tmp/half1"
awk 'BEGIN { for (i = 0; i < 16; ++i) print "0.5 0.5\n#" }' >"$tmp/half2"
if succeeds "1D step at one point" "$MCSPEC" integrate --csv --family heaviside --integrands 4096 "$tmp/half1"; then
    csv_shape "1D step --csv" "$tmp/out" 1
    problems=$(awk -F, 'NR == 2 { d = $3 - 1 / 12; if (d < 0) d = -d; if (!(d < 5 * $4) || $5 != "" || $6 != "") print $0 }' "$tmp/out")
    if [ -z "$problems" ]; then ok; else bad "1D step: want 1/12 within 5 se, no exact, no prediction: $problems"; fi
fi
if succeeds "2D disk at one point" "$MCSPEC" integrate --csv --family disk --integrands 4096 "$tmp/half2"; then
    csv_shape "2D disk --csv" "$tmp/out" 1
    problems=$(awk -F, 'NR == 2 { pi = atan2(0, -1); want = 0.07 * pi - 0.00682 * pi * pi
        d = $3 - want; if (d < 0) d = -d; if (!(d < 5 * $4) || $5 != "" || $6 == "") print $0 " want " want }' "$tmp/out")
    if [ -z "$problems" ]; then ok; else bad "2D disk: $problems"; fi
fi

# --------------------------------------------------- named patterns, exact
for run_ in "random --dim 2" "jittered --dim 2" "random --dim 1" "stratified --dim 1"; do
    # shellcheck disable=SC2086
    if succeeds "$run_" "$MCSPEC" integrate $run_ --k 64 --k 256 --sets 64 --integrands 8 --seed 5 --csv --family gaussian,gaussian_periodic,heaviside,disk,cosine; then
        csv_shape "$run_ --csv" "$tmp/out" 10
        within "$run_ against exact and predicted" "$tmp/out"
        for fam in gaussian gaussian_periodic heaviside disk cosine; do column_is "$run_ $fam exact" "$tmp/out" "$fam" 5 set; done
        for fam in gaussian heaviside; do column_is "$run_ $fam no prediction" "$tmp/out" "$fam" 6 empty; done
        for fam in gaussian_periodic disk cosine; do column_is "$run_ $fam predicted" "$tmp/out" "$fam" 6 set; done
    fi
done

# ----------------------------------------------------------- slopes
for kind in random jittered; do
    if succeeds "$kind slopes" "$MCSPEC" integrate "$kind" --k 64 --k 256 --k 1024 --k 4096 --sets 16 --integrands 8 --freq 0 --seed 2 --csv --family gaussian,gaussian_periodic,heaviside,disk,cosine,gaussian_mixture; then
        col=11; [ "$kind" = jittered ] && col=12
        problems=$(awk -F, -v col="$col" 'NR > 1 && $2 == 4096 { d = $10 - $col; if (d < 0) d = -d; if (!(d < 0.1)) printf "%s slope %s rate %s; ", $1, $10, $col }' "$tmp/out")
        if [ -z "$problems" ]; then ok; else bad "$kind slopes: $problems"; fi
    fi
done

# ------------------------------------------------------ utk's families
for run_ in "random --dim 2" "jittered --dim 2" "random --dim 1" "stratified --dim 1"; do
    # shellcheck disable=SC2086
    if succeeds "utk $run_" "$MCSPEC" integrate $run_ --k 64 --k 256 --sets 32 --integrands 4 --seed 5 --csv; then
        case $run_ in *"dim 2") rows_=14 utk_="blinn_phong gaussian_mixture" ;; *) rows_=12 utk_=gaussian_mixture ;; esac
        csv_shape "utk $run_ --csv" "$tmp/out" "$rows_"
        within "utk $run_ against exact" "$tmp/out"
        for fam in $utk_; do
            # exact: random sets, and strata of the 1D mixture (by erf); none for 2D jittered
            case "$run_ $fam" in random*|stratified*) want_=set ;; *) want_=empty ;; esac
            column_is "$run_ $fam exact" "$tmp/out" "$fam" 5 "$want_"
            column_is "$run_ $fam no prediction" "$tmp/out" "$fam" 6 empty
        done
        if [ "$rows_" = 12 ] && grep -q '^blinn_phong' "$tmp/out"; then bad "$run_: blinn_phong rows on 1D points"; else ok; fi
    fi
done
for kind in random jittered; do
    if succeeds "$kind blinn_phong slope" "$MCSPEC" integrate "$kind" --k 64 --k 256 --k 1024 --k 4096 --sets 16 --integrands 4 --seed 2 --csv --family blinn_phong; then
        col=11; [ "$kind" = jittered ] && col=12
        problems=$(awk -F, -v col="$col" 'NR > 1 && $2 == 4096 { d = $10 - $col; if (d < 0) d = -d; if (!(d < 0.1)) printf "%s slope %s rate %s; ", $1, $10, $col }' "$tmp/out")
        if [ -z "$problems" ]; then ok; else bad "$kind blinn_phong slope: $problems"; fi
    fi
done

# -------------------------------------------- reproducible, stdin, files
"$MCSPEC" integrate jittered --k 16 --sets 8 --integrands 4 --seed 9 --csv >"$tmp/a" 2>&1
"$MCSPEC" integrate jittered --k 16 --sets 8 --integrands 4 --seed 9 --csv >"$tmp/b" 2>&1
"$MCSPEC" integrate jittered --k 16 --sets 8 --integrands 4 --seed 10 --csv >"$tmp/c" 2>&1
if cmp -s "$tmp/a" "$tmp/b"; then ok; else bad "the same seed gave different output"; fi
if cmp -s "$tmp/a" "$tmp/c"; then bad "another seed gave the same output"; else ok; fi
awk 'BEGIN { srand(3); for (s = 0; s < 6; ++s) { for (i = 0; i < 4; ++i) print rand(), rand(); print "#" } }' >"$tmp/k4"
awk 'BEGIN { srand(4); for (s = 0; s < 6; ++s) { for (i = 0; i < 16; ++i) print rand(), rand(); print "#" } }' >"$tmp/k16"
if succeeds "two files" "$MCSPEC" integrate --csv --family gaussian,gaussian_periodic,heaviside,disk,cosine "$tmp/k16" "$tmp/k4"; then
    csv_shape "two files --csv" "$tmp/out" 10
    for fam in gaussian gaussian_periodic heaviside disk cosine; do column_is "files $fam exact" "$tmp/out" "$fam" 5 empty; done
    if [ "$(awk -F, 'NR > 1 { printf "%s ", $2 }' "$tmp/out")" = "4 16 4 16 4 16 4 16 4 16 " ]; then ok
    else bad "two files: rows not per family and growing K"; fi
    cp "$tmp/out" "$tmp/files.csv"
    cat "$tmp/k16" "$tmp/k4" >"$tmp/in"
    if succeeds "standard input" "$MCSPEC" integrate --csv --family gaussian,gaussian_periodic,heaviside,disk,cosine - && cmp -s "$tmp/out" "$tmp/files.csv"; then ok
    else bad "standard input differs from the files read in the same order"; fi
    : >"$tmp/in"
fi
# A jittered 8 x 8 file (awk's generator) with --exact jittered: within 5 se.
awk 'BEGIN { srand(11); for (s = 0; s < 64; ++s) { for (i = 0; i < 8; ++i) for (j = 0; j < 8; ++j)
    printf "%.9f %.9f\n", (j + 0.999 * rand()) / 8, (i + 0.999 * rand()) / 8; print "#" } }' >"$tmp/jit"
if succeeds "--exact jittered" "$MCSPEC" integrate --exact jittered --csv --family gaussian,gaussian_periodic,heaviside,disk,cosine "$tmp/jit"; then
    csv_shape "--exact jittered --csv" "$tmp/out" 5
    within "a jittered file against exact" "$tmp/out"
    for fam in gaussian gaussian_periodic heaviside disk cosine; do column_is "--exact $fam" "$tmp/out" "$fam" 5 set; done
fi
if succeeds "table" "$MCSPEC" integrate jittered --k 16 --k 64 --sets 8 --integrands 4 && grep -q '^convergence' "$tmp/out" &&
    grep -q '^family  *K  *mse' "$tmp/out"; then ok; else bad "table: no header or convergence section"; fi

# ---------------------------------------------------------------- figure
if command -v gnuplot >/dev/null 2>&1; then
    if succeeds "--plot" "$MCSPEC" integrate jittered --k 16 --k 64 --sets 8 --integrands 4 --plot "$tmp/fig.png" &&
        [ -s "$tmp/fig.png" ]; then ok; else bad "--plot wrote no figure"; fi
else
    skip "--plot (no gnuplot)"
fi

check_summary
