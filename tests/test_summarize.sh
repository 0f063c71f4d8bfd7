#!/bin/sh
# build/summarize on a small CSV whose statistics are worked out by hand:
# exact medians, quartiles (linear interpolation), ratios to cgal, mismatch
# counts, bucket boundaries, column order, the gnuplot data lines, and the
# exit codes and messages on malformed input, and the "insert" row (our
# re-insertion, not a deletion): last column, no ratio to cgal, and the
# "Deletion vs re-insertion" table.  Then the README's results table
# (readme-table.md) on CSVs named as the bench's datasets, and
# scripts/readme-table.sh putting it between a README's markers (and
# failing, changing nothing, without them).  Prints ok/FAIL lines.
SUM=${1:-build/summarize}
PUT=$(dirname "$0")/../scripts/readme-table.sh
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failed=0

ok() { echo "ok summarize/$1"; }
bad() { echo "FAIL summarize/$1: $2"; failed=1; }

# has NAME FILE LINE: FILE holds LINE exactly, as a whole line
has() {
    if grep -qxF -- "$3" "$2" 2>/dev/null; then ok "$1"; else
        bad "$1" "no line \"$3\" in $(basename "$2")"; fi
}

# expect NAME CODE PATTERN CMD...: exit code CODE, stderr matching PATTERN
expect() {
    name=$1; code=$2; pat=$3; shift 3
    "$@" >"$tmp/out" 2>"$tmp/err"
    rc=$?
    if [ $rc -ne "$code" ]; then
        bad "$name" "exit $rc, expected $code; stderr: $(head -c 300 "$tmp/err")"
    elif [ -n "$pat" ] && ! grep -qE -- "$pat" "$tmp/err"; then
        bad "$name" "stderr does not match /$pat/: $(head -c 300 "$tmp/err")"
    else
        ok "$name"
    fi
}

H=dataset,n,vertex,degree,on_hull,variant,us,tets_created,link_us,locate_us,conflict_us,sew_us,match

