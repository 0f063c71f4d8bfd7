#!/bin/sh
# plots.sh [OUTDIR] -- the benchmark's PNG plots (DESIGN 10), drawn by gnuplot
# from OUTDIR/plotdata/, which build/summarize writes (see the top of
# scripts/summarize/main.c for the data files).  OUTDIR defaults to results.
#
# Per dataset D listed in plotdata/datasets.txt:
#   D-time.png    median time per deletion vs degree, log-log, IQR bars
#   D-ratio.png   cgal median / variant median vs degree, log-log, line at 1
#   D-phases.png  stacked median phase times per variant
#   D-tets.png    median tetrahedra created vs degree, log-log
# and time-vs-degree.png, the paper's figure: every unweighted dataset pooled.
# A plot with nothing to show (no cgal rows for the ratio, no phase times,
# no tets counts) is skipped with a note and any older copy removed.  Every
# plot carries machine, compiler, flags, CGAL version and date from
# OUTDIR/meta.txt in its footer.  Each variant keeps one colour and point
# shape in every plot.  Terminal: pngcairo, or png (libgd) when gnuplot has
# no cairo; PLOTS_TERM=png forces the fallback.  Exits 1 if gnuplot is
# missing, the plot data is missing, or any gnuplot run fails.
out=${1:-results}
pd=$out/plotdata
if ! command -v gnuplot >/dev/null 2>&1; then
    echo "plots: gnuplot not found; install the Debian package gnuplot-nox (make deps)" >&2
    exit 1
fi
if [ ! -f "$pd/datasets.txt" ]; then
    echo "plots: $pd/datasets.txt not found; run build/summarize $out $out/*.csv first" >&2
    exit 1
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

if [ "${PLOTS_TERM:-}" != png ] && echo 'set terminal pngcairo' | gnuplot >/dev/null 2>&1; then
    term='pngcairo size 1400,850 enhanced font "DejaVu Sans,15" linewidth 1.5'
    small='font ",11"'
else
    term='png size 1400,850 enhanced font "DejaVuSans,13" linewidth 1.5'
    small='font "DejaVuSans,10"'
fi

# gq STRING: STRING as a gnuplot single-quoted string
gq() { printf "'%s'" "$(printf '%s' "$1" | sed "s/'/''/g")"; }

# The footer: machine, cores, compiler, flags, CGAL, date, commit.
meta() { sed -n "s/^$1:[[:space:]]*//p" "$out/meta.txt" 2>/dev/null | head -n 1; }
# part TEXT...: appends " | TEXT" to the footer unless TEXT is blank
part() { [ -n "$(echo "$*" | tr -d ' ')" ] && footer="${footer:+$footer | }$*"; return 0; }
footer=''
if [ -f "$out/meta.txt" ]; then
    c=$(meta cores)
    part "$(meta machine)${c:+, $c cores}"
    part "$(meta compiler) $(meta flags)"
    c=$(meta cgal); part "${c:+CGAL $c}"
    part "$(meta date)"
    c=$(meta commit); part "${c:+commit $c}"
fi
[ -n "$footer" ] || footer="no meta.txt: machine, compiler, CGAL version and date unknown"

# style NAME INDEX: line colour, point type and dash of a variant
style() {
    case $1 in
        cgal)         echo "lc rgb '#000000' pt 7 dt 1 lw 2.5" ;;
        cgal-rnd)     echo "lc rgb '#7f7f7f' pt 6 dt 2 lw 2" ;;
        sew-full)     echo "lc rgb '#1f77b4' pt 5 dt 1 lw 1.5" ;;
        dtq-only)     echo "lc rgb '#ff7f0e' pt 9 dt 1 lw 1.5" ;;
        guide-only)   echo "lc rgb '#2ca02c' pt 11 dt 1 lw 1.5" ;;
        grr-edge)     echo "lc rgb '#d62728' pt 13 dt 1 lw 2" ;;
        grr-neighbor) echo "lc rgb '#9467bd' pt 4 dt 1 lw 1.5" ;;
        grr-hashing)  echo "lc rgb '#8c564b' pt 8 dt 1 lw 1.5" ;;
        grr-brio)     echo "lc rgb '#e377c2' pt 10 dt 1 lw 1.5" ;;
        *)  case $(( $2 % 6 )) in
                0) c='#17becf' ;; 1) c='#bcbd22' ;; 2) c='#393b79' ;;
                3) c='#637939' ;; 4) c='#8c6d31' ;; *) c='#843c39' ;;
            esac
            echo "lc rgb '$c' pt $(( $2 % 5 + 1 )) dt 4 lw 1.5" ;;
    esac
}

