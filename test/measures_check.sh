#!/bin/sh
# Checks of the commands mcspec discrepancy and mcspec stats (issue 25).
#
# usage: sh test/measures_check.sh   ($MCSPEC names the binary, default
#                                     build/bin/mcspec)
#
#   --help of both; bad usage (unknown option, --dim out of range, two
#   files, a value on a flag): exit 2, one line on stderr, nothing on stdout;
#   hand-made sets against values worked out by hand (the six squared L2
#   discrepancies and the star discrepancy of one point at the centre of the
#   square, their exact random expectations for K = 1; two 1D sets, their
#   mean, standard error and mixed-K expectation; a square grid's and an
#   equally spaced circle's distances);
#   the CSV: header exactly, row counts, numbers or empty fields, root =
#   sqrt(value); the table's header;
#   200 sets of 256 independent uniform points in 2D (awk's generator, a
#   fixed seed): every L2 mean within 5 standard errors of exact_random, the
#   star's mean above the L2 star's (D*_2 <= D* per set), and the average
#   minimum distance within 5 standard errors of the exact nearest-neighbour
#   expectation (1/2) Gamma(K) / Gamma(K + 1/2) over d_max;
#   the star row left out (and said so) when a set has more than 4096
#   points; standard input read like a file; the same bytes twice; --wrap;
#   every malformed input (a coordinate outside [0,1), not a number, the
#   wrong column count, an empty set, an empty or missing file, a bad line
#   after 200 good sets, a single-point set for stats): exit 2, one line on
#   stderr naming the file and the line (the set for stats' single point),
#   nothing on stdout;
#   KIND instead of a file (mcspec discrepancy|stats KIND --dim D --k K):
#   bad kinds, dimensions and option mixes exit 2 with one line; every kind
#   of mcspec sample runs in a dimension it has; the sets are those of
#   mcspec sample (the same CSV as its output read back); the exact column
#   is exact_random for random and within 5 standard errors of the mean for
#   random (2D, 5D), jittered (2D, 8 x 4 strata), stratified (1D) and
#   sobol-owen (1D, K = 32; none at K = 24), and
#   for stats of random sets the average minimum distance (1D, 2D; 3D from
#   K = 52, none at 51) and the 1D minimum distance.
# Ends with a Unity-style summary ("N Tests F Failures 0 Ignored", then OK or
# FAIL) so test/run_tests.sh counts it; exit status non-zero on failure.

MCSPEC=${MCSPEC:-build/bin/mcspec}

# shellcheck source=test/support/check.sh
. "$(dirname "$0")/support/check.sh"
check_start measures_check

if [ ! -x "$MCSPEC" ]; then
    bad "$MCSPEC is not an executable (make cli)"
    check_summary
    exit 1
fi