# Dataset toy, bucket [4,8):
#   cgal     us 10 20 30 40 50   -> median 30, q1 20, q3 40
#   grr-edge us 4 8 12 16 20     -> 12 (8-16), ratio 30/12 = 2.50,
#            tets 10..50 -> 30, link 1..5 -> 3, conflict 2, sew 1.5
#   sew-full us 6 9 15 (3 rows)  -> 9 (7.5-12), ratio 30/9 = 3.33
# bucket [16,24):
#   cgal 100 300 -> 200 (150-250); grr-edge 50 150 -> 100 (75-125) x2.00,
#   tets 7 8 -> 7.5, one mismatch; zeta-x 400 400 -> x0.50, one mismatch.
# grr-edge over all 7 rows: link 1..7 -> 4, us median 16.
# insert (not a deletion, last column, never a ratio to cgal):
#   [4,8) us 2 4 6 8 10 -> 6 (4-8); vs insert: sew-full 9/6 = x1.50,
#   grr-edge 12/6 = x2.00, zeta-x none.  [16,24) us 20 30 -> 25 (22.5-27.5);
#   grr-edge 100/25 = x4.00, zeta-x 400/25 = x16.00, sew-full none.
# Dataset other: cgal 1000, cgal-rnd 800 (x1.25, not in the insert table),
# grr-edge 500 and insert 60 (x8.33, a mismatch) at degree 20.
# Pooled [16,24): grr-edge 50 150 500 -> 150 against cgal 100 300 1000
# -> 300: x2.00; zeta-x (toy only) against toy's cgal 200: x0.50.
# insert pooled 20 30 60 -> 30 (25-45): grr-edge 150/30 = x5.00; zeta-x
# (toy only) against toy's insert 25: x16.00 (not 400/30 = x13.33).
# Dataset edges: cgal only, one row per bucket boundary.
cat >"$tmp/toy.csv" <<EOF
$H
toy,1000,1,5,0,cgal,10,,,,,,1
toy,1000,2,6,0,cgal,20,,,,,,1
toy,1000,3,7,1,cgal,30,,,,,,1
toy,1000,4,5,0,cgal,40,,,,,,1
toy,1000,5,4,0,cgal,50,,,,,,1
toy,1000,1,5,0,grr-edge,4,10,1,,2,1.5,1
toy,1000,2,6,0,grr-edge,8,20,2,,2,1.5,1
toy,1000,3,7,1,grr-edge,12,30,3,,2,1.5,1
toy,1000,4,5,0,grr-edge,16,40,4,,2,1.5,1
toy,1000,5,4,0,grr-edge,20,50,5,,2,1.5,1
toy,1000,1,5,0,sew-full,6,,,,,,1
toy,1000,2,6,0,sew-full,9,,,,,,1
toy,1000,3,7,1,sew-full,15,,,,,,1
toy,1000,6,20,0,cgal,100,,,,,,1
toy,1000,7,23,0,cgal,300,,,,,,1
toy,1000,6,20,0,grr-edge,50,7,6,,2,1.5,0
toy,1000,7,23,0,grr-edge,150,8,7,,2,1.5,1
toy,1000,6,20,0,zeta-x,400,,,,,,1
toy,1000,7,23,0,zeta-x,400,,,,,,0
toy,1000,1,5,0,insert,2,,,,,,1
toy,1000,2,6,0,insert,4,,,,,,1
toy,1000,3,7,1,insert,6,,,,,,1
toy,1000,4,5,0,insert,8,,,,,,1
toy,1000,5,4,0,insert,10,,,,,,1
toy,1000,6,20,0,insert,20,,,,,,1
toy,1000,7,23,0,insert,30,,,,,,1
EOF
printf '%s\r\nother,50,9,20,1,grr-edge,500,9,,,,,1\r\nother,50,9,20,1,cgal,1000,,,,,,1\r\n' "$H" >"$tmp/other.csv"
printf 'other,50,9,20,1,cgal-rnd,800,,,,,,1\r\nother,50,9,20,1,insert,60,,,,,,0\r\n\r\n' >>"$tmp/other.csv"
cat >"$tmp/edges.csv" <<EOF
$H
edges,2000,1,3,0,cgal,1,,,,,,1
edges,2000,2,11,0,cgal,1,,,,,,1
edges,2000,3,12,0,cgal,1,,,,,,1
edges,2000,4,1100,0,cgal,1,,,,,,1
edges,2000,5,1536,0,cgal,1,,,,,,1
EOF
mkdir "$tmp/out1"
printf 'machine: testbox\ncgal: 9.9\n' >"$tmp/out1/meta.txt"

