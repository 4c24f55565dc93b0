#!/bin/sh
# Checks of the mcspec command's saved accumulators (issue 14): --save on
# spectrum, pattern and variance, mcspec merge, mcspec show, the stream rule
# of pattern --streams / --stream, and the atomic writes.
#
# usage: sh test/record_check.sh   ($MCSPEC names the binary, default
#                                   build/bin/mcspec; $GOLDEN the golden
#                                   files, default test/golden; $CORPUS the
#                                   fuzz seed records, default fuzz/corpus/load)
#
#   --help of merge and show;
#   a saved record shows (mcspec show --csv) exactly the numbers the run
#   printed: spectrum, pattern (its first six columns), variance (mean,
#   stderr, variance and its stderr of the --kind row);
#   the same seed saves the same bytes, and no temporary file stays behind;
#   pattern --streams P equals the merge of the P --stream I files byte for
#   byte (P = 1, 3, 4, T not a multiple of P), --streams 1 is the plain run,
#   stream I holds floor(T/P) trials, one more for I < T mod P;
#   merge refuses (exit 2, one line naming the file, OUT untouched) a record
#   of another N or kind, a truncated, corrupted, empty or non-record file,
#   a missing file, and a missing -o; show refuses the same files;
#   show prints every kind the format knows (the fuzz seeds), moment and
#   autocorr with the spectrum header, welford with its own; show --plot
#   refuses a record without a figure (welford, spectrum2d) or with no
#   trials before it looks for gnuplot (none of these checks needs it);
#   --save into a missing directory fails before any work; --save with
#   variance needs --kind; --save, merge -o and --plot refuse a device node,
#   a FIFO and a symbolic link (exit 2, one line), which stay as they were,
#   and replace a regular file; a file-size limit (ulimit -f) below the
#   record is exit 2 and one line, no part file; below stdout, exit 1;
#   provenance (issue 23): pattern and spectrum records are version 2 and
#   say where their trials came from; merge refuses (exit 2, one line, every
#   file byte-identical) the same stream twice, overlapping streams, the
#   same file twice, another pattern (kind, K, importance function), seed
#   (unless --mix-seeds), P or T, the same point file twice, and an OUT that
#   is an input (by name, hard link or symbolic link); the streams of a run
#   merged in any order and grouping give the bytes of --streams P and say
#   'streams 0..P-1 of P'; show of a merged pattern record prints the
#   single run's exact, closed and z columns (with an importance function:
#   given again with --importance, its checksum checked); version 1 records
#   still merge, with one note on stderr, into a record without provenance.
# Ends with a Unity-style summary so test/run_tests.sh counts it.

MCSPEC=${MCSPEC:-build/bin/mcspec}
GOLDEN=${GOLDEN:-test/golden}
CORPUS=${CORPUS:-fuzz/corpus/load}

# shellcheck source=test/support/check.sh
. "$(dirname "$0")/support/check.sh"
check_start record_check

# refused LABEL PATTERN CMD...: exit 2, nothing on stdout, one line on stderr
# matching PATTERN, and $tmp/keep (an old OUT) untouched.
refused() {
    label=$1 pattern=$2
    shift 2
    printf 'old contents\n' >"$tmp/keep"
    run "$@"
    if [ "$rc" -ne 2 ]; then bad "$label: exit status $rc, expected 2"
    elif [ -s "$tmp/out" ]; then bad "$label: wrote to stdout"
    elif [ "$(wc -l <"$tmp/err")" -ne 1 ]; then bad "$label: $(wc -l <"$tmp/err") lines on stderr"
    elif ! grep -Eq -- "$pattern" "$tmp/err"; then bad "$label: '$(cat "$tmp/err")' lacks /$pattern/"
    elif [ "$(cat "$tmp/keep")" != "old contents" ]; then bad "$label: the old OUT changed"
    else ok; fi
}

same_file() { # LABEL A B
    if cmp -s "$2" "$3"; then ok; else bad "$1: $2 and $3 differ"; fi
}

