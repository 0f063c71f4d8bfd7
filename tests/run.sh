#!/bin/sh
# Runs the whole suite: the C test programs and the CLI tests, in the
# release build and in the sanitizer build (smaller sizes), the threaded
# test in the ThreadSanitizer build (a data race fails it), and the
# contract build's tests (fourth argument, if given: the library built with
# -ffp-contract=fast -march=native, src/geom/fp.h; smaller sizes).  The
# programs run TEST_JOBS at a time (default: the number of processors),
# the slowest queued first; their outputs are reported in the order listed
# here.  Counts the "ok"/"FAIL" lines (and shows the lines a test begins
# with "#: ", its summary) and ends with "N passed, N failed";
# exits 1 on any failure, including a test program that crashed or exited
# non-zero.
REL=${1:-build}
ASAN=${2:-build/asan}
TSAN=${3:-build/tsan}
CONTRACT=${4:-}
JOBS=${TEST_JOBS:-$(nproc 2>/dev/null || echo 2)}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export TSAN_OPTIONS=halt_on_error=1

# Single-quotes each argument for a job script.
quote() {
    for a in "$@"; do printf "'%s' " "$(printf '%s' "$a" | sed "s/'/'\\\\''/g")"; done
}

n=0
# job LABEL CMD...: queues CMD as job script $dir/NNN.sh, which writes its
# report to $dir/NNN.log and its time to stderr.
job() {
    n=$((n + 1))
    f=$dir/$(printf %04d $n)
    label=$1; shift
    cat >"$f.sh" <<JOB
start=\$(date +%s)
$(quote "$@") >"$f.out" 2>"$f.err"
rc=\$?
cat "$f.out" >"$f.log"
grep '^#: ' "$f.out" | sed "s/^#: /  $label: /" >&2
if [ \$rc -ne 0 ] && ! grep -q "^FAIL" "$f.out"; then
    echo "FAIL $label: exited with status \$rc" >>"$f.log"
    tail -n 20 "$f.err" | sed 's/^/    /' >>"$f.log"
fi
echo "  $label: \$(( \$(date +%s) - start ))s" >&2
JOB
}

# The slowest programs first, so that no long one starts last.
slow="test_delete test_wgrr test_range test_wdelete test_regular test_link test_contract test_move"
for s in $slow; do
    [ -x "$ASAN/tests/$s" ] && job "asan $s" "$ASAN/tests/$s" small
    [ -x "$REL/tests/$s" ] && job "release $s" "$REL/tests/$s"
done
is_slow() { case " $slow " in *" $1 "*) return 0 ;; esac; return 1; }

for t in "$REL"/tests/test_*; do
    case "$t" in *.o) continue ;; esac
    is_slow "$(basename "$t")" || job "release $(basename "$t")" "$t"
done
job "release layers" sh scripts/layers.sh "$REL/obj"
job "release layers-test" sh tests/test_layers.sh "$REL/obj"
job "release alloc" sh tests/test_alloc.sh
job "release make" sh tests/test_make.sh
job "release fpeval" sh tests/test_fpeval.sh
job "release bench-quick" sh tests/test_bench_quick.sh "$REL"
job "release cli" sh tests/test_cli.sh "$REL/dtdel"
job "release write" sh tests/test_write.sh "$REL/dtdel"
job "release summarize" sh tests/test_summarize.sh "$REL/summarize"
job "release exports" sh tests/test_exports.sh "$REL"
job "release install" sh tests/test_install.sh "$REL"
# the Python package (make python: the compiled extension in place in
# python/dtdel; test_python.py also installs it with make install and
# into a venv with pip)
job "release python" env PYTHONPATH=python /usr/bin/python3 tests/test_python.py "$REL/dtdel"
job "release python-batch" env PYTHONPATH=python:tests /usr/bin/python3 tests/test_python_batch.py "$REL/dtdel"
job "release python-scipy" env PYTHONPATH=python:tests /usr/bin/python3 tests/test_python_scipy.py "$REL/dtdel"
for t in "$ASAN"/tests/test_*; do
    case "$t" in *.o) continue ;; esac
    is_slow "$(basename "$t")" || job "asan $(basename "$t")" "$t" small
done
job "asan cli" sh tests/test_cli.sh "$ASAN/dtdel"
job "asan write" sh tests/test_write.sh "$ASAN/dtdel"
job "asan summarize" sh tests/test_summarize.sh "$ASAN/summarize"
job "tsan test_threads" "$TSAN/tests/test_threads" small
job "tsan test_parallel" "$TSAN/tests/test_parallel" small
if [ -n "$CONTRACT" ]; then
    for t in "$CONTRACT"/tests/test_*; do
        case "$t" in *.o) continue ;; esac
        job "contract $(basename "$t")" "$t" small
    done
fi

ls "$dir"/*.sh | xargs -n 1 -P "$JOBS" sh
log=$dir/all
for f in "$dir"/*.sh; do
    if [ -f "${f%.sh}.log" ]; then cat "${f%.sh}.log"; else echo "FAIL $f: did not run"; fi
done >"$log"

grep -A20 "^FAIL " "$log" | grep -v '^ok ' | sed 's/^/  /'
passed=$(grep -c "^ok " "$log")
failed=$(grep -c "^FAIL " "$log")
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ] && [ "$passed" -gt 0 ]