expect runs 0 "MISMATCHES in toy: 2" "$SUM" "$tmp/out1" "$tmp/toy.csv" "$tmp/other.csv" "$tmp/edges.csv"
md=$tmp/out1/summary.md
has meta-line "$md" "- **machine**: testbox"
has column-order "$md" "| degree | deletions | cgal | sew-full | grr-edge | zeta-x | insert |"
has bucket-4-8 "$md" "| [4,8) | 5 | 30.0 (20.0–40.0) | 9.00 (7.50–12.0) ×3.33 [3 rows] | 12.0 (8.00–16.0) ×2.50 | — | 6.00 (4.00–8.00) |"
has bucket-16-24 "$md" "| [16,24) | 2 | 200 (150–250) | — | 100 (75.0–125) ×2.00 | 400 (400–400) ×0.50 | 25.0 (22.5–27.5) |"
has mismatch-row "$md" "| **mismatches** | 2 | 0 | 0 | **1** | **1** | 0 |"
has mismatch-loud "$md" "**MISMATCHES: 2** deletions differ from CGAL's canonical form (a bug): grr-edge 1; zeta-x 1;"
has mismatch-listed "$md" "- MISMATCH toy n=1000 vertex=7 degree=23 variant=zeta-x ($tmp/toy.csv:20)"
has mismatch-zero "$md" "mismatches: 0"
has mismatch-total "$md" "**MISMATCHES: 3 in total** -- see the datasets below."
has mismatch-insert "$md" "**MISMATCHES: 1** deletions differ from CGAL's canonical form (a bug): insert 1; (the insert rows count re-insertions that did not restore the triangulation)"
has phase-row "$md" "| grr-edge | 7 | 4.00 | — | 2.00 | 1.50 | 16.0 |"
has tets-header "$md" "| degree | grr-edge |"
has tets-row "$md" "| [16,24) | 7.5 |"
has crlf-dataset "$md" "| [16,24) | 1 | 1000 (1000–1000) | 800 (800–800) ×1.25 | 500 (500–500) ×2.00 | 60.0 (60.0–60.0) |"
has pooled-ratio "$md" "| [16,24) | 3 | 300 (200–650) | 800 (800–800) ×1.25 [1 rows] | — | 150 (100–325) ×2.00 | 400 (400–400) ×0.50 [2 rows] | 30.0 (25.0–45.0) |"
# Deletion vs re-insertion: engine deletion variants only (no cgal, cgal-rnd, insert)
has ins-sentence "$md" "Deletion vs re-insertion: median µs of our engine re-inserting the deleted vertex (insert), and per deletion variant its median deletion time divided by that (×2.00: deleting costs twice re-inserting; lower is better, target ≤ 2)."
has ins-header "$md" "| degree | insert µs | sew-full | grr-edge | zeta-x |"
has ins-4-8 "$md" "| [4,8) | 6.00 | ×1.50 | ×2.00 | — |"
has ins-16-24 "$md" "| [16,24) | 25.0 | — | ×4.00 | ×16.00 |"
has ins-other-header "$md" "| degree | insert µs | grr-edge |"
has ins-other "$md" "| [16,24) | 60.0 | ×8.33 |"
has ins-pooled "$md" "| [16,24) | 30.0 | — | ×5.00 | ×16.00 |"
has ins-none "$md" "Deletion vs re-insertion: no insert rows in this dataset."
# one such table per dataset with insert rows (toy, other) and the pooled one
nins=$(grep -c "^| degree | insert µs |" "$md")
if [ "$nins" -eq 3 ]; then ok ins-tables; else bad ins-tables "$nins insert tables, expected 3"; fi
for b in "[0,4)" "[8,12)" "[12,16)" "[1024,1536)" "[1536,2048)"; do
    has "bucket-$b" "$md" "| $b | 1 | 1.00 (1.00–1.00) |"
done
rows=$(awk '/^## /{ on = ($2 == "edges") } on && /^\| \[/{ n++ } END { print n + 0 }' "$md")
if [ "$rows" -eq 5 ]; then ok no-empty-buckets; else
    bad no-empty-buckets "edges has $rows bucket rows, expected 5"; fi

pd=$tmp/out1/plotdata
has dat-title "$pd/toy.dat" "# title: toy (n = 1000), 7 deletions"
has dat-grr-edge-4-8 "$pd/toy.dat" "5.5 12 8 16 2.5 30 3 NaN 2 1.5 4 8 5 0"
has dat-grr-edge-16-24 "$pd/toy.dat" "19.5 100 75 125 2 7.5 6.5 NaN 2 1.5 16 24 2 1"
has dat-cgal "$pd/toy.dat" "5.5 30 20 40 1 NaN NaN NaN NaN NaN 4 8 5 0"
has dat-pooled-zeta "$pd/all-datasets.dat" "19.5 400 400 400 0.5 NaN NaN NaN NaN NaN 16 24 2 1"
has dat-insert-no-ratio "$pd/toy.dat" "5.5 6 4 8 NaN NaN NaN NaN NaN NaN 4 8 5 0"
# block i of toy.dat is variant i of toy.variants
blocks=$(awk '/^# variant /{ printf "%s ", $3 }' "$pd/toy.dat")
if [ "$blocks" = "cgal sew-full grr-edge zeta-x insert " ] &&
   [ "$(tr '\n' ' ' <"$pd/toy.variants")" = "$blocks" ]; then ok variants-file; else
    bad variants-file "blocks \"$blocks\", variants \"$(tr '\n' ' ' <"$pd/toy.variants")\""; fi