# blocks NAME: one line per index block of NAME.dat:
#   "index variant has_time has_ratio has_tets"
blocks() {
    awk '/^# variant /{ if (n) print n-1, v, t, r, k; v = $3; n++; t = r = k = 0; next }
         /^#/ || NF < 6 { next }
         { if ($2 != "NaN") t = 1; if ($5 != "NaN") r = 1; if ($6 != "NaN") k = 1 }
         END { if (n) print n-1, v, t, r, k }' "$pd/$1.dat"
}

# header FILE TITLE SUBTITLE YLABEL: common settings
header() {
    cat <<EOF
set terminal $term
set output $(gq "$1")
set encoding utf8
set title $(gq "$2")."\n".$(gq "$3") noenhanced font ",17"
set xlabel 'degree of the deleted vertex (number of neighbours)'
set ylabel $(gq "$4")
set key outside right top vertical Left reverse noenhanced spacing 1.3 box
set grid xtics ytics mxtics mytics lc rgb '#dddddd' lw 1
set border lw 1.2
set bmargin 6
set label 1 $(gq "$footer") at screen 0.01, screen 0.02 left noenhanced $small tc rgb '#555555'
set datafile missing 'NaN'
set logscale x 2
set xtics (4, 8, 16, 32, 64, 128, 256, 512, 1024, 2048, 4096, 8192, 16384) nomirror
set xtics add ("" 6 1, "" 12 1, "" 24 1, "" 48 1, "" 96 1, "" 192 1, "" 384 1, "" 768 1, "" 1536 1, "" 3072 1, "" 6144 1)
EOF
}

# Log y axis labelled 1-2-5 in each decade, readable over any range.
log125() {
    echo "set logscale y"
    printf 'set ytics ('
    awk 'BEGIN { s = ""; for (e = -3; e <= 8; e++) for (m = 1; m <= 5; m += (m == 2 ? 3 : 1)) {
                   v = m * 10 ^ e; printf (v < 1 ? "%s\"%g\" %g" : "%s\"%.0f\" %g"), s, v, v; s = ", " } }'
    echo ') nomirror'
}

# ranges NAME COL...: axis ranges for NAME.dat: x spans the degree buckets
# shown, y the values in columns COL... (and 1 when COL is "1"); each axis
# spans at least a factor 2.6 so that it shows a labelled tic, with a
# margin so that no point sits on the border.
ranges() {
    f=$pd/$1.dat; shift
    awk -v cols="$*" 'BEGIN { nc = split(cols, c, " ") }
        function widen(lo, hi, axis,   r, m) {
            lo /= 1.25; hi *= 1.25; r = hi / lo
            if (r < 2.6) { m = sqrt(2.6 / r); lo /= m; hi *= m }
            printf "set %srange [%g:%g]\n", axis, lo, hi }
        /^#/ || NF < 12 { next }
        { lo = $11 < 1 ? 1 : $11; if (!xl || lo < xl) xl = lo; if ($12 > xh) xh = $12
          for (i = 1; i <= nc; i++) { v = c[i] == "1" ? 1 : $(c[i])
              if (v == "NaN" || v <= 0) continue
              if (!yl || v < yl) yl = v; if (v > yh) yh = v } }
        END { if (xl) widen(xl * 1.25, xh / 1.25, "x"); if (yl) widen(yl, yh, "y") }' "$f"
}

failed=0
# draw SCRIPT PNG: runs gnuplot on SCRIPT
draw() {
    if gnuplot "$1" >"$tmp/gp.err" 2>&1; then
        grep -v "^$" "$tmp/gp.err" | grep -iv "warning: .*undefined\|skipping data file" | sed 's/^/plots: gnuplot: /' >&2
        echo "plots: wrote $2"
    else
        echo "plots: gnuplot failed on $2:" >&2
        sed 's/^/    /' "$tmp/gp.err" >&2
        failed=1
    fi
}

# skip PNG WHY
skip() { rm -f "$1"; echo "plots: no $1: $2"; }

# time_plot NAME PNG TITLE SUBTITLE: median time with IQR bars; variants are shifted
# sideways by a few percent so that the bars stay apart.
time_plot() {
    nb=$(blocks "$1" | awk '$3 { k++ } END { print k + 0 }')
    if [ "$nb" -eq 0 ]; then skip "$2" "no timings"; return; fi
    {
        header "$2" "$3" "$4" 'time per deletion (µs), median and IQR'
        log125
        ranges "$1" 2 3 4
        printf 'plot '
        sep=''
        k=0
        blocks "$1" | while read -r i v t r tk; do
            [ "$t" = 1 ] || continue
            s=$(style "$v" "$i")
            j=$(awk -v k="$k" -v n="$nb" 'BEGIN { printf "%.4f", 2 ^ ((k - (n - 1) / 2) * 0.03) }')
            printf "%s\\\\\n  %s index %s using (\$1*%s):2:3:4 with yerrorlines %s ps 1.1 title %s" \
                "$sep" "$(gq "$pd/$1.dat")" "$i" "$j" "$s" "$(gq "$v")"
            sep=', '
            k=$((k + 1))
        done
        echo
    } >"$tmp/p.gp"
    draw "$tmp/p.gp" "$2"
}