no_parts() { # LABEL: no temporary file left in $tmp
    if ls "$tmp"/*.part* >/dev/null 2>&1; then bad "$1: a temporary file was left"; else ok; fi
}

# ------------------------------------------------------------------ --help
for c in merge show; do
    if succeeds "$c --help" "$MCSPEC" "$c" --help && grep -q "^usage: mcspec $c" "$tmp/out"
    then ok; else bad "$c --help: no usage line"; fi
done

# ------------------------------------------- a saved record shows the run
succeeds "spectrum --save" "$MCSPEC" spectrum --n 64 --csv --save "$tmp/sp.rec" \
    "$GOLDEN/comb_k8_n64.txt" && cp "$tmp/out" "$tmp/sp.csv"
succeeds "show spectrum" "$MCSPEC" show "$tmp/sp.rec" --csv && same_file "spectrum vs show" \
    "$tmp/sp.csv" "$tmp/out"

pattern() { "$MCSPEC" pattern stratified --n 48 --k 5 --trials "$@"; }
# A pattern record knows its run: show prints every column the run printed,
# the predictions included.
succeeds "pattern --save" pattern 10 --seed 3 --csv --save "$tmp/p.rec" &&
    cp "$tmp/out" "$tmp/p.csv"
succeeds "show pattern" "$MCSPEC" show "$tmp/p.rec" --csv && same_file "pattern vs show" \
    "$tmp/p.csv" "$tmp/out"
succeeds "pattern --save again" pattern 10 --seed 3 --csv --save "$tmp/p2.rec"
same_file "the same seed saves the same bytes" "$tmp/p.rec" "$tmp/p2.rec"
no_parts "after --save"

printf '0.5\n1\n2\n0.25\n1\n3\n' >"$tmp/f6.txt"
succeeds "variance --save" "$MCSPEC" variance --k 3 --trials 50 --kind jitter --csv \
    --save "$tmp/v.rec" "$tmp/f6.txt" &&
    awk -F, 'NR == 2 { print $4 "," $5 "," $6 "," $7 "," $8 }' "$tmp/out" >"$tmp/v.csv"
succeeds "show welford" "$MCSPEC" show "$tmp/v.rec" --csv &&
    awk -F, 'NR == 2 { print $1 "," $2 "," $3 "," $4 "," $5 }' "$tmp/out" >"$tmp/v2.csv" &&
    same_file "variance vs show" "$tmp/v.csv" "$tmp/v2.csv"
if head -n 1 "$tmp/out" | grep -qx 'count,mean,mean_stderr,variance,variance_stderr'
then ok; else bad "show welford: CSV header '$(head -n 1 "$tmp/out")'"; fi

# ------------------------------------------------------------ stream rule
for p in 1 3 4; do
    t=11
    succeeds "pattern --streams $p" pattern "$t" --seed 9 --streams "$p" --csv \
        --save "$tmp/all$p.rec"
    files=
    i=0
    while [ "$i" -lt "$p" ]; do
        succeeds "pattern --stream $i of $p" pattern "$t" --seed 9 --streams "$p" --stream "$i" \
            --save "$tmp/s$p-$i.rec"
        want=$((t / p + (i < t % p ? 1 : 0)))
        "$MCSPEC" show "$tmp/s$p-$i.rec" | head -n 1 | grep -q ", $want trials$" && ok ||
            bad "stream $i of $p: not $want trials: $("$MCSPEC" show "$tmp/s$p-$i.rec" | head -n 1)"
        files="$files $tmp/s$p-$i.rec"
        i=$((i + 1))
    done
    # shellcheck disable=SC2086
    succeeds "merge of $p streams" "$MCSPEC" merge $files -o "$tmp/m$p.rec"
    same_file "--streams $p vs merge of the --stream files" "$tmp/all$p.rec" "$tmp/m$p.rec"
done
succeeds "plain pattern run" pattern 11 --seed 9 --csv --save "$tmp/plain.rec"
same_file "--streams 1 is the plain run" "$tmp/plain.rec" "$tmp/all1.rec"
refused "--stream without its P" "not one of the 1 streams" pattern 11 --stream 1
refused "--stream P" "not one of the 3 streams" pattern 11 --streams 3 --stream 3
refused "fewer trials than streams" "fewer than --streams" pattern 3 --streams 4

# ---------------------------------------------------- merge and show refuse
"$MCSPEC" pattern random --n 32 --k 4 --trials 5 --save "$tmp/n32.rec" >/dev/null
head -c 100 "$tmp/p.rec" >"$tmp/trunc.rec"
cp "$tmp/p.rec" "$tmp/flip.rec"
printf '\001' | dd of="$tmp/flip.rec" bs=1 seek=200 conv=notrunc 2>/dev/null
: >"$tmp/empty.rec"
printf 'freq,power\n1,2\n' >"$tmp/text.rec"
m() { "$MCSPEC" merge "$@" -o "$tmp/keep"; }
refused "merge: another N" "n32.rec holds a spectrum record of N = 32.*cannot merge" \
    m "$tmp/p.rec" "$tmp/n32.rec"
refused "merge: another kind" "v.rec holds a welford record.*cannot merge" \
    m "$tmp/p.rec" "$tmp/v.rec"
refused "merge: truncated" "trunc.rec: truncated" m "$tmp/p.rec" "$tmp/trunc.rec"
refused "merge: a changed byte" "flip.rec: checksum mismatch" m "$tmp/p.rec" "$tmp/flip.rec"
refused "merge: empty file" "empty.rec: truncated" m "$tmp/empty.rec"
refused "merge: not a record" "text.rec: not an mcspec record" m "$tmp/text.rec"
refused "merge: missing file" "cannot read .*nothere.rec" m "$tmp/nothere.rec"
refused "merge: no -o" "give -o OUT" "$MCSPEC" merge "$tmp/p.rec"
refused "merge: no input" "give one or more FILEs" "$MCSPEC" merge -o "$tmp/keep"
for f in trunc flip empty text; do
    refused "show: $f" "$f.rec: " "$MCSPEC" show "$tmp/$f.rec"
done
refused "show: --plot of a welford record" "no plot" "$MCSPEC" show "$tmp/v.rec" --plot x.svg
# What the record allows comes before gnuplot, which is looked for only when
# a figure will be drawn: these hold without gnuplot on PATH.
refused "show: --plot of a welford record, no gnuplot" "v.rec holds a welford record: no plot for it" \
    env PATH=/nonexistent "$MCSPEC" show "$tmp/v.rec" --plot "$tmp/x.svg"
refused "show: --plot of a spectrum2d record, no gnuplot" "holds a spectrum2d record.*: no plot for it" \
    env PATH=/nonexistent "$MCSPEC" show "$CORPUS/spectrum2d-n16x17-t20.rec" --plot "$tmp/x.svg"
refused "show: --plot of an empty spectrum, no gnuplot" "with no trials: nothing to show" \
    env PATH=/nonexistent "$MCSPEC" show "$CORPUS/spectrum-n1-t0.rec" --plot "$tmp/x.svg"
refused "show: --plot x.pdf before reading" "--plot $tmp/x.pdf: the file name must end in .svg or .png" \
    env PATH=/nonexistent "$MCSPEC" show "$tmp/v.rec" --plot "$tmp/x.pdf"
refused "show: --plot of a spectrum record, no gnuplot" "--plot needs gnuplot, which is not on PATH" \
    env PATH=/nonexistent "$MCSPEC" show "$tmp/p.rec" --plot "$tmp/x.svg"
[ -e "$tmp/x.svg" ] && bad "show --plot without gnuplot wrote a figure" || ok
refused "show: --radial of a spectrum" "--radial is for pointset2d" \
    "$MCSPEC" show "$tmp/p.rec" --radial
no_parts "after the refusals"

# ------------------------------------------------------ every kind shows
for f in "$CORPUS"/*.rec; do
    name=${f##*/}
    case $name in
    *-t0.rec) continue ;; # empty accumulators: nothing to show (below)
    spectrum-* | moment-* | autocorr-*) header=freq,mean_re,mean_im,mean_stderr,power,power_stderr ;;
    welford-*) header=count,mean,mean_stderr,variance,variance_stderr ;;
    pointset2d-*) header=kx,ky,power,power_stderr ;;
    pointset-*) header=freq,power,power_stderr ;;
    spectrum2d-*) header=k1,k2,mean_re,mean_im,mean_stderr,power,power_stderr ;;
    pcf-*) header=r,pcf,pcf_stderr,exact ;;
    integrate-*) header=family,k,mse,mse_stderr,exact,predicted,predicted_tail,freq,sets,slope,rate_random,rate_jittered ;;
    discrepancy-*) header=measure,value,stderr,exact_random,root,exact ;;
    spacing-*) header=statistic,value,stderr,exact ;;
    *) bad "unexpected seed $name"; continue ;;
    esac
    if succeeds "show $name" "$MCSPEC" show "$f" --csv && [ "$(head -n 1 "$tmp/out")" = "$header" ]
    then ok; else bad "show $name: header '$(head -n 1 "$tmp/out")'"; fi