nblank=$(awk 'prev == "" && $0 == "" { n++ } { prev = $0 } END { print n + 0 }' "$pd/toy.dat")
if [ "$nblank" -eq 4 ]; then ok block-separators; else
    bad block-separators "$nblank double blank lines, expected 4"; fi
has phases-file "$pd/toy.phases" "grr-edge 4 NaN 2 1.5 16"
if [ "$(tr '\n' ' ' <"$pd/datasets.txt")" = "toy other edges " ]; then ok datasets-list; else
    bad datasets-list "got $(tr '\n' ' ' <"$pd/datasets.txt")"; fi
# The pool of the unweighted datasets says so; with edges given after
# --weighted it pools two datasets (toy, other) and edges is pooled apart.
has pooled-heading "$md" "## All unweighted datasets"
has pooled-title "$pd/all-datasets.dat" "# title: all-datasets, 3 unweighted datasets, 13 deletions"
mkdir "$tmp/outw"
expect runs-weighted 0 "" "$SUM" "$tmp/outw" "$tmp/toy.csv" "$tmp/other.csv" --weighted "$tmp/edges.csv"
has pooled-title-weighted "$tmp/outw/plotdata/all-datasets.dat" "# title: all-datasets, 2 unweighted datasets, 8 deletions"
has pooled-weighted-heading "$tmp/outw/summary.md" "## All weighted datasets"
# What weights cost: wuniform beside uniform at n = 100000, bucket by
# bucket, medians worked out by hand (cgal 30 and 10 us, auto 3 and 2 on
# the weighted side at degree 13; 20 and 2.5 on the unweighted side), a
# bucket on one side only left out; whelix beside helix at every size.
{ echo "$H"
  for r in 1,13,cgal,30 2,13,cgal,10 1,13,auto,3 2,13,auto,2 3,40,cgal,100 3,40,auto,10; do
      echo "$r" | awk -F, '{ printf "wuniform,100000,%s,%s,0,%s,%s,,,,,,1\n", $1, $2, $3, $4 }'; done
  echo "whelix,1000,1,150,0,cgal,600,,,,,,1"; echo "whelix,1000,1,150,0,auto,6,,,,,,1"; } >"$tmp/wu.csv"
{ echo "$H"
  echo "uniform,100000,1,14,0,cgal,20,,,,,,1"; echo "uniform,100000,1,14,0,auto,2.5,,,,,,1"
  echo "uniform,1000,2,14,0,cgal,99,,,,,,1"; echo "uniform,1000,2,14,0,auto,99,,,,,,1"
  echo "helix,16000,1,140,0,cgal,800,,,,,,1"; echo "helix,16000,1,140,0,auto,4,,,,,,1"; } >"$tmp/u.csv"
mkdir "$tmp/outc"
expect runs-weight-cost 0 "" "$SUM" "$tmp/outc" "$tmp/u.csv" --weighted "$tmp/wu.csv"
has weight-cost-uniform "$tmp/outc/summary.md" \
    "| wuniform / uniform, 100 000 | [12,16) | 2 / 1 | 20.0 | 20.0 | 1.00 | 2.50 | 2.50 | 1.00 | 8.00× | 8.00× |"
has weight-cost-helix "$tmp/outc/summary.md" \
    "| whelix / helix, every n | [128,192) | 1 / 1 | 600 | 800 | 0.75 | 6.00 | 4.00 | 1.50 | 100× | 200× |"
if grep -q "^| wuniform / uniform, 100 000 | \[32,48)" "$tmp/outc/summary.md"; then
    bad weight-cost-one-side "a bucket with rows on one side only has a row"; else ok weight-cost-one-side; fi