# expect LABEL CSV WANT: every "name col value" line of WANT (col 2..5 of the
# CSV, value a number or "empty") holds in the CSV to 1e-12 relative.
expect() {
    problems=$(awk -F, -v want="$3" '
        BEGIN { n = split(want, lines, "\n")
                for (i = 1; i <= n; ++i) if (split(lines[i], w, " ") == 3) { key[w[1] SUBSEP w[2]] = w[3]; seen[w[1]] = 0 } }
        NR > 1 { for (c = 2; c <= NF; ++c) if (($1 SUBSEP c) in key) {
                     v = key[$1 SUBSEP c]; seen[$1] = 1
                     if (v == "empty") { if ($c != "") printf "%s col %d: %s, expected empty; ", $1, c, $c }
                     else { d = $c - v; if (d < 0) d = -d; s = v < 0 ? -v : v
                            if ($c == "" || d > 1e-12 * (s > 1e-300 ? s : 1)) printf "%s col %d: %s, expected %s; ", $1, c, $c, v } } }
        END { for (r in seen) if (!seen[r]) printf "no row %s; ", r }' "$2")
    if [ -z "$problems" ]; then ok; else bad "$1: $problems"; fi
}

echo "== $MCSPEC discrepancy, stats"

# ---------------------------------------------------------------- --help
for c in discrepancy stats; do
    if succeeds "$c --help" "$MCSPEC" "$c" --help && grep -q "^usage: mcspec $c" "$tmp/out"
    then ok; else bad "$c --help: no usage line"; fi
done
if "$MCSPEC" discrepancy --help | grep -q 'measure,value,stderr,exact_random,root,exact'; then ok
else bad "discrepancy --help does not give the CSV header"; fi
if "$MCSPEC" stats --help | grep -q 'statistic,value,stderr,exact'; then ok
else bad "stats --help does not give the CSV header"; fi

# ------------------------------------------------------------- bad usage
usage_error "discrepancy --dim 65" '--dim expects a whole number from 1 to 64' \
    "$MCSPEC" discrepancy --dim 65 -
usage_error "stats --dim 9" '--dim expects a whole number from 1 to 8' "$MCSPEC" stats --dim 9 -
for c in discrepancy stats; do
    usage_error "$c --dim 0" '--dim expects' "$MCSPEC" "$c" --dim 0 -
    usage_error "$c --bogus" "unknown option '--bogus'" "$MCSPEC" "$c" --bogus -
    usage_error "$c two files" "unexpected argument" "$MCSPEC" "$c" a b
    usage_error "$c --csv=1" 'takes no value' "$MCSPEC" "$c" --csv=1 -
done

# ------------------------------------------------ hand-made: one point, 2D
# D^2 = C0 - 2 g + h(x, x) at x = (1/2, 1/2), each by hand from the table of
# include/mcspec/discrepancy.h; exact random for K = 1 is E h(x, x) - C0; the
# star: the closed box [0, 1/2]^2 holds the point, 1 - 1/4 = 3/4.
printf '0.5 0.5\n' >"$tmp/centre"
if succeeds "discrepancy of one point" "$MCSPEC" discrepancy --csv "$tmp/centre"; then
    csv_shape "discrepancy --csv" "$tmp/out" 'measure,value,stderr,exact_random,root,exact' 7 6
    expect "one point at the centre" "$tmp/out" "$(cat <<'EOF'
l2_star 2 0.079861111111111111
l2_star 3 empty
l2_star 4 0.13888888888888889
l2_star 5 0.2825970826302195
l2_centered 2 0.17361111111111111
l2_centered 4 0.38888888888888889
l2_wraparound 2 0.47222222222222222
l2_wraparound 4 0.47222222222222222
l2_symmetric 2 1.2777777777777778
l2_symmetric 4 2.2222222222222222
l2_generalized 2 0.24652777777777778
l2_generalized 4 0.47222222222222222
l2_unanchored 2 0.038194444444444444
l2_unanchored 4 0.020833333333333333
star 2 0.5625
star 4 empty
star 5 0.75
EOF
)"
fi

# ------------------------------- hand-made: one point, 3D, dimension read
# No --dim: the first line's three columns fix it. D^2 = 3^-3 - 2 (3/8)^3 +
# (1/2)^3 = 391/6912; exact random for K = 1: (1/2)^3 - 3^-3 = 19/216.
printf '0.5 0.5 0.5\n' >"$tmp/centre3"
if succeeds "discrepancy of one 3D point" "$MCSPEC" discrepancy --csv "$tmp/centre3"; then
    csv_shape "discrepancy 3D --csv" "$tmp/out" 'measure,value,stderr,exact_random,root,exact' 6 6
    expect "one point at the centre of the cube" "$tmp/out" "$(printf '%s\n' \
        'l2_star 2 0.056568287037037037' 'l2_star 4 0.087962962962962963')"
fi
if succeeds "discrepancy table in 3D" "$MCSPEC" discrepancy "$tmp/centre3"; then
    if grep -q '1 point sets in 3D' "$tmp/out"; then ok; else bad "3D table: no '1 point sets in 3D'"; fi