ratio_plot() {
    if ! blocks "$1" | awk '$2 != "cgal" && $4 { f = 1 } END { exit !f }'; then
        skip "$2" "no variant shares a degree bucket with cgal rows"; return
    fi
    {
        header "$2" "$3" "$4" 'speed-up over CGAL (cgal median / variant median)'
        echo "set logscale y 2"
        echo "set format y '%g'"
        echo "set ytics (0.125, 0.25, 0.5, 0.75, 1, 1.5, 2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64, 96, 128, 256, 512, 1024)"
        ranges "$1" 5 1
        printf "plot 1 with lines lc rgb '#000000' lw 2 dt 1 title 'CGAL (ratio 1)'"
        blocks "$1" | while read -r i v t r tk; do
            if [ "$r" != 1 ] || [ "$v" = cgal ]; then continue; fi
            printf ", \\\\\n  %s index %s using 1:5 with linespoints %s ps 1.3 title %s" \
                "$(gq "$pd/$1.dat")" "$i" "$(style "$v" "$i")" "$(gq "$v")"
        done
        echo
    } >"$tmp/p.gp"
    draw "$tmp/p.gp" "$2"
}

tets_plot() {
    if ! blocks "$1" | awk '$5 { f = 1 } END { exit !f }'; then
        skip "$2" "no tetrahedra counts"; return
    fi
    {
        header "$2" "$3" "$4" 'tetrahedra created per deletion (median)'
        log125
        ranges "$1" 6
        printf 'plot '
        sep=''
        blocks "$1" | while read -r i v t r tk; do
            [ "$tk" = 1 ] || continue
            printf "%s\\\\\n  %s index %s using 1:6 with linespoints %s ps 1.3 title %s" \
                "$sep" "$(gq "$pd/$1.dat")" "$i" "$(style "$v" "$i")" "$(gq "$v")"
            sep=', '
        done
        echo
    } >"$tmp/p.gp"
    draw "$tmp/p.gp" "$2"
}

phases_plot() {
    f=$pd/$1.phases
    if [ ! -f "$f" ] || ! grep -qv '^#' "$f"; then skip "$2" "no phase times"; return; fi
    nv=$(grep -cv '^#' "$f")
    {
        header "$2" "$3" "$4" 'median time per deletion (µs)'
        cat <<EOF
unset logscale x
unset xtics
set xtics nomirror rotate by -30 left noenhanced
unset xlabel
set style data histograms
set style histogram rowstacked
set style fill solid 0.85 border rgb '#333333'
set boxwidth 0.6
set yrange [0:*]
set xrange [-0.6:$nv-0.4]
set key outside right top vertical Left reverse noenhanced spacing 1.3 box title 'phase (bottom to top)'
plot $(gq "$f") using 2:xtic(1) title 'link deletion' lc rgb '#4e79a7', \\
  '' using 3 title 'point location' lc rgb '#f28e2b', \\
  '' using 4 title 'conflict DT' lc rgb '#59a14f', \\
  '' using 5 title 'sewing' lc rgb '#e15759', \\
  '' using 0:6 with points pt 2 ps 2.5 lw 2 lc rgb '#000000' title 'median total'
EOF
    } >"$tmp/p.gp"
    draw "$tmp/p.gp" "$2"
}

while read -r d; do
    [ -n "$d" ] || continue
    if [ ! -f "$pd/$d.dat" ]; then
        echo "plots: $pd/$d.dat missing" >&2; failed=1; continue
    fi
    sub=$(sed -n 's/^# title: //p' "$pd/$d.dat" | head -n 1)
    time_plot "$d" "$out/$d-time.png" "Deletion time vs degree" "$sub"
    ratio_plot "$d" "$out/$d-ratio.png" "Speed-up over CGAL vs degree" "$sub"
    phases_plot "$d" "$out/$d-phases.png" "Phase split, median over all deletions" "$sub"
    tets_plot "$d" "$out/$d-tets.png" "Tetrahedra created vs degree" "$sub"
done <"$pd/datasets.txt"

if [ -f "$pd/all-datasets.dat" ]; then
    sub=$(sed -n 's/^# title: all-datasets, //p' "$pd/all-datasets.dat" | head -n 1)
    time_plot all-datasets "$out/time-vs-degree.png" "Deletion time vs degree, unweighted datasets pooled" "$sub"
else
    echo "plots: $pd/all-datasets.dat missing" >&2; failed=1
fi
exit $failed