# Malformed input: exit 1, FILE:LINE and what is wrong.
printf '%s\ntoy,10,1,5,0,cgal,1,,,,,,1\ntoy,10,2,5,0,cgal,1,,,,,1\n' "$H" >"$tmp/fields.csv"
printf '%s\ntoy,10,1,5,0,cgal,fast,,,,,,1\n' "$H" >"$tmp/us.csv"
printf '%s\ntoy,10,1,5,0,cgal,1,,,,,,1\ntoy,10,1,5,0,cgal,1,,,,,,2\n' "$H" >"$tmp/match.csv"
printf '%s\ntoy,10,1,5,0,cgal,nan,,,,,,1\n' "$H" >"$tmp/nan.csv"
printf '%s\ntoy,10,1,5,0,grr-edge,1,x,,,,,1\n' "$H" >"$tmp/tets.csv"
printf '%s\ntoy,10,1,5,0,grr-edge,1,3,1,-2,,,1\n' "$H" >"$tmp/phase.csv"
printf '%s\n../x,10,1,5,0,cgal,1,,,,,,1\n' "$H" >"$tmp/name.csv"
printf 'dataset,n,vertex,degree,variant,us\ntoy,10,1,5,cgal,1\n' >"$tmp/header.csv"
printf '%s\n' "$H" >"$tmp/empty.csv"
: >"$tmp/nothing.csv"
mkdir "$tmp/out2"
expect bad-field-count 1 "fields\.csv:3: expected 13 comma-separated fields, got 12" "$SUM" "$tmp/out2" "$tmp/fields.csv"
expect bad-us 1 "us\.csv:2: us must be" "$SUM" "$tmp/out2" "$tmp/us.csv"
expect bad-match 1 "match\.csv:3: match must be 0 or 1" "$SUM" "$tmp/out2" "$tmp/match.csv"
expect bad-nan 1 "nan\.csv:2: us must be" "$SUM" "$tmp/out2" "$tmp/nan.csv"
expect bad-tets 1 "tets\.csv:2: tets_created" "$SUM" "$tmp/out2" "$tmp/tets.csv"
expect bad-phase 1 "phase\.csv:2: locate_us" "$SUM" "$tmp/out2" "$tmp/phase.csv"
expect bad-dataset-name 1 "name\.csv:2: dataset must be" "$SUM" "$tmp/out2" "$tmp/name.csv"
expect bad-header 1 "header\.csv:1: header must be" "$SUM" "$tmp/out2" "$tmp/header.csv"
expect second-file-line 1 "us\.csv:2" "$SUM" "$tmp/out2" "$tmp/toy.csv" "$tmp/us.csv"
expect no-rows 1 "no data rows" "$SUM" "$tmp/out2" "$tmp/empty.csv"
expect empty-file 1 "nothing\.csv:1: empty file" "$SUM" "$tmp/out2" "$tmp/nothing.csv"
expect missing-file 1 "cannot open .*nope\.csv" "$SUM" "$tmp/out2" "$tmp/nope.csv"
expect usage 2 "usage: summarize OUTDIR CSV" "$SUM" "$tmp/out2"
if [ -e "$tmp/out2/summary.md" ]; then bad no-output-on-error "summary.md written"; else
    ok no-output-on-error; fi

# The README table: rows picked by dataset and size or degree bucket,
# cgal's median µs, cgal median / variant median per column.
#   moment n = 64 (degree 64): cgal 1000 3000 -> 2000; auto 10 30 -> 20,
#     x100; gift-wrap 16 -> x125; cgal-rnd 500 1500 -> 1000, x2.00;
#     auto-paired and insert are no columns.  n = 256: cgal 52233, auto
#     46.77 -> x1117 (1116.8).  n = 1024: not in this run.
#   helix n = 16000: the top bucket [256,384) only (degree 190 left out):
#     degrees 284 286 -> ~285; cgal 20000 40000 -> 30 000; auto 100 200
#     -> 150, x200.
#   uniform [12,16) (degree 16 left out): cgal 30 40 50 -> 40.0; auto
#     2 4 8 -> 4, x10.0; zeta-x (another variant: after the known ones,
#     before cgal-rnd) 16 at degree 12 only -> x2.50; gift-wrap none.
#   mismatches: all rows count, the one at degree 16 too.
#   build.txt: two blocks, their ratios; the first block's mesh file
#     (build-bench --write), in the churn line's paragraph.
mkdir "$tmp/rd"
printf 'commit: abc1234\ndate: 2026-01-01T00:00Z\nmode: full (scale 1)\nmachine: testbox\ncores: 2\ncgal: 9.9\n' \
    >"$tmp/rd/meta.txt"