fi
printf '0.5 0.5 0.5\n0.25 0.25\n' >"$tmp/ragged"
for c in discrepancy stats; do
    usage_error "$c ragged columns" 'line 2: expected 3 columns, found 2' "$MCSPEC" "$c" "$tmp/ragged"
done
awk 'BEGIN { for (i = 0; i < 4; ++i) { for (d = 0; d < 9; ++d) printf "%s0.%d", d ? " " : "", i + 1; print "" } }' >"$tmp/nine"
usage_error "stats of 9D points" 'have 9 coordinates; the spacing statistics take 1 to 8' \
    "$MCSPEC" stats "$tmp/nine"
succeeds "discrepancy of 9D points" "$MCSPEC" discrepancy --csv "$tmp/nine"

# ---------------------------------------------- hand-made: two sets in 1D
# {1/2}: D^2 = 1/12; {1/4, 3/4}: 1/48 (piece by piece); mean 5/96, standard
# error |a - b| / 2 = 1/32; exact (1/2 - 1/3) times the mean of 1/K, 1/8.
printf '0.5\n#\n0.25\n0.75\n' >"$tmp/two1d"
if succeeds "discrepancy --dim 1" "$MCSPEC" discrepancy --dim 1 --csv "$tmp/two1d"; then
    csv_shape "discrepancy --dim 1 --csv" "$tmp/out" 'measure,value,stderr,exact_random,root,exact' 6 6
    expect "two 1D sets" "$tmp/out" "$(printf '%s\n' 'l2_star 2 0.052083333333333333' \
        'l2_star 3 0.03125' 'l2_star 4 0.125')"
fi
if succeeds "discrepancy table" "$MCSPEC" discrepancy --dim 1 "$tmp/two1d"; then
    if grep -Eq '^measure +value +stderr +exact_random +root +exact +z$' "$tmp/out"; then ok
    else bad "discrepancy table: no header line"; fi
    if [ "$(grep -c '^l2_' "$tmp/out")" -eq 6 ] && ! grep -q '^star' "$tmp/out"; then ok
    else bad "discrepancy table in 1D: not the six L2 rows"; fi
fi

# ------------------------------------------ hand-made: spatial statistics
# A 16 x 16 grid: every nearest neighbour at 1/16, over d_max =
# sqrt(2 / (sqrt(3) 256)): sqrt(sqrt(3) / 2). Ten equally spaced points on the
# circle: every gap 1/10 = d_max.
awk 'BEGIN { for (i = 0; i < 256; ++i) printf "%.17g %.17g\n", (i % 16 + 0.5) / 16, (int(i / 16) + 0.5) / 16 }' >"$tmp/grid"
if succeeds "stats of a grid" "$MCSPEC" stats --csv "$tmp/grid"; then
    csv_shape "stats --csv" "$tmp/out" 'statistic,value,stderr,exact' 6 4
    expect "a 16 x 16 grid" "$tmp/out" "$(printf '%s\n' 'min_distance 2 0.93060485910209959' \
        'avg_min_distance 2 0.93060485910209959' 'min_distance 3 empty')"
fi
awk 'BEGIN { for (i = 0; i < 10; ++i) print i / 10 }' >"$tmp/circle"
if succeeds "stats --dim 1" "$MCSPEC" stats --dim 1 --csv "$tmp/circle"; then
    expect "ten points on the circle" "$tmp/out" "$(printf '%s\n' 'min_distance 2 1' 'avg_min_distance 2 1')"
fi
if succeeds "stats table" "$MCSPEC" stats "$tmp/grid"; then
    if grep -Eq '^statistic +value +stderr +exact +z$' "$tmp/out" && grep -q '^avg_min_distance' "$tmp/out"
    then ok; else bad "stats table: no header line or rows"; fi
fi

# ------------------------------------- 200 random sets of 256 points (2D)
awk 'BEGIN { srand(42); for (s = 0; s < 200; ++s) { if (s) print "#"
             for (i = 0; i < 256; ++i) printf "%.17g %.17g\n", rand(), rand() } }' >"$tmp/random"