done
refused "show: an empty spectrum" "no trials" "$MCSPEC" show "$CORPUS/spectrum-n1-t0.rec"
# Version 1 records (the fuzz seeds) have no provenance: they merge, with
# one note on stderr, into a record that has none either. (A copy: the same
# file twice is refused.)
cp "$CORPUS/pointset2d-f7-t5.rec" "$tmp/ps-copy.rec"
run "$MCSPEC" merge "$CORPUS/pointset2d-f7-t5.rec" "$tmp/ps-copy.rec" -o "$tmp/ps2.rec"
if [ "$rc" -ne 0 ]; then bad "merge of two version 1 records: exit status $rc: $(cat "$tmp/err")"
elif [ "$(wc -l <"$tmp/err")" -ne 1 ] ||
    ! grep -q "^mcspec merge: note: .*pointset2d-f7-t5.rec and .*ps-copy.rec are version 1 records, with no provenance: merged without the checks" "$tmp/err"
then bad "merge of two version 1 records: stderr '$(cat "$tmp/err")'"
else ok; fi
"$MCSPEC" show "$tmp/ps2.rec" | head -n 1 | grep -q ', 10 trials$' && ok ||
    bad "merge of two 5-trial point sets: not 10 trials"
"$MCSPEC" show "$tmp/ps2.rec" | sed -n 2p | grep -qx 'provenance: none (a format version 1 record)' && ok ||
    bad "merge of version 1 records: the output claims a provenance"

