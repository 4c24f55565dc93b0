#!/bin/sh
# make check-mpi: mcspec-mpi against the single-process runs (docs/scaling.md).
#
#   MCSPEC=build/bin/mcspec MCSPEC_MPI=build/bin/mcspec-mpi sh test/mpi_check.sh
#
# For P = 1, 2, 4 ranks (oversubscribed, so two cores do): the file of
# `mpirun -np P mcspec-mpi pattern ...` against `mcspec pattern ... --streams P`
# and against `mcspec merge` of the P files of `--stream I`, every entry of
# `mcspec show --csv` within 1e-12 relative, and the bytes identical (the
# three do the same merges in the same order), the provenance of the mpi
# record ('streams 0..P-1 of P', the same bytes as the single process's), and
# mcspec show of it printing the single run's table, predictions included
# (with --importance given again). Then the failure paths: a rank
# that reports a failure, a rank that dies, and bad usage, each with a
# non-zero exit, a message and no file (an old file of that name untouched).
# Then `mcspec-mpi spectrum` over several point files at P = 1, 2, 3, 4
# against `mcspec spectrum` with the same arguments: the CSV, the table and
# the --save record byte for byte (2D radial with width-2 annuli and the
# default F, the 2D plane, 1D through --dims, psa files); its bad usage
# (exit 2, rank 0's one line), --help once, and a rank that fails.
# Ends with a Unity-style "N Tests N Failures 0 Ignored" line.
set -u
MCSPEC=${MCSPEC:-build/bin/mcspec}
MCSPEC_MPI=${MCSPEC_MPI:-build/bin/mcspec-mpi}
MPIRUN=${MPIRUN:-mpirun}
TOL=${TOL:-1e-12}
ulimit -c 0 2>/dev/null || true
work=$(mktemp -d "${TMPDIR:-/tmp}/mcspec-mpi-check.XXXXXX")
trap 'rm -rf "$work"' EXIT INT TERM

# --oversubscribe: more ranks than cores; root needs its own flag.
mpiflags="--oversubscribe"
[ "$(id -u)" -eq 0 ] && mpiflags="$mpiflags --allow-run-as-root"
mpi() { np=$1; shift; "$MPIRUN" $mpiflags -np "$np" "$@"; }

tests=0
failures=0
pass() { tests=$((tests + 1)); echo "PASS: $1"; }
fail() { tests=$((tests + 1)); failures=$((failures + 1)); echo "FAIL: $1"; }

# Largest relative difference of two `mcspec show --csv` tables (same header,
# same rows); empty fields must be empty in both. Prints it, or "mismatch".
max_rel() {
    awk -F, 'NR == FNR { a[FNR] = $0; n = FNR; next }
        {
            if (!(FNR in a)) { bad = 1; exit }
            m = split(a[FNR], x, ","); if (m != NF) { bad = 1; exit }
            for (i = 1; i <= NF; ++i) {
                if (FNR == 1 || x[i] == $i) continue
                if (x[i] == "" || $i == "") { bad = 1; exit }
                d = x[i] - $i; d = d < 0 ? -d : d
                s = x[i] < 0 ? -x[i] : x[i]; t = $i < 0 ? -$i : $i; s = s > t ? s : t
                r = s > 0 ? d / s : d; if (r > worst) worst = r
            }
            rows = FNR
        }
        END { if (bad || rows != n) print "mismatch"; else printf "%.3g\n", worst + 0 }' "$1" "$2"
}

# compare LABEL A.rec B.rec: entries within TOL, and the same bytes.
compare() {
    "$MCSPEC" show "$2" --csv >"$work/a.csv" && "$MCSPEC" show "$3" --csv >"$work/b.csv" ||
        { fail "$1: mcspec show failed"; return; }
    rel=$(max_rel "$work/a.csv" "$work/b.csv")
    if [ "$rel" = mismatch ] || awk -v r="$rel" -v t="$TOL" 'BEGIN { exit !(r > t) }'; then
        fail "$1: largest relative difference $rel (allowed $TOL)"
    else
        pass "$1: largest relative difference $rel"
    fi
    if cmp -s "$2" "$3"; then pass "$1: identical bytes"; else fail "$1: the bytes differ"; fi
}