if succeeds "discrepancy of random sets" "$MCSPEC" discrepancy --csv "$tmp/random"; then
    cp "$tmp/out" "$tmp/random.csv"
    csv_shape "random sets" "$tmp/random.csv" 'measure,value,stderr,exact_random,root,exact' 7 6
    echo "   z = (value - exact_random) / stderr over 200 sets of 256 random points:"
    awk -F, 'NR > 1 && $4 != "" { printf "   %-15s %7.2f\n", $1, ($2 - $4) / $3 }' "$tmp/random.csv"
    problems=$(awk -F, 'NR > 1 && $4 != "" { z = ($2 - $4) / $3; if (z < -5 || z > 5) printf "%s z = %.2f; ", $1, z }
        NR > 1 { r = sqrt($2 > 0 ? $2 : 0); d = r - $5; if (d < 0) d = -d; if (d > 1e-15 + 1e-12 * r) printf "%s root %s, sqrt %s; ", $1, $5, r }
        $1 == "l2_star" { l2 = $2 } $1 == "star" { st = $2 }
        END { if (!(st >= l2)) printf "star %s below l2_star %s", st, l2 }' "$tmp/random.csv")
    if [ -z "$problems" ]; then ok; else bad "random sets: $problems"; fi
    # shellcheck disable=SC2016 # $1 and $2 are the inner shell's
    if succeeds "discrepancy from stdin" sh -c '"$1" discrepancy --csv - <"$2"' sh "$MCSPEC" "$tmp/random" &&
        cmp -s "$tmp/out" "$tmp/random.csv"; then ok; else bad "stdin: not the file's bytes"; fi
    if succeeds "discrepancy again" "$MCSPEC" discrepancy --csv "$tmp/random" && cmp -s "$tmp/out" "$tmp/random.csv"
    then ok; else bad "discrepancy: not the same bytes twice"; fi
fi
if succeeds "stats of random sets" "$MCSPEC" stats --csv "$tmp/random"; then
    # (1/2) Gamma(K) / Gamma(K + 1/2) by its asymptotic series (exact to 1e-12 at K = 256)
    problems=$(awk -F, 'BEGIN { k = 256; g = (1 + 1 / (8 * k) + 1 / (128 * k * k) - 5 / (1024 * k ^ 3) - 21 / (32768 * k ^ 4)) / sqrt(k)
                                want = 0.5 * g / sqrt(2 / (sqrt(3) * k)) }
        $1 == "avg_min_distance" { z = ($2 - want) / $3; printf "z %.2f", z; if (z < -5 || z > 5) printf " FAIL (%s vs %s)", $2, want }' "$tmp/out")
    echo "   avg_min_distance against the nearest-neighbour expectation: $problems"
    case $problems in "z "*FAIL* | "") bad "stats of random sets: $problems" ;; *) ok ;; esac
fi

# ---------------------------------------- a set too large for the star
awk 'BEGIN { srand(7); for (i = 0; i < 4097; ++i) printf "%.17g %.17g\n", rand(), rand() }' >"$tmp/big"
if succeeds "discrepancy of 4097 points" "$MCSPEC" discrepancy --csv "$tmp/big"; then
    if [ "$(tail -n +2 "$tmp/out" | wc -l)" -eq 6 ] && ! grep -q '^star' "$tmp/out"; then ok
    else bad "4097 points: the star row is there"; fi
fi
if succeeds "discrepancy table of 4097 points" "$MCSPEC" discrepancy "$tmp/big" &&
    grep -q 'star: not computed (a set has more than 4096 points)' "$tmp/out"; then ok
else bad "4097 points: the table does not say why the star is missing"; fi

