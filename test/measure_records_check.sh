#!/bin/sh
# Checks of the records of the measure commands (issue 25): --save on
# mcspec pcf, integrate, discrepancy and stats, mcspec merge of their
# records, mcspec show of them.
#
# usage: sh test/measure_records_check.sh   ($MCSPEC names the binary,
#                                            default build/bin/mcspec)
#
#   two point files A and B (awk's generator, fixed seeds; 10 and 7 sets of
#   64 points in 2D) and AB, their sets one after the other:
#   the record of one run shows (--csv) the bytes the run printed
#   (discrepancy, pcf of a file and of a drawn KIND with its exact column,
#   stats' first two rows; integrate but its prediction columns, which the
#   record does not hold: empty);
#   save A and B, merge: show of the merge equals the one run over AB to
#   rounding (1e-12 relative, every number of the CSV) for pcf (RDF and
#   kernel), discrepancy and stats; the merge in either order gives the
#   same bytes (the inputs' canonical order); integrate (whose runs draw
#   other integrands for B alone) against Chan's merge of the two shows'
#   mean and standard error, worked out here;
#   standard input saves like the file (the same record but its name);
#   merge refuses (exit 2, one line, OUT not written) records of another
#   radius, estimator, family or dim, another kind, the same file twice, and
#   of a drawn KIND the same stream twice and another seed (but with
#   --mix-seeds);
#   --save refuses a directory, a symbolic link and a missing directory
#   before any work; integrate --save without --family or over sets of
#   several K.
# Ends with a Unity-style summary ("N Tests F Failures 0 Ignored", then OK or
# FAIL) so test/run_tests.sh counts it; exit status non-zero on failure.

MCSPEC=${MCSPEC:-build/bin/mcspec}

# shellcheck source=test/support/check.sh
. "$(dirname "$0")/support/check.sh"
check_start measure_records_check

if [ ! -x "$MCSPEC" ]; then
    bad "$MCSPEC is not an executable (make cli)"
    check_summary
    exit 1
fi

# points SEED SETS FILE: SETS sets of 64 uniform points in 2D.
points() {
    awk -v seed="$1" -v sets="$2" 'BEGIN { srand(seed);
        for (t = 0; t < sets; ++t) { for (i = 0; i < 64; ++i) printf "%.17g %.17g\n", rand(), rand();
                                     print "#" } }' >"$3"
}
points 11 10 "$tmp/a.txt"
points 12 7 "$tmp/b.txt"
cat "$tmp/a.txt" "$tmp/b.txt" >"$tmp/ab.txt"