# One run configuration: KIND N K T SEED [--importance FILE].
check_run() {
    kind=$1 n=$2 k=$3 t=$4 seed=$5
    shift 5
    for p in 1 2 4; do
        tag="$kind N=$n K=$k T=$t $* P=$p"
        out="$work/mpi.rec"
        rm -f "$out"
        if ! mpi "$p" "$MCSPEC_MPI" pattern "$kind" --n "$n" --k "$k" --trials "$t" \
            --seed "$seed" "$@" --save "$out" >"$work/mpi.out" 2>&1; then
            fail "$tag: mcspec-mpi failed: $(head -n 3 "$work/mpi.out")"
            continue
        fi
        "$MCSPEC" pattern "$kind" --n "$n" --k "$k" --trials "$t" --seed "$seed" "$@" \
            --streams "$p" --save "$work/one.rec" --csv >"$work/one.csv" ||
            { fail "$tag: mcspec pattern --streams failed"; continue; }
        files=
        i=0
        while [ "$i" -lt "$p" ]; do
            "$MCSPEC" pattern "$kind" --n "$n" --k "$k" --trials "$t" --seed "$seed" "$@" \
                --streams "$p" --stream "$i" --save "$work/s$i.rec" --csv >/dev/null ||
                fail "$tag: mcspec pattern --stream $i failed"
            files="$files $work/s$i.rec"
            i=$((i + 1))
        done
        # shellcheck disable=SC2086
        "$MCSPEC" merge $files -o "$work/merged.rec" >/dev/null ||
            { fail "$tag: mcspec merge failed"; continue; }
        compare "$tag: mpi vs --streams" "$out" "$work/one.rec"
        compare "$tag: mpi vs merge of --stream files" "$out" "$work/merged.rec"
        streams="streams 0..$((p - 1)) of $p"
        [ "$p" -eq 1 ] && streams="stream 0 of 1"
        origin=$("$MCSPEC" show "$out" | sed -n 2p)
        case $origin in
        "drawn: $kind, N = $n bins, K = $k samples,"*"seed $seed: $streams (trials 0..$((t - 1)) of $t)")
            pass "$tag: the mpi record holds $streams" ;;
        *) fail "$tag: the mpi record's provenance: '$origin'" ;;
        esac
        if "$MCSPEC" show "$out" "$@" --csv >"$work/show.csv" && cmp -s "$work/show.csv" "$work/one.csv"
        then pass "$tag: mcspec show of the mpi record prints the single run's table"
        else fail "$tag: mcspec show $* of the mpi record differs from mcspec pattern --csv"; fi
    done
}

# expect_failure LABEL EXPECTED-TEXT CMD...: non-zero exit, the text on
# stderr, and the old FILE ($work/keep.rec) byte-identical.
expect_failure() {
    label=$1 text=$2
    shift 2
    printf 'an old file\n' >"$work/keep.rec"
    cp "$work/keep.rec" "$work/keep.orig"
    if "$@" >"$work/fail.out" 2>&1; then
        fail "$label: exit status 0"
    elif ! grep -q "$text" "$work/fail.out"; then
        fail "$label: no message '$text': $(head -n 2 "$work/fail.out")"
    elif ! cmp -s "$work/keep.rec" "$work/keep.orig"; then
        fail "$label: the old file changed"
    elif ls "$work"/keep.rec.part* >/dev/null 2>&1; then
        fail "$label: a temporary file was left"
    else
        pass "$label"
    fi
}

printf '0.5\n1\n2\n0.25\n1\n1\n3\n0.75\n' >"$work/g8.txt"
check_run stratified 64 8 1001 7
check_run random 8 5 1000 11 --importance "$work/g8.txt"
check_run jitter 250 16 500 3

save="--save $work/keep.rec"
# shellcheck disable=SC2086
expect_failure "a rank reporting a failure" "not written" \
    env MCSPEC_MPI_FAIL_RANK=2 "$MPIRUN" $mpiflags -x MCSPEC_MPI_FAIL_RANK -np 4 \
    "$MCSPEC_MPI" pattern random --n 64 --k 8 --trials 100 $save
# shellcheck disable=SC2086
expect_failure "a rank that dies" "" \
    env MCSPEC_MPI_ABORT_RANK=1 "$MPIRUN" $mpiflags -x MCSPEC_MPI_ABORT_RANK -np 2 \
    "$MCSPEC_MPI" pattern random --n 64 --k 8 --trials 100 $save
# shellcheck disable=SC2086
expect_failure "fewer trials than ranks" "fewer than the 4 ranks" \
    mpi 4 "$MCSPEC_MPI" pattern random --n 64 --k 8 --trials 3 $save
# shellcheck disable=SC2086
expect_failure "an unknown pattern" "which pattern" \
    mpi 2 "$MCSPEC_MPI" pattern bogus --n 64 --k 8 --trials 100 $save

