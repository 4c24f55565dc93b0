#!/bin/sh
# Checks of the peers' conventions in mcspec spectrum (issue 24): the default
# F, annuli of width W, the normalised columns, psa's files, --dims and the
# PFM image.
#
# usage: sh test/spectrum_check.sh   ($MCSPEC names the binary, default
#                                     build/bin/mcspec; $PYTHON a python3
#                                     with numpy, default /usr/bin/python3)
#
#   the default F: ceil(5 sqrt(K_max)) for K = 1, 2, 1024, 16384 (5, 8, 160,
#   640), said on the table's F line, and the rows it gives; --freq auto the
#   same in 1D; the explicit F unchanged;
#   annuli of width W = 1, 2, 3 against a numpy reference that forms every
#   set's periodogram by the direct sum, its annulus averages, their mean and
#   standard error over the sets and psa's anisotropy of the mean (skipped
#   without numpy), to 1e-9 relative; W = 1 given equals W = 1 by default;
#   --norm: the appended columns are frequency / sqrt(K);
#   psa's files: three files give the bytes of one utk file of the same sets;
#   --save of them records three inputs and shows the same rows;
#   --dims 0,2 of a 3D file gives the bytes of the 2D file of those columns,
#   --dims 1 the bytes of the 1D file;
#   --pfm: the header, the size, and every pixel equal as float32 to the
#   CSV's power (numpy; an od check without it), DC included;
#   every bad value: exit 2, one line on stderr, nothing on stdout.
# Ends with a Unity-style summary so test/run_tests.sh counts it.

MCSPEC=${MCSPEC:-build/bin/mcspec}
PYTHON=${PYTHON:-/usr/bin/python3}

# shellcheck source=test/support/check.sh
. "$(dirname "$0")/support/check.sh"
check_start spectrum_check

if [ ! -x "$MCSPEC" ]; then
    bad "$MCSPEC is not an executable (make cli)"
    check_summary
    exit 1
fi
have_numpy=0
"$PYTHON" -c 'import numpy' 2>/dev/null && have_numpy=1

# points SEED SETS K DIM [psa]: SETS sets of K uniform points of DIM
# coordinates from awk's generator, utk's '#' between sets (or, with psa,
# one set only, its count first).
points() {
    awk -v seed="$1" -v sets="$2" -v k="$3" -v dim="$4" -v psa="${5:-}" 'BEGIN {
        srand(seed)
        for (s = 0; s < sets; ++s) {
            if (psa != "") print k
            for (j = 0; j < k; ++j) {
                line = ""
                for (d = 0; d < dim; ++d) line = line (d ? " " : "") sprintf("%.17g", rand())
                print line
            }
            if (psa == "" && s + 1 < sets) print "#"
        } }'
}