# close LABEL X Y: two CSVs of the same shape, every field equal as text or
# within 1e-12 relative (1e-300 absolute) as numbers.
close() {
    problems=$(awk -F, 'NR == FNR { line[FNR] = $0; n = FNR; next }
        { if (!(FNR in line)) { printf "extra row %d; ", FNR; next }
          m = split(line[FNR], a, ",")
          if (m != NF) { printf "row %d: %d fields, %d; ", FNR, m, NF; next }
          for (i = 1; i <= NF; ++i) {
              if (a[i] == $i) continue
              x = a[i] + 0; y = $i + 0; d = x - y; if (d < 0) d = -d
              s = (x < 0 ? -x : x); t = (y < 0 ? -y : y); if (t > s) s = t
              if (a[i] == "" || $i == "" || d > 1e-12 * s + 1e-300)
                  printf "row %d field %d: %s against %s; ", FNR, i, a[i], $i } }
        END { if (FNR != n) printf "%d rows against %d", FNR, n }' "$2" "$3")
    if [ -z "$problems" ]; then ok; else bad "$1: $problems"; fi
}

# same_out LABEL FILE: $tmp/out is FILE byte for byte.
same_out() {
    if cmp -s "$tmp/out" "$2"; then ok; else bad "$1: the show differs from the run"; fi
}

# ---- a record shows what its run printed ----
succeeds "discrepancy --save" "$MCSPEC" discrepancy --csv --save "$tmp/d-a.rec" "$tmp/a.txt" &&
    cp "$tmp/out" "$tmp/d-a.csv"
succeeds "show discrepancy" "$MCSPEC" show "$tmp/d-a.rec" --csv && same_out "show discrepancy" "$tmp/d-a.csv"
if grep -q '^star,' "$tmp/d-a.csv"; then ok; else bad "discrepancy: no star row"; fi
succeeds "pcf --save" "$MCSPEC" pcf --rdf --bins 12 --radius 2 --csv --save "$tmp/p-a.rec" "$tmp/a.txt" &&
    cp "$tmp/out" "$tmp/p-a.csv"
succeeds "show pcf" "$MCSPEC" show "$tmp/p-a.rec" --csv && same_out "show pcf" "$tmp/p-a.csv"
succeeds "pcf KIND --save" "$MCSPEC" pcf jittered --k 64 --sets 30 --bins 10 --csv --save "$tmp/p-j.rec" &&
    cp "$tmp/out" "$tmp/p-j.csv"
succeeds "show pcf KIND" "$MCSPEC" show "$tmp/p-j.rec" --csv && same_out "show pcf KIND (exact column)" "$tmp/p-j.csv"
if awk -F, 'NR > 1 && $4 == "" { e = 1 } END { exit e }' "$tmp/out"; then ok; else bad "show pcf KIND: an empty exact"; fi
succeeds "pcf random --dim 1 --save" "$MCSPEC" pcf random --dim 1 --k 64 --sets 10 --bins 8 --csv \
    --save "$tmp/p-r1.rec" && cp "$tmp/out" "$tmp/p-r1.csv"
succeeds "show pcf 1D random" "$MCSPEC" show "$tmp/p-r1.rec" --csv &&
    same_out "show pcf 1D random (exact column)" "$tmp/p-r1.csv"
succeeds "stats --save" "$MCSPEC" stats --csv --save "$tmp/s-a.rec" "$tmp/a.txt" &&
    head -n 3 "$tmp/out" >"$tmp/s-a.csv"
succeeds "show spacing" "$MCSPEC" show "$tmp/s-a.rec" --csv && same_out "show spacing (stats' first rows)" "$tmp/s-a.csv"
succeeds "integrate --save" "$MCSPEC" integrate --family gaussian_periodic --exact random --csv \
    --save "$tmp/i-a.rec" "$tmp/a.txt" && cp "$tmp/out" "$tmp/i-a.csv"
# the record has all but predicted, predicted_tail and freq (fields 6 to 8)
awk -F, -v OFS=, 'NR > 1 { $6 = ""; $7 = ""; $8 = "" } { print }' "$tmp/i-a.csv" >"$tmp/i-a-rec.csv"
succeeds "show integrate" "$MCSPEC" show "$tmp/i-a.rec" --csv && same_out "show integrate" "$tmp/i-a-rec.csv"
# a drawn KIND's record shows its exact column too (E[D^2] of the jittered
# grid, E of random points' distances), and a record of --dim 3 is refused
succeeds "discrepancy KIND --save" "$MCSPEC" discrepancy jittered --dim 2 --k 64 --sets 20 --csv \
    --save "$tmp/d-j.rec" && cp "$tmp/out" "$tmp/d-j.csv"
succeeds "show discrepancy KIND" "$MCSPEC" show "$tmp/d-j.rec" --csv &&
    same_out "show discrepancy KIND (exact column)" "$tmp/d-j.csv"
if awk -F, '$1 == "l2_star" && $6 != "" { e = 1 } END { exit !e }' "$tmp/out"; then ok
else bad "show discrepancy KIND: no exact l2_star"; fi
succeeds "stats KIND --save" "$MCSPEC" stats random --dim 2 --k 64 --sets 20 --csv \
    --save "$tmp/s-r.rec" && head -n 3 "$tmp/out" >"$tmp/s-r.csv"
succeeds "show spacing KIND" "$MCSPEC" show "$tmp/s-r.rec" --csv &&
    same_out "show spacing KIND (exact column)" "$tmp/s-r.csv"
if awk -F, '$1 == "avg_min_distance" && $4 != "" { e = 1 } END { exit !e }' "$tmp/out"; then ok
else bad "show spacing KIND: no exact avg_min_distance"; fi
usage_error "discrepancy KIND --dim 3 --save" "--dim 1 or 2" "$MCSPEC" discrepancy random --dim 3 --k 8 --save "$tmp/d3.rec"
if [ ! -e "$tmp/d3.rec" ]; then ok; else bad "discrepancy --dim 3 --save wrote a record"; fi
for f in d-a p-a s-a i-a; do # the table too
    if succeeds "show $f (table)" "$MCSPEC" show "$tmp/$f.rec" && grep -q "read from .*a.txt (" "$tmp/out"
    then ok; else bad "show $f: no provenance line"; fi
done
# standard input: the same record but the input's name
"$MCSPEC" discrepancy --save "$tmp/d-in.rec" - <"$tmp/a.txt" >/dev/null 2>&1 ||
    bad "discrepancy --save from standard input failed"
succeeds "show of standard input's record" "$MCSPEC" show "$tmp/d-in.rec" --csv && same_out "standard input" "$tmp/d-a.csv"

# ---- two runs merged against one run over both ----
merged() { # LABEL CMD-ARGS...: saves A, B and AB, merges A and B, compares shows
    label=$1
    shift
    "$@" --save "$tmp/m-a.rec" "$tmp/a.txt" >/dev/null &&
        "$@" --save "$tmp/m-b.rec" "$tmp/b.txt" >/dev/null &&
        "$@" --save "$tmp/m-ab.rec" "$tmp/ab.txt" >/dev/null || { bad "$label: a run failed"; return; }
    succeeds "$label: merge" "$MCSPEC" merge "$tmp/m-a.rec" "$tmp/m-b.rec" -o "$tmp/m-1.rec"
    succeeds "$label: merge, other order" "$MCSPEC" merge "$tmp/m-b.rec" "$tmp/m-a.rec" -o "$tmp/m-2.rec"
    if cmp -s "$tmp/m-1.rec" "$tmp/m-2.rec"; then ok; else bad "$label: the merge depends on the order"; fi
    "$MCSPEC" show "$tmp/m-1.rec" --csv >"$tmp/m-1.csv" && "$MCSPEC" show "$tmp/m-ab.rec" --csv >"$tmp/m-ab.csv" ||
        { bad "$label: show failed"; return; }
    close "$label: merge against one run" "$tmp/m-ab.csv" "$tmp/m-1.csv"
}
merged "discrepancy" "$MCSPEC" discrepancy
merged "pcf rdf" "$MCSPEC" pcf --rdf --bins 8 --radius 2
merged "pcf kernel" "$MCSPEC" pcf --bins 8 --radius 1.5 --sigma 0.2
merged "stats" "$MCSPEC" stats

# integrate: Chan's merge of the two shows' mean and standard error
"$MCSPEC" integrate --family disk --csv --save "$tmp/i-1.rec" "$tmp/a.txt" >/dev/null &&
    "$MCSPEC" integrate --family disk --csv --save "$tmp/i-2.rec" "$tmp/b.txt" >/dev/null ||
    bad "integrate: a run failed"
succeeds "integrate: merge" "$MCSPEC" merge "$tmp/i-1.rec" "$tmp/i-2.rec" -o "$tmp/i-12.rec"
"$MCSPEC" show "$tmp/i-1.rec" --csv | sed -n 2p >"$tmp/i-1.row"
"$MCSPEC" show "$tmp/i-2.rec" --csv | sed -n 2p >"$tmp/i-2.row"
"$MCSPEC" show "$tmp/i-12.rec" --csv | sed -n 2p >"$tmp/i-12.row"
problems=$(cat "$tmp/i-1.row" "$tmp/i-2.row" "$tmp/i-12.row" | awk -F, '
    function far(x, y) { d = x - y; if (d < 0) d = -d; return d > 1e-12 * (x < 0 ? -x : x) }
    NR <= 2 { n[NR] = $9; m[NR] = $3; s[NR] = $4; next }
    { N = n[1] + n[2]; d = m[2] - m[1]; mean = m[1] + d * n[2] / N
      m2 = s[1]^2 * n[1] * (n[1] - 1) + s[2]^2 * n[2] * (n[2] - 1) + d * d * n[1] * n[2] / N
      se = sqrt(m2 / (N - 1) / N)
      if ($9 != N) printf "sets %s, expected %d; ", $9, N
      if (far(mean, $3)) printf "mse %s, Chan %.17g; ", $3, mean
      if (far(se, $4)) printf "stderr %s, Chan %.17g; ", $4, se }')
if [ -z "$problems" ]; then ok; else bad "integrate merge: $problems"; fi

# ---- refusals ----
"$MCSPEC" pcf --rdf --bins 8 --radius 1.5 --save "$tmp/r15.rec" "$tmp/b.txt" >/dev/null
"$MCSPEC" pcf --bins 8 --radius 2 --save "$tmp/gauss.rec" "$tmp/b.txt" >/dev/null
"$MCSPEC" pcf --rdf --bins 8 --radius 2 --save "$tmp/rdf-a.rec" "$tmp/a.txt" >/dev/null
"$MCSPEC" integrate --family heaviside --save "$tmp/i-h.rec" "$tmp/b.txt" >/dev/null
awk 'NF == 2 { print $1 } NF != 2 { print }' "$tmp/b.txt" >"$tmp/b1.txt"
"$MCSPEC" discrepancy --save "$tmp/d-1d.rec" "$tmp/b1.txt" >/dev/null
"$MCSPEC" discrepancy --save "$tmp/d-b.rec" "$tmp/b.txt" >/dev/null
refused() { # LABEL PATTERN FILES...: merge exit 2, one line, no OUT
    label=$1 pattern=$2
    shift 2
    rm -f "$tmp/no.rec"
    usage_error "$label" "$pattern" "$MCSPEC" merge "$@" -o "$tmp/no.rec"
    if [ -e "$tmp/no.rec" ]; then bad "$label: OUT written"; else ok; fi
}
refused "merge: another radius" "cannot merge" "$tmp/rdf-a.rec" "$tmp/r15.rec"
refused "merge: another estimator" "cannot merge" "$tmp/rdf-a.rec" "$tmp/gauss.rec"
refused "merge: another family" "cannot merge" "$tmp/i-1.rec" "$tmp/i-h.rec"
refused "merge: another dim" "cannot merge" "$tmp/d-b.rec" "$tmp/d-1d.rec"
refused "merge: another kind" "cannot merge" "$tmp/d-b.rec" "$tmp/s-a.rec"
refused "merge: the same file twice" "twice" "$tmp/d-a.rec" "$tmp/d-a.rec"
cp "$tmp/d-a.rec" "$tmp/d-a-copy.rec"
refused "merge: the same point file twice" "same|twice" "$tmp/d-a.rec" "$tmp/d-a-copy.rec"
# drawn sets carry their run: the same stream twice, another seed (unless --mix-seeds)
"$MCSPEC" pcf jittered --k 64 --sets 5 --seed 1 --save "$tmp/j1.rec" >/dev/null
"$MCSPEC" pcf jittered --k 64 --sets 5 --seed 1 --save "$tmp/j1-again.rec" >/dev/null
"$MCSPEC" pcf jittered --k 64 --sets 5 --seed 2 --save "$tmp/j2.rec" >/dev/null
refused "merge: the same stream twice" "twice" "$tmp/j1.rec" "$tmp/j1-again.rec"
refused "merge: another seed" "seed" "$tmp/j1.rec" "$tmp/j2.rec"
succeeds "merge --mix-seeds" "$MCSPEC" merge "$tmp/j1.rec" "$tmp/j2.rec" --mix-seeds -o "$tmp/j12.rec"
mkdir "$tmp/dir"
usage_error "--save into a directory" "directory" "$MCSPEC" discrepancy --save "$tmp/dir" "$tmp/a.txt"
ln -s "$tmp/d-b.rec" "$tmp/link.rec"
usage_error "--save onto a symbolic link" "symbolic link" "$MCSPEC" stats --save "$tmp/link.rec" "$tmp/a.txt"
usage_error "--save into a missing directory" "" "$MCSPEC" pcf --save "$tmp/none/x.rec" "$tmp/a.txt"
usage_error "integrate --save without --family" "--family" "$MCSPEC" integrate --save "$tmp/x.rec" "$tmp/a.txt"
usage_error "integrate --save over two families" "one family" "$MCSPEC" integrate --family disk,cosine --save "$tmp/x.rec" "$tmp/a.txt"
printf '0.1 0.2\n0.3 0.4\n#\n0.5 0.6\n#\n' >"$tmp/two-k.txt"
usage_error "integrate --save over two K" "sizes K" "$MCSPEC" integrate --family disk --save "$tmp/x.rec" "$tmp/two-k.txt"
if [ -e "$tmp/x.rec" ]; then bad "a refused --save wrote its file"; else ok; fi

check_summary
