#!/bin/sh
# Checks of the command mcspec pcf (issue 25) and of the spectral rows of
# mcspec stats.
#
# usage: sh test/pcf_check.sh   ($MCSPEC names the binary, default
#                                build/bin/mcspec)
#
#   --help; bad usage and input (an unknown option, a radius or sigma that is
#   not a positive number, --bins with --bin-width, --spectral without --rdf,
#   --exact other than random, --k without a KIND, a KIND without --k,
#   --sets for a file, a set too small for the radius, 3D points, a
#   malformed line): exit 2, one line on stderr, nothing on stdout;
#   the CSV: header exactly, one row per bin of 4 fields;
#   a hand-made 1D lattice of 8 points against its RDF worked out by hand
#   (16/7 in the bins of distances 1 and 2 spacings, 0 elsewhere);
#   200 random 2D sets of 256 points (awk's generator, fixed seed) with
#   --exact random: every bin of the RDF and of the kernel PCF within 5
#   standard errors of exact; 200 jittered sets of 256 points drawn by the
#   command: every RDF bin within 5 standard errors of the exact jittered
#   RDF, and every kernel PCF bin of 100 such sets; a grid's RDF equal to its exact one; --bin-width; --spectral: its
#   header, F rows, difference = power_from_rdf - power, and the two powers
#   within 5 standard errors at frequencies past 3 / R; the same bytes twice;
#   --plot renders a PNG (when gnuplot is on PATH);
#   mcspec stats of a 16 x 16 grid: effective_nyquist 15/16 (the periodogram
#   is 0 below the comb at 16 and C_16 > 0.5, so psa's scan stops at 15).
# Ends with a Unity-style summary ("N Tests F Failures 0 Ignored", then OK or
# FAIL) so test/run_tests.sh counts it; exit status non-zero on failure.

MCSPEC=${MCSPEC:-build/bin/mcspec}

# shellcheck source=test/support/check.sh
. "$(dirname "$0")/support/check.sh"
check_start pcf_check

if [ ! -x "$MCSPEC" ]; then
    bad "$MCSPEC is not an executable (make cli)"
    check_summary
    exit 1
fi

# within5 LABEL FILE: every row with an exact value has |pcf - exact| <= 5 stderr
# (or agrees to 1e-12 where the stderr is 0); prints the worst z.
within5() {
    problems=$(awk -F, 'NR > 1 && $4 != "" { d = $2 - $4; if (d < 0) d = -d
                   if ($3 == "" || $3 == 0) { if (d > 1e-12 * (1 + $4)) printf "r %s: %s vs %s; ", $1, $2, $4 }
                   else { z = d / $3; if (z > worst) worst = z; if (z > 5) printf "r %s: z %.2f; ", $1, z } ; n++ }
        END { if (n == 0) printf "no exact values"; else printf "worst %.2f", worst }' "$2")
    echo "   $1: |z| $problems"
    case $problems in worst*) ok ;; *) bad "$1: $problems" ;; esac
}

echo "== $MCSPEC pcf"

if succeeds "pcf --help" "$MCSPEC" pcf --help && grep -q "^usage: mcspec pcf" "$tmp/out" &&
    grep -q 'r,pcf,pcf_stderr,exact' "$tmp/out"; then ok; else bad "pcf --help: no usage or CSV header"; fi

printf '0.1 0.2\n0.3 0.4\n' >"$tmp/two"
usage_error "unknown option" 'unknown option' "$MCSPEC" pcf --nope "$tmp/two"
usage_error "--radius -1" '^mcspec pcf: --radius -1: give a positive number' "$MCSPEC" pcf --radius -1 "$tmp/two"
usage_error "--sigma abc" '^mcspec pcf: --sigma abc: give a positive number' "$MCSPEC" pcf --sigma abc "$tmp/two"
usage_error "--bins and --bin-width" 'give one of them' "$MCSPEC" pcf --bins 4 --bin-width 0.1 "$tmp/two"
usage_error "--spectral without --rdf" '--spectral needs --rdf' "$MCSPEC" pcf --spectral 8 "$tmp/two"
usage_error "--exact grid" "the only model a point file can be said to follow is 'random'" \
    "$MCSPEC" pcf --exact grid "$tmp/two"