# ---- the default F ------------------------------------------------------------
for kf in 1:5 2:8 1024:160 16384:640; do
    k=${kf%%:*} f=${kf##*:}
    points 7 1 "$k" 2 >"$tmp/k$k.txt"
    if succeeds "default F for K = $k" "$MCSPEC" spectrum --dim 2 --radial "$tmp/k$k.txt"; then
        if grep -q "^F = $f: the default of utk and psa, ceil(5 sqrt(K)) = $f for K = $k" "$tmp/out"; then ok
        else bad "default F for K = $k: F line '$(sed -n 2p "$tmp/out")', expected F = $f"; fi
    fi
    if [ "$k" -le 1024 ] && succeeds "default F for K = $k, CSV" "$MCSPEC" spectrum --dim 2 --radial --csv "$tmp/k$k.txt"; then
        rows=$(($(wc -l <"$tmp/out") - 1))
        [ "$rows" -eq $((f + 1)) ] && ok || bad "default F for K = $k: $rows annuli, expected $((f + 1))"
    fi
done
# The largest K of the sets decides; --freq auto in 1D the same rule.
{ points 3 1 4 2; echo "#"; points 4 1 100 2; } >"$tmp/mixed.txt"
succeeds "default F of mixed sets" "$MCSPEC" spectrum --dim 2 --radial "$tmp/mixed.txt" &&
    { grep -q '^F = 50: .* = 50 for K = 100' "$tmp/out" && ok || bad "mixed sets: $(sed -n 2p "$tmp/out")"; }
points 5 2 100 1 >"$tmp/one.txt"
if succeeds "--freq auto in 1D" "$MCSPEC" spectrum --freq auto --csv "$tmp/one.txt"; then
    [ "$(($(wc -l <"$tmp/out") - 1))" -eq 51 ] && ok || bad "--freq auto in 1D: not 51 rows"
fi
# Standard input is read twice for the default F.
cp "$tmp/k1024.txt" "$tmp/in"
run "$MCSPEC" spectrum --dim 2 --radial --csv -
cp "$tmp/out" "$tmp/stdin.csv"
: >"$tmp/in"
succeeds "default F from a file" "$MCSPEC" spectrum --dim 2 --radial --csv "$tmp/k1024.txt" &&
    { cmp -s "$tmp/out" "$tmp/stdin.csv" && ok || bad "default F: standard input differs from the file"; }

# ---- annuli of width W against numpy ------------------------------------------
points 11 20 64 2 >"$tmp/w.txt"
for w in 1 2 3; do
    if ! succeeds "--bin-width $w" "$MCSPEC" spectrum --dim 2 --freq 12 --radial --bin-width "$w" --csv "$tmp/w.txt"; then
        continue
    fi
    cp "$tmp/out" "$tmp/w$w.csv"
    nb=$(((12 + 1) / w))
    [ "$(($(wc -l <"$tmp/w$w.csv") - 1))" -eq "$nb" ] && ok || bad "--bin-width $w: not $nb annuli"
    if [ "$have_numpy" = 1 ]; then
        problems=$("$PYTHON" - "$tmp/w.txt" "$tmp/w$w.csv" "$w" 12 <<'EOF'
import sys, numpy as np
sets, cur = [], []
for line in open(sys.argv[1]):
    if line.startswith('#'):
        sets.append(np.array(cur)); cur = []
    elif line.strip():
        cur.append([float(t) for t in line.split()])
sets.append(np.array(cur))
W, F = int(sys.argv[3]), int(sys.argv[4])
k = np.arange(-F, F + 1)
kx, ky = np.meshgrid(k, k)
s2 = kx * kx + ky * ky
r = np.floor(np.sqrt(s2)).astype(int)
while (r * r > s2).any(): r[r * r > s2] -= 1
while (((r + 1) ** 2) <= s2).any(): r[((r + 1) ** 2) <= s2] += 1
P = []
for x in sets:
    ph = np.exp(-2j * np.pi * (np.multiply.outer(kx, x[:, 0]) + np.multiply.outer(ky, x[:, 1])))
    P.append(np.abs(ph.sum(axis=2)) ** 2 / len(x))
P = np.array(P)
rows = [l.strip().split(',') for l in open(sys.argv[2])][1:]
bad = []
for b in range((F + 1) // W):
    m = (r >= b * W) & (r < (b + 1) * W)
    per = P[:, m].mean(axis=1)
    mean, se = per.mean(), per.std(ddof=1) / np.sqrt(len(per))
    Pm = P.mean(axis=0)[m]
    var = Pm.var(ddof=1) if m.sum() > 1 else 0.0
    db = 10 * np.log10(var / Pm.mean() ** 2) if var > 0 else None
    got = rows[b]
    if int(got[0]) != b * W: bad.append('radius %s' % got[0])
    for name, want, g in (('power', mean, got[1]), ('stderr', se, got[2])):
        if abs(float(g) - want) > 1e-9 * max(abs(want), 1e-300): bad.append('%s %d: %s vs %r' % (name, b, g, want))
    if db is None:
        if got[3] != '': bad.append('anisotropy %d: %s, none expected' % (b, got[3]))
    elif got[3] == '' or abs(float(got[3]) - db) > 1e-9 * abs(db):
        bad.append('anisotropy %d: %s vs %r' % (b, got[3], db))
print('; '.join(bad))
EOF
)
        [ -z "$problems" ] && ok || bad "--bin-width $w against numpy: $problems"
    fi
done
[ "$have_numpy" = 1 ] || skip "--bin-width against numpy (no numpy at $PYTHON)"
succeeds "--bin-width by default" "$MCSPEC" spectrum --dim 2 --freq 12 --radial --csv "$tmp/w.txt" &&
    { cmp -s "$tmp/out" "$tmp/w1.csv" && ok || bad "--bin-width 1 differs from the default"; }
# A wider annulus has a smaller standard error than its unit annuli's (it averages more).
awk -F, 'NR == FNR { if (FNR > 1) s1[$1] = $3; next } FNR > 1 && $1 >= 4 && !($3 < s1[$1]) { print "r=" $1 }' \
    "$tmp/w1.csv" "$tmp/w3.csv" >"$tmp/se.txt"
[ -s "$tmp/se.txt" ] && bad "--bin-width 3: standard errors not below width 1's at $(tr '\n' ' ' <"$tmp/se.txt")" || ok

# ---- --norm -------------------------------------------------------------------
if succeeds "--norm radial" "$MCSPEC" spectrum --dim 2 --freq 12 --radial --bin-width 2 --norm --csv "$tmp/w.txt"; then
    [ "$(head -n 1 "$tmp/out")" = "radius,power,power_stderr,anisotropy_db,radius_norm" ] && ok ||
        bad "--norm radial header: $(head -n 1 "$tmp/out")"
    cut -d, -f1-4 "$tmp/out" | tail -n +2 >"$tmp/a"; tail -n +2 "$tmp/w2.csv" >"$tmp/b"
    cmp -s "$tmp/a" "$tmp/b" && ok || bad "--norm changed the columns before it"
    problems=$(tail -n +2 "$tmp/out" | awk -F, '{ d = $5 - $1 / 8; if (d < 0) d = -d; if (d > 1e-15) print $1 }')
    [ -z "$problems" ] && ok || bad "--norm: radius / sqrt(64) wrong at $problems"
fi
if succeeds "--norm 2D" "$MCSPEC" spectrum --dim 2 --freq 2 --norm --csv "$tmp/w.txt"; then
    [ "$(head -n 1 "$tmp/out")" = "kx,ky,power,power_stderr,kx_norm,ky_norm" ] && ok || bad "--norm 2D header"
    problems=$(tail -n +2 "$tmp/out" | awk -F, '$5 != $1 / 8 || $6 != $2 / 8 { print $1 "," $2 }')
    [ -z "$problems" ] && ok || bad "--norm 2D values at $problems"
fi
succeeds "--norm 1D" "$MCSPEC" spectrum --freq 4 --norm --csv "$tmp/one.txt" &&
    { [ "$(head -n 1 "$tmp/out")" = "freq,power,power_stderr,freq_norm" ] && [ "$(sed -n 3p "$tmp/out" | cut -d, -f4)" = 0.10000000000000001 ] && ok ||
        bad "--norm 1D: $(head -n 3 "$tmp/out" | tr '\n' ' ')"; }

# ---- psa's files --------------------------------------------------------------
for i in 0 1 2; do points $((20 + i)) 1 50 2 psa >"$tmp/psa$i.txt"; tail -n +2 "$tmp/psa$i.txt" >"$tmp/utk$i.txt"; done
{ cat "$tmp/utk0.txt"; echo "#"; cat "$tmp/utk1.txt"; echo "#"; cat "$tmp/utk2.txt"; } >"$tmp/utk.txt"
succeeds "utk file of the three sets" "$MCSPEC" spectrum --dim 2 --radial --bin-width 2 --csv "$tmp/utk.txt" && cp "$tmp/out" "$tmp/utk.csv"
if succeeds "three psa files" "$MCSPEC" spectrum --format psa --radial --bin-width 2 --csv \
    --save "$tmp/psa.rec" "$tmp/psa0.txt" "$tmp/psa1.txt" "$tmp/psa2.txt"; then
    cmp -s "$tmp/out" "$tmp/utk.csv" && ok || bad "three psa files differ from the utk file of their sets"
    succeeds "show of the psa record" "$MCSPEC" show "$tmp/psa.rec" &&
        { grep -q '3 inputs' "$tmp/out" && ok || bad "the psa record's provenance: $(grep -i input "$tmp/out" | head -n 1)"; }
fi
succeeds "several utk files" "$MCSPEC" spectrum --dim 2 --radial --bin-width 2 --csv "$tmp/utk0.txt" "$tmp/utk1.txt" "$tmp/utk2.txt" &&
    { cmp -s "$tmp/out" "$tmp/utk.csv" && ok || bad "three utk files differ from their concatenation"; }
printf '3\n0.1 0.2\n0.3 0.4\n' >"$tmp/short.psa"
usage_error "psa: fewer points than the count" 'short.psa: line 3: the file ends after 2 of the 3 points line 1 announces' \
    "$MCSPEC" spectrum --format psa "$tmp/short.psa"
printf '1\n0.1 0.2\n0.3 0.4\n' >"$tmp/long.psa"
usage_error "psa: more points than the count" 'long.psa: line 3: more points than the 1 of line 1' "$MCSPEC" spectrum --format psa "$tmp/long.psa"
printf '0.1 0.2\n' >"$tmp/nocount.psa"
usage_error "psa: no count line" 'line 1: a psa file starts with its point count' "$MCSPEC" spectrum --format psa "$tmp/nocount.psa"
printf '0\n' >"$tmp/zero.psa"
usage_error "psa: count 0" 'line 1: a psa file starts with its point count' "$MCSPEC" spectrum --format psa "$tmp/zero.psa"
printf '1\n#\n0.1 0.2\n' >"$tmp/hash.psa"
usage_error "psa: a '#' line" "line 2: a '#' line" "$MCSPEC" spectrum --format psa "$tmp/hash.psa"
printf '1\n0.1 1.5\n' >"$tmp/out1.psa"
usage_error "psa: a point outside" 'line 2: coordinate 1.5 is outside' "$MCSPEC" spectrum --format psa "$tmp/out1.psa"
: >"$tmp/empty.psa"
usage_error "psa: empty file" 'empty.psa: the input is empty' "$MCSPEC" spectrum --format psa "$tmp/empty.psa"
usage_error "psa: second file bad" 'short.psa: line 3' "$MCSPEC" spectrum --format psa "$tmp/psa0.txt" "$tmp/short.psa"
# Malformed point lines of a psa file: the point handling utk's reader shares.
printf '2\n0.1 0.2\n0.3 x\n' >"$tmp/nan.psa"
usage_error "psa: a coordinate not a number" "^mcspec spectrum: $tmp/nan.psa: line 3: coordinate 'x' is not a number\$" \
    "$MCSPEC" spectrum --format psa "$tmp/nan.psa"
printf '2\n0.1 0.2\n0.3 0.4 0.5\n' >"$tmp/cols.psa"
usage_error "psa: a third column" "^mcspec spectrum: $tmp/cols.psa: line 3: expected 2 columns, found 3 \\(a weight column needs --weights\\)\$" \
    "$MCSPEC" spectrum --format psa "$tmp/cols.psa"
usage_error "psa --dims: a point wider than the first" "^mcspec spectrum: $tmp/cols.psa: line 3: expected 2 columns, found 3 \\(every point has as many coordinates as the first\\)\$" \
    "$MCSPEC" spectrum --format psa --dims 0,1 --freq 4 "$tmp/cols.psa"
awk 'BEGIN { print 1; for (i = 0; i < 65; ++i) printf "0.5 "; print "" }' >"$tmp/wide.psa"
usage_error "psa --dims: 65 columns" "^mcspec spectrum: $tmp/wide.psa: line 2: 65 columns: a point has 1 to 64 coordinates\$" \
    "$MCSPEC" spectrum --format psa --dims 0,1 --freq 4 "$tmp/wide.psa"
printf '\n \n' >"$tmp/blank.psa"
usage_error "psa: only blank lines" "^mcspec spectrum: $tmp/blank.psa: no count line, only blank lines \\(a psa file starts with its point count\\)\$" \
    "$MCSPEC" spectrum --format psa "$tmp/blank.psa"
usage_error "--format unknown" "--format expects utk or psa, not 'pbrt'" "$MCSPEC" spectrum --format pbrt "$tmp/psa0.txt"
usage_error "--format psa binned" '--format psa is for point sets' "$MCSPEC" spectrum --format psa --dim 1 "$tmp/psa0.txt"

# ---- --dims -------------------------------------------------------------------
points 31 4 40 3 >"$tmp/p3.txt"
awk '/^#/ { print; next } { print $1, $3 }' "$tmp/p3.txt" >"$tmp/p13.txt"
awk '/^#/ { print; next } { print $2 }' "$tmp/p3.txt" >"$tmp/p2.txt"
succeeds "2D file of x and z" "$MCSPEC" spectrum --dim 2 --freq 6 --csv "$tmp/p13.txt" && cp "$tmp/out" "$tmp/p13.csv"
succeeds "--dims 0,2 of a 3D file" "$MCSPEC" spectrum --dims 0,2 --freq 6 --csv "$tmp/p3.txt" &&
    { cmp -s "$tmp/out" "$tmp/p13.csv" && ok || bad "--dims 0,2 differs from the 2D file of x and z"; }
succeeds "--dims 0,2 --dim 2" "$MCSPEC" spectrum --dim 2 --dims 0,2 --freq 6 --csv "$tmp/p3.txt" &&
    { cmp -s "$tmp/out" "$tmp/p13.csv" && ok || bad "--dim 2 --dims 0,2 differs"; }
succeeds "1D file of y" "$MCSPEC" spectrum --freq 9 --csv "$tmp/p2.txt" && cp "$tmp/out" "$tmp/p2.csv"
succeeds "--dims 1 of a 3D file" "$MCSPEC" spectrum --dims 1 --freq 9 --csv "$tmp/p3.txt" &&
    { cmp -s "$tmp/out" "$tmp/p2.csv" && ok || bad "--dims 1 differs from the 1D file of y"; }
succeeds "--dims 0,2, default F" "$MCSPEC" spectrum --dims 0,2 --radial "$tmp/p3.txt" &&
    { grep -q '^F = 32: ' "$tmp/out" && ok || bad "--dims 0,2: default F line $(sed -n 2p "$tmp/out")"; }
usage_error "--dims past the file" '--dims names coordinate 3 .*have 3 coordinates' "$MCSPEC" spectrum --dims 0,3 --freq 2 "$tmp/p3.txt"
usage_error "--dims twice the same" '--dims 1,1 names coordinate 1 twice' "$MCSPEC" spectrum --dims 1,1 --freq 2 "$tmp/p3.txt"
usage_error "--dims x" "--dims expects one coordinate index or two" "$MCSPEC" spectrum --dims x --freq 2 "$tmp/p3.txt"
usage_error "--dims three" "--dims expects one coordinate index or two.*not '0,1,2'" "$MCSPEC" spectrum --dims 0,1,2 --freq 2 "$tmp/p3.txt"
usage_error "--dims 64" "--dims expects .* 0 to 63" "$MCSPEC" spectrum --dims 64 --freq 2 "$tmp/p3.txt"
usage_error "--dims -1" "--dims expects" "$MCSPEC" spectrum --dims -1,2 --freq 2 "$tmp/p3.txt"
usage_error "--dims empty" "--dims (needs a value|expects)" "$MCSPEC" spectrum --dims '' --freq 2 "$tmp/p3.txt"
usage_error "--dims 0, (no second)" "--dims expects" "$MCSPEC" spectrum --dims 0, --freq 2 "$tmp/p3.txt"
usage_error "--dims against --dim" '--dims 0,2 reads 2 coordinates but --dim is 1' "$MCSPEC" spectrum --dim 1 --dims 0,2 --freq 2 "$tmp/p3.txt"
usage_error "--dims 1 binned" '--dims 1 \(1D\) needs --freq' "$MCSPEC" spectrum --dims 1 "$tmp/p3.txt"

# ---- --pfm -------------------------------------------------------------------
if succeeds "--pfm" "$MCSPEC" spectrum --dim 2 --freq 12 --csv --pfm "$tmp/w.pfm" "$tmp/w.txt"; then
    cp "$tmp/out" "$tmp/plane.csv"
    [ "$(head -c 14 "$tmp/w.pfm" | od -An -c | tr -d ' \n')" = 'Pf\n2525\n-1.0\n' ] && ok ||
        bad "--pfm header: $(head -c 14 "$tmp/w.pfm" | od -An -c)"
    [ "$(wc -c <"$tmp/w.pfm")" -eq $((14 + 4 * 25 * 25)) ] && ok || bad "--pfm: $(wc -c <"$tmp/w.pfm") bytes, not 14 + 4 x 625"
    if [ "$have_numpy" = 1 ]; then
        problems=$("$PYTHON" - "$tmp/w.pfm" "$tmp/plane.csv" <<'EOF'
import sys, numpy as np
raw = open(sys.argv[1], 'rb').read()
parts = raw.split(b'\n', 3)
w, h = map(int, parts[1].split()); scale = float(parts[2])
img = np.frombuffer(parts[3], dtype='<f4' if scale < 0 else '>f4').reshape(h, w)
rows = np.loadtxt(sys.argv[2], delimiter=',', skiprows=1)
F = (w - 1) // 2
bad = []
for kx, ky, p in rows[:, :3]:
    # PFM: the first scan line is the bottom one, ky = -F.
    v = img[int(ky) + F, int(kx) + F]
    if v != np.float32(p): bad.append('(%d,%d): %r vs %r' % (kx, ky, v, p))
if scale != -1.0 or w != h: bad.append('scale %r, %d x %d' % (scale, w, h))
if len(rows) != w * h: bad.append('%d rows for %d pixels' % (len(rows), w * h))
print('; '.join(bad[:5]))
EOF
)
        [ -z "$problems" ] && ok || bad "--pfm read back: $problems"
    else
        skip "--pfm read back (no numpy at $PYTHON)"
    fi
fi
succeeds "--pfm with --radial" "$MCSPEC" spectrum --dim 2 --freq 12 --radial --csv --pfm "$tmp/w2.pfm" "$tmp/w.txt" &&
    { cmp -s "$tmp/w.pfm" "$tmp/w2.pfm" && ok || bad "--pfm with --radial differs from without"; }
usage_error "--pfm in 1D" '--pfm needs --dim 2' "$MCSPEC" spectrum --freq 4 --pfm "$tmp/x.pfm" "$tmp/one.txt"
usage_error "--pfm binned" '--pfm is for point sets' "$MCSPEC" spectrum --pfm "$tmp/x.pfm" "$tmp/one.txt"
usage_error "--pfm onto a directory" "directory" "$MCSPEC" spectrum --dim 2 --freq 2 --pfm "$tmp" "$tmp/w.txt"
usage_error "--pfm without a value" '--pfm needs a value' "$MCSPEC" spectrum --dim 2 --freq 2 --pfm

# ---- the fast path against the direct sum and the theory (issue 24's "done when", scaled down) ----
# 16 sets of 256 points at the default F = 80: AUTO (the NUFFT here)
# against --path direct at every wave vector and annulus, to 1e-9 max(P, 1);
# random points against <P> = 1 and jittered 16 x 16 against the closed form
# (mcspec pattern's exact column), within 5 standard errors.
points 41 16 256 2 >"$tmp/r16.txt"
awk 'BEGIN { srand(43); for (s = 0; s < 16; ++s) { for (j = 0; j < 16; ++j) for (i = 0; i < 16; ++i)
        printf "%.17g %.17g\n", (i + rand()) / 16, (j + rand()) / 16; if (s < 15) print "#" } }' >"$tmp/j16.txt"
