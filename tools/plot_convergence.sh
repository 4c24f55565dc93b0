#!/bin/sh
# Renders question 6 of examples/sec5_open_questions: the exact Var[I]
# against K on log-log axes (lines) with the measured values and their
# standard errors (points), for the smooth integrand fs and the one with an
# edge fe, one colour per pattern.
#   tools/plot_convergence.sh SEC5_BINARY OUT.png|OUT.svg
set -eu
bin=$1
out=$2
command -v gnuplot >/dev/null 2>&1 || { echo "plot_convergence: gnuplot not on PATH" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$bin" --convergence-csv "$tmp/conv.csv" >/dev/null
for f in fs fe; do
    for p in random stratified jitter homogenized; do
        awk -F, -v f="$f" -v p="$p" 'NR > 1 && $1 == f && $2 == p { print $4, $5, $6, $7 }' \
            "$tmp/conv.csv" >"$tmp/$f-$p.dat"
    done
done
n=$(awk -F, 'NR == 2 { print $3 }' "$tmp/conv.csv")
case "$out" in
*.svg) term="svg size 1100,520 dynamic font 'Sans,11'" ;;
*) term="pngcairo size 1100,520 font 'Sans,10'" ;;
esac
cat >"$tmp/plot.gp" <<GP
set terminal $term
set output '$tmp/out'
set multiplot layout 1,2 title "Question 6: exact Var[I] against K (lines), measured with 1 standard error (points); N = $n bins"
set logscale xy
set format y '10^{%L}'
set xlabel 'samples per trial K'
set ylabel 'Var[I]'
set key bottom left
kinds = "random stratified jitter homogenized"
set xrange [1.5:200]
set grid
do for [f in "fs fe"] {
  set title (f eq "fs" ? "fs: smooth, not periodic (random K^{-1}, stratified K^{-3})" : "fe: with an edge (random K^{-1}, stratified K^{-2})")
  plot for [i=1:4] '$tmp/'.f.'-'.word(kinds, i).'.dat' using 1:2 with lines lw 2 lc i title word(kinds, i).' exact', \
       for [i=1:4] '$tmp/'.f.'-'.word(kinds, i).'.dat' using 1:3:4 with yerrorbars pt 7 ps 0.6 lc i title word(kinds, i).' measured ± 1 s.e.'
}
unset multiplot
GP
gnuplot "$tmp/plot.gp"
mv "$tmp/out" "$out"
