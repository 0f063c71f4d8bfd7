#!/bin/sh
# Runs the whole suite: the C test programs and the CLI tests, first in the
# release build, then in the sanitizer build (smaller sizes), then the
# threaded test in the ThreadSanitizer build (a data race fails it), and the
# contract build's tests (fourth argument, if given: the library built with
# -ffp-contract=fast -march=native, src/geom/fp.h; smaller sizes).  Counts the
# "ok"/"FAIL" lines and ends with "N passed, N failed"; exits 1 on any
# failure, including a test program that crashed or exited non-zero.
REL=${1:-build}
ASAN=${2:-build/asan}
TSAN=${3:-build/tsan}
CONTRACT=${4:-}
log=$(mktemp)
trap 'rm -f "$log"' EXIT

run() {   # run LABEL CMD...
    label=$1; shift
    start=$(date +%s)
    "$@" >"$log.out" 2>"$log.err"
    rc=$?
    cat "$log.out" >>"$log"
    if [ $rc -ne 0 ] && ! grep -q "^FAIL" "$log.out"; then
        echo "FAIL $label: exited with status $rc" >>"$log"
        tail -n 20 "$log.err" | sed 's/^/    /' >>"$log"
    fi
    echo "  $label: $(( $(date +%s) - start ))s" >&2
    rm -f "$log.out" "$log.err"
}

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export TSAN_OPTIONS=halt_on_error=1

for t in "$REL"/tests/test_*; do
    case "$t" in *.o) continue ;; esac
    run "release $(basename "$t")" "$t"
done
run "release layers" sh scripts/layers.sh "$REL/obj"
run "release layers-test" sh tests/test_layers.sh "$REL/obj"
run "release alloc" sh tests/test_alloc.sh
run "release make" sh tests/test_make.sh
run "release bench-quick" sh tests/test_bench_quick.sh "$REL"
run "release cli" sh tests/test_cli.sh "$REL/dtdel"
run "release write" sh tests/test_write.sh "$REL/dtdel"
run "release summarize" sh tests/test_summarize.sh "$REL/summarize"
run "release exports" sh tests/test_exports.sh "$REL"
run "release install" sh tests/test_install.sh "$REL"
# the Python bindings (make python: python/dtdel loads the release libdtdel.so)
run "release python" env PYTHONPATH=python /usr/bin/python3 tests/test_python.py "$REL/dtdel"
for t in "$ASAN"/tests/test_*; do
    case "$t" in *.o) continue ;; esac
    run "asan $(basename "$t")" "$t" small
done
run "asan cli" sh tests/test_cli.sh "$ASAN/dtdel"
run "asan write" sh tests/test_write.sh "$ASAN/dtdel"
run "asan summarize" sh tests/test_summarize.sh "$ASAN/summarize"
run "tsan test_threads" "$TSAN/tests/test_threads" small
if [ -n "$CONTRACT" ]; then
    for t in "$CONTRACT"/tests/test_*; do
        case "$t" in *.o) continue ;; esac
        run "contract $(basename "$t")" "$t" small
    done
fi

grep -A20 "^FAIL " "$log" | grep -v '^ok ' | sed 's/^/  /'
passed=$(grep -c "^ok " "$log")
failed=$(grep -c "^FAIL " "$log")
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ] && [ "$passed" -gt 0 ]
