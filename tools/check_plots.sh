#!/bin/sh
# Renders the figures of docs/plots/figures.list with `mcspec ... --plot` and
# checks them (issue 13).
#
# usage: sh tools/check_plots.sh [-b MCSPEC] [-l LIST] [-o OUTDIR] [-r]
#   -b  the mcspec binary (default build/bin/mcspec)
#   -l  the figure list (default docs/plots/figures.list; its header says the format)
#   -o  where to render (default build/plots-check)
#   -r  render only: each figure as OUTDIR/NAME.png, no checks (`make plots`
#       uses it with -o docs/plots)
#
# Without -r each figure is rendered twice from the same seeded command, as
# OUTDIR/NAME.png and as its SVG twin OUTDIR/NAME.svg, and checked:
#   the PNG: PNG signature, IHDR chunk first, width x height as cli/plot.h's
#            CLI_PLOT_WIDTH x CLI_PLOT_HEIGHT;
#   the SVG: root <svg> element with that width and height; every legend
#            entry the list names, each with its data drawn (see svg_series),
#            which is what the PNG twin, from the same command, shows too;
#            the entry '<image>' stands for an image panel instead (an
#            embedded PNG, as gnuplot's `with image` writes it);
# and docs/plots/NAME.png, the copy README shows, must exist and pass the
# PNG checks too. Ends with a Unity-style summary ("N Tests F Failures 0
# Ignored", then OK or FAIL); exit status non-zero on failure.

bin=build/bin/mcspec
list=docs/plots/figures.list
out=build/plots-check
render_only=0
while getopts b:l:o:r opt; do
    case $opt in
    b) bin=$OPTARG ;;
    l) list=$OPTARG ;;
    o) out=$OPTARG ;;
    r) render_only=1 ;;
    *) echo "usage: sh tools/check_plots.sh [-b MCSPEC] [-l LIST] [-o OUTDIR] [-r]" >&2; exit 2 ;;
    esac
done

if [ ! -x "$bin" ]; then echo "check_plots: $bin is not an executable (make cli)" >&2; exit 2; fi
if [ ! -r "$list" ]; then echo "check_plots: cannot read $list" >&2; exit 2; fi
command -v gnuplot >/dev/null 2>&1 || {
    echo "check_plots: gnuplot is not installed (Debian: apt-get install gnuplot-nox)" >&2; exit 2; }
mkdir -p "$out" || exit 2

width=$(sed -n 's/^#define CLI_PLOT_WIDTH \([0-9][0-9]*\).*/\1/p' cli/plot.h)
height=$(sed -n 's/^#define CLI_PLOT_HEIGHT \([0-9][0-9]*\).*/\1/p' cli/plot.h)
[ -n "$width" ] && [ -n "$height" ] || { echo "check_plots: no size in cli/plot.h" >&2; exit 2; }

passed=0
failed=0
ok() { passed=$((passed + 1)); }
bad() { failed=$((failed + 1)); echo "FAIL $1"; }

trim() { printf '%s' "$1" | sed 's/^[[:space:]]*//; s/[[:space:]]*$//'; }

# "W H" from a PNG's IHDR (bytes 16..23, big-endian), or nothing if the
# signature and the first chunk are not a PNG's.
png_size() {
    sig=$(od -An -tx1 -N16 "$1" 2>/dev/null | tr -d ' \n')
    [ "$sig" = "89504e470d0a1a0a0000000d49484452" ] || return 0
    od -An -tu1 -j16 -N8 "$1" | tr -s ' \n' '  ' | awk '{
        printf "%d %d\n", (($1 * 256 + $2) * 256 + $3) * 256 + $4, (($5 * 256 + $6) * 256 + $7) * 256 + $8 }'
}

check_png() { # file label
    size=$(png_size "$1")
    if [ -z "$size" ]; then bad "$2: not a PNG file"
    elif [ "$size" != "$width $height" ]; then bad "$2: PNG is $size, expected $width $height"
    else ok; fi
}

# "W H" from the attributes of the SVG's root element.
svg_size() {
    tr '\n' ' ' <"$1" | sed -n 's/^[^<]*\(<?[^>]*>[^<]*\)*<svg\([^>]*\)>.*$/\2/p' |
        sed -n 's/.*[[:space:]]width="\([0-9.]*\)".*[[:space:]]height="\([0-9.]*\)".*/\1 \2/p'
}

# 0 if the SVG has a legend entry with this text and draws its data: the
# series' plot group (gnuplot's <g id="gnuplot_plot_I"><title>TEXT</title>,
# closed by a tab-indented </g>) holds at least 10 coordinate pairs (a
# legend sample has at most 5).
svg_series() { # file text
    sed 's/&lt;/</g; s/&gt;/>/g; s/&quot;/"/g; s/&amp;/\&/g' "$1" | awk -v t="$2" '
        index($0, "<text>" t) { legend = 1 }
        !seen && index($0, "<title>" t) { inside = 1; seen = 1; next }
        inside && /^\t<\/g>/ { inside = 0 }
        inside { pairs += gsub(/[0-9.]+,[0-9.]+/, "&") }
        END { exit !(legend && pairs >= 10) }'
}

render() { # name args ext
    # shellcheck disable=SC2086 # the argument list is split at blanks on purpose
    "$bin" $2 --plot "$out/$1.$3" >/dev/null 2>"$out/$1.$3.err"
}

grep -v '^[[:space:]]*#' "$list" | grep -v '^[[:space:]]*$' >"$out/.figures" || true
while IFS='|' read -r name series args; do
    name=$(trim "$name")
    args=$(trim "$args")
    series=$(trim "$series")
    if [ -z "$name" ] || [ -z "$args" ]; then bad "$list: malformed line for '$name'"; continue; fi
    if [ "$render_only" -eq 1 ]; then
        if render "$name" "$args" png; then echo "rendered $out/$name.png"; ok
        else bad "$name: mcspec $args: $(cat "$out/$name.png.err")"; fi
        rm -f "$out/$name.png.err"
        continue
    fi
    for ext in png svg; do
        if render "$name" "$args" "$ext"; then ok; else
            bad "$name.$ext: mcspec $args: $(cat "$out/$name.$ext.err")"; continue; fi
        if [ "$ext" = png ]; then
            check_png "$out/$name.png" "$name.png"
            continue
        fi
        size=$(svg_size "$out/$name.svg")
        if [ "$size" = "$width $height" ]; then ok; else
            bad "$name.svg: root <svg> size '$size', expected $width $height"; fi
        old_ifs=$IFS
        IFS=';'
        for s in $series; do
            IFS=$old_ifs
            s=$(trim "$s")
            if [ "$s" = "<image>" ]; then
                # An image panel (gnuplot's `with image`): an embedded PNG.
                if grep -q "<image .*data:image/png;base64," "$out/$name.svg"; then ok
                else bad "$name.svg: no embedded image"; fi
            elif svg_series "$out/$name.svg" "$s"; then ok; else bad "$name.svg: no drawn series '$s'"; fi
        done
        IFS=$old_ifs
    done
    rm -f "$out/$name.png.err" "$out/$name.svg.err"
    check_png "docs/plots/$name.png" "docs/plots/$name.png (run make plots)"
done <"$out/.figures"
rm -f "$out/.figures"

echo "-----------------------"
echo "$((passed + failed)) Tests $failed Failures 0 Ignored"
if [ "$failed" -eq 0 ]; then echo "OK"; else echo "FAIL"; fi
[ "$failed" -eq 0 ]
