#!/bin/sh
# test_bench_quick.sh BUILD -- `make bench-quick` writes its figures into
# results/quick/ and leaves README.md and the full run's results/ byte for
# byte as they were.  Runs scripts/bench.sh quick (what make bench-quick
# runs) on a copy of the tracked tree, with the deletion bench scaled down
# and BENCH_SIZES=tiny, so it takes seconds; the binaries are BUILD's.
# Prints "ok NAME" / "FAIL NAME: why" lines; exits 1 on a failure.
top=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-build}" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
ok() { echo "ok bench-quick/$1"; }
bad() { echo "FAIL bench-quick/$1: $2"; fail=1; }

tree=$tmp/tree
mkdir -p "$tree"
(cd "$top" && git ls-files -z README.md scripts results datasets | xargs -0 tar cf -) | (cd "$tree" && tar xf -)
(cd "$tree" && find README.md results -type f | sort | xargs md5sum) >"$tmp/before"
(cd "$tree" && DTDEL="$build/dtdel" DTDEL_COUNT="$build/dtdel" SUMMARIZE="$build/summarize" DTDEL_PYTHONPATH="$top/python" \
    BENCH_SIZES=tiny sh scripts/bench.sh quick 0.02) >"$tmp/out" 2>"$tmp/err"
rc=$?
[ $rc -eq 0 ] && ok runs || bad runs "scripts/bench.sh quick exited $rc: $(tail -n 5 "$tmp/err")"
(cd "$tree" && find README.md results -path results/quick -prune -o -type f -print | sort | xargs md5sum) >"$tmp/after"
if cmp -s "$tmp/before" "$tmp/after"; then
    ok readme-and-results-unchanged
else
    bad readme-and-results-unchanged "changed: $(diff "$tmp/before" "$tmp/after" | grep '^[<>]' | head -n 4 | tr '\n' ' ')"
fi
[ -s "$tree/results/quick/summary.md" ] && ok writes-results-quick ||
    bad writes-results-quick "no results/quick/summary.md"
# the weighted rows (issue 44): deletion tables and edits at tiny sizes,
# every result compared with CGAL's (0 mismatches; n/a while the engine
# refuses a call on weighted points)
q=$tree/results/quick
grep -qx "wbench: 0 mismatches" "$q/wdelete.txt" 2>/dev/null && [ -s "$q/weighted/wuniform.csv" ] &&
    ok weighted-deletions || bad weighted-deletions "wdelete.txt: $(tail -n 2 "$q/wdelete.txt" 2>/dev/null | tr '\n' ' ')"
nw=$(grep -cE '^(wreweight|wmove|wdelete-set 10%|wdelete-set 90%):.*(; 0 mismatches|mismatches n/a)' "$q/wedits.txt" 2>/dev/null)
[ "$nw" = 4 ] && ok weighted-edits || bad weighted-edits "wedits.txt: $(head -c 400 "$q/wedits.txt" 2>/dev/null)"
grep -q "^## All weighted datasets" "$q/summary.md" 2>/dev/null && grep -q "^| weighted edits" "$q/readme-table.md" &&
    ok weighted-summary || bad weighted-summary "no weighted rows in summary.md or readme-table.md"
# the mesh file of build-bench --write: its size and time in the notes, the file gone
grep -q "Written by \`dd_write\` as a binary .vtu, the triangulation of .* MB, in .* s\." "$q/readme-table.md" &&
    [ ! -e "$q/build-write.vtu" ] && ok write-note ||
    bad write-note "no dd_write note in readme-table.md, or results/quick/build-write.vtu left: $(grep write "$q/build.txt")"
# the parallel construction rows (issue 59): ours on 2 threads against our
# 1 thread and CGAL's Parallel_tag, both identical to CGAL's; weighted too
grep -q "^parallel: 2 threads, dtdel .*x its 1 thread, .*x CGAL Parallel_tag on 2 threads" "$q/build.txt" 2>/dev/null &&
    grep -q "^weighted parallel: 2 threads" "$q/build.txt" && [ "$(grep -c '^identical to CGAL: yes' "$q/build.txt")" -eq 3 ] &&
    grep -qx "identical to 1 thread: yes" "$q/build.txt" &&
    grep -q "on 2 threads .*× our one thread and .*× CGAL's Parallel_tag on as many, weighted points" "$q/readme-table.md" &&
    ok parallel-rows || bad parallel-rows "build.txt: $(tail -n 14 "$q/build.txt" 2>/dev/null | tr '\n' ' ')"
# the Python package against scipy: its table and notes
[ "$(grep -c '^| .* | .* | .* | .*× |$' "$q/readme-table.md" 2>/dev/null)" -gt 0 ] &&
    grep -q "^| Python: \`dtdel.Delaunay\` against" "$q/readme-table.md" &&
    [ "$(sed -n '/^| Python: /,/^$/p' "$q/readme-table.md" | grep -c '×')" -eq 5 ] &&
    grep -q "An array call from Python takes .* its C call's own time" "$q/readme-table.md" &&
    grep -q "Two threads build two triangulations" "$q/readme-table.md" &&
    ok python-rows || bad python-rows "python.txt: $(head -c 600 "$q/python.txt" 2>/dev/null)"
grep -q "results/quick/summary.md" "$tmp/err" && ok says-where ||
    bad says-where "the run does not say where its results are"
exit $fail