# within LABEL A.csv B.csv FIRST: every value column from FIRST on within 1e-9 max(|B|, 1).
within() {
    problems=$(awk -F, -v first="$4" 'NR == FNR { a[FNR] = $0; next } FNR > 1 {
        n = split(a[FNR], x, ",")
        for (i = first; i <= NF; ++i) { if (x[i] == "" && $i == "") continue
            d = x[i] - $i; d = d < 0 ? -d : d; s = $i < 0 ? -$i : $i; s = s > 1 ? s : 1
            if (x[i] == "" || $i == "" || d > 1e-9 * s) { print FNR ": " a[FNR] " vs " $0; exit } } }' "$2" "$3")
    [ -z "$problems" ] && ok || bad "$1: $problems"
}
for kind in r16 j16; do
    for layout in --radial ""; do
        t=$kind-plane first=3
        [ -n "$layout" ] && t=$kind first=2
        # shellcheck disable=SC2086
        succeeds "$kind $layout AUTO" "$MCSPEC" spectrum --dim 2 $layout --csv "$tmp/$kind.txt" && cp "$tmp/out" "$tmp/$t-auto.csv"
        # shellcheck disable=SC2086
        succeeds "$kind $layout direct" "$MCSPEC" spectrum --dim 2 $layout --path direct --csv "$tmp/$kind.txt" && cp "$tmp/out" "$tmp/$t-direct.csv"
        [ "$(wc -l <"$tmp/$t-auto.csv")" -eq "$(wc -l <"$tmp/$t-direct.csv")" ] && ok || bad "$kind $layout: row counts differ"
        within "$kind $layout: AUTO against --path direct" "$tmp/$t-auto.csv" "$tmp/$t-direct.csv" "$first"
    done
