#!/bin/sh
# make bench (full) / make bench-quick: the deletion benchmark, then the
# construction benchmark, then tables and plots, all into results/.
#   1. build/count/dtdel bench  -> results/phases/*.csv (phase split, counters on)
#   2. build/dtdel bench        -> results/<dataset>.csv (timings, phases merged)
#   3. build/summarize          -> results/summary.md, results/plotdata/,
#                                  results/readme-table.md
#   4. scripts/plots.sh         -> results/*.png
#   5. scripts/readme-table.sh  -> README.md's results table (between its
#                                  bench-table markers), from step 3's
#                                  results/readme-table.md
#   (2b. build/dtdel bench --reps 1 on uniform, sphere, bunny -> results/cold/)
#   (2c. build/dtdel build-bench -> results/build.txt, seq-bench -> results/sequence.txt,
#        query-bench, edit-bench, refine-bench -> results/queries.txt, edits.txt, refine.txt)
mode=${1:-full}
scale=${2:-1}
set -e
mkdir -p results/phases
commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
{
    echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
    echo "cores: $(nproc)"
    echo "compiler: $(${CC:-cc} --version | head -n 1)"
    echo "flags: ${CFLAGS_USED:-see Makefile}"
    echo "cgal: $(dpkg-query -W -f='${Version}' libcgal-dev 2>/dev/null || echo unknown) (Debian libcgal-dev)"
    echo "date: $(date -u +%Y-%m-%dT%H:%MZ)"
    echo "commit: $commit"
    echo "mode: $mode (scale $scale)"
} >results/meta.txt
echo "bench ($mode): phase split with the counting build" >&2
build/count/dtdel bench --mode "$mode" --scale "$scale" --out results/phases
echo "bench ($mode): timings with the release build" >&2
rc=0
build/dtdel bench --mode "$mode" --scale "$scale" --out results --phases results/phases || rc=$?
# Cold pass: every deletion timed once (--reps 1), so neither CGAL nor we
# run with branch predictors and caches trained by the repetitions of the
# same deletion: results/cold/summary.md, low-degree datasets only.
mkdir -p results/cold
{ cat results/meta.txt; echo "reps: 1 (each deletion timed once)"; } >results/cold/meta.txt
for ds in uniform sphere bunny; do
    build/dtdel bench --mode "$mode" --scale "$scale" --reps 1 --dataset "$ds" --out results/cold || rc=$?
done
build/summarize results/cold results/cold/*.csv
n=1000000 nh=16000
[ "$mode" = quick ] && n=200000 nh=4000
build/dtdel build-bench "$n" --reps 5 >results/build.txt || rc=$?
# and on a curve, where point location is most of the work
echo >>results/build.txt
build/dtdel build-bench "$nh" --dataset helix >>results/build.txt || rc=$?
cat results/build.txt
# whole workloads: a random sequence of deletions, no repetition, cold
# caches (seq-bench), on uniform points and on the degenerate grid
ns=1000000 ng=27000
[ "$mode" = quick ] && ns=200000 ng=8000
build/dtdel seq-bench "$ns" --fraction 0.1 >results/sequence.txt || rc=$?
echo >>results/sequence.txt
build/dtdel seq-bench "$ng" --dataset grid --fraction 0.5 >>results/sequence.txt || rc=$?
cat results/sequence.txt
# insertion of new points, location and nearest-vertex queries against
# CGAL (with and without Fast_location), and memory under churn
nq=200000 kq=50000 lq=100000
[ "$mode" = quick ] && nq=50000 kq=10000 lq=20000
build/dtdel query-bench "$nq" --inserts "$kq" --queries "$kq" --live "$lq" >results/queries.txt || rc=$?
cat results/queries.txt
# moves (smoothing) against move_if_no_collision, set deletion against
# remove(first, last)
ne=100000 me=200000
[ "$mode" = quick ] && ne=20000 me=40000
build/dtdel edit-bench "$ne" --set "$me" >results/edits.txt || rc=$?
cat results/edits.txt
# refinement: the circumcentre of the largest cell inserted, again and
# again, our queue fed by dd_created_cells, CGAL's by find_conflicts and
# insert_in_hole; both must end in the same triangulation
nr=100000 kr=100000
[ "$mode" = quick ] && nr=20000 kr=20000
build/dtdel refine-bench "$nr" --inserts "$kr" >results/refine.txt || rc=$?
cat results/refine.txt
csvs=$(ls results/*.csv)
build/summarize results $csvs
sh scripts/plots.sh results
sh scripts/readme-table.sh results/readme-table.md README.md
echo "results: results/summary.md, results/*.png and README.md's table" >&2
exit $rc