# ------------------------------------------------------------ --save fails early
refused "--save into a missing directory" "cannot write $tmp/no/such/dir/x.rec" \
    pattern 10 --save "$tmp/no/such/dir/x.rec"
refused "--save of a directory" "it is a directory" pattern 10 --save "$tmp"
refused "variance --save without --kind" "choose its pattern with --kind" \
    "$MCSPEC" variance --k 3 --save "$tmp/v3.rec" "$tmp/f6.txt"

# ------------------------------------------------ --save onto special files
# The atomic write renames a new file onto FILE, which would put a regular
# file in place of a device node, a FIFO or a symbolic link: anything but a
# regular file (or nothing) is refused before any work, and left as it was.
# node_kept LABEL PATH TYPE: PATH is still of TYPE (stat's %F) with the
# device numbers and target it had; no part file beside it.
node_kept() {
    if [ "$(stat -c '%F %t:%T' "$2")" != "$3" ]; then bad "$1: $2 is now $(stat -c '%F %t:%T' "$2")"
    elif [ -L "$2" ] && [ "$(readlink "$2")" != "$tmp/keep" ]; then bad "$1: the link changed"
    elif ls "$tmp"/sp/*.part* >/dev/null 2>&1; then bad "$1: a temporary file was left"
    else ok; fi
}
mkdir -p "$tmp/sp"
mkfifo "$tmp/sp/fifo"
ln -s "$tmp/keep" "$tmp/sp/link"
printf '0.25\n0.5\n' >"$tmp/sp/pts.txt"
if [ "$(id -u)" -eq 0 ] && mknod "$tmp/sp/dev" c 1 7 2>/dev/null; then
    refused "pattern --save onto a character device" \
        "^mcspec pattern: cannot write $tmp/sp/dev: it is a character device, not a regular file" \
        pattern 10 --save "$tmp/sp/dev"
    node_kept "pattern --save onto a character device" "$tmp/sp/dev" "character special file 1:7"
    refused "merge -o onto a character device" "cannot write $tmp/sp/dev: it is a character device" \
        "$MCSPEC" merge "$tmp/p.rec" -o "$tmp/sp/dev"
    node_kept "merge -o onto a character device" "$tmp/sp/dev" "character special file 1:7"
    mknod "$tmp/sp/dev.svg" c 1 7
    refused "--plot onto a character device" "--plot $tmp/sp/dev.svg: it is a character device" \
        pattern 10 --plot "$tmp/sp/dev.svg"
    node_kept "--plot onto a character device" "$tmp/sp/dev.svg" "character special file 1:7"
else
    skip "--save onto a device node: mknod needs root"
fi
refused "pattern --save onto a FIFO" "cannot write $tmp/sp/fifo: it is a FIFO, not a regular file" \
    pattern 10 --save "$tmp/sp/fifo"
node_kept "pattern --save onto a FIFO" "$tmp/sp/fifo" "fifo 0:0"
refused "spectrum --save onto a FIFO" "^mcspec spectrum: cannot write $tmp/sp/fifo: it is a FIFO" \
    "$MCSPEC" spectrum --n 4 --save "$tmp/sp/fifo" "$tmp/sp/pts.txt"
node_kept "spectrum --save onto a FIFO" "$tmp/sp/fifo" "fifo 0:0"
refused "variance --save onto a FIFO" "^mcspec variance: cannot write $tmp/sp/fifo: it is a FIFO" \
    "$MCSPEC" variance --k 3 --kind random --save "$tmp/sp/fifo" "$tmp/f6.txt"
node_kept "variance --save onto a FIFO" "$tmp/sp/fifo" "fifo 0:0"
refused "merge -o onto a FIFO" "^mcspec merge: cannot write $tmp/sp/fifo: it is a FIFO" \
    "$MCSPEC" merge "$tmp/p.rec" -o "$tmp/sp/fifo"
node_kept "merge -o onto a FIFO" "$tmp/sp/fifo" "fifo 0:0"
refused "pattern --save onto a symbolic link" \
    "cannot write $tmp/sp/link: it is a symbolic link, not a regular file" pattern 10 --save "$tmp/sp/link"
node_kept "pattern --save onto a symbolic link" "$tmp/sp/link" "symbolic link 0:0"
# A file-size limit (ulimit -f) below the record: the command ignores
# SIGXFSZ, so the write fails with EFBIG (it was killed, status 153, and left
# FILE.partXXXXXX): exit 2, one line naming FILE and the limit, no part file.
# stdout goes to /dev/null, which no limit covers.
( ulimit -f 8 && exec "$MCSPEC" pattern random --n 4096 --k 4 --trials 2 --save "$tmp/sp/big.rec" \
    ) </dev/null >/dev/null 2>"$tmp/err"
rc=$?
if [ "$rc" -ne 2 ]; then bad "--save past ulimit -f: exit status $rc, expected 2"
elif [ "$(wc -l <"$tmp/err")" -ne 1 ]; then bad "--save past ulimit -f: $(wc -l <"$tmp/err") lines on stderr"
elif ! grep -Eq "^mcspec pattern: cannot write $tmp/sp/big.rec: .*file-size limit" "$tmp/err"
then bad "--save past ulimit -f: '$(cat "$tmp/err")'"
elif [ -e "$tmp/sp/big.rec" ] || ls "$tmp"/sp/*.part* >/dev/null 2>&1
then bad "--save past ulimit -f: left $(ls "$tmp/sp" | tr '\n' ' ')"
else ok; fi
# The same limit on stdout: exit 1 (the output could not be written), one line.
( ulimit -f 1 && exec "$MCSPEC" pattern random --n 4096 --k 4 --trials 2 --csv \
    ) </dev/null >"$tmp/sp/out.csv" 2>"$tmp/err"
rc=$?
if [ "$rc" -eq 1 ] && [ "$(wc -l <"$tmp/err")" -eq 1 ] && grep -q '^mcspec: cannot write the output' "$tmp/err"
then ok; else bad "stdout past ulimit -f: exit status $rc, '$(cat "$tmp/err")'"; fi
rm -f "$tmp/sp/out.csv"
# A regular file is replaced, as before.
printf 'old\n' >"$tmp/sp/old.rec"
succeeds "pattern --save onto a regular file" pattern 10 --seed 3 --save "$tmp/sp/old.rec"
same_file "pattern --save onto a regular file" "$tmp/p.rec" "$tmp/sp/old.rec"

# ------------------------------------------------------------ provenance
# Every file of $tmp/pv byte-identical after a refusal: snap, then kept.
mkdir -p "$tmp/pv"
snap() { (cd "$tmp/pv" && cksum ./*) >"$tmp/pv.sum"; }
kept() {
    if (cd "$tmp/pv" && cksum ./*) | cmp -s - "$tmp/pv.sum"; then ok
    else bad "$1: a file changed: $( (cd "$tmp/pv" && cksum ./*) | diff "$tmp/pv.sum" - | tr '\n' ' ')"; fi
}
# refused_kept LABEL PATTERN CMD...: refused, and nothing in $tmp/pv changed.
refused_kept() {
    label=$1
    snap
    refused "$@"
    kept "$label"
}
pv=$tmp/pv
run4() { "$MCSPEC" pattern stratified --n 24 --k 5 --trials 23 --seed 9 --streams 4 "$@"; }
run4 --csv --save "$pv/all.rec" >"$tmp/all.csv"
for i in 0 1 2 3; do run4 --stream "$i" --save "$pv/s$i.rec" --csv >/dev/null; done
version=$(od -An -tu1 -j8 -N1 "$pv/s0.rec" | tr -d ' ')
[ "$version" = 2 ] && ok || bad "a pattern record is format version $version, not 2"
"$MCSPEC" show "$pv/s2.rec" | sed -n 2p |
    grep -qx 'drawn: stratified, N = 24 bins, K = 5 samples, seed 9: stream 2 of 4 (trials 12..17 of 23)' &&
    ok || bad "show of stream 2: '$("$MCSPEC" show "$pv/s2.rec" | sed -n 2p)'"

# Any order, at once or in pieces: the bytes of --streams 4, streams 0..3 of 4.
succeeds "merge of 4 streams, in order" "$MCSPEC" merge "$pv/s0.rec" "$pv/s1.rec" "$pv/s2.rec" \
    "$pv/s3.rec" -o "$tmp/in-order.rec"
succeeds "merge of 4 streams, another order" "$MCSPEC" merge "$pv/s2.rec" "$pv/s0.rec" \
    "$pv/s3.rec" "$pv/s1.rec" -o "$tmp/shuffled.rec"
same_file "merges of 4 streams in two orders" "$tmp/in-order.rec" "$tmp/shuffled.rec"
same_file "merge of 4 streams vs --streams 4" "$tmp/in-order.rec" "$pv/all.rec"
"$MCSPEC" show "$tmp/shuffled.rec" | sed -n 2p |
    grep -qx 'drawn: stratified, N = 24 bins, K = 5 samples, seed 9: streams 0..3 of 4 (trials 0..22 of 23)' &&
    ok || bad "merged streams: '$("$MCSPEC" show "$tmp/shuffled.rec" | sed -n 2p)'"
succeeds "merge of streams 3, 2" "$MCSPEC" merge "$pv/s3.rec" "$pv/s2.rec" -o "$pv/m23.rec"
succeeds "merge of streams 1, 0" "$MCSPEC" merge "$pv/s1.rec" "$pv/s0.rec" -o "$pv/m01.rec"
succeeds "merge of the two halves" "$MCSPEC" merge "$pv/m23.rec" "$pv/m01.rec" -o "$tmp/halves.rec"
same_file "merge of the halves vs --streams 4" "$tmp/halves.rec" "$pv/all.rec"
succeeds "merge of a half and two streams" "$MCSPEC" merge "$pv/s1.rec" "$pv/m23.rec" "$pv/s0.rec" \
    -o "$tmp/mixed.rec"
same_file "merge of a half and two streams vs --streams 4" "$tmp/mixed.rec" "$pv/all.rec"

# show of the merged streams: the single run's exact, closed and z columns.
succeeds "show of the merged streams" "$MCSPEC" show "$tmp/shuffled.rec" --csv &&
    same_file "show of merged streams vs the single run" "$tmp/all.csv" "$tmp/out"
cut -d, -f7 "$tmp/out" >"$tmp/exact-show.csv"
cut -d, -f7 "$tmp/all.csv" >"$tmp/exact-run.csv"
if [ "$(head -n 1 "$tmp/exact-show.csv")" = exact ] && [ "$(grep -c . "$tmp/exact-show.csv")" -eq 14 ]
then same_file "the exact column of show vs the single run" "$tmp/exact-run.csv" "$tmp/exact-show.csv"
else bad "show of merged streams: no exact column: $(head -n 1 "$tmp/out")"; fi

# The refusals: exit 2, one line, nothing written or changed.
cp "$pv/s0.rec" "$pv/copy0.rec"
m() { "$MCSPEC" merge "$@" -o "$tmp/keep"; }
refused_kept "merge: the same stream twice" \
    "^mcspec merge: $pv/s0.rec and $pv/copy0.rec both hold stream 0 of seed 9: its trials would count twice$" \
    m "$pv/s0.rec" "$pv/copy0.rec"
refused_kept "merge: overlapping streams" "m01.rec and .*/s1.rec both hold stream 1 of seed 9" \
    m "$pv/m01.rec" "$pv/s1.rec" "$pv/s2.rec"
refused_kept "merge: the same file twice" "^mcspec merge: $pv/s1.rec is given twice: its trials would count twice$" \
    m "$pv/s1.rec" "$pv/s2.rec" "$pv/s1.rec"
"$MCSPEC" pattern jitter --n 24 --k 5 --trials 23 --seed 9 --streams 4 --stream 1 --save "$pv/jitter1.rec" >/dev/null
refused_kept "merge: another pattern" "jitter1.rec holds trials of jitter, .*s0.rec of stratified: different patterns" \
    m "$pv/s0.rec" "$pv/jitter1.rec"
"$MCSPEC" pattern stratified --n 24 --k 4 --trials 23 --seed 9 --streams 4 --stream 1 --save "$pv/k4.rec" >/dev/null
refused_kept "merge: another K" "k4.rec holds trials of N = 24, K = 4, .*s0.rec of N = 24, K = 5: different patterns" \
    m "$pv/s0.rec" "$pv/k4.rec"
awk 'BEGIN { for (i = 1; i <= 24; ++i) print 1 + (i % 3) }' >"$pv/g.txt"
awk 'BEGIN { for (i = 1; i <= 24; ++i) print 1 + (i % 4) }' >"$pv/g2.txt"
run4 --stream 1 --importance "$pv/g.txt" --save "$pv/imp1.rec" >/dev/null
run4 --stream 0 --importance "$pv/g2.txt" --save "$pv/imp0-g2.rec" >/dev/null
refused_kept "merge: with and without an importance function" \
    "imp1.rec was drawn with an importance function, .*s0.rec without" m "$pv/s0.rec" "$pv/imp1.rec"
refused_kept "merge: another importance function" \
    "imp1.rec and .*imp0-g2.rec were drawn with different importance functions \(weights CRC-32 0x[0-9a-f]{8} and 0x[0-9a-f]{8}\)" \
    m "$pv/imp0-g2.rec" "$pv/imp1.rec"
"$MCSPEC" pattern stratified --n 24 --k 5 --trials 23 --seed 8 --streams 4 --stream 1 --save "$pv/seed8.rec" >/dev/null
refused_kept "merge: another seed" "seed8.rec is of seed 8, .*s0.rec of seed 9: different runs, cannot merge \(--mix-seeds" \
    m "$pv/s0.rec" "$pv/seed8.rec"
"$MCSPEC" pattern stratified --n 24 --k 5 --trials 23 --seed 9 --streams 3 --stream 1 --save "$pv/p3.rec" >/dev/null
refused_kept "merge: another P" "p3.rec is of a run split into 3 streams, .*s0.rec into 4: different runs" \
    m "$pv/s0.rec" "$pv/p3.rec"
"$MCSPEC" pattern stratified --n 24 --k 5 --trials 24 --seed 9 --streams 4 --stream 1 --save "$pv/t24.rec" >/dev/null
refused_kept "merge: another T" "t24.rec is of a run of 24 trials, .*s0.rec of 23: different runs" \
    m "$pv/s0.rec" "$pv/t24.rec"
"$MCSPEC" spectrum --n 24 --save "$pv/pts-a.rec" "$GOLDEN/comb_k8_n64.txt" >/dev/null
"$MCSPEC" spectrum --n 24 --save "$pv/pts-b.rec" - <"$GOLDEN/comb_k8_n64.txt" >/dev/null
refused_kept "merge: the same point file twice" \
    "pts-a.rec and .*pts-b.rec both hold the point sets of <stdin> \(CRC-32 0x[0-9a-f]{8}\): they would count twice" \
    m "$pv/pts-a.rec" "$pv/pts-b.rec"
refused_kept "merge: points and a pattern" "s0.rec holds trials drawn from a pattern, .*pts-a.rec point sets read from files" \
    m "$pv/pts-a.rec" "$pv/s0.rec"
refused_kept "merge: -o an input" "^mcspec merge: OUT $pv/s1.rec is the input $pv/s1.rec: write the merge to another file$" \
    "$MCSPEC" merge "$pv/s0.rec" "$pv/s1.rec" -o "$pv/s1.rec"
refused_kept "merge: -o an input, twice" "OUT $pv/s0.rec is the input $pv/s0.rec" \
    "$MCSPEC" merge "$pv/s0.rec" "$pv/s0.rec" -o "$pv/s0.rec"
ln "$pv/s2.rec" "$pv/hard2.rec"
refused_kept "merge: -o a hard link to an input" "OUT $pv/hard2.rec is the input $pv/s2.rec \(the same file\)" \
    "$MCSPEC" merge "$pv/s0.rec" "$pv/s2.rec" -o "$pv/hard2.rec"
ln -s "$pv/s3.rec" "$pv/link3.rec"
refused_kept "merge: an input linking to OUT" "OUT $pv/s3.rec is the input $pv/link3.rec \(the same file\)" \
    "$MCSPEC" merge "$pv/s0.rec" "$pv/link3.rec" -o "$pv/s3.rec"
refused_kept "merge: an input and a link to it" "s3.rec is given twice \(the same file as .*link3.rec\)" \
    m "$pv/link3.rec" "$pv/s3.rec"

# A version 1 record among version 2 ones: merged with the note, OUT without
# provenance; the ones that have a provenance are still checked.
"$MCSPEC" pattern stratified --n 16 --k 3 --trials 9 --seed 2 --save "$pv/n16.rec" >/dev/null
cp "$pv/n16.rec" "$pv/n16-copy.rec"
run "$MCSPEC" merge "$pv/n16.rec" "$CORPUS/spectrum-n16-t20.rec" -o "$tmp/old-and-new.rec"
if [ "$rc" -eq 0 ] && [ "$(wc -l <"$tmp/err")" -eq 1 ] &&
    grep -q "^mcspec merge: note: .*spectrum-n16-t20.rec is a version 1 record, with no provenance" "$tmp/err" &&
    [ "$(od -An -tu1 -j8 -N1 "$tmp/old-and-new.rec" | tr -d ' ')" = 1 ]
then ok; else bad "merge of a version 1 and a version 2 record: exit $rc, '$(cat "$tmp/err")'"; fi
refused_kept "merge: the same stream twice beside a version 1 record" "n16.rec and .*n16-copy.rec both hold stream 0 of seed 2" \
    m "$pv/n16.rec" "$CORPUS/spectrum-n16-t20.rec" "$pv/n16-copy.rec"

# --mix-seeds: another seed of the same run adds its streams.
succeeds "merge --mix-seeds" "$MCSPEC" merge "$pv/s0.rec" "$pv/seed8.rec" --mix-seeds -o "$tmp/seeds.rec"
"$MCSPEC" show "$tmp/seeds.rec" | sed -n 2p |
    grep -q 'seed 8: stream 1 of 4 (trials 6..11 of 23); seed 9: stream 0 of 4 (trials 0..5 of 23)$' && ok ||
    bad "merge --mix-seeds: '$("$MCSPEC" show "$tmp/seeds.rec" | sed -n 2p)'"
refused "merge of a mixed record without --mix-seeds" "seeds.rec holds runs of several seeds: give --mix-seeds" \
    m "$tmp/seeds.rec" "$pv/s1.rec"

# show with an importance function: given again, its checksum checked.
for i in 0 2 3; do run4 --stream "$i" --importance "$pv/g.txt" --save "$pv/imp$i.rec" >/dev/null; done
run4 --importance "$pv/g.txt" --csv >"$tmp/imp.csv"
succeeds "merge of importance streams" "$MCSPEC" merge "$pv/imp3.rec" "$pv/imp1.rec" "$pv/imp0.rec" \
    "$pv/imp2.rec" -o "$tmp/imp.rec"
succeeds "show --importance" "$MCSPEC" show "$tmp/imp.rec" --importance "$pv/g.txt" --csv &&
    same_file "show --importance of merged streams vs the single run" "$tmp/imp.csv" "$tmp/out"
succeeds "show without --importance" "$MCSPEC" show "$tmp/imp.rec" --csv &&
    { [ "$(head -n 1 "$tmp/out")" = freq,mean_re,mean_im,mean_stderr,power,power_stderr ] && ok ||
      bad "show without --importance: header $(head -n 1 "$tmp/out")"; }
"$MCSPEC" show "$tmp/imp.rec" | sed -n 3p | grep -q '^exact, closed: give --importance WEIGHTS' && ok ||
    bad "show without --importance: no note saying how to get the predictions"
refused "show --importance of other weights" \
    "^mcspec show: $pv/g2.txt is not the importance function $tmp/imp.rec was drawn with \(its weights' CRC-32 is 0x[0-9a-f]{8}, the record's 0x[0-9a-f]{8}\)$" \
    "$MCSPEC" show "$tmp/imp.rec" --importance "$pv/g2.txt"
refused "show --importance of a record without one" "s0.rec was drawn without an importance function: drop --importance" \
    "$MCSPEC" show "$pv/s0.rec" --importance "$pv/g.txt"
refused "show --importance of a point-set record" "pts-a.rec holds no pattern run: --importance is for records of mcspec pattern" \
    "$MCSPEC" show "$pv/pts-a.rec" --importance "$pv/g.txt"

check_summary