printf 'dataset uniform, n = 1000000, 6 cells\nspeed ratio dtdel/cgal: 2.07\nidentical to CGAL: yes\n%s\n\n' \
    'write: /tmp/x/build-write.vtu (dd_write) of 6 finite cells: 169704411 bytes (169.7 MB) in 0.244 s' >"$tmp/rd/build.txt"
printf 'dataset helix, n = 16000, 2 cells\nspeed ratio dtdel/cgal: 4.24\nidentical to CGAL: yes\n' >>"$tmp/rd/build.txt"
cat >"$tmp/moment.csv" <<EOF2
$H
moment,64,1,64,1,cgal,1000,,,,,,1
moment,64,2,64,1,cgal,3000,,,,,,1
moment,64,1,64,1,auto,10,5,,,,,1
moment,64,2,64,1,auto,30,5,,,,,1
moment,64,1,64,1,gift-wrap,16,5,,,,,1
moment,64,1,64,1,cgal-rnd,500,,,,,,1
moment,64,2,64,1,cgal-rnd,1500,,,,,,1
moment,64,1,64,1,auto-paired,1,,,,,,1
moment,64,1,64,1,insert,1,,,,,,1
moment,256,3,256,1,cgal,52233,,,,,,1
moment,256,3,256,1,auto,46.77,,,,,,1
EOF2
cat >"$tmp/helix.csv" <<EOF2
$H
helix,16000,1,190,1,cgal,5,,,,,,1
helix,16000,1,190,1,auto,1,,,,,,1
helix,16000,2,284,1,cgal,20000,,,,,,1
helix,16000,3,286,1,cgal,40000,,,,,,1
helix,16000,2,284,1,auto,100,,,,,,1
helix,16000,3,286,1,auto,200,,,,,,1
EOF2
cat >"$tmp/uniform.csv" <<EOF2
$H
uniform,100000,1,12,0,cgal,30,,,,,,1
uniform,100000,2,13,0,cgal,40,,,,,,1
uniform,100000,3,15,0,cgal,50,,,,,,1
uniform,100000,4,16,0,cgal,1000,,,,,,1
uniform,100000,1,12,0,auto,2,,,,,,1
uniform,100000,2,13,0,auto,4,,,,,,1
uniform,100000,3,15,0,auto,8,,,,,,1
uniform,100000,4,16,0,auto,1,,,,,,0
uniform,100000,1,12,0,zeta-x,16,,,,,,1
EOF2
mkdir -p "$tmp/rd"
cat >"$tmp/rd/queries.txt" <<'EOQ'
dataset uniform, n = 200000; new points and queries uniform in the same cube (seed 1)
insert: 50000: dtdel 4.00 us, CGAL 40.00 us (10.0x), CGAL Fast_location 30.00 us (7.5x); identical to CGAL: yes
locate: 50000: dtdel 1.00 us, CGAL 20.00 us (20.0x), CGAL Fast_location 5.00 us (5.0x); same cells as CGAL: NO
churn: 1000 live vertices, 12 rounds of deleting half and inserting as many: RSS 10.0 MiB after round 2, 11.0 MiB after round 12 (1.10x); arrays 5.0 MiB, 5.0 MiB (1.00x); valid: yes
EOQ
cat >"$tmp/rd/edits.txt" <<'EOQ'
smoothing: 1000 uniform points, 2 passes of a random step of 5% of the mean spacing: dtdel 2.00 us, CGAL move_if_no_collision 28.00 us (14.0x); kept by the filter 30.0%; identical to CGAL: yes
smoothing (Morton order): 1000 uniform points, 2 passes of a random step of 5% of the mean spacing: dtdel 1.50 us, CGAL move_if_no_collision 27.00 us (18.0x); kept by the filter 30.5%; identical to CGAL: NO
delete-set 90%: 1800 of 2000 uniform points: dtdel 1.00 us a vertex, CGAL remove(first, last) 30.00 us (30.0x); identical to CGAL: yes
EOQ
cat >"$tmp/rd/regular.txt" <<'EOQ'
regular-build: 1000000 wuniform weighted points, 70000 hidden (CGAL), 3 runs each: dtdel 1.000 s, CGAL 2.000 s (2.00x); 0 mismatches
regular-insert: 50000 wuniform weighted points into 200000, 15000 hidden at the end (CGAL): dtdel n/a (unsupported), CGAL hinted insert 60.00 us; mismatches n/a
EOQ
expect readme-runs 0 "" "$SUM" "$tmp/rd" "$tmp/moment.csv" "$tmp/helix.csv" "$tmp/uniform.csv"
has readme-regular-build "$tmp/rd/readme-table.md" "| regular triangulation, build 1 000 000 weighted points | 1.00 | 2.00 | 2.0× | | |"
has readme-regular-insert-na "$tmp/rd/readme-table.md" "| regular triangulation, insert 50 000 weighted points into 200 000 | n/a | 60.00 | n/a | | |"
has readme-queries-header "$tmp/rd/readme-table.md" "| beyond deletion (uniform points) | dtdel µs | CGAL µs | ratio | CGAL Fast_location µs | ratio |"
has readme-queries-insert "$tmp/rd/readme-table.md" "| insert a new point, 200 000 points | 4.00 | 40.00 | 10.0× | 30.00 | 7.5× |"
has readme-queries-differ "$tmp/rd/readme-table.md" "| locate, 200 000 points (**differs from CGAL**) | 1.00 | 20.00 | 20.0× | 5.00 | 5.0× |"
has readme-edits-move "$tmp/rd/readme-table.md" "| move (smoothing 1000 points, 2 passes, input order) | 2.00 | 28.00 | 14.0× | | |"
has readme-edits-move-morton "$tmp/rd/readme-table.md" "| move (smoothing 1000 points, 2 passes, Morton order) (**differs from CGAL**) | 1.50 | 27.00 | 18.0× | | |"
if grep -A1 -F "input order) |" "$tmp/rd/readme-table.md" | tail -n 1 | grep -qF "Morton order)"; then
    ok readme-edits-move-order; else bad readme-edits-move-order "the Morton row does not follow the input-order row"; fi
