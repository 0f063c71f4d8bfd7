#!/bin/sh
# make bench (full) / make bench-quick: the deletion benchmark, then the
# construction benchmark, then tables and plots.  The full run writes into
# results/ and rewrites README.md's results table; the quick run writes
# into results/quick/ (not tracked) and leaves README.md and results/ as
# they are, so its smaller figures are never taken for the project's.
#   1. $DTDEL_COUNT bench       -> OUT/phases/*.csv (phase split, counters on)
#   2. $DTDEL bench             -> OUT/<dataset>.csv (timings, phases merged)
#   3. build/summarize          -> OUT/summary.md, OUT/plotdata/,
#                                  OUT/readme-table.md
#   4. scripts/plots.sh         -> OUT/*.png
#   5. scripts/readme-table.sh  -> README.md's results table (between its
#                                  bench-table markers), from step 3's
#                                  OUT/readme-table.md: full run only
#   (2b. $DTDEL bench --reps 1 on uniform, sphere, bunny -> OUT/cold/)
#   (2c. $DTDEL build-bench -> OUT/build.txt (with dd_write's .vtu of the
#        same triangulation: size, time), seq-bench -> OUT/sequence.txt,
#        query-bench, edit-bench, refine-bench -> OUT/queries.txt, edits.txt, refine.txt,
#        batch-bench -> OUT/batch.txt, scripts/pybench.py -> OUT/python.txt,
#        regular-bench -> OUT/regular.txt)
#   (2d. weighted points, hidden points kept (issue 44): $DTDEL wbench ->
#        OUT/weighted/<dataset>.csv and OUT/wdelete.txt, the per-degree
#        deletion tables against CGAL's regular remove(); $DTDEL
#        wedits-bench -> OUT/wedits.txt, the re-weighting, move and set
#        deletion passes; summarize takes the CSVs after --weighted)
# DTDEL, DTDEL_COUNT and SUMMARIZE name the binaries (default build/dtdel,
# build/count/dtdel and build/summarize).  BENCH_SIZES=tiny runs the
# deletion bench on uniform points only and shrinks the whole-workload
# rows to a few thousand points: for tests of this script
# (tests/test_bench_quick.sh), never for figures.
mode=${1:-full}
scale=${2:-1}
DTDEL=${DTDEL:-build/dtdel}
DTDEL_COUNT=${DTDEL_COUNT:-build/count/dtdel}
SUMMARIZE=${SUMMARIZE:-build/summarize}
out=results
[ "$mode" = quick ] && out=results/quick
only=
[ "${BENCH_SIZES:-}" = tiny ] && only="--dataset uniform"
set -e
# by_mode FULL QUICK TINY: this run's size (BENCH_SIZES=tiny before the mode)
by_mode() {
    if [ "${BENCH_SIZES:-}" = tiny ]; then echo "$3"
    elif [ "$mode" = quick ]; then echo "$2"
    else echo "$1"; fi
}
# run FILE CMD...: CMD's output into $out/FILE, then shown; a failure sets rc
run() {
    f=$1; shift
    "$@" >"$out/$f" || rc=$?
    cat "$out/$f"
}
mkdir -p "$out/phases"
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
} >"$out/meta.txt"
echo "bench ($mode): phase split with the counting build" >&2
"$DTDEL_COUNT" bench --mode "$mode" --scale "$scale" $only --out $out/phases
echo "bench ($mode): timings with the release build" >&2
rc=0
"$DTDEL" bench --mode "$mode" --scale "$scale" $only --out "$out" --phases $out/phases || rc=$?
# Cold pass: every deletion timed once (--reps 1), so neither CGAL nor we
# run with branch predictors and caches trained by the repetitions of the
# same deletion: $out/cold/summary.md, low-degree datasets only.
mkdir -p $out/cold
{ cat $out/meta.txt; echo "reps: 1 (each deletion timed once)"; } >$out/cold/meta.txt
for ds in uniform sphere bunny; do
    "$DTDEL" bench --mode "$mode" --scale "$scale" --reps 1 --dataset "$ds" --out $out/cold || rc=$?