# --------------------------------------------------------------- --wrap
printf '1.25 0.5\n' >"$tmp/wrapped"
printf '0.25 0.5\n' >"$tmp/plain"
if succeeds "--wrap" "$MCSPEC" discrepancy --wrap --csv "$tmp/wrapped" && cp "$tmp/out" "$tmp/w.csv" &&
    succeeds "no wrap needed" "$MCSPEC" discrepancy --csv "$tmp/plain" && cmp -s "$tmp/out" "$tmp/w.csv"
then ok; else bad "--wrap: 1.25 is not read as 0.25"; fi

# ------------------------------------------------- KIND instead of a file
for c in discrepancy stats; do
    usage_error "$c: unknown kind" "^mcspec $c: unknown kind 'bogus' \(one of random, " \
        "$MCSPEC" "$c" bogus --dim 2 --k 8
    usage_error "$c: a dimension the kind lacks" "^mcspec $c: jittered has dimensions 2 only, not 3" \
        "$MCSPEC" "$c" jittered --dim 3 --k 8
    usage_error "$c: KIND without --dim" "^mcspec $c: give --dim D with KIND random" \
        "$MCSPEC" "$c" random --k 8
    usage_error "$c: --k without KIND" "^mcspec $c: --k draws sets of a KIND: give KIND" \
        "$MCSPEC" "$c" --k 8 --dim 2
    usage_error "$c: KIND without --k" "^mcspec $c: KIND random draws sets with --dim D --k K: give --k K" \
        "$MCSPEC" "$c" random --dim 2
    usage_error "$c: --sets with a file" "^mcspec $c: --sets and --seed go with KIND --k K" \
        "$MCSPEC" "$c" --sets 3 "$tmp/random"
    usage_error "$c: --wrap with KIND" "^mcspec $c: --wrap goes with a point file" \
        "$MCSPEC" "$c" random --dim 2 --k 8 --wrap
done
usage_error "stats: KIND in 9D" "^mcspec stats: --dim expects a whole number from 1 to 8" \
    "$MCSPEC" stats random --dim 9 --k 8
usage_error "stats: KIND of one point" "^mcspec stats: --k expects a whole number from 2 to " \
    "$MCSPEC" stats random --dim 2 --k 1

# every kind of mcspec sample, in 2D where it has it, else 1D
kinds=$("$MCSPEC" discrepancy bogus --dim 2 --k 8 2>&1 | sed 's/.*(one of //; s/)$//; s/,//g')
fails=""
for kind in $kinds; do
    dim=2
    case $kind in stratified | homogenized | uniform | jitter | van-der-corput) dim=1 ;; esac
    for c in discrepancy stats; do
        run "$MCSPEC" "$c" "$kind" --dim "$dim" --k 16 --sets 3 --csv
        if [ "$rc" -ne 0 ] || [ -s "$tmp/err" ] || [ "$(wc -l <"$tmp/out")" -lt 3 ]; then
            fails="$fails $c $kind ($rc: $(head -n 1 "$tmp/err"));"
        fi
    done
done
if [ -n "$kinds" ] && [ -z "$fails" ]; then ok; else bad "kinds:${fails:- no kinds listed}"; fi

# the sets are mcspec sample's: its output read back gives the same columns
# shellcheck disable=SC2016 # $1 and $2 are the inner shell's
if succeeds "sample | discrepancy" sh -c '"$1" sample halton-owen --dim 3 --k 40 --sets 20 --seed 5 >"$2"' \
    sh "$MCSPEC" "$tmp/sampled" &&
    succeeds "discrepancy of the file" "$MCSPEC" discrepancy --csv "$tmp/sampled" &&
    cut -d, -f1-5 "$tmp/out" >"$tmp/from_file" &&
    succeeds "discrepancy KIND" "$MCSPEC" discrepancy halton-owen --dim 3 --k 40 --sets 20 --seed 5 --csv &&
    cut -d, -f1-5 "$tmp/out" >"$tmp/from_kind" && cmp -s "$tmp/from_file" "$tmp/from_kind"