done
succeeds "--path nufft" "$MCSPEC" spectrum --dim 2 --radial --path nufft --csv "$tmp/r16.txt" &&
    within "--path nufft against --path direct" "$tmp/out" "$tmp/r16-direct.csv" 2
grep -q 'F = 80: the default' "$tmp/j16-auto.csv" && bad "CSV with a note line" || ok
problems=$(awk -F, 'FNR > 2 { z = ($2 - 1) / $3; if (z < 0) z = -z; if (z > 5) print "r=" $1 " z=" z }' "$tmp/r16-auto.csv")
[ -z "$problems" ] && ok || bad "random: radial averages against <P> = 1: $problems"
if succeeds "jittered exact" "$MCSPEC" pattern jittered --dim 2 --k 256 --freq 80 --radial --trials 2 --csv; then
    problems=$(cut -d, -f5 "$tmp/out" | paste -d, "$tmp/j16-auto.csv" - | awk -F, 'FNR > 2 {
        z = ($2 - $5) / $3; if (z < 0) z = -z; if ($5 == "" || z > 5) print "r=" $1 " z=" z }')
    [ -z "$problems" ] && ok || bad "jittered: radial averages against the closed form: $problems"
fi
usage_error "--path bogus" "--path expects auto, direct or nufft, not 'bogus'" "$MCSPEC" spectrum --dim 2 --path bogus "$tmp/w.txt"
usage_error "--path binned" "--path is for point sets" "$MCSPEC" spectrum --path direct "$tmp/one.txt"