has readme-edits-set "$tmp/rd/readme-table.md" "| delete a set, 90% of 2000 | 1.00 | 30.00 | 30.0× | | |"
has readme-queries-churn-and-write "$tmp/rd/readme-table.md" "Under churn (\`dtdel query-bench\`: 12 rounds of deleting half of 1000 vertices and inserting as many), resident memory after the last round is 1.10× that after round 2. Written by \`dd_write\` as a binary .vtu, the triangulation of 1 000 000 points (6 finite cells) is 169.7 MB, in 0.24 s."
rt=$tmp/rd/readme-table.md
has readme-header "$rt" "| dataset | degree | deletions | CGAL µs | auto | gift-wrap | zeta-x | cgal-rnd |"
has readme-moment-64 "$rt" "| moment, n = 64 | 64 | 2 | 2000 | 100× | 125× | — | 2.00× |"
has readme-moment-256 "$rt" "| moment, n = 256 | 256 | 1 | 52 233 | 1117× | — | — | — |"
has readme-helix-top "$rt" "| helix, n = 16 000 | ~285 | 2 | 30 000 | 200× | — | — | — |"
has readme-uniform "$rt" "| uniform, n = 100 000 | 12–15 | 3 | 40.0 | 10.0× | — | 2.50× | — |"
has readme-missing "$rt" "Not in this run: moment n = 1024; helix n = 64 000; sphere, degree 4–7; sphere, degree 8–11; bunny, degree 12–15; grid, degree 12–15; cosphere, degree 16–23."
has readme-mismatches "$rt" "**mismatches: 1** (results that differ from CGAL's triangulation: a bug; summary.md lists them)"
has readme-run "$rt" "Run: commit abc1234, 2026-01-01T00:00Z, mode full (scale 1); testbox, 2 cores; CGAL 9.9. Construction of DT(S) (\`dtdel build-bench\`): 2.07× CGAL's speed on uniform, n = 1 000 000; 4.24× on helix, n = 16 000."
nrows=$(grep -c '^| [a-z]*, n = [0-9 ]* | [0-9~]' "$rt")   # the deletion table's rows
if [ "$nrows" -eq 4 ]; then ok readme-rows; else bad readme-rows "$nrows rows, expected 4"; fi
# no mismatch, no meta.txt, no build.txt
mkdir "$tmp/rd2"
expect readme-bare 0 "" "$SUM" "$tmp/rd2" "$tmp/moment.csv" "$tmp/helix.csv"
has readme-no-mismatch "$tmp/rd2/readme-table.md" "mismatches: 0 (every result of the run equals CGAL's triangulation)"
has readme-no-meta "$tmp/rd2/readme-table.md" "Run: commit ?, ?, mode ?; ?, ? cores; CGAL ?."
if grep -q "Construction\|Written by" "$tmp/rd2/readme-table.md"; then
    bad readme-no-build "a construction line or a mesh file's note without build.txt"; else ok readme-no-build; fi