then ok; else bad "discrepancy KIND: not the columns of mcspec sample's sets read back"; fi
if succeeds "stats KIND twice" "$MCSPEC" stats random --dim 2 --k 30 --sets 10 --seed 9 --csv &&
    cp "$tmp/out" "$tmp/s1" && succeeds "stats KIND again" "$MCSPEC" stats random --dim 2 --k 30 --sets 10 --seed 9 --csv &&
    cmp -s "$tmp/out" "$tmp/s1"; then ok; else bad "stats KIND: not the same bytes twice"; fi

# z = (value - exact) / stderr within 5 (CSV columns: 2 value, 3 stderr, 4 exact_random, 6 exact)
# disc_z LABEL ROWS RANDOM NEXACT ARGS...: RANDOM 1 when exact must be exact_random
# (else below it), NEXACT rows with an exact value.
disc_z() {
    label=$1 rows=$2 random=$3 nexact=$4
    shift 4
    if succeeds "$label" "$MCSPEC" discrepancy "$@" --csv; then
        csv_shape "$label" "$tmp/out" 'measure,value,stderr,exact_random,root,exact' "$rows" 6
        line=$(awk -F, 'NR > 1 && $6 != "" { printf "%s %.2f  ", $1, ($2 - $6) / $3 }' "$tmp/out")
        echo "   $label: z $line"
        problems=$(awk -F, -v random="$random" -v n="$nexact" '
            NR > 1 && $6 != "" { ++m; z = ($2 - $6) / $3; if (z < -5 || z > 5) printf "%s z = %.2f; ", $1, z
                                 if (random && $6 != $4) printf "%s exact %s != exact_random %s; ", $1, $6, $4
                                 if (!random && !($6 < $4)) printf "%s exact %s not below random %s; ", $1, $6, $4 }
            END { if (m != n) printf "%d exact values, expected %d", m, n }' "$tmp/out")
        if [ -z "$problems" ]; then ok; else bad "$label: $problems"; fi
    fi
}
disc_z "discrepancy random 2D" 7 1 6 random --dim 2 --k 64 --sets 400 --seed 11
disc_z "discrepancy random 5D" 6 1 6 random --dim 5 --k 32 --sets 400 --seed 12
disc_z "discrepancy jittered 8x4" 7 0 6 jittered --dim 2 --k 32 --sets 400 --seed 13
disc_z "discrepancy stratified 1D" 6 0 6 stratified --dim 1 --k 16 --sets 400 --seed 14
disc_z "discrepancy sobol-owen 1D, K = 32" 6 0 6 sobol-owen --dim 1 --k 32 --sets 2000 --seed 15
disc_z "discrepancy sobol-owen 1D, K = 24 (no exact)" 6 0 0 sobol-owen --dim 1 --k 24 --sets 10
disc_z "discrepancy n-rooks (no exact)" 7 0 0 n-rooks --dim 2 --k 16 --sets 10
if succeeds "discrepancy jittered table" "$MCSPEC" discrepancy jittered --dim 2 --k 32 --sets 10 &&
    grep -q '^mcspec discrepancy: jittered 8 x 4 strata (seed 1), 10 point sets in 2D, K = 32' "$tmp/out" &&
    grep -Eq '^measure +value +stderr +exact_random +root +exact +z$' "$tmp/out"
then ok; else bad "discrepancy jittered table: no source line or header"; fi

# stats_z LABEL ROWS WANT ARGS...: WANT = " statistic ..." the rows with an
# exact value; z within 5.
stats_z() {
    label=$1 rows=$2 want=$3
    shift 3
    if succeeds "$label" "$MCSPEC" stats "$@" --csv; then
        csv_shape "$label" "$tmp/out" 'statistic,value,stderr,exact' "$rows" 4
        line=$(awk -F, 'NR > 1 && $4 != "" { printf "%s %.2f  ", $1, ($2 - $4) / $3 }' "$tmp/out")
        echo "   $label: z $line"
        problems=$(awk -F, -v want="$want" '
            NR > 1 && $4 != "" { got = got " " $1; z = ($2 - $4) / $3; if (z < -5 || z > 5) printf "%s z = %.2f; ", $1, z }
            END { if (got != want) printf "exact rows \"%s\", expected \"%s\"", got, want }' "$tmp/out")
        if [ -z "$problems" ]; then ok; else bad "$label: $problems"; fi
    fi
}
stats_z "stats random 2D" 6 " avg_min_distance" random --dim 2 --k 64 --sets 400 --seed 21
stats_z "stats random 2D, K = 3" 6 " avg_min_distance" random --dim 2 --k 3 --sets 4000 --seed 22
stats_z "stats random 1D" 6 " min_distance avg_min_distance" random --dim 1 --k 16 --sets 2000 --seed 23
stats_z "stats random 3D, K = 52" 2 " avg_min_distance" random --dim 3 --k 52 --sets 300 --seed 24
stats_z "stats random 3D, K = 51 (no exact)" 2 "" random --dim 3 --k 51 --sets 3
stats_z "stats jittered (no exact)" 6 "" jittered --dim 2 --k 16 --sets 10
if succeeds "stats random 1D exact" "$MCSPEC" stats random --dim 1 --k 16 --sets 2 --csv; then
    expect "stats random 1D exact" "$tmp/out" "min_distance 4 0.0625
avg_min_distance 4 0.5
effective_nyquist 4 empty"
fi

# ------------------------------------------------------- malformed input
for c in discrepancy stats; do
    printf '0.1 0.2\n0.3 0.4\n0.5 1.5\n' >"$tmp/bad"
    usage_error "$c: coordinate 1.5" "^mcspec $c: $tmp/bad: line 3: coordinate 1.5 is outside \[0,1\)" "$MCSPEC" "$c" "$tmp/bad"
    printf '0.1 0.2\n0.3 abc\n' >"$tmp/bad"
    usage_error "$c: not a number" "^mcspec $c: $tmp/bad: line 2: coordinate 'abc' is not a number" "$MCSPEC" "$c" "$tmp/bad"
    printf '0.1 0.2\n0.3 0.4 0.5\n' >"$tmp/bad"
    usage_error "$c: three columns" "^mcspec $c: $tmp/bad: line 2: expected 2 columns, found 3" "$MCSPEC" "$c" "$tmp/bad"
    printf '0.1 nan\n' >"$tmp/bad"
    usage_error "$c: NaN" "^mcspec $c: $tmp/bad: line 1: " "$MCSPEC" "$c" "$tmp/bad"
    printf '0.1 0.2\n0.2 0.1\n#\n#\n0.3 0.4\n' >"$tmp/bad"
    usage_error "$c: empty set" "^mcspec $c: $tmp/bad: line 4: empty point set" "$MCSPEC" "$c" "$tmp/bad"
    : >"$tmp/bad"
    usage_error "$c: empty input" "^mcspec $c: $tmp/bad: the input is empty" "$MCSPEC" "$c" "$tmp/bad"
    usage_error "$c: missing file" "^mcspec $c: cannot read '$tmp/missing'" "$MCSPEC" "$c" "$tmp/missing"
    { cat "$tmp/random"; printf '0.5 -0.5\n'; } >"$tmp/bad"
    usage_error "$c: a bad line after 200 sets" "^mcspec $c: $tmp/bad: line 51400: coordinate -0.5" "$MCSPEC" "$c" --csv "$tmp/bad"
done
printf '0.1 0.2\n0.3 0.4\n#\n0.5 0.6\n#\n0.7 0.8\n0.9 0.1\n' >"$tmp/bad"
usage_error "stats: a single-point set" "^mcspec stats: $tmp/bad: point set 2 has a single point" "$MCSPEC" stats "$tmp/bad"
succeeds "discrepancy takes a single-point set" "$MCSPEC" discrepancy --csv "$tmp/bad"

check_summary
