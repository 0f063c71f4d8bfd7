#!/bin/sh
# abbench.sh -- is engine B faster than engine A, as the bench measures it?
#
#   scripts/abbench.sh DTDEL_A DTDEL_B [DATASET [RUNS [MINDEG]]]
#
# Runs `dtdel bench --mode full --dataset DATASET` RUNS times with each
# binary (default uniform, 10 runs), in turns A B, B A, A B, ... (so that
# neither binary always runs second of a pair), and compares their
# deletion / re-insertion ratios: per run, the median over the vertices
# of degree >= MINDEG (default 32) of the paired row's deletion time over
# the re-insertion's (auto-paired and insert, timed in turn on the same
# vertex; see src/bench/bench.c).  Prints each run's median, then per
# binary the mean and standard deviation over its runs, and B - A with
# its standard error.
#
# Why not a loop timing the same vertex again and again: there the
# branch predictor learns the very deletion, so changes that only remove
# mispredicted branches show nothing.  One bench run's median moves from
# run to run by as much as the differences looked for, hence the
# repetitions and the standard error.
set -e
[ $# -ge 2 ] || { echo "usage: $0 DTDEL_A DTDEL_B [DATASET [RUNS [MINDEG]]]" >&2; exit 2; }
A=$1 B=$2 DS=${3:-uniform} N=${4:-10} LO=${5:-32}
for bin in "$A" "$B"; do
    [ -x "$bin" ] || { echo "$0: $bin is not an executable" >&2; exit 2; }
done
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# median over the vertices of one run's CSV (file $1) of paired / insert
run_ratio() {
    awk -F, -v lo="$LO" 'NR > 1 && $4 >= lo && $6 == "auto-paired" { d[$2 ":" $3] = $7 }
                         NR > 1 && $4 >= lo && $6 == "insert" { i[$2 ":" $3] = $7 }
                         END { for (k in d) if ((k in i) && i[k] > 0) print d[k] / i[k] }' "$1" |
        sort -g | awk '{ a[NR] = $1 } END { if (NR == 0) print "nan"; else if (NR % 2) print a[(NR + 1) / 2];
                                            else print (a[NR / 2] + a[NR / 2 + 1]) / 2 }'
}

i=1
while [ "$i" -le "$N" ]; do
    if [ $((i % 2)) = 1 ]; then order="A B"; else order="B A"; fi
    for x in $order; do
        if [ "$x" = A ]; then bin=$A; else bin=$B; fi
        "$bin" bench --mode full --dataset "$DS" --out "$tmp/$x" > "$tmp/log" 2>&1 ||
            { cat "$tmp/log" >&2; echo "$0: $bin bench failed" >&2; exit 1; }
        grep -q " 0 mismatches" "$tmp/log" || { cat "$tmp/log" >&2; echo "$0: $bin: mismatches" >&2; exit 1; }
        echo "$x $(run_ratio "$tmp/$x/$DS.csv")"
    done
    i=$((i + 1))
done | awk -v ds="$DS" -v lo="$LO" '
    { print "run " int((NR + 1) / 2) " " $1 ": " $2; n[$1]++; s[$1] += $2; ss[$1] += $2 * $2 }
    END {
        for (x in n) { m[x] = s[x] / n[x]; v[x] = n[x] > 1 ? (ss[x] - n[x] * m[x] * m[x]) / (n[x] - 1) : 0 }
        printf "%s, degree >= %d: deletion / re-insertion, median over the vertices, mean over the runs\n", ds, lo
        for (x in n) printf "  %s: %.4f (sd %.4f, %d runs)\n", x, m[x], sqrt(v[x] > 0 ? v[x] : 0), n[x]
        printf "  B - A: %+.4f (standard error %.4f)\n", m["B"] - m["A"], sqrt(v["A"] / n["A"] + v["B"] / n["B"])
    }'