usage_error "--k for a file" '--k is for a named kind' "$MCSPEC" pcf --k 64 "$tmp/two"
usage_error "KIND without --k" '^mcspec pcf: jittered: --k K is required' "$MCSPEC" pcf jittered
usage_error "--sets for a file" '--sets and --seed are for a named pattern' "$MCSPEC" pcf --sets 3 "$tmp/two"
usage_error "--dim for a file" "--dim is for a named kind" "$MCSPEC" pcf --dim 1 "$tmp/two"
usage_error "a kind without 1D" "pmj02 has dimensions 2 only" "$MCSPEC" pcf pmj02 --dim 1 --k 64
# every kind of mcspec sample draws: blue noise with no exact column, 1D
# random with g = 1 exactly for the RDF
if succeeds "pcf poisson-disk" "$MCSPEC" pcf poisson-disk --k 256 --sets 4 --bins 6 --csv &&
    awk -F, 'NR > 1 && ($4 != "" || $2 == "") { e = 1 } END { exit e || NR != 7 }' "$tmp/out"; then ok
else bad "pcf poisson-disk: not 6 rows with an empty exact column"; fi
if succeeds "pcf random --dim 1 --rdf" "$MCSPEC" pcf random --dim 1 --rdf --k 64 --sets 4 --bins 6 --csv &&
    awk -F, 'NR > 1 && $4 != 1 { e = 1 } END { exit e || NR != 7 }' "$tmp/out"; then ok
else bad "pcf random --dim 1: the exact RDF is not 1 in every bin"; fi
usage_error "a set too small" "set 1 has 2 points; the radius 3 \+ 8 sigma mean spacings reaches past half the torus" \
    "$MCSPEC" pcf "$tmp/two"
usage_error "a pattern too small" "set 1 has 16 points; the radius 3 mean spacings" \
    "$MCSPEC" pcf jittered --k 16 --rdf
printf '0.1 0.2 0.3\n0.3 0.4 0.5\n' >"$tmp/three"
usage_error "3D points" 'the points have 3 coordinates; the pair correlation takes 1 or 2' "$MCSPEC" pcf "$tmp/three"
printf '0.1 0.2\n0.3 1.5\n' >"$tmp/bad"
usage_error "coordinate 1.5" "^mcspec pcf: $tmp/bad: line 2: coordinate 1.5 is outside" "$MCSPEC" pcf "$tmp/bad"

# A 1D lattice of 8 points: distances 1, 2, 3, 4 spacings (8 pairs each, 4 at 4);
# radius 3 in 6 bins of 0.5: bins 2 and 4 hold 8 pairs each, g = 2 8 / (8 7 2 (0.5 / 8)) = 16/7.
awk 'BEGIN { for (i = 0; i < 8; ++i) print i / 8 }' >"$tmp/lattice"
if succeeds "lattice RDF" "$MCSPEC" pcf --rdf --bins 6 --csv "$tmp/lattice"; then
    if [ "$(head -n 1 "$tmp/out")" = "r,pcf,pcf_stderr,exact" ]; then ok; else bad "header '$(head -n 1 "$tmp/out")'"; fi
    problems=$(awk -F, 'NR > 1 { want = (NR == 4 || NR == 6) ? 16 / 7 : 0; d = $2 - want; if (d < 0) d = -d
                 if (NF != 4 || d > 1e-15 || $3 != "" || $4 != "") printf "row %d: %s; ", NR, $0 }
        END { if (NR != 7) printf "%d lines", NR }' "$tmp/out")
    if [ -z "$problems" ]; then ok; else bad "lattice: $problems"; fi
fi

awk 'BEGIN { srand(25); for (s = 0; s < 200; ++s) { if (s) print "#"
             for (i = 0; i < 256; ++i) printf "%.17g %.17g\n", rand(), rand() } }' >"$tmp/random"