# ---- bad values ---------------------------------------------------------------
usage_error "--bin-width 0" '--bin-width expects a whole number' "$MCSPEC" spectrum --dim 2 --radial --bin-width 0 "$tmp/w.txt"
usage_error "--bin-width x" "--bin-width expects a whole number.*not 'x'" "$MCSPEC" spectrum --dim 2 --radial --bin-width x "$tmp/w.txt"
usage_error "--bin-width -2" "--bin-width expects a whole number" "$MCSPEC" spectrum --dim 2 --radial --bin-width -2 "$tmp/w.txt"
usage_error "--bin-width too big" '--bin-width expects a whole number from 1 to 16385' "$MCSPEC" spectrum --dim 2 --radial --bin-width 16386 "$tmp/w.txt"
usage_error "--bin-width without --radial" '--bin-width needs --radial' "$MCSPEC" spectrum --dim 2 --bin-width 2 "$tmp/w.txt"
usage_error "--bin-width wider than F + 1" '--bin-width 14 is wider than the annuli up to F = 12 hold: give 1 to 13' \
    "$MCSPEC" spectrum --dim 2 --freq 12 --radial --bin-width 14 "$tmp/w.txt"
usage_error "--bin-width wider than the default F + 1" '--bin-width 42 is wider than the annuli up to F = 40 \(the default for K = 64\)' \
    "$MCSPEC" spectrum --dim 2 --radial --bin-width 42 "$tmp/w.txt"
