#!/bin/sh
# Checks of the commands mcspec sample and mcspec projections (issue 26).
#
# usage: sh test/sample_check.sh   ($MCSPEC names the binary, default
#                                   build/bin/mcspec)
#
#   --help of both; bad usage (an unknown kind, a kind outside its
#   dimensions, --dim or --k missing, --k 0, --radius above --freq, --dim
#   with a file, a 1D file): exit 2, one line on stderr saying what to fix,
#   nothing on stdout;
#   every kind of the table in one of its dimensions: K T point lines of D
#   fields in [0,1), T - 1 '#' lines; the same seed twice the same bytes,
#   another seed other bytes;
#   read back: mcspec spectrum --dim 2 of `sample sobol-owen` is mcspec
#   pattern sobol-owen --dim 2's power and stderr columns byte for byte (the
#   same draws), and mcspec discrepancy's l2_wraparound of a 2D file is
#   mcspec projections' discrepancy of its pair, to 1e-12;
#   projections: the CSV header's first columns exactly; random points in 6D
#   flag nothing; a file whose dimension 6 repeats dimension 0 (c-ray's
#   sampler) flags (0,6) and nothing else; the heat map (when gnuplot is
#   there) is a PNG;
#   examples/sampler_check ($SAMPLER_CHECK): c-ray's repeated dimensions
#   flag (0,6) and (1,7), the shared seed (2,4) and (3,5) and nothing else,
#   padded and random nothing.
# Ends with a Unity-style summary so test/run_tests.sh counts it.

MCSPEC=${MCSPEC:-build/bin/mcspec}

# shellcheck source=test/support/check.sh
. "$(dirname "$0")/support/check.sh"
check_start sample_check

if [ ! -x "$MCSPEC" ]; then
    bad "$MCSPEC is not an executable (make cli)"
    SAMPLER_CHECK=${SAMPLER_CHECK:-build/examples/sampler_check}
if [ ! -x "$SAMPLER_CHECK" ]; then
    bad "$SAMPLER_CHECK is not an executable (make examples)"
elif succeeds "sampler_check" "$SAMPLER_CHECK" --k 512 --sets 16 --seed 3; then
    line() { grep "^$1 " "$tmp/out"; }
    case $(line c-ray) in *"(0,6)"*"(1,7)"*) ok ;; *) bad "c-ray: $(line c-ray)" ;; esac
    if line shared-seed | grep -Eq "2 of 28 pairs flagged: \(2,4\) peak [0-9]+ \(3,5\) peak [0-9]+$"; then ok
    else bad "shared-seed: $(line shared-seed)"; fi
    for s in padded random; do
        if line "$s" | grep -q "0 of 28 pairs flagged: none"; then ok; else bad "$s: $(line "$s")"; fi
    done
fi

check_summary
    exit 1
fi

for c in sample projections; do
    if succeeds "$c --help" "$MCSPEC" "$c" --help && grep -q "usage: mcspec $c" "$tmp/out"; then ok
    else bad "$c --help lacks its usage line"; fi
done

usage_error "unknown kind" "unknown kind 'blue' \(one of random, .*padded, dart-throwing, .*pmj02bn\)" "$MCSPEC" sample blue --dim 2 --k 4
usage_error "halton in 3D" "halton has dimensions 2 only, not 3" "$MCSPEC" sample halton --dim 3 --k 4
usage_error "padded in 1D" "padded has dimensions 2 to 64, not 1" "$MCSPEC" sample padded --dim 1 --k 4
usage_error "sample without --dim" "give --dim" "$MCSPEC" sample sobol-owen --k 4
usage_error "sample without --k" "give --k" "$MCSPEC" sample sobol-owen --dim 4
usage_error "sample --k 0" "--k" "$MCSPEC" sample sobol-owen --dim 4 --k 0
usage_error "sample --dim 65" "--dim" "$MCSPEC" sample sobol-owen --dim 65 --k 4
usage_error "projections --radius > --freq" "--radius 5 is above --freq 4" "$MCSPEC" projections lattice --dim 3 --k 8 --freq 4 --radius 5
usage_error "projections KIND without --dim" "give --dim" "$MCSPEC" projections lattice --k 8
usage_error "projections --dim with a file" "with KIND --k K, not a file" "$MCSPEC" projections "$tmp/none" --dim 3
usage_error "projections of a kind outside its dimensions" "jittered has dimensions 2 only, not 3" "$MCSPEC" projections jittered --dim 3 --k 16