# ---- mcspec-mpi spectrum: the sets of many files over the ranks ----------------
# points SEED SETS K: utk sets of K uniform points in the square (awk's generator).
points() {
    awk -v seed="$1" -v sets="$2" -v k="$3" 'BEGIN { srand(seed)
        for (s = 0; s < sets; ++s) { for (j = 0; j < k; ++j) printf "%.17g %.17g\n", rand(), rand()
            if (s + 1 < sets) print "#" } }'
}
points 1 5 300 >"$work/m1.txt"
points 2 4 200 >"$work/m2.txt"
points 3 1 500 >"$work/m3.txt"
for i in 0 1 2; do { echo 64; points $((10 + i)) 1 64; } >"$work/psa$i.txt"; done
# check_spectrum LABEL ARGS...: mpi at P = 1, 2, 3, 4 against one process,
# the CSV and the record byte for byte.
check_spectrum() {
    label=$1
    shift
    if ! "$MCSPEC" spectrum "$@" --csv --save "$work/sp-one.rec" >"$work/sp-one.csv" 2>"$work/sp.err"; then
        fail "spectrum $label: mcspec spectrum failed: $(head -n 2 "$work/sp.err")"
        return
    fi
    for p in 1 2 3 4; do
        rm -f "$work/sp-mpi.rec"
        if ! mpi "$p" "$MCSPEC_MPI" spectrum "$@" --csv --save "$work/sp-mpi.rec" >"$work/sp-mpi.csv" 2>"$work/sp.err"; then
            fail "spectrum $label P=$p: mcspec-mpi failed: $(head -n 2 "$work/sp.err")"
            continue
        fi
        if cmp -s "$work/sp-one.csv" "$work/sp-mpi.csv"; then pass "spectrum $label P=$p: the CSV's bytes"
        else fail "spectrum $label P=$p: the CSV differs from one process's"; fi
        if cmp -s "$work/sp-one.rec" "$work/sp-mpi.rec"; then pass "spectrum $label P=$p: the record's bytes"
        else fail "spectrum $label P=$p: the record differs from one process's"; fi
    done
}
check_spectrum "2D radial, width 2, default F" --dim 2 --radial --bin-width 2 "$work/m1.txt" "$work/m2.txt" "$work/m3.txt"
check_spectrum "2D plane, F = 6" --dim 2 --freq 6 "$work/m1.txt" "$work/m2.txt"
check_spectrum "1D, --dims 1, F = 40" --dims 1 --freq 40 "$work/m1.txt" "$work/m3.txt"
check_spectrum "psa files" --format psa --radial "$work/psa0.txt" "$work/psa1.txt" "$work/psa2.txt"
# The table too (its notes name the command spectrum, as one process does).
"$MCSPEC" spectrum --dim 2 --radial "$work/m1.txt" "$work/m2.txt" >"$work/t-one.txt" 2>/dev/null
if mpi 3 "$MCSPEC_MPI" spectrum --dim 2 --radial "$work/m1.txt" "$work/m2.txt" >"$work/t-mpi.txt" 2>/dev/null &&
    cmp -s "$work/t-one.txt" "$work/t-mpi.txt"; then pass "spectrum P=3: the table's bytes"
else fail "spectrum P=3: the table differs from one process's"; fi
# spectrum_usage LABEL TEXT ARGS...: exit 2, one line of ours on stderr
# (rank 0's only; mpirun adds its own) holding TEXT, nothing on stdout.
spectrum_usage() {
    label=$1 text=$2
    shift 2
    mpi 3 "$MCSPEC_MPI" spectrum "$@" >"$work/u.out" 2>"$work/u.err"
    st=$?
    if [ "$st" -ne 2 ]; then fail "spectrum usage, $label: exit status $st"
    elif [ -s "$work/u.out" ]; then fail "spectrum usage, $label: wrote to stdout"
    elif [ "$(grep -c '^mcspec' "$work/u.err")" -ne 1 ] || ! grep -q -- "$text" "$work/u.err"; then
        fail "spectrum usage, $label: stderr '$(head -n 3 "$work/u.err")'"
    else pass "spectrum usage, $label"; fi
}
spectrum_usage "binned" "point-set spectra only" "$work/m1.txt"
spectrum_usage "standard input" "cannot share standard input" --dim 2 -
spectrum_usage "no file" "cannot share standard input" --dim 2
spectrum_usage "--bin-width 0" "--bin-width expects a whole number" --dim 2 --radial --bin-width 0 "$work/m1.txt"
printf '0.1 0.2\n0.3 1.5\n' >"$work/m4.txt"
spectrum_usage "a bad line" "m4.txt: line 2: coordinate 1.5 is outside" --dim 2 "$work/m1.txt" "$work/m4.txt"
mpi 2 "$MCSPEC_MPI" spectrum --help >"$work/h.out" 2>&1
if [ "$(grep -c '^usage: mcspec spectrum' "$work/h.out")" -eq 1 ]; then pass "spectrum --help printed once"
else fail "spectrum --help: $(grep -c '^usage' "$work/h.out") usage lines"; fi
# shellcheck disable=SC2086
expect_failure "spectrum: a rank reporting a failure" "failed (first: set 1, on rank 1); nothing printed or written" \
    env MCSPEC_MPI_FAIL_RANK=1 "$MPIRUN" $mpiflags -x MCSPEC_MPI_FAIL_RANK -np 3 \
    "$MCSPEC_MPI" spectrum --dim 2 --freq 4 $save "$work/m1.txt"

echo "-----------------------"
echo "$tests Tests $failures Failures 0 Ignored"
[ "$failures" -eq 0 ]