succeeds "--bin-width F + 1" "$MCSPEC" spectrum --dim 2 --freq 12 --radial --bin-width 13 --csv "$tmp/w.txt" &&
    { [ "$(wc -l <"$tmp/out")" -eq 2 ] && ok || bad "--bin-width 13 at F = 12: not one annulus"; }
usage_error "--freq auto0" "--freq expects a whole number from 1 to 16384 for --dim 2.*not 'auto0'" "$MCSPEC" spectrum --dim 2 --freq auto0 "$tmp/w.txt"
usage_error "--norm binned" '--norm is for point sets' "$MCSPEC" spectrum --norm "$tmp/one.txt"
usage_error "--radial binned" '--radial needs --dim 2' "$MCSPEC" spectrum --radial "$tmp/one.txt"
usage_error "stdin among files" "standard input \('-'\) can only be read alone" "$MCSPEC" spectrum --dim 2 "$tmp/w.txt" -
usage_error "binned, two files" "unexpected argument .*several files need --freq F or --dim 2" "$MCSPEC" spectrum "$tmp/one.txt" "$tmp/one.txt"
set --
for i in 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17; do set -- "$@" "$tmp/psa0.txt"; done
usage_error "--save of 17 files" '--save records at most 16 input files' "$MCSPEC" spectrum --format psa --save "$tmp/x.rec" "$@"
succeeds "17 files without --save" "$MCSPEC" spectrum --format psa --radial --csv "$@"
usage_error "missing second file" "cannot read '$tmp/nope.txt'" "$MCSPEC" spectrum --dim 2 "$tmp/w.txt" "$tmp/nope.txt"

check_summary