if succeeds "random RDF" "$MCSPEC" pcf --rdf --exact random --radius 2.5 --bins 25 --csv "$tmp/random"; then
    within5 "random sets, RDF" "$tmp/out"
    if [ "$(wc -l <"$tmp/out")" -eq 26 ]; then ok; else bad "random RDF: $(wc -l <"$tmp/out") lines"; fi
    cp "$tmp/out" "$tmp/first.csv"
    if succeeds "random RDF again" "$MCSPEC" pcf --rdf --exact random --radius 2.5 --bins 25 --csv "$tmp/random" &&
        cmp -s "$tmp/out" "$tmp/first.csv"; then ok; else bad "not the same bytes twice"; fi
fi
if succeeds "random kernel PCF" "$MCSPEC" pcf --exact random --radius 2 --bins 20 --sigma 0.15 --csv "$tmp/random"; then
    within5 "random sets, kernel PCF" "$tmp/out"
fi
if succeeds "jittered RDF" "$MCSPEC" pcf jittered --k 256 --sets 200 --rdf --bin-width 0.1 --csv; then
    within5 "jittered sets, RDF" "$tmp/out"
    if [ "$(wc -l <"$tmp/out")" -eq 31 ]; then ok; else bad "--bin-width 0.1 of 3: $(wc -l <"$tmp/out") lines"; fi
fi
if succeeds "jittered kernel PCF" "$MCSPEC" pcf jittered --k 256 --sets 100 --radius 2 --bins 20 --csv; then
    within5 "jittered sets, kernel PCF" "$tmp/out"
fi
if succeeds "grid RDF" "$MCSPEC" pcf grid --k 64 --sets 1 --rdf --radius 3.3 --bins 23 --csv; then
    within5 "the grid, RDF" "$tmp/out"
fi
if succeeds "spectral check" "$MCSPEC" pcf jittered --k 256 --sets 100 --rdf --radius 6 --bins 60 --spectral 30 --csv; then
    if [ "$(head -n 1 "$tmp/out")" = "freq,power_from_rdf,power,power_stderr,difference" ]; then ok
    else bad "spectral header '$(head -n 1 "$tmp/out")'"; fi
    # R = 6 / 16 absolute: past 3 / R = 8 cycles the truncation's ringing is small.
    problems=$(awk -F, 'NR > 1 { d = $2 - $3 - $5; if (d < 0) d = -d; if (d > 1e-12) printf "row %d: difference; ", NR
                                 if ($1 > 8) { z = ($2 - $3) / $4; if (z < -5 || z > 5) printf "f %s: z %.2f; ", $1, z } }
        END { if (NR != 31) printf "%d lines", NR }' "$tmp/out")
    if [ -z "$problems" ]; then ok; else bad "spectral: $problems"; fi
fi
if command -v gnuplot >/dev/null 2>&1; then
    if succeeds "--plot" "$MCSPEC" pcf n-rooks --k 256 --sets 20 --rdf --plot "$tmp/g.png" --csv &&
        [ -s "$tmp/g.png" ] && [ "$(head -c 4 "$tmp/g.png" | od -An -c | tr -d ' ')" = "211PNG" ]
    then ok; else bad "--plot: no PNG"; fi
else
    skip "--plot (no gnuplot)"
fi

awk 'BEGIN { for (i = 0; i < 256; ++i) printf "%.17g %.17g\n", (i % 16 + 0.5) / 16, (int(i / 16) + 0.5) / 16 }' >"$tmp/grid"
if succeeds "stats of a grid" "$MCSPEC" stats --csv "$tmp/grid"; then
    problems=$(awk -F, '$1 == "effective_nyquist" || $1 == "effective_nyquist_of_mean" { n++; if ($2 != 0.9375) printf "%s %s; ", $1, $2 }
        $1 == "oscillations" { n++; if (!($2 > 0)) printf "oscillations %s; ", $2 }
        END { if (n != 3) printf "%d spectral rows", n }' "$tmp/out")
    if [ -z "$problems" ]; then ok; else bad "stats of a grid: $problems"; fi
fi

check_summary