if [ -n "$(tail -n 1 "$rt")" ] && [ -n "$(tail -n 1 "$tmp/rd2/readme-table.md")" ]; then ok readme-no-trailing-blank; else
    bad readme-no-trailing-blank "the table file ends with a blank line"; fi

# readme-table.sh: the lines between the markers replaced, nothing else
printf '# Title\n\ntext before\n<!-- bench-table:begin -->\nold table\n\nold line\n<!-- bench-table:end -->\ntext after\n' \
    >"$tmp/README.md"
{ printf '# Title\n\ntext before\n<!-- bench-table:begin -->\n\n'; cat "$rt"
  printf '\n<!-- bench-table:end -->\ntext after\n'; } >"$tmp/want.md"
expect put-runs 0 "" sh "$PUT" "$rt" "$tmp/README.md"
if cmp -s "$tmp/README.md" "$tmp/want.md"; then ok put-replaces; else
    bad put-replaces "$(diff "$tmp/want.md" "$tmp/README.md" | head -c 300)"; fi
expect put-again 0 "" sh "$PUT" "$rt" "$tmp/README.md"
if cmp -s "$tmp/README.md" "$tmp/want.md"; then ok put-idempotent; else
    bad put-idempotent "a second run changed the README"; fi
printf '# Title\nno markers here\n' >"$tmp/plain.md"
cp "$tmp/plain.md" "$tmp/plain0.md"
expect put-no-markers 1 "bench-table:begin.*once.*found 0 and 0" sh "$PUT" "$rt" "$tmp/plain.md"
printf 'a\n<!-- bench-table:begin -->\nb\n' >"$tmp/half.md"
expect put-no-end 1 "found 1 and 0" sh "$PUT" "$rt" "$tmp/half.md"
printf '<!-- bench-table:end -->\nb\n<!-- bench-table:begin -->\n' >"$tmp/swapped.md"
expect put-swapped 1 "comes before" sh "$PUT" "$rt" "$tmp/swapped.md"
printf '<!-- bench-table:begin -->\n<!-- bench-table:end -->\n<!-- bench-table:end -->\n' >"$tmp/twice.md"
expect put-twice 1 "found 1 and 2" sh "$PUT" "$rt" "$tmp/twice.md"
expect put-no-table 1 "cannot read the table" sh "$PUT" "$tmp/none.md" "$tmp/README.md"
expect put-usage 2 "usage" sh "$PUT"
if cmp -s "$tmp/plain.md" "$tmp/plain0.md" && cmp -s "$tmp/README.md" "$tmp/want.md"; then
    ok put-unchanged-on-error; else bad put-unchanged-on-error "a failed run changed its README"; fi
exit $failed