# Every kind in one of its dimensions: shape, range, separators.
for spec in random:5 stratified:1 homogenized:1 uniform:1 jitter:1 jittered:2 grid:2 \
    shifted-grid:2 n-rooks:2 multi-jittered:2 cmj:2 van-der-corput:1 halton:2 hammersley:2 \
    kronecker:2 sobol-owen:9 halton-permuted:7 halton-owen:7 lattice:6 padded:5 \
    dart-throwing:2 poisson-disk:3 lloyd:2 pmj02:2 pmj02bn:2 dart-throwing:1; do
    kind=${spec%%:*} d=${spec#*:}
    if succeeds "sample $kind" "$MCSPEC" sample "$kind" --dim "$d" --k 16 --sets 3 --seed 9; then
        problems=$(awk -v d="$d" '
            $0 == "#" { seps++; next }
            { pts++; if (NF != d) bad = bad " line " NR ": " NF " fields"
              for (i = 1; i <= NF; i++) if (!($i >= 0 && $i < 1)) bad = bad " line " NR ": " $i }
            END { if (pts != 48) bad = bad " " pts " points"; if (seps != 2) bad = bad " " seps " separators"
                  printf "%s", bad }' "$tmp/out")
        if [ -z "$problems" ]; then ok; else bad "sample $kind:$problems"; fi
    fi
done

"$MCSPEC" sample halton-owen --dim 4 --k 32 --sets 2 --seed 5 >"$tmp/a" 2>&1
"$MCSPEC" sample halton-owen --dim 4 --k 32 --sets 2 --seed 5 >"$tmp/b" 2>&1
"$MCSPEC" sample halton-owen --dim 4 --k 32 --sets 2 --seed 6 >"$tmp/c" 2>&1
if cmp -s "$tmp/a" "$tmp/b"; then ok; else bad "the same seed gave other bytes"; fi
if cmp -s "$tmp/a" "$tmp/c"; then bad "another seed gave the same bytes"; else ok; fi

# Read back by mcspec spectrum: the draws of mcspec pattern (the same
# points; spectrum merges one set at a time and pattern adds them to one
# accumulator, so the sums round apart in the last bits: 1e-12 relative).
"$MCSPEC" sample sobol-owen --dim 2 --k 64 --sets 20 --seed 3 >"$tmp/sobol.txt"
"$MCSPEC" spectrum "$tmp/sobol.txt" --dim 2 --freq 3 --csv | cut -d, -f1-4 >"$tmp/s1"
"$MCSPEC" pattern sobol-owen --dim 2 --k 64 --freq 3 --trials 20 --seed 3 --csv | cut -d, -f1-4 >"$tmp/s2"
far=$(paste -d, "$tmp/s1" "$tmp/s2" | awk -F, 'NR == 1 { next } { for (i = 1; i <= 4; ++i) {
        a = $i; b = $(i + 4); d = a - b; if (d < 0) d = -d; s = a < 0 ? -a : a
        if (d > 1e-12 * (s > 1 ? s : 1)) n++ } } END { print n + 0, NR }')
if [ -s "$tmp/s1" ] && [ "${far% *}" = 0 ] && [ "$(wc -l <"$tmp/s1")" = "$(wc -l <"$tmp/s2")" ]; then ok
else bad "spectrum of sample sobol-owen differs from pattern sobol-owen ($far)"; fi

# Read back by mcspec discrepancy: the projection's wrap-around L2.
"$MCSPEC" sample random --dim 2 --k 50 --sets 3 --seed 4 >"$tmp/r2.txt"
wd1=$("$MCSPEC" discrepancy "$tmp/r2.txt" --csv | awk -F, '$1 == "l2_wraparound" { print $2 }')
wd2=$("$MCSPEC" projections "$tmp/r2.txt" --disc-sets 3 --csv | awk -F, 'NR == 2 { print $6 }')
if awk -v a="$wd1" -v b="$wd2" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(a > 0 && d <= 1e-12 * a) }'; then ok
else bad "discrepancy $wd1 against projections $wd2"; fi