done
"$SUMMARIZE" $out/cold $out/cold/*.csv
# and that triangulation written by dd_write as a binary .vtu, once: the
# file's size and the time (summarize's notes); the file is removed
n=$(by_mode 1000000 200000 2000) nh=$(by_mode 16000 4000 500)
"$DTDEL" build-bench "$n" --reps 5 --write $out/build-write.vtu >$out/build.txt || rc=$?
rm -f $out/build-write.vtu
# and on a curve, where point location is most of the work
echo >>$out/build.txt
"$DTDEL" build-bench "$nh" --dataset helix >>$out/build.txt || rc=$?
# on 2 threads: ours against our 1 thread and CGAL's Parallel_tag, then
# weighted points against our 1 thread (issue 59's rows)
echo >>$out/build.txt
"$DTDEL" build-bench "$n" --threads 2 --reps $(by_mode 5 3 1) >>$out/build.txt || rc=$?
cat $out/build.txt
# whole workloads: a random sequence of deletions, no repetition, cold
# caches (seq-bench), on uniform points and on the degenerate grid
ns=$(by_mode 1000000 200000 2000) ng=$(by_mode 27000 8000 1000)
"$DTDEL" seq-bench "$ns" --fraction 0.1 >$out/sequence.txt || rc=$?
echo >>$out/sequence.txt
"$DTDEL" seq-bench "$ng" --dataset grid --fraction 0.5 >>$out/sequence.txt || rc=$?
cat $out/sequence.txt
# insertion of new points, location and nearest-vertex queries against
# CGAL (with and without Fast_location), and memory under churn
nq=$(by_mode 200000 50000 2000) kq=$(by_mode 50000 10000 500) lq=$(by_mode 100000 20000 1000)
run queries.txt "$DTDEL" query-bench "$nq" --inserts "$kq" --queries "$kq" --live "$lq"
# moves (smoothing) against move_if_no_collision, set deletion against
# remove(first, last)
ne=$(by_mode 100000 20000 1000) me=$(by_mode 200000 40000 2000)
run edits.txt "$DTDEL" edit-bench "$ne" --set "$me"
# refinement: the circumcentre of the largest cell inserted, again and
# again, our queue fed by dd_created_cells, CGAL's by find_conflicts and
# insert_in_hole; both must end in the same triangulation
nr=$(by_mode 100000 20000 1000)
run refine.txt "$DTDEL" refine-bench "$nr" --inserts "$nr"
# the whole-array calls against CGAL's best for a batch: range insertion
# (points, weighted points), sorted hinted location, the weighted move pass
nb=$(by_mode 200000 50000 2000) mb=$(by_mode 50000 10000 500) qb=$(by_mode 1000000 200000 5000) wb=$(by_mode 100000 20000 1000)
run batch.txt "$DTDEL" batch-bench "$nb" --inserts "$mb" --queries "$qb" --weighted "$wb"
# the Python package (make python) against scipy.spatial.Delaunay
run python.txt env PYTHONPATH="${DTDEL_PYTHONPATH:-$PWD/python}" /usr/bin/python3 scripts/pybench.py "$(by_mode full quick tiny)"
# regular triangulations (weighted points, hidden points kept): the
# construction and the insertion of new weighted points against CGAL's
# Regular_triangulation_3; cells and hidden sets must agree
nw=$(by_mode 1000000 200000 2000) nw0=$(by_mode 200000 50000 1000) mw=$(by_mode 50000 10000 500)
run regular.txt "$DTDEL" regular-bench "$nw" --base "$nw0" --inserts "$mw"
# weighted points (regular triangulations, hidden points kept, the bench's
# mode): every deletion strategy against CGAL's Regular_triangulation_3
# remove() per degree, then the re-weighting pass, the move pass and the
# set deletions; results compared with CGAL's, cells and hidden sets
mkdir -p $out/weighted
rm -f $out/weighted/*.csv
run wdelete.txt "$DTDEL" wbench --mode "$(by_mode full quick tiny)" --scale "$scale" --out $out/weighted
nwe=$(by_mode 100000 20000 1000) mwe=$(by_mode 200000 40000 2000)
run wedits.txt "$DTDEL" wedits-bench "$nwe" --set "$mwe"
csvs=$(ls $out/*.csv)
wcsvs=$(ls $out/weighted/*.csv 2>/dev/null || true)
"$SUMMARIZE" "$out" $csvs ${wcsvs:+--weighted $wcsvs}
sh scripts/plots.sh "$out"
if [ "$mode" = full ]; then
    sh scripts/readme-table.sh "$out/readme-table.md" README.md
    echo "results: $out/summary.md, $out/*.png and README.md's table" >&2
else
    echo "results: $out/summary.md and $out/*.png (quick run: README.md and results/ unchanged)" >&2
fi
exit $rc