# Projections: the CSV header, nothing flagged for random, (0,6) for a repeat.
header="dim_i,dim_j,radial_low,radial_low_stderr,anisotropy_db,discrepancy,peak,peak_stderr,flagged"
"$MCSPEC" sample random --dim 7 --k 128 --sets 40 --seed 2 >"$tmp/r7.txt"
if succeeds "projections random" "$MCSPEC" projections "$tmp/r7.txt" --csv; then
    case $(head -n 1 "$tmp/out") in "$header",*) ok ;; *) bad "projections CSV header: $(head -n 1 "$tmp/out")" ;; esac
    rows=$(tail -n +2 "$tmp/out" | wc -l) flagged=$(tail -n +2 "$tmp/out" | awk -F, '$9 == 1' | wc -l)
    if [ "$rows" -eq 21 ] && [ "$flagged" -eq 0 ]; then ok; else bad "random 7D: $rows rows, $flagged flagged"; fi
fi
awk '$0 == "#" { print; next } { $7 = $1; print }' "$tmp/r7.txt" >"$tmp/repeat.txt"
if succeeds "projections of a repeated dimension" "$MCSPEC" projections "$tmp/repeat.txt"; then
    if grep -q "^1 of 21 pairs flagged: (0,6)$" "$tmp/out"; then ok; else bad "repeat: $(tail -n 1 "$tmp/out")"; fi
fi
if command -v gnuplot >/dev/null 2>&1; then
    if succeeds "projections --plot" "$MCSPEC" projections "$tmp/repeat.txt" --plot "$tmp/heat.png" &&
        [ "$(head -c 4 "$tmp/heat.png" | od -An -c | tr -d ' ')" = "211PNG" ]; then ok
    else bad "projections --plot did not write a PNG"; fi
else
    skip "projections --plot (no gnuplot)"
fi

SAMPLER_CHECK=${SAMPLER_CHECK:-build/examples/sampler_check}
if [ ! -x "$SAMPLER_CHECK" ]; then
    bad "$SAMPLER_CHECK is not an executable (make examples)"
elif succeeds "sampler_check" "$SAMPLER_CHECK" --k 512 --sets 16 --seed 3; then
    line() { grep "^$1 " "$tmp/out"; }
    case $(line c-ray) in *"(0,6)"*"(1,7)"*) ok ;; *) bad "c-ray: $(line c-ray)" ;; esac
    if line shared-seed | grep -Eq "2 of 28 pairs flagged: \(2,4\) peak [0-9]+ \(3,5\) peak [0-9]+$"; then ok
    else bad "shared-seed: $(line shared-seed)"; fi
    for s in padded random; do
        if line "$s" | grep -q "0 of 28 pairs flagged: none"; then ok; else bad "$s: $(line "$s")"; fi
    done
fi

# Owen's exact theory in mcspec pattern --dim 2 (docs/owen.md): Sobol at
# K = 2^m by the net route and at K = 48 by the pair counts, Owen-scrambled
# Halton (bases 2, 3) by the pair counts; every wave vector within 5 SE of
# 3000 trials. Permuted Halton has none, and the report says so.
for spec in sobol-owen:64 sobol-owen:48 halton-owen:100; do
    kind=${spec%%:*} k=${spec#*:}
    if succeeds "pattern $kind --dim 2 --k $k" "$MCSPEC" pattern "$kind" --dim 2 --k "$k" --freq 6 \
        --trials 3000 --seed 5 --csv; then
        verdict=$(awk -F, 'NR > 1 { if ($5 == "") e++; else { n++; z = $6 < 0 ? -$6 : $6; if (z > m) m = z } }
                  END { if (e > 0 || n != 169 || m >= 5) printf "%d without exact, %d with, max |z| %.2f", e, n, m }' "$tmp/out")
        if [ -z "$verdict" ]; then ok; else bad "Owen theory for $kind at K = $k: $verdict"; fi
    fi
done
if succeeds "pattern halton-permuted --dim 2" "$MCSPEC" pattern halton-permuted --dim 2 --k 16 --freq 2 --trials 10; then
    if grep -q '^exact: none for this kind' "$tmp/out"; then ok; else bad "halton-permuted: the report does not say it has no exact theory"; fi
fi

check_summary
